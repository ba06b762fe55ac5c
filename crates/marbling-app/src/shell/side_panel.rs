//! The side panel: the sections of `sections.rs` in order (files and export are drawn
//! here; each other section is its feature's `ui`) and the status bar.

use crate::action::Action;
use crate::app::MarblingApp;
use crate::frame::with_frame;
use crate::platform;
use crate::shell::layout::status_button;
use crate::shell::mode::Mode;
use crate::shell::sections::{self, Section};
use egui::{Color32, RichText};

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
            Section::File => self.file_section(ui),
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

    pub(crate) fn file_section(&mut self, ui: &mut egui::Ui) {
        ui.horizontal_wrapped(|ui| {
            let gallery = ui
                .button("Gallery")
                .on_hover_text("The traditional patterns, and a blank sheet");
            self.control("gallery", &gallery);
            if gallery.clicked() {
                self.apply(Action::ShowGallery(true));
                self.apply(Action::SetMode(Mode::Marbling));
            }
            let new = ui
                .button("New")
                .on_hover_text("A blank sheet of the size below");
            self.control("new", &new);
            if new.clicked() {
                self.apply(Action::NewSheet);
            }
            let open = ui.button("Open…").on_hover_text("Open a design JSON file");
            self.control("open", &open);
            if open.clicked() {
                platform::pick_file(
                    self.panels.pick.clone(),
                    platform::DESIGN_FILE,
                    ui.ctx().clone(),
                );
            }
            let save = ui.button("Save JSON");
            self.control("save-json", &save);
            if save.clicked() {
                let json = self.editor.history.design().to_json_pretty();
                match platform::save_file("design.json", "application/json", json.as_bytes()) {
                    Ok(()) => self.info("design saved as JSON"),
                    Err(e) => self.error(e),
                }
            }
            let copy = ui
                .button("Copy link")
                .on_hover_text("A link that opens this design");
            self.control("copy-link", &copy);
            with_frame!(self, |f| self.panels.qr.button_ui(ui, &mut f));
            if copy.clicked() {
                // A zoomed or panned view goes with the link; the fitted one does not.
                let view = match (self.editor.view, self.editor.fit) {
                    (Some(v), Some((fitted, _))) if v == fitted => None,
                    (Some(v), _) => Some(v.spec(self.editor.canvas_size)),
                    (None, _) => None,
                };
                let link = crate::store::links::design_link(self.editor.history.design(), view);
                let fragment = link.split_once('#').map_or(0, |(_, f)| f.len());
                if self.editor.history.design().background_image.is_some()
                    && fragment > marbling_core::MAX_PICTURE_LINK_CHARS
                {
                    self.panels.pictures.offer_link_choice(self.editor.key);
                    self.error(format!(
                        "the picture makes the link {} KB; links hold about {} KB: downscale the picture for the link, or save the JSON file",
                        fragment / 1024,
                        marbling_core::MAX_PICTURE_LINK_CHARS / 1024
                    ));
                    return;
                }
                if link.len() > marbling_core::MAX_LINK_CHARS {
                    let json = self.editor.history.design().to_json_pretty();
                    let saved =
                        platform::save_file("design.json", "application/json", json.as_bytes());
                    self.error(format!(
                        "the link would be {} characters, more than browsers accept ({}): {}",
                        link.len(),
                        marbling_core::MAX_LINK_CHARS,
                        match saved {
                            Ok(()) => "the design was saved as JSON instead".to_owned(),
                            Err(e) => e,
                        }
                    ));
                    return;
                }
                if let Some((_, fragment)) = link.split_once('#') {
                    platform::set_fragment(fragment);
                    self.editor.last_fragment = Some(fragment.to_owned());
                }
                ui.ctx().copy_text(link.clone());
                self.info(format!("link copied ({} characters)", link.len()));
            }
        });
        with_frame!(self, |f| self.panels.pictures.link_offer_ui(ui, &mut f));
        with_frame!(self, |f| self.panels.qr.offer_ui(ui, &mut f));
        ui.horizontal(|ui| {
            ui.label("New sheet");
            ui.add(
                egui::DragValue::new(&mut self.panels.new_size[0])
                    .range(1..=marbling_core::MAX_SIDE)
                    .suffix(" px"),
            );
            ui.label("×");
            ui.add(
                egui::DragValue::new(&mut self.panels.new_size[1])
                    .range(1..=marbling_core::MAX_SIDE)
                    .suffix(" px"),
            );
        });
        let mut aloud = crate::shell::accessibility::reading_aloud(ui.ctx());
        let read = ui
            .checkbox(&mut aloud, "Read controls aloud")
            .on_hover_text(
                "Alt+Shift+R: each control is spoken as it takes focus (Tab moves between \
             controls, Enter presses one)",
            );
        self.control("read-aloud", &read);
        if read.changed() {
            crate::shell::accessibility::set_reading_aloud(ui.ctx(), aloud);
        }
    }

    pub(crate) fn status_bar(&mut self, ui: &mut egui::Ui) {
        let now = ui.input(|i| i.time);
        if let Some(m) = &mut self.panels.message {
            let (current, again) = m.shown_at(now);
            if let Some(s) = again {
                ui.ctx()
                    .request_repaint_after(std::time::Duration::from_secs_f64(s));
            }
            if !current {
                self.panels.message = None;
            }
        }
        // The live preview's note, only while the preview is on screen (a drag, or an
        // exact frame still being drawn).
        let drawing = self.rendering.progress().filter(|p| *p < 1.0);
        let previewing = self.editor.active.is_some() || drawing.is_some();
        // One row, always the same height (a second row would move the canvas's edge
        // under the user's finger); the message comes last.
        let mut said = Vec::new();
        let touch = self.panels.layout.touch();
        if touch {
            // Finger-sized buttons, and the row as tall whether or not they show.
            crate::shell::layout::touch_spacing(ui);
            if self.panels.zoom_to.is_open() && self.editor.view.is_some() {
                // An open Zoom to box takes its own row above: a phone's one row holds
                // the size, the zoom and fit, not the field, Go and Close beside them.
                ui.horizontal(|ui| with_frame!(self, |f| self.panels.zoom_to.ui(ui, &mut f)));
            }
        }
        ui.horizontal(|ui| {
            if touch {
                ui.set_min_height(crate::shell::layout::TOUCH_TARGET);
                // The buttons first, where a narrow screen does not cut them off.
                self.zoom_controls(ui, true, &mut said);
            }
            let (w, h) = self.editor.shown.size();
            let what = match self.editor.mode {
                Mode::Noise => format!("{} noise", self.noise.settings().spec.source.type_name()),
                Mode::Marbling if self.editor.landing => "the gallery".to_owned(),
                Mode::Marbling => match self.editor.shown.op_count() {
                    1 => "1 op".to_owned(),
                    n => format!("{n} ops"),
                },
            };
            let size = format!("{w}×{h} · {what} · {}", self.rendering.backend);
            ui.label(size.as_str());
            said.insert(0, size);
            if previewing && self.rendering.fast_paint.preview_reduced() {
                said.push("· preview 1 sample/px".to_owned());
                ui.label("· preview 1 sample/px").on_hover_text(
                    "Frames came slower than 30 per second while dragging, so the live \
                     preview takes one sample per pixel; released ops are still rendered \
                     exactly with the chosen antialiasing.",
                );
            }
            // The exact frame's progress while its tiles are drawn (a noise on a software
            // GPU can take a minute), in whole per cent (each change redraws the panel).
            if let Some(p) = drawing.filter(|_| self.editor.active.is_none()) {
                let text = format!("· drawing {:.0} %", (p * 100.0).floor());
                ui.label(text.as_str());
                said.push(text);
            }
            if !touch {
                self.zoom_controls(ui, false, &mut said);
            }
            if let Some(m) = &self.panels.message {
                let color = if m.error {
                    Color32::from_rgb(255, 110, 110)
                } else {
                    ui.visuals().text_color()
                };
                said.push(m.text.clone());
                ui.label(RichText::new(&m.text).color(color));
            }
        });
        self.hooks.status = said.join(" ");
    }

    /// The zoom, *fit* and the Zoom to box, while the view is zoomed or panned (on touch
    /// layouts an open box is drawn in its own row instead).
    fn zoom_controls(&mut self, ui: &mut egui::Ui, touch: bool, said: &mut Vec<String>) {
        let Some(v) = &self.editor.view else { return };
        said.push(v.zoom_label());
        ui.label(v.zoom_label());
        if status_button(ui, touch, "fit").clicked() {
            self.editor.view = None;
        }
        if !(touch && self.panels.zoom_to.is_open()) {
            with_frame!(self, |f| self.panels.zoom_to.ui(ui, &mut f));
        }
    }
}
