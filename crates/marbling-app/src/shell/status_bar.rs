//! The status line under the canvas: the sheet's size, what it holds and the renderer,
//! the live preview's note, the exact frame's progress, the zoom with *fit* and the
//! Zoom to box, and the message. One row, always the same height (on touch layouts an
//! open Zoom to box takes a row of its own above).

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::zoom_to::ZoomTo;
use crate::noise::Noise;
use crate::shell::layout::status_button;
use crate::shell::message::Message;
use crate::shell::mode::Mode;
use crate::state::Rendering;
use egui::{Color32, RichText};

/// What the status line shows and may change.
pub(crate) struct Line<'a> {
    /// The message (it goes when its time is up).
    pub message: &'a mut Option<Message>,
    /// The Zoom to box.
    pub zoom_to: &'a mut ZoomTo,
    /// The renderer: its name, the exact frame's progress, the preview's quality.
    pub rendering: &'a Rendering,
    /// The noise playground (the noise type's name).
    pub noise: &'a Noise,
}

/// Draws the status line: the sheet's size, what it holds and the renderer, the live
/// preview's note, the drawing progress, the zoom controls and the message. Returns
/// what it says, for the `data-status` hook.
pub(crate) fn ui(ui: &mut egui::Ui, line: Line<'_>, f: &mut Frame<'_>) -> String {
    let Line {
        message,
        zoom_to,
        rendering,
        noise,
    } = line;
    let editor = f.editor;
    let now = ui.input(|i| i.time);
    if let Some(m) = message.as_mut() {
        let (current, again) = m.shown_at(now);
        if let Some(s) = again {
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_secs_f64(s));
        }
        if !current {
            *message = None;
        }
    }
    // The live preview's note, only while the preview is on screen (a drag, or an
    // exact frame still being drawn).
    let drawing = rendering.progress().filter(|p| *p < 1.0);
    let previewing = editor.active.is_some() || drawing.is_some();
    // One row, always the same height (a second row would move the canvas's edge
    // under the user's finger); the message comes last.
    let mut said = Vec::new();
    let touch = f.layout.touch();
    if touch {
        // Finger-sized buttons, and the row as tall whether or not they show.
        crate::shell::layout::touch_spacing(ui);
        if zoom_to.is_open() && editor.view.is_some() {
            // An open Zoom to box takes its own row above: a phone's one row holds
            // the size, the zoom and fit, not the field, Go and Close beside them.
            ui.horizontal(|ui| zoom_to.ui(ui, f));
        }
    }
    ui.horizontal(|ui| {
        if touch {
            ui.set_min_height(crate::shell::layout::TOUCH_TARGET);
            // The buttons first, where a narrow screen does not cut them off.
            zoom_controls(ui, true, zoom_to, &mut said, f);
        }
        let (w, h) = editor.shown.size();
        let what = match editor.mode {
            Mode::Noise => format!("{} noise", noise.settings().spec.source.type_name()),
            Mode::Marbling if editor.landing => "the gallery".to_owned(),
            Mode::Marbling => match editor.shown.op_count() {
                1 => "1 op".to_owned(),
                n => format!("{n} ops"),
            },
        };
        let size = format!("{w}×{h} · {what} · {}", rendering.backend);
        ui.label(size.as_str());
        said.insert(0, size);
        if previewing && rendering.fast_paint.preview_reduced() {
            said.push("· preview 1 sample/px".to_owned());
            ui.label("· preview 1 sample/px").on_hover_text(
                "Frames came slower than 30 per second while dragging, so the live \
                     preview takes one sample per pixel; released ops are still rendered \
                     exactly with the chosen antialiasing.",
            );
        }
        // The exact frame's progress while its tiles are drawn (a noise on a software
        // GPU can take a minute), in whole per cent (each change redraws the panel).
        if let Some(p) = drawing.filter(|_| editor.active.is_none()) {
            let text = format!("· drawing {:.0} %", (p * 100.0).floor());
            ui.label(text.as_str());
            said.push(text);
        }
        if !touch {
            zoom_controls(ui, false, zoom_to, &mut said, f);
        }
        if let Some(m) = message.as_ref() {
            let color = if m.error {
                Color32::from_rgb(255, 110, 110)
            } else {
                ui.visuals().text_color()
            };
            said.push(m.text.clone());
            ui.label(RichText::new(&m.text).color(color));
        }
    });
    said.join(" ")
}

/// The zoom, *fit* and the Zoom to box, while the view is zoomed or panned (on touch
/// layouts an open box is drawn in its own row instead).
fn zoom_controls(
    ui: &mut egui::Ui,
    touch: bool,
    zoom_to: &mut ZoomTo,
    said: &mut Vec<String>,
    f: &mut Frame<'_>,
) {
    let Some(v) = &f.editor.view else { return };
    said.push(v.zoom_label());
    ui.label(v.zoom_label());
    if status_button(ui, touch, "fit").clicked() {
        f.act(Action::FitView);
    }
    if !(touch && zoom_to.is_open()) {
        zoom_to.ui(ui, f);
    }
}
