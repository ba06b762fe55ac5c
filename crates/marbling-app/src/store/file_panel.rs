//! The File section: Gallery, New (and the new sheet's size), Open…, Save JSON, Copy
//! link and Show QR, Read controls aloud; and the design files that arrive (picked or
//! dropped), opened as they come.

use crate::action::Action;
use crate::frame::Frame;
use crate::media::picture::Pictures;
use crate::platform::{self, PickSlot};
use crate::shell::mode::Mode;
use crate::store::address_bar::AddressBar;
use crate::store::link_qr::LinkQrWindow;
use marbling_core::Design;

/// Default canvas of a new design, design pixels.
pub const NEW_SIZE: [u32; 2] = [1024, 768];

/// The File section's state.
pub(crate) struct FilePanel {
    /// Where a picked or dropped design file delivers.
    pick: PickSlot,
    /// The size of the sheet New makes, design pixels.
    new_size: [u32; 2],
}

impl Default for FilePanel {
    fn default() -> Self {
        Self {
            pick: PickSlot::default(),
            new_size: NEW_SIZE,
        }
    }
}

/// The sheet Copy link offers to share, and what it may change.
pub(crate) struct Sharing<'a> {
    /// The address bar *Copy link* writes.
    pub address: &'a mut AddressBar,
    /// The pictures (a picture too large for a link offers a downscaled copy).
    pub pictures: &'a mut Pictures,
    /// *Show QR* of the link.
    pub qr: &'a mut LinkQrWindow,
}

impl FilePanel {
    /// Where a picked or dropped design file delivers.
    pub fn slot(&self) -> &PickSlot {
        &self.pick
    }

    /// The size of the sheet New makes, design pixels.
    pub fn new_size(&self) -> [u32; 2] {
        self.new_size
    }

    /// Opens a design file that arrived (picked or dropped); on failure the current
    /// design stays.
    pub fn poll(&mut self, f: &mut Frame<'_>) {
        let picked = self.pick.lock().ok().and_then(|mut s| s.take());
        match picked {
            Some(Ok((name, bytes))) => open_json(&name, &bytes, f),
            Some(Err(e)) => f.error(e),
            None => {}
        }
    }

    /// Draws the section.
    pub fn ui(&mut self, ui: &mut egui::Ui, share: Sharing<'_>, f: &mut Frame<'_>) {
        let Sharing {
            address,
            pictures,
            qr,
        } = share;
        ui.horizontal_wrapped(|ui| {
            let gallery = ui
                .button("Gallery")
                .on_hover_text("The traditional patterns, and a blank sheet");
            f.control("gallery", &gallery);
            if gallery.clicked() {
                f.act(Action::ShowGallery(true));
                f.act(Action::SetMode(Mode::Marbling));
            }
            let new = ui
                .button("New")
                .on_hover_text("A blank sheet of the size below");
            f.control("new", &new);
            if new.clicked() {
                f.act(Action::NewSheet);
            }
            let open = ui.button("Open…").on_hover_text("Open a design JSON file");
            f.control("open", &open);
            if open.clicked() {
                platform::pick_file(self.pick.clone(), platform::DESIGN_FILE, ui.ctx().clone());
            }
            let save = ui.button("Save JSON");
            f.control("save-json", &save);
            if save.clicked() {
                let json = f.editor.history.design().to_json_pretty();
                match platform::save_file("design.json", "application/json", json.as_bytes()) {
                    Ok(()) => f.info("design saved as JSON"),
                    Err(e) => f.error(e),
                }
            }
            let copy = ui
                .button("Copy link")
                .on_hover_text("A link that opens this design");
            f.control("copy-link", &copy);
            qr.button_ui(ui, f);
            if copy.clicked() {
                copy_link(ui.ctx(), address, pictures, f);
            }
        });
        pictures.link_offer_ui(ui, f);
        qr.offer_ui(ui, f);
        ui.horizontal(|ui| {
            ui.label("New sheet");
            ui.add(
                egui::DragValue::new(&mut self.new_size[0])
                    .range(1..=marbling_core::MAX_SIDE)
                    .suffix(" px"),
            );
            ui.label("×");
            ui.add(
                egui::DragValue::new(&mut self.new_size[1])
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
        f.control("read-aloud", &read);
        if read.changed() {
            crate::shell::accessibility::set_reading_aloud(ui.ctx(), aloud);
        }
    }
}

/// *Copy link*: the link to the design (with the view, when zoomed or panned) goes to
/// the clipboard and the address bar; one too long for a browser is saved as JSON
/// instead, and a picture too large for a link is offered downscaled.
fn copy_link(
    ctx: &egui::Context,
    address: &mut AddressBar,
    pictures: &mut Pictures,
    f: &mut Frame<'_>,
) {
    let editor = f.editor;
    // A zoomed or panned view goes with the link; the fitted one does not.
    let view = match (editor.view, editor.fit) {
        (Some(v), Some((fitted, _))) if v == fitted => None,
        (Some(v), _) => Some(v.spec(editor.canvas_size)),
        (None, _) => None,
    };
    let design = editor.history.design();
    let link = crate::store::links::design_link(design, view);
    let fragment = link.split_once('#').map_or(0, |(_, f)| f.len());
    if design.background_image.is_some() && fragment > marbling_core::MAX_PICTURE_LINK_CHARS {
        pictures.offer_link_choice(editor.key);
        f.error(format!(
            "the picture makes the link {} KB; links hold about {} KB: downscale the picture for the link, or save the JSON file",
            fragment / 1024,
            marbling_core::MAX_PICTURE_LINK_CHARS / 1024
        ));
        return;
    }
    if link.len() > marbling_core::MAX_LINK_CHARS {
        let json = design.to_json_pretty();
        let saved = platform::save_file("design.json", "application/json", json.as_bytes());
        f.error(format!(
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
        address.show(fragment);
    }
    ctx.copy_text(link.clone());
    f.info(format!("link copied ({} characters)", link.len()));
}

/// Opens a design from a file's bytes; on failure the current design stays and the
/// status line says why, naming the file.
fn open_json(name: &str, bytes: &[u8], f: &mut Frame<'_>) {
    let Ok(text) = std::str::from_utf8(bytes) else {
        f.error(format!("{name}: not a text file"));
        return;
    };
    match Design::from_json(text) {
        Ok(design) => f.act(Action::Load {
            design,
            from: name.to_owned(),
            from_link: false,
        }),
        Err(e) => f.error(format!("{name}: {}", crate::shell::message::first_line(&e))),
    }
}

/// A blank design of the given size.
pub(crate) fn blank(size: [u32; 2]) -> Design {
    Design::new(size[0], size[1], marbling_core::Rgb8::new(0xf4, 0xec, 0xd8))
}
