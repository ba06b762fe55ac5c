//! The making of a design over time, as the step player and `marbling animate` show
//! it: at `position` steps (a step is a gesture, see [`Design::step_bounds`]) the steps
//! before are done and the next step's ops ease in one after another, each from zero
//! strength (combs, swirls), zero radius (drops) or zero length (strokes).

use crate::Design;

/// What is shown at one moment: the first `done` ops, then op `easing.0` at progress
/// `easing.1` (0..1, before easing) if a step is under way.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Moment {
    /// Ops fully shown.
    pub done: usize,
    /// The op easing in and its (linear) progress.
    pub easing: Option<(usize, f64)>,
}

/// The moment `position` steps into a making with step `bounds` (clamped to
/// 0..=steps).
pub fn moment(bounds: &[usize], position: f64) -> Moment {
    let steps = bounds.len().saturating_sub(1);
    let p = if position.is_nan() {
        0.0
    } else {
        position.clamp(0.0, steps as f64)
    };
    let step = (p.floor() as usize).min(steps);
    let t = p - step as f64;
    if step >= steps || t <= 0.0 {
        return Moment {
            done: bounds.get(step).copied().unwrap_or(0),
            easing: None,
        };
    }
    let (first, end) = (bounds[step], bounds[step + 1]);
    let x = t * (end - first) as f64;
    let k = (x.floor() as usize).min(end - first - 1);
    Moment {
        done: first + k,
        easing: Some((first + k, x - k as f64)),
    }
}

/// The design as it looks `position` steps into its making (a copy, for exports).
pub fn design_at(design: &Design, position: f64) -> Design {
    let m = moment(&design.step_bounds(), position);
    let mut d = design.clone();
    d.truncate_ops(m.done);
    if let Some((k, t)) = m.easing {
        d.ops.push(design.ops[k].scaled(ease(t)));
    }
    d
}

/// Smoothstep easing, 0 → 0 and 1 → 1 with zero slope at both ends.
pub fn ease(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};
    use crate::{Op, Point};
    use std::sync::Arc;

    #[test]
    fn moments_walk_the_steps_and_the_last_is_the_design() {
        let mut d = random_design(3, 100, 100, 10, Mix::Mixed);
        d.set_gesture_sizes([4, 1, 5]);
        let b = d.step_bounds();
        assert_eq!(
            moment(&b, 0.0),
            Moment {
                done: 0,
                easing: None
            }
        );
        assert_eq!(
            moment(&b, 1.0),
            Moment {
                done: 4,
                easing: None
            }
        );
        assert_eq!(
            moment(&b, 0.5),
            Moment {
                done: 2,
                easing: Some((2, 0.0))
            }
        );
        assert_eq!(moment(&b, 2.5).easing, Some((7, 0.5)));
        assert_eq!(
            moment(&b, 9.0),
            Moment {
                done: 10,
                easing: None
            }
        );
        assert_eq!(moment(&b, f64::NAN).done, 0);
        assert_eq!(design_at(&d, 3.0), d);
        assert_eq!(design_at(&d, 2.5).ops.len(), 8);
        assert!(design_at(&d, 2.5).validate().is_ok());
    }

    #[test]
    fn a_stroke_plays_along_its_path() {
        use crate::Stylus;
        let op = Op::Stylus(Stylus {
            path: Arc::from([
                Point::new(0.0, 0.0),
                Point::new(100.0, 0.0),
                Point::new(100.0, 100.0),
            ]),
            wake: 4.0,
            tips: None,
        });
        let Op::Stylus(half) = op.scaled(0.75) else {
            panic!()
        };
        // Three quarters of 200 px: the first segment and half the second.
        assert_eq!(
            &half.path[..],
            [
                Point::new(0.0, 0.0),
                Point::new(100.0, 0.0),
                Point::new(100.0, 50.0)
            ]
        );
        let Op::Stylus(none) = op.scaled(0.0) else {
            panic!()
        };
        assert_eq!(none.sub_steps(), 0);
        assert_eq!(op.scaled(1.0), op);
    }
}
