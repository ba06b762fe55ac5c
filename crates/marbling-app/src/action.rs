//! Everything that changes the design goes through [`Editor::apply`]: panels,
//! keys and the canvas say what the user asked for as an [`Action`], and this file
//! says what happens then (history step, refresh, autosave, recent designs, link).

use crate::gpu::canvas_gpu::StandIn;
use crate::marbling::editor::Editor;
use crate::marbling::history::Surface;
use crate::noise::Noise;
use crate::shell::message::Message;
use crate::shell::mode::Mode;
use crate::state::Panels;
use crate::store::address_bar::AddressBar;
use crate::store::prefs::Prefs;
use crate::store::session::Session;
use marbling_core::{Design, Op, Rgb8};

/// What the user asked for.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// A tool's gesture: its ops become one history step.
    Commit(Vec<Op>),
    /// The design becomes `design` (Open, the gallery, a share link); the previous one
    /// stays one undo away and goes to *Recent designs*.
    Load {
        /// The design to show.
        design: Design,
        /// Where it came from, for the history list and the status bar.
        from: String,
        /// True for a `#d=` link in the address bar (which then stays there).
        from_link: bool,
    },
    /// A blank sheet of the chosen size with the palette's paper.
    NewSheet,
    /// Takes the newest step back.
    Undo,
    /// Puts the most recently undone step back.
    Redo,
    /// Shows the state after the first `n` steps (`None`: all of them).
    View(Option<usize>),
    /// Puts design point `centre` of the spec in the canvas's middle at its zoom.
    ZoomTo(marbling_core::ViewSpec),
    /// Fits the sheet to the canvas again (*fit*).
    FitView,
    /// Restores abandoned branch `i` as a new step.
    Restore(usize),
    /// Restores entry `i` of *Recent designs*.
    OpenRecent(usize),
    /// A plain paper colour (it replaces a noise or picture background).
    SetPaperColor(Rgb8),
    /// A picture background, or none; `what` names the change.
    SetBackgroundImage {
        /// The picture (it replaces a noise background), or `None` for the plain paper.
        image: Option<marbling_core::ImageBackground>,
        /// What changed ("picture photo.jpg", "fit: contain").
        what: String,
    },
    /// Opens the step player playing from the first step (true) or closes it, showing
    /// the whole design.
    Play(bool),
    /// Moves the open player to `position` steps (see `Playback::at`), playing on or
    /// paused.
    Seek {
        /// Steps done, with the fraction of the next.
        position: f64,
        /// Whether it goes on playing.
        playing: bool,
    },
    /// Plays the open player's making backwards from the end (a looping recording's
    /// way back; the player's negative velocity moves it).
    PlayBackward,
    /// Switches between marbling and the noise playground.
    SetMode(Mode),
    /// Shows the gallery in place of the canvas, or the canvas again.
    ShowGallery(bool),
    /// A noise background and grain overlays; `what` names the change.
    SetSurface {
        /// The new background and overlays.
        surface: Surface,
        /// What changed ("noise background", "paper-grain").
        what: String,
    },
}

/// What an action may change beside the document: the parts the frame loop lends.
pub(crate) struct Around<'a> {
    /// The noise playground (the picture shown in its mode).
    pub noise: &'a mut Noise,
    /// Storage: the autosave owed, *Recent designs*.
    pub session: &'a mut Session,
    /// The address bar's link (dropped after an edit).
    pub address: &'a mut AddressBar,
    /// The panels: the status line, New's size, the phone's sheet and rail.
    pub panels: &'a mut Panels,
    /// The tool preferences (the palette's paper for New).
    pub prefs: &'a Prefs,
}

impl Around<'_> {
    fn info(&mut self, text: impl Into<String>) {
        self.panels.message = Some(Message::info(text.into()));
    }

    fn error(&mut self, text: impl Into<String>) {
        self.panels.message = Some(Message::error(text.into()));
    }
}

impl Editor {
    /// Carries out `action`: the only place where the design and its history change.
    pub(crate) fn apply(&mut self, action: Action, mut around: Around<'_>) {
        // Only a change of the document ends the start-up design's pristine state, and
        // the status line's message about the one before.
        let pristine = match action {
            Action::SetMode(_)
            | Action::ShowGallery(_)
            | Action::Play(_)
            | Action::Seek { .. }
            | Action::PlayBackward
            | Action::View(_)
            | Action::ZoomTo(_)
            | Action::FitView => self.pristine,
            _ => {
                around.panels.message = None;
                std::mem::take(&mut self.pristine)
            }
        };
        let shown_size = self.shown.size();
        // An edit: the design before it, with the op it added, stands in while the new
        // design's exact frame is drawn. Any other change of state (Undo, Redo, another
        // document): an earlier state that looks the same, found once it is made.
        let stand_in = match &action {
            Action::Load { .. } | Action::NewSheet | Action::OpenRecent(_) => {
                // A new document is edited at once: the gallery gives way.
                self.landing = false;
                StandIn::other_state(None)
            }
            Action::Commit(ops) => StandIn {
                key: Some(self.key),
                op: match ops.as_slice() {
                    [op] if crate::marbling::canvas::previewable(op) => Some(op.clone()),
                    _ => None,
                },
                paper: false,
            },
            _ => StandIn::other_state(None),
        };
        let changed = match action {
            Action::Commit(ops) => match self.history.push_ops(ops) {
                Ok(()) => true,
                Err(e) => {
                    around.error(e.to_string());
                    false
                }
            },
            Action::Load {
                design,
                from,
                from_link,
            } => {
                if pristine {
                    // Nothing to keep (the start-up design nobody touched, maybe never
                    // seen behind the gallery): this design starts the history.
                    self.view = None;
                    self.history = crate::History::new(design);
                } else {
                    self.replace_document(around.session, design, format!("opened {from}"));
                }
                around.info(format!("opened {from}"));
                if from_link {
                    self.after_change(&mut around);
                    self.fit_if_resized(shown_size);
                    return;
                }
                true
            }
            Action::NewSheet => {
                let size = around.panels.file.new_size();
                let mut d = crate::store::file_panel::blank(size);
                d.background = around
                    .prefs
                    .paper()
                    .unwrap_or(self.history.design().background);
                self.replace_document(
                    around.session,
                    d,
                    format!("new sheet {}×{}", size[0], size[1]),
                );
                around.info("a new design (Undo brings the previous one back)");
                true
            }
            Action::Undo => self.history.undo(),
            Action::Redo => self.history.redo(),
            Action::ZoomTo(spec) => {
                self.view_request = Some(spec);
                return;
            }
            Action::FitView => {
                self.view = None;
                return;
            }
            Action::View(n) => {
                self.history.view(n);
                self.playback = None;
                self.refresh_saying(&mut around);
                self.fit_if_resized(shown_size);
                self.set_stand_in(stand_in);
                return;
            }
            Action::Play(on) => {
                self.history.view(None);
                self.playback = on.then(crate::marbling::playback::Playback::start);
                // On a phone the player takes the bottom sheet's or the side panel's room
                // (a tab or the rail opens it again).
                if on {
                    match around.panels.layout {
                        crate::shell::layout::Layout::Portrait => around.panels.sheet.close(),
                        crate::shell::layout::Layout::Landscape => {
                            around.panels.rail.close_panel();
                        }
                        crate::shell::layout::Layout::Desktop => {}
                    }
                }
                self.refresh_saying(&mut around);
                self.fit_if_resized(shown_size);
                return;
            }
            Action::Seek { position, playing } => {
                let steps = self.history.design().gesture_sizes().len();
                let mut p = crate::marbling::playback::Playback::at(position, steps);
                p.playing = playing && p.step < steps;
                self.playback = Some(p);
                self.refresh_saying(&mut around);
                return;
            }
            Action::PlayBackward => {
                let steps = self.history.design().gesture_sizes().len();
                let mut p = crate::marbling::playback::Playback::at(steps as f64, steps);
                p.playing = steps > 0;
                self.playback = Some(p);
                self.refresh_saying(&mut around);
                return;
            }
            Action::SetMode(mode) => {
                self.set_mode_saying(mode, &mut around);
                return;
            }
            Action::ShowGallery(on) => {
                self.landing = on;
                return;
            }
            Action::Restore(i) => self.history.restore(i),
            Action::OpenRecent(i) => match around.session.recent().design(i) {
                Ok(d) => {
                    let label = around.session.recent().entries[i].label.clone();
                    self.replace_document(
                        around.session,
                        d,
                        format!("restored recent design ({label})"),
                    );
                    around.info("restored a recent design (Undo goes back)");
                    true
                }
                Err(e) => {
                    around.error(e);
                    false
                }
            },
            Action::SetPaperColor(c) => {
                let mut paper = self.history.shown_paper();
                paper.background = c;
                paper.background_noise = None;
                paper.background_image = None;
                self.history.push_paper(paper, c.to_string(), true);
                true
            }
            Action::SetBackgroundImage { image, what } => {
                let mut paper = self.history.shown_paper();
                if image.is_some() {
                    paper.background_noise = None;
                }
                paper.background_image = image;
                self.history.push_paper(paper, what.clone(), false);
                self.set_mode_saying(Mode::Marbling, &mut around);
                around.info(format!("design surface: {what}"));
                true
            }
            Action::SetSurface {
                surface: (background, overlays),
                what,
            } => {
                let mut paper = self.history.shown_paper();
                if background.is_some() {
                    paper.background_image = None;
                }
                paper.background_noise = background;
                paper.overlays = overlays;
                self.history.push_paper(paper, what.clone(), false);
                self.set_mode_saying(Mode::Marbling, &mut around);
                around.info(format!("design surface: {what}"));
                true
            }
        };
        if changed {
            // The address bar's link (a design, or a noise the design may now be marbling)
            // no longer shows what is on screen.
            around.address.design_changed();
            self.after_change(&mut around);
            self.fit_if_resized(shown_size);
            self.set_stand_in(stand_in);
        }
    }

    /// What stands in for the state just made while its exact frame is drawn: `s`, or for
    /// a change that is not an edit, an earlier state that looks the same.
    fn set_stand_in(&mut self, mut s: StandIn) {
        if s.paper {
            s.key = self.earlier_look_alike();
        }
        self.stand_in = Some((self.key, s));
    }

    /// The design changed: stop playback, redraw, autosave soon.
    fn after_change(&mut self, around: &mut Around<'_>) {
        self.playback = None;
        self.refresh_saying(around);
        around.session.design_changed();
    }

    /// A sheet of another size (New, Open, or undoing either) is fitted to the canvas.
    fn fit_if_resized(&mut self, before: (u32, u32)) {
        if self.shown.size() != before {
            self.view = None;
        }
    }

    /// A new document step; the design it replaces goes to *Recent designs*.
    fn replace_document(&mut self, session: &mut Session, design: Design, label: String) {
        let current = self.history.design();
        if !current.ops.is_empty() || current.uses_v2() {
            let kept = current.clone();
            session.keep_recent(&kept, format!("before {label}"));
        }
        self.mode = Mode::Marbling;
        self.active = None;
        self.history.push_document(design, label);
    }

    fn refresh_saying(&mut self, around: &mut Around<'_>) {
        if let Err(e) = self.refresh(around.noise) {
            around.error(e);
        }
    }

    fn set_mode_saying(&mut self, mode: Mode, around: &mut Around<'_>) {
        if let Err(e) = self.set_mode(mode, around.noise) {
            around.error(e);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::MarblingApp;
    use crate::marbling::history::EditError;
    use marbling_core::{MAX_OPS, Point, Spray};

    fn app() -> MarblingApp {
        MarblingApp::with_design(
            Design::new(40, 30, Rgb8::new(250, 250, 250)),
            "test".into(),
            false,
        )
    }

    fn spray(x: f64) -> Op {
        Op::Spray(Spray {
            center: Point::new(x, 5.0),
            radius: 2.0,
            color: Rgb8::new(0, 0, 0),
        })
    }

    #[test]
    fn a_stroke_then_new_then_undo_leaves_the_stroke_and_keeps_a_recent_copy() {
        let mut a = app();
        a.apply(Action::Commit(
            (0..30).map(|i| spray(f64::from(i))).collect(),
        ));
        let stroke = a.editor.history.design().clone();
        assert_eq!(a.editor.shown.op_count(), 30);
        a.apply(Action::NewSheet);
        assert!(a.editor.history.design().ops.is_empty());
        assert_eq!(a.session.recent().entries.len(), 1);
        assert!(a.session.owes_autosave() && a.session.owes_recent());
        a.editor.view = Some(crate::marbling::view::ViewState::fit(
            &a.editor.shown.design,
            [800.0, 600.0],
        ));
        a.apply(Action::Undo);
        assert_eq!(a.editor.history.design(), &stroke);
        assert!(
            a.editor.view.is_none(),
            "the 40×30 sheet is fitted again after the undo"
        );
        a.apply(Action::Undo);
        assert!(a.editor.history.design().ops.is_empty());
        a.apply(Action::OpenRecent(0));
        assert_eq!(a.editor.history.design(), &stroke);
    }

    #[test]
    fn play_and_earlier_steps_are_views_of_the_design_not_copies() {
        let mut a = app();
        for i in 0..3 {
            a.apply(Action::Commit(vec![
                spray(f64::from(i)),
                spray(f64::from(i) + 0.5),
            ]));
        }
        let design = a.editor.history.design_shared().clone();
        a.apply(Action::View(Some(1)));
        assert_eq!(a.editor.shown.op_count(), 2);
        assert!(std::sync::Arc::ptr_eq(&a.editor.shown.design, &design));
        a.apply(Action::Play(true));
        assert!(a.editor.playback.is_some());
        assert_eq!(
            a.editor.shown.op_count(),
            0,
            "nothing shown before the first step"
        );
        a.apply(Action::Seek {
            position: 1.5,
            playing: false,
        });
        // Half way into the second step (two sprays): the first spray of it done,
        // the second starting.
        assert_eq!(a.editor.shown.ops, 3);
        assert_eq!(a.editor.shown.tail.len(), 1);
        assert!(std::sync::Arc::ptr_eq(&a.editor.shown.design, &design));
        a.apply(Action::Play(false));
        assert!(a.editor.playback.is_none());
        assert_eq!(a.editor.shown, crate::marbling::shown::Shown::all(design));
    }

    #[test]
    fn paper_colour_is_an_undoable_step_that_keeps_the_ops() {
        let mut a = app();
        a.apply(Action::Commit(vec![spray(1.0)]));
        a.apply(Action::SetPaperColor(Rgb8::new(10, 20, 30)));
        assert_eq!(a.editor.shown.design.background, Rgb8::new(10, 20, 30));
        assert_eq!(
            a.editor.history.steps().last().expect("a value").label,
            "paper #0a141e"
        );
        a.apply(Action::Undo);
        assert_eq!(a.editor.shown.design.background, Rgb8::new(250, 250, 250));
        assert_eq!(a.editor.shown.op_count(), 1);
    }

    #[test]
    fn an_edit_past_the_cap_is_refused_with_a_message_and_nothing_is_saved() {
        let mut d = Design::new(40, 30, Rgb8::new(250, 250, 250));
        d.ops = (0..MAX_OPS).map(|i| spray(i as f64 % 40.0)).collect();
        let mut a = MarblingApp::with_design(d.clone(), "test".into(), false);
        a.apply(Action::Commit(vec![spray(3.0)]));
        let m = a.panels.message.clone().expect("a message");
        assert!(m.error);
        assert_eq!(
            m.text,
            EditError::TooManyOps {
                have: MAX_OPS,
                adding: 1
            }
            .to_string()
        );
        assert_eq!(a.editor.history.design(), &d);
        assert!(!a.session.owes_autosave());
    }

    /// A status message is about the last thing done: the next edit takes it away (an
    /// error too), while stepping the player or viewing a step keeps it.
    #[test]
    fn a_status_message_goes_at_the_next_edit() {
        let mut a = app();
        a.apply(Action::Commit(vec![spray(1.0)]));
        a.info("opened Stone (battal)");
        a.apply(Action::View(Some(0)));
        a.apply(Action::View(None));
        assert!(a.panels.message.is_some(), "viewing a step is not an edit");
        a.apply(Action::Commit(vec![spray(2.0)]));
        assert!(a.panels.message.is_none(), "the drop after the opening");
        a.error("share link: not valid base64url");
        a.apply(Action::Undo);
        assert!(a.panels.message.is_none(), "an undo after an error");
    }

    #[test]
    fn viewing_an_earlier_step_then_editing_keeps_the_later_steps_restorable() {
        let mut a = app();
        for i in 0..4 {
            a.apply(Action::Commit(vec![spray(f64::from(i))]));
        }
        let full = a.editor.history.design().clone();
        a.apply(Action::View(Some(1)));
        assert_eq!(a.editor.shown.op_count(), 1);
        a.apply(Action::Commit(vec![spray(30.0), spray(31.0)]));
        assert_eq!(a.editor.shown.op_count(), 3);
        assert_eq!(a.editor.history.branches().len(), 1);
        a.apply(Action::Restore(0));
        assert_eq!(a.editor.history.design(), &full);
    }
}
