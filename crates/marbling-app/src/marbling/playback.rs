//! The step player: the making of a design played step by step (a step is a gesture,
//! see `Design::gesture_sizes`), each step's ops eased in from zero strength (combs,
//! swirls), zero radius (drops) or zero length (strokes); it can pause, step and scrub.

use crate::marbling::shown::Shown;
use marbling_core::making::{ease, moment};
use marbling_core::{Design, Op};
use std::sync::Arc;

/// Where the player is: `step` steps are done and the next is `t` (0..1) of the way in;
/// `step` = the number of steps is the whole design.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Playback {
    /// Steps fully shown.
    pub step: usize,
    /// Progress of the next step, 0..1.
    pub t: f64,
    /// Advancing with time (else paused).
    pub playing: bool,
}

impl Playback {
    /// Playing from the first step.
    pub fn start() -> Self {
        Self {
            step: 0,
            t: 0.0,
            playing: true,
        }
    }

    /// Paused at `position` steps (0..=`steps`; the fraction is the next step's
    /// progress).
    pub fn at(position: f64, steps: usize) -> Self {
        let p = position.clamp(0.0, steps as f64);
        let step = (p.floor() as usize).min(steps);
        Self {
            step,
            t: if step == steps { 0.0 } else { p - step as f64 },
            playing: false,
        }
    }

    /// Steps done, with the fraction of the next.
    pub fn position(&self) -> f64 {
        self.step as f64 + self.t
    }

    /// Advances by `dt` seconds at `steps_per_second`; at the end it stops on the
    /// whole design, and with a negative speed (backward) at the start on the bare
    /// tank. Returns whether it is still playing.
    pub fn advance(&mut self, dt: f64, steps_per_second: f64, steps: usize) -> bool {
        if !self.playing {
            return false;
        }
        let next = self.position() + dt * steps_per_second;
        *self = Self {
            playing: true,
            ..Self::at(next, steps)
        };
        // Forward it stops at the end; backward (a negative speed) at the start.
        if (steps_per_second >= 0.0 && self.step >= steps)
            || (steps_per_second < 0.0 && next <= 0.0)
        {
            self.playing = false;
        }
        self.playing
    }

    /// The step whose caption describes what is shown: the one easing in, else the
    /// last one done (`None` before the first).
    pub fn current_step(&self) -> Option<usize> {
        if self.t > 0.0 {
            Some(self.step)
        } else {
            self.step.checked_sub(1)
        }
    }

    /// The op easing in now and its eased fraction (for drawing the tool), given the
    /// design's step bounds (`Design::step_bounds`).
    pub fn easing_op<'a>(&self, full: &'a Design, bounds: &[usize]) -> Option<(&'a Op, f64)> {
        let (k, frac) = self.op_in_step(bounds)?;
        Some((&full.ops[k], ease(frac)))
    }

    /// The index of the op easing in and its progress, `None` between steps.
    fn op_in_step(&self, bounds: &[usize]) -> Option<(usize, f64)> {
        moment(bounds, self.position()).easing
    }

    /// The design as it looks at this moment: the steps done, then the next step's
    /// ops eased in one after another (a view of `full`, no copy).
    pub fn frame(&self, full: &Arc<Design>, bounds: &[usize]) -> Shown {
        match self.op_in_step(bounds) {
            Some((k, frac)) => Shown {
                design: full.clone(),
                ops: k,
                tail: vec![full.ops[k].scaled(ease(frac))],
            },
            None => Shown {
                design: full.clone(),
                ops: moment(bounds, self.position()).done.min(full.ops.len()),
                tail: Vec::new(),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn played_backward_it_stops_on_the_bare_tank() {
        let mut p = Playback::at(3.0, 3);
        p.playing = true;
        let mut frames = 0;
        while p.advance(0.1, -2.0, 3) {
            frames += 1;
            assert!(p.position() < 3.0 && p.position() > 0.0);
        }
        assert_eq!(frames, 14, "3 steps at 2 steps/s backward, 0.1 s a frame");
        assert_eq!((p.position(), p.playing), (0.0, false));
    }

    #[test]
    fn the_player_eases_each_step_in_and_ends_on_the_design() {
        let mut full = random_design(1, 100, 100, 20, Mix::Mixed);
        full.set_gesture_sizes([3, 1, 5, 1, 10]);
        let full = Arc::new(full);
        let bounds = full.step_bounds();
        assert_eq!(bounds, vec![0, 3, 4, 9, 10, 20]);
        let steps = bounds.len() - 1;
        let mut p = Playback::start();
        assert_eq!(p.frame(&full, &bounds).op_count(), 0);
        let mut frames = 0;
        while p.advance(0.1, 2.0, steps) {
            let f = p.frame(&full, &bounds).to_design();
            assert!(f.validate().is_ok());
            let done = bounds[p.step];
            assert_eq!(&f.ops[..done], &full.ops[..done]);
            frames += 1;
        }
        assert_eq!(frames, 24, "5 steps at 2 steps/s, 0.1 s a frame");
        assert_eq!(p.frame(&full, &bounds), Shown::all(full.clone()));
        assert!(!p.playing && p.current_step() == Some(4));
        // Scrubbing to whole steps shows their prefixes; half way into step 2 (5 ops)
        // shows its first two ops done and the third half eased in.
        for k in 0..=steps {
            assert_eq!(
                Playback::at(k as f64, steps)
                    .frame(&full, &bounds)
                    .op_count(),
                bounds[k]
            );
        }
        let half = Playback::at(2.5, steps);
        let f = half.frame(&full, &bounds);
        assert_eq!((f.ops, f.tail.len()), (6, 1));
        assert_eq!(
            half.easing_op(&full, &bounds).map(|(_, e)| e),
            Some(ease(0.5))
        );
        assert_eq!(Playback::at(99.0, steps).position(), steps as f64);
        assert_eq!(full.ops[3].scaled(1.0), full.ops[3]);
        assert_eq!((ease(0.0), ease(0.5), ease(1.0)), (0.0, 0.5, 1.0));
    }
}
