//! The side panel: the sections of `sections.rs` in order (files, export, inks,
//! history and recent designs are drawn here; the Tool section is
//! src/marbling/tool_panel.rs) and the status bar.

use crate::INK_SETS;
use crate::action::Action;
use crate::app::MarblingApp;
use crate::frame::with_frame;
use crate::platform;
use crate::shell::mode::Mode;
use crate::shell::sections::{self, Section};
use crate::store::export::ExportSize;
use egui::{Color32, RichText};
use marbling_core::Rgb8;

fn color32(c: Rgb8) -> Color32 {
    Color32::from_rgb(c.r, c.g, c.b)
}

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
            Section::Export => self.export_section(ui, frame),
            Section::Noise => with_frame!(self, |f| self.noise.ui(ui, &mut f)),
            Section::Surface => {
                with_frame!(self, |f| crate::noise::panel::surface_ui(ui, &mut f));
            }
            Section::Tool => {
                with_frame!(self, |f| crate::marbling::tool_panel::ui(ui, &mut f));
            }
            Section::Ink => self.ink_section(ui),
            Section::Picture => with_frame!(self, |f| self.panels.pictures.ui(ui, &mut f)),
            Section::Video => with_frame!(self, |f| self.rendering.video.ui(ui, &mut f)),
            Section::History => self.history_section(ui),
            Section::Recent => self.recent_section(ui),
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
            if copy.clicked() {
                let link = self.share_link();
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

    pub(crate) fn export_section(&mut self, ui: &mut egui::Ui, frame: &eframe::Frame) {
        ui.label(RichText::new("Export").strong());
        ui.horizontal_wrapped(|ui| {
            ui.label("PNG size");
            for size in ExportSize::CHOICES {
                let r = ui.selectable_value(&mut self.panels.export_size, size, size.label());
                self.control(size.control_name(), &r);
            }
        });
        let design = self.editor.history.design();
        let scale = self.panels.export_size.scale(design);
        let size_text = match marbling_core::output_size(design, scale) {
            Ok((w, h)) => format!("{w} × {h} px"),
            Err(e) => e.to_string(),
        };
        ui.horizontal_wrapped(|ui| {
            if let Some((export, _)) = &self.rendering.export {
                let (w, h) = export.size();
                ui.label(format!("rendering {w} × {h}…"));
                let cancel = ui.button("Cancel");
                self.control("export-cancel", &cancel);
                if cancel.clicked() {
                    self.rendering.export = None;
                    self.info("export cancelled");
                }
            } else {
                if self.rendering.svg.progress().is_none() {
                    let png = ui
                        .button("Export PNG")
                        .on_hover_text(format!("An exact render, {size_text}"));
                    self.control("export-png", &png);
                    if png.clicked() {
                        self.start_png_export(frame);
                    }
                }
                with_frame!(self, |f| self.rendering.svg.ui(ui, &mut f));
            }
            let view3d = ui
                .selectable_label(self.panels.view3d.open, "3D view")
                .on_hover_text(
                    "The design on a vase, sphere, cylinder, book or plane, exact at any zoom",
                );
            self.control("view3d", &view3d);
            if view3d.clicked() {
                self.panels.view3d.open = !self.panels.view3d.open;
            }
        });
        ui.label(RichText::new(size_text).weak());
    }

    pub(crate) fn ink_section(&mut self, ui: &mut egui::Ui) {
        ui.label(RichText::new("Ink").strong());
        let before = self.prefs.palette;
        egui::ComboBox::from_label("palette")
            .selected_text(INK_SETS[self.prefs.palette].name)
            .show_ui(ui, |ui| {
                for (i, p) in INK_SETS.iter().enumerate() {
                    ui.selectable_value(&mut self.prefs.palette, i, p.name);
                }
            });
        if self.prefs.palette != before {
            self.prefs.ink = INK_SETS[self.prefs.palette].inks[0];
        }
        ui.horizontal_wrapped(|ui| {
            for &c in INK_SETS[self.prefs.palette].inks {
                let selected = c == self.prefs.ink;
                let (rect, resp) =
                    ui.allocate_exact_size(egui::vec2(24.0, 24.0), egui::Sense::click());
                ui.painter().rect_filled(rect, 4.0, color32(c));
                if selected {
                    ui.painter().rect_stroke(
                        rect,
                        4.0,
                        egui::Stroke::new(2.0, Color32::WHITE),
                        egui::StrokeKind::Outside,
                    );
                }
                if resp.on_hover_text(c.to_string()).clicked() {
                    self.prefs.ink = c;
                }
            }
        });
        ui.horizontal(|ui| {
            let mut rgb = [self.prefs.ink.r, self.prefs.ink.g, self.prefs.ink.b];
            if egui::color_picker::color_edit_button_srgb(ui, &mut rgb).changed() {
                self.prefs.ink = Rgb8::new(rgb[0], rgb[1], rgb[2]);
            }
            ui.label("ink");
            let bg = self.editor.history.design().background;
            let mut rgb = [bg.r, bg.g, bg.b];
            let paper = egui::color_picker::color_edit_button_srgb(ui, &mut rgb);
            self.control("paper-color", &paper);
            if paper.changed() {
                self.apply(Action::SetPaperColor(Rgb8::new(rgb[0], rgb[1], rgb[2])));
            }
            ui.label("paper");
        });
    }

    /// Undo and Redo (in the History section, and beside the tools on a phone).
    pub(crate) fn undo_redo(&mut self, ui: &mut egui::Ui) {
        let undo = ui
            .add_enabled(self.editor.history.can_undo(), egui::Button::new("Undo"))
            .on_hover_text("Ctrl/Cmd+Z: takes the last gesture back");
        self.control("undo", &undo);
        if undo.clicked() {
            self.apply(Action::Undo);
        }
        let redo = ui
            .add_enabled(self.editor.history.can_redo(), egui::Button::new("Redo"))
            .on_hover_text("Ctrl/Cmd+Shift+Z");
        self.control("redo", &redo);
        if redo.clicked() {
            self.apply(Action::Redo);
        }
    }

    pub(crate) fn history_section(&mut self, ui: &mut egui::Ui) {
        ui.label(RichText::new("History").strong());
        ui.horizontal(|ui| {
            self.undo_redo(ui);
            let playing = self.editor.playback.is_some();
            let play = ui
                .add_enabled(
                    !self.editor.history.design().ops.is_empty(),
                    egui::Button::new(if playing { "Close player" } else { "Play" }),
                )
                .on_hover_text("Play the making step by step, with captions and the maths");
            self.control("play", &play);
            if play.clicked() {
                self.apply(Action::Play(!playing));
            }
        });
        if self.editor.landing && self.editor.pristine {
            // The start-up design behind the gallery is nobody's history yet.
            ui.label("Pick a pattern in the gallery, or start a new sheet: its steps show here.");
            return;
        }
        let n = self.editor.history.steps().len();
        // The player's step while it is open, else the step viewed.
        let shown = match self.editor.playback {
            Some(p) => p.current_step().map_or(0, |k| k + 1),
            None => self.editor.history.shown_steps(),
        };
        let mut clicked = None;
        let mut redo_to = None;
        let mut rows_drawn = Vec::new();
        // Undone steps stay listed, greyed, until a new edit drops them: a click on one
        // redoes up to it.
        let undone: Vec<String> = self
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
        if self.panels.history_scrolled != Some((shown, rows)) {
            // A new step, an undo or a step played: the current row comes into view at
            // the list's bottom (greyed undone steps below it stay reachable).
            self.panels.history_scrolled = Some((shown, rows));
            let row = row_height + ui.spacing().item_spacing.y;
            list = list.vertical_scroll_offset(((shown + 1) as f32 * row - LIST_HEIGHT).max(0.0));
        }
        list.show_rows(ui, row_height, rows, |ui, rows| {
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
                    format!("{i}. {}", self.editor.history.steps()[i - 1].label)
                };
                let r = ui.selectable_label(i == shown, label);
                if r.clicked() {
                    clicked = Some(i);
                }
                rows_drawn.push((format!("history-{i}"), r));
            }
        });
        for (name, r) in rows_drawn {
            self.control(name, &r);
        }
        if let Some(k) = clicked {
            self.apply(Action::View(Some(k)));
        }
        for _ in 0..redo_to.unwrap_or(0) {
            self.apply(Action::Redo);
        }
        if self.editor.history.is_viewing_earlier() {
            ui.label(
                RichText::new(format!(
                    "Showing step {shown} of {n}. Editing now starts a new branch; the later steps stay restorable below."
                ))
                .weak(),
            );
        }
        let branches: Vec<String> = self
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
                self.control(format!("restore-{i}"), &r);
                if r.clicked() {
                    self.apply(Action::Restore(i));
                }
            }
        }
    }

    pub(crate) fn recent_section(&mut self, ui: &mut egui::Ui) {
        let count = self.session.recent.entries.len();
        let header = egui::CollapsingHeader::new(format!("Recent designs ({count})"))
            .id_salt("recent")
            .show(ui, |ui| {
                if count == 0 {
                    ui.label(
                        RichText::new(
                            "Designs replaced by New, Open, a link or the gallery are kept here.",
                        )
                        .weak(),
                    );
                }
                let mut open = None;
                let mut made_one = false;
                for i in 0..count {
                    let e = self.session.recent.entries[i].clone();
                    let thumb = match self.panels.recent_thumbnails.get(&e.fragment) {
                        Some(t) => t.clone(),
                        None if !made_one => {
                            made_one = true;
                            let t =
                                crate::store::thumbnails::recent_thumbnail(&self.session.recent, i)
                                    .map(|img| {
                                        ui.ctx().load_texture(
                                            format!("recent {i}"),
                                            img,
                                            egui::TextureOptions::LINEAR,
                                        )
                                    });
                            self.panels
                                .recent_thumbnails
                                .insert(e.fragment.clone(), t.clone());
                            t
                        }
                        None => {
                            ui.ctx().request_repaint();
                            None
                        }
                    };
                    let r = ui
                        .horizontal(|ui| {
                            let size = egui::vec2(64.0, 48.0);
                            match &thumb {
                                Some(t) => {
                                    ui.add(
                                        egui::Image::new((t.id(), size)).fit_to_exact_size(size),
                                    );
                                }
                                None => {
                                    let (rect, _) =
                                        ui.allocate_exact_size(size, egui::Sense::hover());
                                    ui.painter().rect_stroke(
                                        rect,
                                        2.0,
                                        ui.visuals().widgets.noninteractive.bg_stroke,
                                        egui::StrokeKind::Inside,
                                    );
                                    ui.painter().text(
                                        rect.center(),
                                        egui::Align2::CENTER_CENTER,
                                        "no preview",
                                        egui::FontId::proportional(10.0),
                                        ui.visuals().weak_text_color(),
                                    );
                                }
                            }
                            // Labels that cannot be selected, so a click anywhere on
                            // the entry opens it.
                            ui.vertical(|ui| {
                                ui.add(
                                    egui::Label::new(format!(
                                        "{} · {} ops · {}×{}",
                                        crate::store::recent::date_label(e.saved_ms),
                                        e.ops,
                                        e.size[0],
                                        e.size[1]
                                    ))
                                    .selectable(false),
                                );
                                ui.add(
                                    egui::Label::new(RichText::new(&e.label).weak())
                                        .selectable(false),
                                );
                            });
                        })
                        .response
                        .interact(egui::Sense::click())
                        .on_hover_text("Restore this design (undoable)");
                    if r.hovered() {
                        ui.painter().rect_stroke(
                            r.rect.expand(1.0),
                            2,
                            ui.visuals().widgets.hovered.fg_stroke,
                            egui::StrokeKind::Outside,
                        );
                    }
                    self.control(format!("recent-{i}"), &r);
                    if r.clicked() {
                        open = Some(i);
                    }
                }
                if let Some(i) = open {
                    self.apply(Action::OpenRecent(i));
                }
            });
        self.control("recent", &header.header_response);
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
        ui.horizontal(|ui| {
            let (w, h) = self.editor.shown.size();
            let what = match self.editor.mode {
                Mode::Noise => format!("{} noise", self.noise.settings().spec.source.type_name()),
                Mode::Marbling if self.editor.landing => "the gallery".to_owned(),
                Mode::Marbling => match self.editor.shown.op_count() {
                    1 => "1 op".to_owned(),
                    n => format!("{n} ops"),
                },
            };
            said.push(format!("{w}×{h} · {what} · {}", self.rendering.backend));
            ui.label(said[0].as_str());
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
            if let Some(v) = &self.editor.view {
                said.push(format!("zoom {:.0} %", v.zoom * 100.0));
                ui.label(format!("zoom {:.0} %", v.zoom * 100.0));
                if ui.small_button("fit").clicked() {
                    self.editor.view = None;
                }
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
}
