//! The landscape-phone layout's controls: a narrow rail beside the canvas with the
//! tools, Undo and Redo; its top button opens the full side panel next to it.

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::tools::ToolKind;
use crate::shell::layout::{RAIL_WIDTH, TOUCH_TARGET, touch_spacing};
use crate::shell::mode::Mode;

/// The rail and whether the full side panel beside it is open.
#[derive(Debug, Default)]
pub(crate) struct ToolRail {
    panel_open: bool,
}

impl ToolRail {
    /// Whether the full side panel beside the rail is open.
    pub fn panel_open(&self) -> bool {
        self.panel_open
    }

    /// Closes the full side panel (a gesture on the canvas gives it the room back).
    pub fn close_panel(&mut self) {
        self.panel_open = false;
    }

    /// Shows the rail as the leftmost panel of `ui` (the whole window).
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        egui::Panel::left("marbling_rail")
            .frame(egui::Frame::side_top_panel(ui.style()))
            .show_separator_line(false)
            .resizable(false)
            .exact_size(RAIL_WIDTH)
            .show(ui, |ui| {
                touch_spacing(ui);
                let full = egui::vec2(ui.available_width(), TOUCH_TARGET);
                egui::ScrollArea::vertical().show(ui, |ui| {
                    let open = self.panel_open;
                    let more = ui
                        .add(egui::Button::selectable(open, "≡ Panel").min_size(full))
                        .on_hover_text("All the controls: files, export, ink, history, noise");
                    frame.control("rail-panel", &more);
                    if more.clicked() {
                        self.panel_open = !open;
                    }
                    let marbling = frame.editor.mode == Mode::Marbling;
                    for t in ToolKind::ALL {
                        let selected = frame.prefs.tool == t && marbling;
                        let r =
                            ui.add(egui::Button::selectable(selected, t.label()).min_size(full));
                        frame.control(format!("rail-{}", t.name()), &r);
                        if r.clicked() {
                            frame.prefs.tool = t;
                            frame.act(Action::SetMode(Mode::Marbling));
                        }
                    }
                    let history = &frame.editor.history;
                    let (can_undo, can_redo) = (history.can_undo(), history.can_redo());
                    let undo = ui.add_enabled(can_undo, egui::Button::new("Undo").min_size(full));
                    frame.control("rail-undo", &undo);
                    if undo.clicked() {
                        frame.act(Action::Undo);
                    }
                    let redo = ui.add_enabled(can_redo, egui::Button::new("Redo").min_size(full));
                    frame.control("rail-redo", &redo);
                    if redo.clicked() {
                        frame.act(Action::Redo);
                    }
                });
            });
    }
}
