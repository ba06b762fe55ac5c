//! The side panel's History section: Undo and Redo, Play, the list of steps (the
//! current one scrolled into view, undone ones greyed until a new edit drops them) and
//! the abandoned branches.

use crate::action::Action;
use crate::frame::Frame;
use egui::RichText;

/// Undo and Redo (in the History section, and beside the tools on a phone).
pub(crate) fn undo_redo_ui(ui: &mut egui::Ui, frame: &mut Frame<'_>) {
    let undo = ui
        .add_enabled(frame.editor.history.can_undo(), egui::Button::new("Undo"))
        .on_hover_text("Ctrl/Cmd+Z: takes the last gesture back");
    frame.control("undo", &undo);
    if undo.clicked() {
        frame.act(Action::Undo);
    }
    let redo = ui
        .add_enabled(frame.editor.history.can_redo(), egui::Button::new("Redo"))
        .on_hover_text("Ctrl/Cmd+Shift+Z");
    frame.control("redo", &redo);
    if redo.clicked() {
        frame.act(Action::Redo);
    }
}

/// The History section and where its list was last scrolled to.
#[derive(Debug, Default)]
pub(crate) struct HistoryPanel {
    /// The (current row, row count) the list was scrolled for.
    scrolled: Option<(usize, usize)>,
}

impl HistoryPanel {
    /// The History section: Undo, Redo, Play, the steps (undone ones greyed, for Redo)
    /// and the abandoned branches.
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.label(RichText::new("History").strong());
        ui.horizontal(|ui| {
            undo_redo_ui(ui, frame);
            let playing = frame.editor.playback.is_some();
            let play = ui
                .add_enabled(
                    !frame.editor.history.design().ops.is_empty(),
                    egui::Button::new(if playing { "Close player" } else { "Play" }),
                )
                .on_hover_text("Play the making step by step, with captions and the maths");
            frame.control("play", &play);
            if play.clicked() {
                frame.act(Action::Play(!playing));
            }
        });
        if frame.editor.landing && frame.editor.pristine {
            // The start-up design behind the gallery is nobody's history yet.
            ui.label("Pick a pattern in the gallery, or start a new sheet: its steps show here.");
            return;
        }
        let n = frame.editor.history.steps().len();
        // The player's step while it is open, else the step viewed.
        let shown = match frame.editor.playback {
            Some(p) => p.current_step().map_or(0, |k| k + 1),
            None => frame.editor.history.shown_steps(),
        };
        let mut clicked = None;
        let mut redo_to = None;
        let mut rows_drawn = Vec::new();
        // Undone steps stay listed, greyed, until a new edit drops them: a click on one
        // redoes up to it.
        let undone: Vec<String> = frame
            .editor
            .history
            .undone()
            .map(|s| s.label.clone())
            .collect();
        let weak = ui.visuals().weak_text_color();
        const LIST_HEIGHT: f32 = 124.0;
        // A row is a selectable label: one interactive height.
        let row_height = ui.spacing().interact_size.y;
        let rows = n + 1 + undone.len();
        let mut list = egui::ScrollArea::vertical()
            .max_height(LIST_HEIGHT)
            .id_salt("history");
        if self.scrolled != Some((shown, rows)) {
            // A new step, an undo or a step played: the current row comes into view at
            // the list's bottom (greyed undone steps below it stay reachable).
            self.scrolled = Some((shown, rows));
            let row = row_height + ui.spacing().item_spacing.y;
            list = list.vertical_scroll_offset(((shown + 1) as f32 * row - LIST_HEIGHT).max(0.0));
        }
        let shown_list = list.show_rows(ui, row_height, rows, |ui, rows| {
            for i in rows {
                if i > n {
                    let j = i - n - 1;
                    let r = ui
                        .selectable_label(
                            false,
                            RichText::new(format!("{i}. {}", undone[j])).color(weak),
                        )
                        .on_hover_text("Undone: click to redo up to here");
                    if r.clicked() {
                        redo_to = Some(j + 1);
                    }
                    rows_drawn.push((format!("redo-step-{}", j + 1), r));
                    continue;
                }
                let label = if i == 0 {
                    "start".to_owned()
                } else {
                    format!("{i}. {}", frame.editor.history.steps()[i - 1].label)
                };
                let r = ui.selectable_label(i == shown, label);
                if r.clicked() {
                    clicked = Some(i);
                }
                rows_drawn.push((format!("history-{i}"), r));
            }
        });
        // Rows the list's own scrolling hides are not listed (they are not where they
        // would be clicked); one in the list's window but past the screen is.
        let window = shown_list.inner_rect.y_range();
        for (name, r) in rows_drawn {
            if window.contains(r.rect.center().y) {
                frame.control(name, &r);
            }
        }
        if let Some(k) = clicked {
            frame.act(Action::View(Some(k)));
        }
        for _ in 0..redo_to.unwrap_or(0) {
            frame.act(Action::Redo);
        }
        if frame.editor.history.is_viewing_earlier() {
            ui.label(
                RichText::new(format!(
                    "Showing step {shown} of {n}. Editing now starts a new branch; the later steps stay restorable below."
                ))
                .weak(),
            );
        }
        let branches: Vec<String> = frame
            .editor
            .history
            .branches()
            .iter()
            .map(|b| b.label.clone())
            .collect();
        if !branches.is_empty() {
            ui.label(RichText::new("Abandoned branches (click to restore)").weak());
            for (i, label) in branches.iter().enumerate().rev() {
                let r = ui
                    .button(format!("↺ {label}"))
                    .on_hover_text("Brings this design back as a new step (undoable)");
                frame.control(format!("restore-{i}"), &r);
                if r.clicked() {
                    frame.act(Action::Restore(i));
                }
            }
        }
    }
}
