//! The document being edited and how it is shown: its history, the state on the
//! canvas (the whole design, a viewed step or a playback frame, or the noise
//! playground's picture), the view, the gesture under way and the player's position.
//! What changes the document is [`Editor::apply`] (src/action.rs).

use crate::History;
use crate::gpu::canvas_gpu::StandIn;
use crate::marbling::canvas::ActiveGesture;
use crate::marbling::playback::Playback;
use crate::marbling::shown::Shown;
use crate::marbling::view::ViewState;
use crate::noise::Noise;
use crate::shell::mode::Mode;
use marbling_core::{Design, ViewSpec};
use std::sync::Arc;

/// The sheet under the noise preview (where 2×2 tiles leave it uncovered).
const PREVIEW_PAPER: marbling_core::Rgb8 = marbling_core::Rgb8::new(40, 40, 44);

/// How many shown states [`Editor::recent`] remembers (the GPU holds the preview caches
/// of two).
pub const RECENT_STATES: usize = 4;

/// The document being edited and how it is shown: history, view, gesture, playback, and
/// the noise playground's parameters.
pub(crate) struct Editor {
    /// The design's history (the design is its current state).
    pub history: History,
    /// Bumped whenever the shown design changes (the GPU brings its upload up to date).
    pub key: u64,
    /// What may stand in for the shown design (`.0` = [`Self::key`]) while its exact
    /// frame is drawn: the design before the last edit, and the op the edit added.
    pub stand_in: Option<(u64, StandIn)>,
    /// The last few states shown, newest last, by key ([`RECENT_STATES`] at most): an
    /// Undo or Redo back to one of them has its preview cache stand in.
    pub recent: std::collections::VecDeque<(u64, Shown)>,
    /// The design on the canvas (the history, a viewed step or a playback frame).
    pub shown: Shown,
    /// `None` until the canvas size is known (then the design is fitted).
    pub view: Option<ViewState>,
    /// The last view made to fit the canvas, and the window and canvas it was made for
    /// (window width and height in points, physical pixels per point, canvas width and
    /// height in points): while `view` is still that one, a resized window, a changed
    /// pixel ratio or a canvas grown or shrunk by a panel fits it again.
    pub fit: Option<(ViewState, [f64; 5])>,
    /// A view asked for by a link's `v=` or the Zoom to box (centre and zoom), set on
    /// the canvas at its next layout.
    pub view_request: Option<ViewSpec>,
    /// The canvas's size at the last layout, points.
    pub canvas_size: [f64; 2],
    /// Two fingers are on the canvas: the view follows them unsnapped (snapping every
    /// frame would let the pinch's anchor drift), and is snapped when they lift.
    pub pinching: bool,
    /// The fingers on the canvas (src/marbling/fingers.rs).
    pub fingers: crate::marbling::fingers::Fingers,
    /// The tool being dragged.
    pub active: Option<ActiveGesture>,
    /// Seed of the next gesture's random choices.
    pub next_seed: u64,
    /// Play in progress.
    pub playback: Option<Playback>,
    /// True while the design is the start-up example nobody has touched (a link then
    /// replaces it instead of stacking on it).
    pub pristine: bool,
    /// The gallery is shown in place of the canvas (src/shell/landing.rs).
    pub landing: bool,
    /// Marbling or the noise playground.
    pub mode: Mode,
}

impl Editor {
    /// Editing `design`, fitted to the canvas on the first frame.
    pub fn new(design: Design) -> Self {
        let history = History::new(design);
        Self {
            shown: Shown::all(history.design_shared().clone()),
            history,
            key: 0,
            stand_in: None,
            recent: std::collections::VecDeque::new(),
            view: None,
            fit: None,
            view_request: None,
            canvas_size: [0.0; 2],
            pinching: false,
            fingers: Default::default(),
            active: None,
            next_seed: 1,
            playback: None,
            pristine: false,
            landing: false,
            mode: Mode::Marbling,
        }
    }

    /// Adds the state shown now to [`Self::recent`].
    pub fn remember_shown(&mut self) {
        self.recent.push_back((self.key, self.shown.clone()));
        if self.recent.len() > RECENT_STATES {
            self.recent.pop_front();
        }
    }

    /// The latest earlier state (key) that looks like the one shown now, if remembered.
    pub fn earlier_look_alike(&self) -> Option<u64> {
        self.recent
            .iter()
            .rev()
            .find(|(k, s)| *k != self.key && s.looks_like(&self.shown))
            .map(|(k, _)| *k)
    }

    /// The shown design changed: new key, new snapshot.
    pub fn refresh(&mut self, noise: &mut Noise) -> Result<(), String> {
        self.key += 1;
        if self.mode == Mode::Noise {
            let d = self.history.design();
            let size = [d.width, d.height];
            // The CPU preview draws a spec the background cannot hold: the GPU then
            // draws a bare sheet under it, not the (costly) base noise.
            let noise = if noise.settings().needs_preview() {
                Ok(marbling_core::Design::new(size[0], size[1], PREVIEW_PAPER))
            } else {
                noise
                    .layer_for(self.view)
                    .and_then(|layer| noise.settings().design(size, layer))
            };
            match noise {
                Ok(noise) => self.shown = crate::marbling::shown::Shown::all(Arc::new(noise)),
                Err(e) => return Err(format!("noise: {e}")),
            }
            return Ok(());
        }
        self.shown = match &self.playback {
            Some(p) => {
                let full = self.history.design_shared();
                p.frame(full, &full.step_bounds())
            }
            None => self.history.shown(),
        };
        self.remember_shown();
        Ok(())
    }

    /// Switches between marbling and the noise playground.
    pub fn set_mode(&mut self, mode: Mode, noise: &mut Noise) -> Result<(), String> {
        if mode == self.mode {
            return Ok(());
        }
        self.mode = mode;
        self.playback = None;
        self.active = None;
        noise.forget_shown();
        self.refresh(noise)
    }
}
