//! The status bar's *Zoom to* box: a design point and a zoom typed as `x, y, zoom`
//! (the numbers a share link's `v=` holds), the view then centred there.

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::view::ViewState;
use crate::shell::layout::status_button;
use marbling_core::ViewSpec;

/// The box's state: closed, or open with the text being typed.
#[derive(Debug, Default)]
pub(crate) struct ZoomTo {
    /// The text in the open box.
    text: Option<String>,
    /// Why the typed view was refused (the text then shows red, this on hover), until
    /// the text changes.
    refused: Option<String>,
}

/// The widest the text field gets, points.
const FIELD_WIDTH: f32 = 170.0;
/// The narrowest, points (a short window gives it what is left of the status bar).
const FIELD_MIN_WIDTH: f32 = 70.0;
/// What the Go and Close buttons beside the field take, points (small buttons).
const BUTTONS_WIDTH: f32 = 90.0;
/// The same on touch layouts ([`crate::shell::layout::TOUCH_TARGET`]-high buttons).
const TOUCH_BUTTONS_WIDTH: f32 = 130.0;

impl ZoomTo {
    /// Whether the box is open (on touch layouts it takes a row of its own).
    pub(crate) fn is_open(&self) -> bool {
        self.text.is_some()
    }

    /// The *Zoom to…* button, and the box while it is open (filled with the current
    /// view); Enter or *Go* asks for the typed view, a bad one is said in the status
    /// line and the box stays open.
    pub(crate) fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        let current = frame
            .editor
            .view
            .map(|v: ViewState| v.spec(frame.editor.canvas_size));
        let touch = frame.layout.touch();
        let Some(text) = &mut self.text else {
            let open = status_button(ui, touch, "Zoom to…")
                .on_hover_text("Centre a design point at a zoom (up to 1000000×): x, y, zoom");
            frame.control("zoom-to", &open);
            if open.clicked() {
                self.text = Some(current.map(|v| v.to_rounded_string()).unwrap_or_default());
            }
            return;
        };
        // Go and Close stay on screen in a short status bar: the field takes what is left.
        let buttons = if touch {
            TOUCH_BUTTONS_WIDTH
        } else {
            BUTTONS_WIDTH
        };
        let width = (ui.available_width() - buttons).clamp(FIELD_MIN_WIDTH, FIELD_WIDTH);
        let mut edit = egui::TextEdit::singleline(text)
            .desired_width(width)
            .hint_text("x, y, zoom");
        if self.refused.is_some() {
            edit = edit.text_color(egui::Color32::from_rgb(255, 110, 110));
        }
        let mut field = ui.add(edit);
        if field.changed() {
            self.refused = None;
        }
        if let Some(why) = &self.refused {
            field = field.on_hover_text(why.as_str());
        }
        frame.control("zoom-to-text", &field);
        let go = status_button(ui, touch, "Go");
        frame.control("zoom-to-go", &go);
        let close = status_button(ui, touch, "Close").on_hover_text("Close the Zoom to box");
        frame.control("zoom-to-close", &close);
        let entered = field.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        if go.clicked() || entered {
            match ViewSpec::parse(text) {
                Ok(spec) => {
                    frame.act(Action::ZoomTo(spec));
                    frame.info(format!("zoomed to {spec}"));
                    self.text = None;
                    self.refused = None;
                }
                Err(e) => {
                    let why = format!("Zoom to: {e}");
                    self.refused = Some(why.clone());
                    frame.error(why);
                }
            }
        } else if close.clicked() {
            self.text = None;
            self.refused = None;
        }
    }
}
