//! *Show QR*: the share link's QR code in a window, for a teacher's projector or a
//! phone held up to the screen (made by `marbling_core::share_qr`). A link
//! too long for a QR code is refused with its length, and the shortest form is offered:
//! the ops rounded and a picture downscaled, for the QR code only (the design keeps its
//! own). While the window is open it follows the design.

use crate::frame::Frame;
use crate::platform;
use crate::store::links::design_link;
use egui::RichText;
use marbling_core::share_qr::{MAX_QR_LINK_BYTES, link_qr, shortest_for_link};

/// Largest side of the code on screen, points.
const MAX_SIDE_PT: f32 = 360.0;

/// The window's code and what it was made for.
struct ShownQr {
    /// The design key it shows.
    key: u64,
    texture: egui::TextureHandle,
    version: i16,
    /// The link's length, characters.
    chars: usize,
}

/// *Show QR* and its window.
#[derive(Default)]
pub(crate) struct LinkQrWindow {
    /// The window is open; `shortest`: it shows the shortest form's link.
    open: Option<Shortest>,
    shown: Option<ShownQr>,
    /// The design key a too-long link was refused for: the shortest-form offer shows.
    offer: Option<u64>,
}

/// Whether the code is of the design's link as it is or of its shortest form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Shortest(bool);

impl LinkQrWindow {
    /// `data-qr`: `v<version> <characters>` while the window shows a code.
    pub fn hook(&self) -> Option<String> {
        self.open?;
        let s = self.shown.as_ref()?;
        Some(format!("v{} {}", s.version, s.chars))
    }

    /// *Show QR* (beside *Copy link*).
    pub fn button_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        // A toggle that looks like a button, lit while the window is open.
        let show = ui
            .add(egui::Button::new("Show QR").selected(self.open.is_some()))
            .on_hover_text("The link as a QR code, for a projector or a phone");
        frame.control("show-qr", &show);
        if show.clicked() {
            if self.open.is_some() {
                self.close();
            } else {
                self.open = Some(Shortest(false));
                self.shown = None;
            }
        }
    }

    /// The shortest-form offer after a refused link (under the file buttons).
    pub fn offer_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        if self.offer != Some(frame.editor.key) {
            self.offer = None;
            return;
        }
        let shortest = ui
            .button("QR code of the shortest form")
            .on_hover_text("The ops rounded and a picture downscaled, for the QR code only");
        frame.control("qr-shortest", &shortest);
        if shortest.clicked() {
            self.offer = None;
            self.open = Some(Shortest(true));
            self.shown = None;
        }
    }

    /// The window, while open: the code made again when the design changes.
    pub fn window_ui(&mut self, ctx: &egui::Context, frame: &mut Frame<'_>) {
        let Some(shortest) = self.open else {
            return;
        };
        let key = frame.editor.key;
        if self.shown.as_ref().is_none_or(|s| s.key != key) {
            match make(ctx, frame, shortest, key) {
                Ok(s) => self.shown = Some(s),
                Err(e) => {
                    frame.error(e);
                    if !shortest.0 {
                        self.offer = Some(key);
                    }
                    self.close();
                    return;
                }
            }
        }
        let Some(s) = &self.shown else { return };
        let mut open = true;
        // Beside the panel, at the window's top right, as the 3D view.
        let corner = ctx.content_rect().right_top() + egui::vec2(-8.0, 8.0);
        let side = MAX_SIDE_PT.min(ctx.content_rect().width() - 40.0).max(96.0);
        egui::Window::new("QR code of the link")
            .open(&mut open)
            .pivot(egui::Align2::RIGHT_TOP)
            .default_pos(corner)
            .resizable(false)
            .collapsible(false)
            .auto_sized()
            .min_width(side)
            .show(ctx, |ui| {
                let r = ui.add(egui::Image::new((s.texture.id(), egui::vec2(side, side))));
                frame.control("qr-code", &r);
                let what = if shortest.0 {
                    "the shortest form (ops rounded, picture downscaled)"
                } else {
                    "this design"
                };
                ui.label(format!(
                    "Version {} · {} characters · opens {what}",
                    s.version, s.chars
                ));
                ui.label(RichText::new("Scan it with a phone's camera.").weak());
            });
        if !open {
            self.close();
        }
    }

    fn close(&mut self) {
        self.open = None;
        self.shown = None;
    }
}

/// The code of the design's link (or of its shortest form) as a texture.
fn make(
    ctx: &egui::Context,
    frame: &Frame<'_>,
    shortest: Shortest,
    key: u64,
) -> Result<ShownQr, String> {
    let design = frame.editor.history.design();
    let link = if shortest.0 {
        // What the fragment may take once the page's address and `#` are in front.
        let budget = MAX_QR_LINK_BYTES.saturating_sub(platform::base_url().len() + 1);
        let short = shortest_for_link(design, budget).ok_or_else(|| {
            format!(
                "even the shortest form makes a link longer than a QR code holds ({MAX_QR_LINK_BYTES} characters): share the link or the JSON file"
            )
        })?;
        design_link(&short, None)
    } else {
        design_link(design, None)
    };
    let qr = link_qr(&link).map_err(|e| {
        if shortest.0 {
            format!("{e}: share the link or the JSON file")
        } else {
            format!("{e}: try the QR code of its shortest form, or share the link")
        }
    })?;
    let img = qr.to_image(4);
    let image = egui::ColorImage::from_rgba_unmultiplied(
        [img.width as usize, img.height as usize],
        &img.pixels,
    );
    // Nearest: the modules stay crisp at any size.
    let texture = ctx.load_texture("link-qr", image, egui::TextureOptions::NEAREST);
    Ok(ShownQr {
        key,
        texture,
        version: qr.version,
        chars: link.len(),
    })
}
