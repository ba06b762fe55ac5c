//! The address bar: the fragment it holds, opened when it changes (a link pasted or
//! followed, Back), set by *Copy link*, and dropped once the design on screen is no
//! longer the one it holds (so a reload shows the edited design, from the autosave).

use crate::action::Action;
use crate::frame::Frame;
use crate::noise::Noise;
use crate::platform;
use crate::shell::mode::Mode;
use crate::store::links::{self, Link};

/// The fragment the address bar holds, as last read or written.
#[derive(Default)]
pub(crate) struct AddressBar {
    /// The fragment last read or set (`None`: none, or dropped after an edit).
    last: Option<String>,
}

impl AddressBar {
    /// The fragment last read or set.
    pub fn fragment(&self) -> Option<&str> {
        self.last.as_deref()
    }

    /// Remembers `fragment` as what the address bar holds (a restarted renderer's).
    pub fn remember(&mut self, fragment: Option<String>) {
        self.last = fragment;
    }

    /// Shows `fragment` in the address bar (*Copy link*).
    pub fn show(&mut self, fragment: &str) {
        platform::set_fragment(fragment);
        self.last = Some(fragment.to_owned());
    }

    /// The design changed: a link to a design or a noise no longer shows what is on
    /// screen, so it leaves the address bar.
    pub fn design_changed(&mut self) {
        if self.last.as_deref().is_some_and(|f| {
            f.split('&')
                .any(|p| p.starts_with("d=") || p.starts_with("n="))
        }) {
            platform::clear_fragment();
            self.last = None;
        }
    }

    /// Opens what a changed fragment holds: a `#d=` design (with its `&v=` view) or an
    /// `#n=` noise; a broken link keeps the current design and says what is wrong.
    pub fn follow(&mut self, noise: &mut Noise, f: &mut Frame<'_>) {
        if !platform::fragment_changed() {
            return;
        }
        let fragment = platform::fragment();
        if fragment == self.last {
            return;
        }
        self.last = fragment.clone();
        let Some(fragment) = fragment else {
            return;
        };
        if links::is_link(&fragment) {
            // What the link holds, or why it cannot be opened, is shown, not the gallery.
            f.act(Action::ShowGallery(false));
        }
        match links::read(&fragment) {
            Link::None => {}
            Link::Noise(spec) => {
                let opened = spec.and_then(|spec| {
                    let opened = noise.open(*spec);
                    opened.map_err(|e| format!("noise link: {e}"))
                });
                match opened {
                    Ok(()) => {
                        f.act(Action::SetMode(Mode::Noise));
                        f.info("noise link opened");
                    }
                    Err(e) => f.error(crate::shell::message::first_line_of(&e)),
                }
            }
            Link::Design(Ok(design)) => {
                if *design != *f.editor.history.design() {
                    f.act(Action::Load {
                        design: *design,
                        from: "share link".to_owned(),
                        from_link: true,
                    });
                }
                match links::view_of(&fragment) {
                    Some(Ok(view)) => f.act(Action::ZoomTo(view)),
                    Some(Err(e)) => f.error(e),
                    None => {}
                }
            }
            Link::Design(Err(e)) => f.error(crate::shell::message::first_line_of(&e)),
        }
    }
}
