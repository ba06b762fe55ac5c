//! The portrait layout's controls: a bottom sheet under the canvas with a row of tabs
//! (tools, ink, history, files, noise) over the chosen part of the side panel. Tapping
//! the open tab, or the arrow, collapses the sheet to its tab row.

use crate::action::Action;
use crate::app::MarblingApp;
use crate::shell::layout::{SHEET_MAX_FRACTION, SheetTab, TOUCH_TARGET, touch_spacing};
use crate::shell::mode::Mode;
use crate::shell::sections;

impl MarblingApp {
    /// Shows the bottom sheet as the lowest panel of `ui` (the whole window).
    pub(crate) fn bottom_sheet(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let open_height = (ui.max_rect().height() * SHEET_MAX_FRACTION).round();
        let panel = egui::Panel::bottom("marbling_sheet")
            .frame(egui::Frame::side_top_panel(ui.style()))
            .show_separator_line(false)
            .resizable(false);
        let panel = if self.panels.sheet_open {
            panel.exact_size(open_height)
        } else {
            panel
        };
        panel.show(ui, |ui| {
            touch_spacing(ui);
            self.sheet_tabs(ui);
            if self.panels.sheet_open {
                egui::ScrollArea::vertical()
                    .auto_shrink([false, false])
                    .show(ui, |ui| self.sheet_content(ui, frame));
            }
        });
    }

    /// The tab row and the collapse arrow, sharing the sheet's width.
    fn sheet_tabs(&mut self, ui: &mut egui::Ui) {
        let open = self.panels.sheet_open;
        let current = self.shown_tab();
        ui.horizontal(|ui| {
            let gaps = ui.spacing().item_spacing.x * SheetTab::ALL.len() as f32;
            let width = ((ui.available_width() - TOUCH_TARGET - gaps) / SheetTab::ALL.len() as f32)
                .max(TOUCH_TARGET);
            for tab in SheetTab::ALL {
                let button = egui::Button::selectable(open && current == tab, tab.label())
                    .min_size(egui::vec2(width, TOUCH_TARGET));
                let r = ui.add(button);
                self.control(tab.control(), &r);
                if r.clicked() {
                    self.choose_tab(tab, open && current == tab);
                }
            }
            let arrow = ui
                .add(
                    egui::Button::new(if open { "▼" } else { "▲" })
                        .min_size(egui::vec2(TOUCH_TARGET, TOUCH_TARGET)),
                )
                .on_hover_text(if open {
                    "Collapse the controls: more room for the sheet"
                } else {
                    "Open the controls"
                });
            self.control("sheet-toggle", &arrow);
            if arrow.clicked() {
                self.panels.sheet_open = !open;
            }
        });
    }

    /// The tab the sheet shows: the noise playground shows its own tab.
    fn shown_tab(&self) -> SheetTab {
        match (self.editor.mode, self.panels.sheet_tab) {
            (Mode::Noise, SheetTab::Files) => SheetTab::Files,
            (Mode::Noise, _) => SheetTab::Noise,
            (Mode::Marbling, SheetTab::Noise) => SheetTab::Tools,
            (Mode::Marbling, tab) => tab,
        }
    }

    /// A tap on `tab`: opens it (switching to the noise playground or back), or
    /// collapses the sheet when it was the open tab.
    fn choose_tab(&mut self, tab: SheetTab, was_open: bool) {
        if was_open {
            self.panels.sheet_open = false;
            return;
        }
        self.panels.sheet_open = true;
        self.panels.sheet_tab = tab;
        match tab {
            SheetTab::Noise => self.apply(Action::SetMode(Mode::Noise)),
            SheetTab::Files => {}
            _ => self.apply(Action::SetMode(Mode::Marbling)),
        }
    }

    fn sheet_content(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let tab = self.shown_tab();
        if tab == SheetTab::Tools {
            // Undo beside the tools, where a phone's user draws.
            ui.horizontal(|ui| self.undo_redo(ui));
        }
        for (section, rule) in sections::shown(self.editor.mode, Some(tab)) {
            if rule {
                ui.separator();
            }
            self.section(section, ui, frame);
        }
    }
}
