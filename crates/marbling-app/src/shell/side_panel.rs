//! The side panel: the mode switch, then the sections of `sections.rs` in order, each
//! its feature's `ui`.

use crate::action::Action;
use crate::app::MarblingApp;
use crate::frame::with_frame;
use crate::shell::mode::Mode;
use crate::shell::sections::{self, Section};
use egui::RichText;

impl MarblingApp {
    pub(crate) fn side_panel(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        ui.horizontal(|ui| {
            let mut mode = self.editor.mode;
            let m = ui.selectable_value(
                &mut mode,
                Mode::Marbling,
                RichText::new("Marbling").heading(),
            );
            self.control("mode-marbling", &m);
            let n = ui.selectable_value(&mut mode, Mode::Noise, RichText::new("Noise").heading());
            self.control("mode-noise", &n);
            self.apply(Action::SetMode(mode));
        });
        for (section, rule) in sections::shown(self.editor.mode, None) {
            if rule {
                ui.separator();
            }
            self.section(section, ui, frame);
        }
    }

    /// Draws one section of the panel.
    pub(crate) fn section(&mut self, section: Section, ui: &mut egui::Ui, frame: &eframe::Frame) {
        match section {
            Section::File => {
                let share = crate::store::file_panel::Sharing {
                    address: &mut self.address,
                    pictures: &mut self.panels.pictures,
                    qr: &mut self.panels.qr,
                };
                with_frame!(self, |f| self.panels.file.ui(ui, share, &mut f));
            }
            Section::Export => with_frame!(self, |f| self.panels.export.ui(
                ui,
                frame,
                &mut self.panels.print,
                &mut self.panels.view3d,
                &mut f
            )),
            Section::Noise => with_frame!(self, |f| self.noise.ui(ui, &mut f)),
            Section::Surface => {
                with_frame!(self, |f| crate::noise::panel::surface_ui(ui, &mut f));
            }
            Section::Tool => {
                with_frame!(self, |f| crate::marbling::tool_panel::ui(ui, &mut f));
                // Under the Flow tool, and under any other while it shows (its Stop).
                if self.prefs.tool == crate::marbling::tools::ToolKind::Flow
                    || self.rendering.stream.is_on()
                {
                    with_frame!(self, |f| self.rendering.stream.ui(ui, &mut f));
                }
            }
            Section::Ink => with_frame!(self, |f| self.panels.ink.ui(ui, &mut f)),
            Section::Picture => with_frame!(self, |f| self.panels.pictures.ui(ui, &mut f)),
            Section::Video => with_frame!(self, |f| self.rendering.video.ui(ui, &mut f)),
            Section::Midi => with_frame!(self, |f| self.panels.midi.ui(ui, &mut f)),
            Section::Sound => with_frame!(self, |f| self.panels.sound.ui(ui, &mut f)),
            Section::History => with_frame!(self, |f| self.panels.history.ui(ui, &mut f)),
            Section::Recent => {
                let recent = self.session.recent();
                with_frame!(self, |f| self.panels.recent.ui(ui, recent, &mut f));
            }
        }
    }
}
