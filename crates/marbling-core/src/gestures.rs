//! Gestures: runs of consecutive ops that one user action made (a spray stroke of 340
//! droplets, a rake of 9 tines) and that undo and redo take back together.
//!
//! A design stores only the runs of two or more ops, as `"gestures": [[first, count], …]`
//! (sorted, non-overlapping, inside `ops`); every op outside a run is a gesture of its
//! own. The field is optional in every schema version and written only when a run
//! exists, so a design made op by op is written exactly as before.

use crate::Design;

/// Ops `first .. first + count` of a design were made by one gesture (`count ≥ 2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GestureSpan {
    /// Index of the gesture's first op.
    pub first: usize,
    /// Number of ops in the gesture, at least 2.
    pub count: usize,
}

impl GestureSpan {
    /// One past the gesture's last op.
    pub fn end(self) -> usize {
        self.first + self.count
    }
}

impl Design {
    /// The number of ops of each gesture, oldest first; they add up to `ops.len()`.
    /// Ops outside [`Design::gestures`] count as gestures of one op.
    pub fn gesture_sizes(&self) -> Vec<usize> {
        let mut sizes = Vec::new();
        let mut at = 0;
        for g in &self.gestures {
            sizes.extend(std::iter::repeat_n(1, g.first.saturating_sub(at)));
            sizes.push(g.count);
            at = g.end();
        }
        sizes.extend(std::iter::repeat_n(1, self.ops.len().saturating_sub(at)));
        sizes
    }

    /// Sets [`Design::gestures`] from the op count of each gesture, oldest first (the
    /// inverse of [`Design::gesture_sizes`]); zero sizes are skipped.
    pub fn set_gesture_sizes(&mut self, sizes: impl IntoIterator<Item = usize>) {
        self.gestures.clear();
        let mut at = 0;
        for n in sizes {
            if n >= 2 {
                self.gestures.push(GestureSpan {
                    first: at,
                    count: n,
                });
            }
            at += n;
        }
    }

    /// Keeps the first `n` ops and the gestures that lie wholly inside them (a gesture
    /// cut in two keeps its first part as one gesture).
    pub fn truncate_ops(&mut self, n: usize) {
        self.ops.truncate(n);
        let len = self.ops.len();
        self.gestures.retain(|g| g.first + 1 < len);
        if let Some(g) = self.gestures.last_mut() {
            g.count = g.count.min(len - g.first);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Op, Point, Rgb8, Spray};

    fn design(n: usize) -> Design {
        let mut d = Design::new(10, 10, Rgb8::new(0, 0, 0));
        d.ops = (0..n)
            .map(|i| {
                Op::Spray(Spray {
                    center: Point::new(i as f64, 0.0),
                    radius: 1.0,
                    color: Rgb8::new(0, 0, 0),
                })
            })
            .collect();
        d
    }

    #[test]
    fn sizes_round_trip_through_spans() {
        let mut d = design(10);
        d.set_gesture_sizes([1, 3, 1, 1, 4]);
        assert_eq!(
            d.gestures,
            vec![
                GestureSpan { first: 1, count: 3 },
                GestureSpan { first: 6, count: 4 }
            ]
        );
        assert_eq!(d.gesture_sizes(), vec![1, 3, 1, 1, 4]);
        d.gestures.clear();
        assert_eq!(d.gesture_sizes(), vec![1; 10]);
    }

    #[test]
    fn truncating_cuts_or_drops_the_gestures_past_the_end() {
        let mut d = design(10);
        d.set_gesture_sizes([1, 3, 1, 1, 4]);
        d.truncate_ops(8);
        assert_eq!(d.gesture_sizes(), vec![1, 3, 1, 1, 2]);
        d.truncate_ops(7);
        assert_eq!(d.gesture_sizes(), vec![1, 3, 1, 1, 1]);
        d.truncate_ops(2);
        assert_eq!(d.gesture_sizes(), vec![1, 1]);
    }
}
