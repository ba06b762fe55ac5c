//! What a feature's `ui` gets and gives back in one frame: the shared state it may read
//! (the document, read only) or set (the tool preferences), and what it asks for: the
//! actions the frame loop then applies in order (src/action.rs), the status-line news,
//! and where its named controls were drawn (the `data-controls` hook). A feature owns
//! its own state; everything else it touches goes through here.

use crate::action::Action;
use crate::marbling::editor::Editor;
use crate::shell::layout::Layout;
use crate::shell::message::Message;
use crate::store::prefs::Prefs;
use std::borrow::Cow;

/// One feature's view of the frame (see the module doc).
pub(crate) struct Frame<'a> {
    /// The document and how it is shown. Read only: a change is an [`Action`].
    pub editor: &'a Editor,
    /// The tool, its settings, the palette and ink (kept in storage).
    pub prefs: &'a mut Prefs,
    /// The screen's arrangement (touch wording, target sizes).
    pub layout: Layout,
    asked: Asked,
}

/// What a feature asked for in a frame, for [`crate::app::MarblingApp::take_asked`].
#[derive(Default)]
pub(crate) struct Asked {
    /// Actions, in the order asked.
    pub actions: Vec<Action>,
    /// The last status-line message asked for.
    pub message: Option<Message>,
    /// Named controls and where they were drawn, in drawing order.
    pub controls: Vec<(Cow<'static, str>, egui::Rect)>,
}

impl Asked {
    /// Remembers where a named control was drawn (see [`Frame::control`]).
    pub fn control(&mut self, name: impl Into<Cow<'static, str>>, response: &egui::Response) {
        if let Some(rect) = shown_rect(response) {
            self.controls.push((name.into(), rect));
        }
    }
}

impl<'a> Frame<'a> {
    /// A frame for a feature that reads `editor` and may set `prefs`.
    pub fn new(editor: &'a Editor, prefs: &'a mut Prefs, layout: Layout) -> Self {
        Self {
            editor,
            prefs,
            layout,
            asked: Asked::default(),
        }
    }

    /// Asks for `action` (applied after the feature's `ui` returns).
    pub fn act(&mut self, action: Action) {
        self.asked.actions.push(action);
    }

    /// News for the status line.
    pub fn info(&mut self, text: impl Into<String>) {
        self.asked.message = Some(Message::info(text.into()));
    }

    /// A problem for the status line (and `data-error`).
    pub fn error(&mut self, text: impl Into<String>) {
        self.asked.message = Some(Message::error(text.into()));
    }

    /// Remembers where a named control was drawn (for the `data-controls` hook): the
    /// part of it that shows when its scroll area cuts it; not one scrolled out of its
    /// area whose centre lies on the screen (over some other control); one scrolled past
    /// the screen's edge is listed whole, for a scroll to bring.
    pub fn control(&mut self, name: impl Into<Cow<'static, str>>, response: &egui::Response) {
        self.asked.control(name, response);
    }

    /// What the feature asked for.
    pub fn finish(self) -> Asked {
        self.asked
    }
}

/// Where a control shows for `data-controls` (see [`Frame::control`]), if anywhere.
pub(crate) fn shown_rect(response: &egui::Response) -> Option<egui::Rect> {
    let (whole, shown) = (response.rect, response.interact_rect);
    if !shown.contains(whole.center()) && response.ctx.content_rect().contains(whole.center()) {
        return None;
    }
    Some(if shown.is_positive() { shown } else { whole })
}

/// Runs `body` with a [`Frame`] named `$f` made from the app `$app`'s editor, prefs and
/// layout, then carries out what it asked for
/// ([`crate::app::MarblingApp::take_asked`]); the value is `body`'s.
macro_rules! with_frame {
    ($app:ident, |$f:ident| $body:expr) => {{
        let mut $f = $crate::frame::Frame::new(&$app.editor, &mut $app.prefs, $app.panels.layout);
        let value = $body;
        let asked = $f.finish();
        $app.take_asked(asked);
        value
    }};
}
pub(crate) use with_frame;
