//! The landscape-phone layout's controls: a narrow rail beside the canvas with the
//! tools, Undo and Redo; its top button opens the full side panel next to it.

use crate::action::Action;
use crate::app::MarblingApp;
use crate::marbling::tools::ToolKind;
use crate::shell::layout::{RAIL_WIDTH, TOUCH_TARGET, touch_spacing};
use crate::shell::mode::Mode;

impl MarblingApp {
    /// Shows the rail as the leftmost panel of `ui` (the whole window).
    pub(crate) fn tool_rail(&mut self, ui: &mut egui::Ui) {
        egui::Panel::left("marbling_rail")
            .frame(egui::Frame::side_top_panel(ui.style()))
            .show_separator_line(false)
            .resizable(false)
            .exact_size(RAIL_WIDTH)
            .show(ui, |ui| {
                touch_spacing(ui);
                let full = egui::vec2(ui.available_width(), TOUCH_TARGET);
                egui::ScrollArea::vertical().show(ui, |ui| {
                    let open = self.panels.rail_panel_open;
                    let more = ui
                        .add(egui::Button::selectable(open, "≡ Panel").min_size(full))
                        .on_hover_text("All the controls: files, export, ink, history, noise");
                    self.control("rail-panel", &more);
                    if more.clicked() {
                        self.panels.rail_panel_open = !open;
                    }
                    for t in ToolKind::ALL {
                        let selected = self.prefs.tool == t && self.editor.mode == Mode::Marbling;
                        let r =
                            ui.add(egui::Button::selectable(selected, t.label()).min_size(full));
                        self.control(format!("rail-{}", t.name()), &r);
                        if r.clicked() {
                            self.prefs.tool = t;
                            self.apply(Action::SetMode(Mode::Marbling));
                        }
                    }
                    let undo = ui.add_enabled(
                        self.editor.history.can_undo(),
                        egui::Button::new("Undo").min_size(full),
                    );
                    self.control("rail-undo", &undo);
                    if undo.clicked() {
                        self.apply(Action::Undo);
                    }
                    let redo = ui.add_enabled(
                        self.editor.history.can_redo(),
                        egui::Button::new("Redo").min_size(full),
                    );
                    self.control("rail-redo", &redo);
                    if redo.clicked() {
                        self.apply(Action::Redo);
                    }
                });
            });
    }
}
