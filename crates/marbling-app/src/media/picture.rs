//! Pictures as the design's background: *Open image…*, a file dropped on the window,
//! a picture pasted from the clipboard; the fit (stretch, cover, contain) and removing
//! the picture. Each is one undoable step of the paper; a file that is not a picture,
//! is damaged or too large leaves the design as it is and says why.

use crate::action::Action;
use crate::frame::Frame;
use crate::platform::{self, PickSlot};
use egui::RichText;
use marbling_core::image_background::IMAGE_FITS;
use marbling_core::{ImageBackground, ImageFit, MAX_PICTURE_LINK_CHARS, with_link_sized_picture};

/// Whether the file `name` is opened as a picture (else as a design document).
pub fn is_picture(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    platform::IMAGE_FILE
        .1
        .iter()
        .any(|ext| lower.ends_with(&format!(".{ext}")))
}

/// Where picked and pasted pictures arrive, and the offer made when *Copy link* found
/// the picture too large for a link.
#[derive(Default)]
pub(crate) struct Pictures {
    pick: PickSlot,
    /// The key of the design the offer is for (it goes when the design changes).
    link_offer: Option<u64>,
}

/// Makes the picture file `bytes` (named `name`) the design's background, keeping the
/// current picture's fit; a bad file leaves the design and says why.
pub(crate) fn open_image(name: &str, bytes: &[u8], frame: &mut Frame<'_>) {
    let fit = frame
        .editor
        .history
        .design()
        .background_image
        .as_ref()
        .map_or(ImageFit::default(), |b| b.fit);
    match ImageBackground::from_file_bytes(bytes, fit) {
        Ok(image) => {
            let p = image.pixels();
            let what = format!("picture {name} ({}×{})", p.width, p.height);
            let big = image.source().len() > crate::store::autosave::AUTOSAVE_PICTURE_CHARS;
            frame.act(Action::SetBackgroundImage {
                image: Some(image),
                what,
            });
            if big {
                frame.info(format!(
                    "{name} is large: the autosave keeps it at {} px; Save JSON keeps it whole",
                    crate::store::autosave::AUTOSAVE_PICTURE_SIDE
                ));
            }
        }
        Err(e) => frame.error(format!("{name}: {e}; the design is unchanged")),
    }
}

/// Files dropped on the window: pictures go to `pictures`, anything else to `designs`
/// (read asynchronously on the web; they arrive through the pick slots).
pub(crate) fn route_dropped_files(ctx: &egui::Context, pictures: &PickSlot, designs: &PickSlot) {
    let dropped = ctx.input(|i| i.raw.dropped_files.clone());
    for file in dropped {
        let name = file.path().file_name().map_or_else(
            || file.path().display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        );
        let slot = if is_picture(&name) { pictures } else { designs };
        platform::read_dropped(file, name, slot.clone(), ctx.clone());
    }
}

impl Pictures {
    /// Where a picked, pasted or dropped picture delivers.
    pub fn slot(&self) -> &PickSlot {
        &self.pick
    }

    /// Offers the downscale-or-save choice for the design of `key`.
    pub fn offer_link_choice(&mut self, key: u64) {
        self.link_offer = Some(key);
    }

    /// A picked or pasted picture, when one has arrived.
    pub fn poll(&mut self, frame: &mut Frame<'_>) {
        let picked = self.pick.lock().ok().and_then(|mut s| s.take());
        match picked {
            Some(Ok((name, bytes))) => open_image(&name, &bytes, frame),
            Some(Err(e)) => frame.error(e),
            None => {}
        }
    }

    /// After *Copy link* found the picture too large for a link: downscale it for the
    /// link (the design keeps it whole) or save the JSON file instead.
    pub fn link_offer_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        if self.link_offer != Some(frame.editor.key) {
            self.link_offer = None;
            return;
        }
        ui.horizontal_wrapped(|ui| {
            let shrink = ui.button("Downscale the picture for the link");
            frame.control("link-downscale", &shrink);
            if shrink.clicked() {
                self.link_offer = None;
                let design = frame.editor.history.design();
                match with_link_sized_picture(design, MAX_PICTURE_LINK_CHARS) {
                    Some(small) => {
                        let link = crate::store::links::design_link(&small, None);
                        let p = small.background_image.as_ref().map(|b| b.pixels());
                        let (w, h) = p.map_or((0, 0), |p| (p.width, p.height));
                        ui.ctx().copy_text(link.clone());
                        frame.info(format!(
                            "link copied ({} characters) with the picture at {w}×{h}; your design keeps it whole",
                            link.len()
                        ));
                    }
                    None => frame.error(
                        "even a 96-pixel picture does not fit a link with these ops: save the JSON file",
                    ),
                }
            }
            let save = ui.button("Save JSON instead");
            frame.control("link-save-json", &save);
            if save.clicked() {
                self.link_offer = None;
                let json = frame.editor.history.design().to_json_pretty();
                match platform::save_file("design.json", "application/json", json.as_bytes()) {
                    Ok(()) => frame.info("design saved as JSON"),
                    Err(e) => frame.error(e),
                }
            }
        });
    }

    /// The *Picture* section: open a picture, and with one, its fit and removing it.
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        let current = frame.editor.history.design().background_image.clone();
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new("Picture").strong());
            let open = ui
                .button("Open image…")
                .on_hover_text("Marble a photo: PNG, JPEG or WebP up to 4096×4096 (or drop one on the sheet, or paste one)");
            frame.control("open-image", &open);
            if open.clicked() {
                platform::pick_file(self.pick.clone(), platform::IMAGE_FILE, ui.ctx().clone());
            }
        });
        let Some(image) = current else { return };
        ui.horizontal_wrapped(|ui| {
            let p = image.pixels();
            ui.label(format!("{}×{}", p.width, p.height));
            for name in IMAGE_FITS {
                let fit = ImageFit::from_name(name).unwrap_or_default();
                let r = ui.selectable_label(image.fit == fit, *name);
                frame.control(format!("image-fit-{name}"), &r);
                if r.clicked() && image.fit != fit {
                    frame.act(Action::SetBackgroundImage {
                        image: Some(image.with_fit(fit)),
                        what: format!("picture fit: {name}"),
                    });
                }
            }
            let remove = ui.small_button("remove");
            frame.control("remove-image", &remove);
            if remove.clicked() {
                frame.act(Action::SetBackgroundImage {
                    image: None,
                    what: "picture removed".to_owned(),
                });
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::is_picture;
    use crate::action::Action;
    use crate::app::MarblingApp;
    use crate::frame::with_frame;
    use marbling_core::{Design, ImageFit, Op, Point, Rgb8, Spray};

    fn app() -> MarblingApp {
        MarblingApp::with_design(
            Design::new(40, 30, Rgb8::new(250, 250, 250)),
            "test".into(),
            false,
        )
    }

    fn photo() -> Vec<u8> {
        marbling_core::synth::test_photo(3, 20, 10)
            .to_png()
            .expect("png")
    }

    #[test]
    fn a_picture_is_an_undoable_step_with_its_fit_and_keeps_the_ops() {
        let mut a = app();
        a.apply(Action::Commit(vec![Op::Spray(Spray {
            center: Point::new(5.0, 5.0),
            radius: 2.0,
            color: Rgb8::new(0, 0, 0),
        })]));
        with_frame!(a, |f| super::open_image("photo.png", &photo(), &mut f));
        let d = a.editor.history.design().clone();
        let img = d.background_image.as_ref().expect("a picture");
        assert_eq!((img.pixels().width, img.fit), (20, ImageFit::Cover));
        assert_eq!(d.ops.len(), 1, "the ops are kept");
        assert_eq!(
            a.editor.history.steps().last().expect("a step").label,
            "picture photo.png (20×10)"
        );
        // The fit is a step of its own; undo goes back through both.
        a.apply(Action::SetBackgroundImage {
            image: Some(img.with_fit(ImageFit::Contain)),
            what: "picture fit: contain".into(),
        });
        let fit = |a: &MarblingApp| {
            a.editor
                .history
                .design()
                .background_image
                .as_ref()
                .map(|b| b.fit)
        };
        assert_eq!(fit(&a), Some(ImageFit::Contain));
        a.apply(Action::Undo);
        assert_eq!(fit(&a), Some(ImageFit::Cover));
        a.apply(Action::Undo);
        assert_eq!(fit(&a), None);
        a.apply(Action::Redo);
        assert_eq!(fit(&a), Some(ImageFit::Cover));
        // A paper colour replaces the picture.
        a.apply(Action::SetPaperColor(Rgb8::new(1, 2, 3)));
        assert_eq!(fit(&a), None);
        assert_eq!(a.editor.history.design().ops.len(), 1);
    }

    #[test]
    fn a_bad_picture_leaves_the_design_and_says_why() {
        let mut a = app();
        with_frame!(a, |f| super::open_image("photo.png", &photo(), &mut f));
        let before = a.editor.history.design().clone();
        let steps = a.editor.history.steps().len();
        let mut cut = photo();
        cut.truncate(cut.len() / 2);
        for (name, bytes) in [("broken.png", cut), ("notes.jpg", b"hello".to_vec())] {
            with_frame!(a, |f| super::open_image(name, &bytes, &mut f));
            assert_eq!(a.editor.history.design(), &before, "{name}");
            assert_eq!(a.editor.history.steps().len(), steps, "{name}");
            let m = a.panels.message.as_ref().expect("a message");
            assert!(m.error && m.text.starts_with(name), "{}", m.text);
            assert!(m.text.contains("unchanged"), "{}", m.text);
        }
    }

    #[test]
    fn pictures_are_told_by_their_extension() {
        assert!(is_picture("Photo.JPG"));
        assert!(is_picture("a.webp"));
        assert!(!is_picture("design.json"));
        assert!(!is_picture("jpg"));
    }
}
