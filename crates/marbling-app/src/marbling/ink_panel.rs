//! The side panel's Ink section: the palette, its inks, a picked ink colour, and the
//! paper colour (an undoable step); and palettes brought in — *Import palette…* (a GIMP
//! `.gpl`, a picture's main colours, or a text file of hex colours), hex colours pasted
//! into a field — and the chosen palette saved as a `.gpl`.

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::ink_sets::INK_SETS;
use crate::platform::{self, PickSlot};
use egui::{Color32, RichText};
use marbling_core::Rgb8;
use marbling_core::ink_palette::{InkPalette, PICTURE_INKS};

/// A palette file: GIMP, a picture, or text.
const PALETTE_FILE: platform::FileKind = (
    "palette (GIMP .gpl, a picture, or hex colours)",
    &["gpl", "txt", "png", "jpg", "jpeg", "webp"],
);

fn color32(c: Rgb8) -> Color32 {
    Color32::from_rgb(c.r, c.g, c.b)
}

/// The Ink section's own state: where a picked palette file arrives, the pasted text
/// and how many colours a picture gives.
pub(crate) struct InkPanel {
    pick: PickSlot,
    pasted: String,
    picture_inks: usize,
}

impl Default for InkPanel {
    fn default() -> Self {
        Self {
            pick: PickSlot::default(),
            pasted: String::new(),
            picture_inks: 5,
        }
    }
}

impl InkPanel {
    /// The Ink section: the palette, its inks, the ink and paper colours, and palettes
    /// imported, pasted and saved.
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        self.poll(frame);
        ui.label(RichText::new("Ink").strong());
        let before = frame.prefs.palette;
        let imported = frame.prefs.imported.as_ref().map(|p| p.name.clone());
        let palette = egui::ComboBox::from_label("palette")
            .selected_text(frame.prefs.palette_name().to_owned())
            .show_ui(ui, |ui| {
                for (i, p) in INK_SETS.iter().enumerate() {
                    ui.selectable_value(&mut frame.prefs.palette, i, p.name);
                }
                if let Some(name) = imported {
                    ui.selectable_value(&mut frame.prefs.palette, INK_SETS.len(), name);
                }
            });
        frame.control("palette", &palette.response);
        if frame.prefs.palette != before {
            frame.prefs.ink = frame.prefs.inks()[0];
        }
        ui.horizontal_wrapped(|ui| {
            for (i, &c) in frame.prefs.inks().to_vec().iter().enumerate() {
                let selected = c == frame.prefs.ink;
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
                frame.control(format!("ink-{i}"), &resp);
                if resp.on_hover_text(c.to_string()).clicked() {
                    frame.prefs.ink = c;
                }
            }
        });
        ui.horizontal(|ui| {
            let mut rgb = [frame.prefs.ink.r, frame.prefs.ink.g, frame.prefs.ink.b];
            if egui::color_picker::color_edit_button_srgb(ui, &mut rgb).changed() {
                frame.prefs.ink = Rgb8::new(rgb[0], rgb[1], rgb[2]);
            }
            ui.label("ink");
            let bg = frame.editor.history.design().background;
            let mut rgb = [bg.r, bg.g, bg.b];
            let paper = egui::color_picker::color_edit_button_srgb(ui, &mut rgb);
            frame.control("paper-color", &paper);
            if paper.changed() {
                frame.act(Action::SetPaperColor(Rgb8::new(rgb[0], rgb[1], rgb[2])));
            }
            ui.label("paper");
        });
        self.import_ui(ui, frame);
    }

    /// *Import palette…*, the colours a picture gives, the pasted hex field and *Save .gpl*.
    fn import_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.horizontal_wrapped(|ui| {
            let import = ui.button("Import palette…").on_hover_text(
                "A GIMP .gpl, a picture (its main colours) or a text file of hex colours",
            );
            frame.control("palette-import", &import);
            if import.clicked() {
                platform::pick_file(self.pick.clone(), PALETTE_FILE, ui.ctx().clone());
            }
            let k = ui
                .add(egui::DragValue::new(&mut self.picture_inks).range(PICTURE_INKS))
                .on_hover_text("Colours taken from a picture");
            frame.control("palette-picture-inks", &k);
            ui.label("from a picture");
            let save = ui
                .button("Save .gpl")
                .on_hover_text("The chosen palette as a GIMP palette file");
            frame.control("palette-save", &save);
            if save.clicked() {
                let name = format!("{}.gpl", file_stem(frame.prefs.palette_name()));
                match platform::save_file(&name, "text/plain", frame.prefs.palette_gpl().as_bytes())
                {
                    Ok(()) => frame.info(format!("palette saved as {name}")),
                    Err(e) => frame.error(e),
                }
            }
        });
        ui.horizontal(|ui| {
            let field = ui.add(
                egui::TextEdit::singleline(&mut self.pasted)
                    .hint_text("#1d3557, #e63946 …")
                    .desired_width(150.0),
            );
            frame.control("palette-hex", &field);
            let enter = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
            let use_it = ui
                .add_enabled(
                    !self.pasted.trim().is_empty(),
                    egui::Button::new("Use colours"),
                )
                .on_hover_text("Hex colours pasted or typed, as a palette");
            frame.control("palette-use", &use_it);
            if use_it.clicked() || (enter && !self.pasted.trim().is_empty()) {
                match InkPalette::from_hex_list(&self.pasted) {
                    Ok(p) => {
                        frame.info(format!("palette of {} pasted colours", p.colors.len()));
                        frame.prefs.import_palette(p);
                    }
                    Err(e) => frame.error(format!("pasted colours: {e}")),
                }
            }
        });
    }

    /// A picked palette file, when one has arrived.
    fn poll(&mut self, frame: &mut Frame<'_>) {
        let picked = self.pick.lock().ok().and_then(|mut s| s.take());
        match picked {
            Some(Ok((name, bytes))) => match InkPalette::import(&name, &bytes, self.picture_inks) {
                Ok(p) => {
                    frame.info(format!("palette {} of {} colours", p.name, p.colors.len()));
                    frame.prefs.import_palette(p);
                }
                Err(e) => frame.error(format!("{name}: {e}")),
            },
            Some(Err(e)) => frame.error(e),
            None => {}
        }
    }
}

/// `name` as a file name: letters, digits, `-` and `_` kept, the rest `-`.
fn file_stem(name: &str) -> String {
    let stem: String = name
        .chars()
        .map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '-'
            }
        })
        .collect();
    if stem.trim_matches('-').is_empty() {
        "palette".to_owned()
    } else {
        stem
    }
}
