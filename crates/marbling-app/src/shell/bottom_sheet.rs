//! The portrait layout's controls: a bottom sheet under the canvas with a row of tabs
//! (tools, ink, history, files, noise) over the chosen part of the side panel. Tapping
//! the open tab, or the arrow, collapses the sheet to its tab row.

use crate::action::Action;
use crate::frame::Frame;
use crate::shell::layout::{SHEET_MAX_FRACTION, SheetTab, TOUCH_TARGET};
use crate::shell::mode::Mode;

/// The sheet's chosen tab and whether it is open.
#[derive(Debug)]
pub(crate) struct BottomSheet {
    tab: SheetTab,
    open: bool,
}

impl Default for BottomSheet {
    fn default() -> Self {
        Self {
            tab: SheetTab::Tools,
            open: true,
        }
    }
}

impl BottomSheet {
    /// The sheet as the lowest panel of `ui` (the whole window): its tab row, and when
    /// open, [`SHEET_MAX_FRACTION`] of the window's height.
    pub fn panel(&self, ui: &egui::Ui) -> egui::Panel {
        let panel = egui::Panel::bottom("marbling_sheet")
            .frame(egui::Frame::side_top_panel(ui.style()))
            .show_separator_line(false)
            .resizable(false);
        if self.open {
            panel.exact_size((ui.max_rect().height() * SHEET_MAX_FRACTION).round())
        } else {
            panel
        }
    }

    /// The tab whose sections the open sheet shows in `mode`; `None` when collapsed.
    pub fn open_tab(&self, mode: Mode) -> Option<SheetTab> {
        self.open.then(|| self.shown_tab(mode))
    }

    /// Collapses the sheet to its tab row (the player takes its room).
    pub fn close(&mut self) {
        self.open = false;
    }

    /// The tab the sheet shows in `mode`: the noise playground shows its own tab.
    fn shown_tab(&self, mode: Mode) -> SheetTab {
        match (mode, self.tab) {
            (Mode::Noise, SheetTab::Files) => SheetTab::Files,
            (Mode::Noise, _) => SheetTab::Noise,
            (Mode::Marbling, SheetTab::Noise) => SheetTab::Tools,
            (Mode::Marbling, tab) => tab,
        }
    }

    /// The tab row and the collapse arrow, sharing the sheet's width.
    pub fn tabs_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        let open = self.open;
        let current = self.shown_tab(frame.editor.mode);
        ui.horizontal(|ui| {
            let gaps = ui.spacing().item_spacing.x * SheetTab::ALL.len() as f32;
            let width = ((ui.available_width() - TOUCH_TARGET - gaps) / SheetTab::ALL.len() as f32)
                .max(TOUCH_TARGET);
            for tab in SheetTab::ALL {
                let button = egui::Button::selectable(open && current == tab, tab.label())
                    .min_size(egui::vec2(width, TOUCH_TARGET));
                let r = ui.add(button);
                frame.control(tab.control(), &r);
                if r.clicked() {
                    self.choose_tab(tab, open && current == tab, frame);
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
            frame.control("sheet-toggle", &arrow);
            if arrow.clicked() {
                self.open = !open;
            }
        });
    }

    /// A tap on `tab`: opens it (switching to the noise playground or back), or
    /// collapses the sheet when it was the open tab.
    fn choose_tab(&mut self, tab: SheetTab, was_open: bool, frame: &mut Frame<'_>) {
        if was_open {
            self.open = false;
            return;
        }
        self.open = true;
        self.tab = tab;
        match tab {
            SheetTab::Noise => frame.act(Action::SetMode(Mode::Noise)),
            SheetTab::Files => {}
            _ => frame.act(Action::SetMode(Mode::Marbling)),
        }
    }
}
