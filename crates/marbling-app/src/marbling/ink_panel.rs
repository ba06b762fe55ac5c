//! The side panel's Ink section: the palette, its inks, a picked ink colour, and the
//! paper colour (an undoable step).

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::ink_sets::INK_SETS;
use egui::{Color32, RichText};
use marbling_core::Rgb8;

fn color32(c: Rgb8) -> Color32 {
    Color32::from_rgb(c.r, c.g, c.b)
}

/// The Ink section: the palette, its inks, the ink and paper colours.
pub(crate) fn ui(ui: &mut egui::Ui, frame: &mut Frame<'_>) {
    ui.label(RichText::new("Ink").strong());
    let before = frame.prefs.palette;
    egui::ComboBox::from_label("palette")
        .selected_text(INK_SETS[frame.prefs.palette].name)
        .show_ui(ui, |ui| {
            for (i, p) in INK_SETS.iter().enumerate() {
                ui.selectable_value(&mut frame.prefs.palette, i, p.name);
            }
        });
    if frame.prefs.palette != before {
        frame.prefs.ink = INK_SETS[frame.prefs.palette].inks[0];
    }
    ui.horizontal_wrapped(|ui| {
        for &c in INK_SETS[frame.prefs.palette].inks {
            let selected = c == frame.prefs.ink;
            let (rect, resp) = ui.allocate_exact_size(egui::vec2(24.0, 24.0), egui::Sense::click());
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
}
