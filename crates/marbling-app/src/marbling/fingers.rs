//! Two-finger navigation from the frame's raw touch events: each move of either finger
//! pans the view by the fingers' midpoint motion and zooms it about the new midpoint by
//! the change of their distance. Reading every event (not egui's per-frame summary)
//! keeps the last moves of a frame in which a finger also lifts: on a slow frame the
//! final motion before lifting would otherwise be lost.

use egui::{Event, Pos2, TouchPhase, Vec2};
use std::collections::BTreeMap;

/// One step of two-finger motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoFingerStep {
    /// The midpoint's motion, points.
    pub pan: Vec2,
    /// New distance / old distance between the fingers.
    pub zoom: f64,
    /// The midpoint after the step, points (the zoom's fixed point).
    pub about: Pos2,
}

/// The fingers on the screen, by touch id.
#[derive(Clone, Debug, Default)]
pub struct Fingers {
    down: BTreeMap<u64, Pos2>,
}

impl Fingers {
    /// How many fingers are down.
    pub fn count(&self) -> usize {
        self.down.len()
    }

    /// Applies the frame's touch events in order and returns the two-finger steps they
    /// make (moves while exactly two fingers are down).
    pub fn feed(&mut self, events: &[Event]) -> Vec<TwoFingerStep> {
        let mut steps = Vec::new();
        for e in events {
            let Event::Touch { id, phase, pos, .. } = e else {
                continue;
            };
            let before = self.pair();
            match phase {
                TouchPhase::Start | TouchPhase::Move => {
                    self.down.insert(id.0, *pos);
                }
                TouchPhase::End | TouchPhase::Cancel => {
                    self.down.remove(&id.0);
                }
            }
            if *phase != TouchPhase::Move {
                continue;
            }
            if let (Some((m0, d0)), Some((m1, d1))) = (before, self.pair())
                && d0 > 0.0
            {
                steps.push(TwoFingerStep {
                    pan: m1 - m0,
                    zoom: f64::from(d1 / d0),
                    about: m1,
                });
            }
        }
        steps
    }

    /// The midpoint and distance of exactly two fingers.
    fn pair(&self) -> Option<(Pos2, f32)> {
        let mut it = self.down.values();
        match (it.next(), it.next(), it.next()) {
            (Some(a), Some(b), None) => Some((a.lerp(*b, 0.5), a.distance(*b))),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::{TouchDeviceId, TouchId, pos2};

    fn touch(id: u64, phase: TouchPhase, x: f32, y: f32) -> Event {
        Event::Touch {
            device_id: TouchDeviceId(0),
            id: TouchId(id),
            phase,
            pos: pos2(x, y),
            force: None,
        }
    }

    #[test]
    fn a_pinch_and_a_pan_in_the_frame_the_fingers_lift_are_kept() {
        let mut f = Fingers::default();
        assert!(
            f.feed(&[
                touch(1, TouchPhase::Start, 100.0, 100.0),
                touch(2, TouchPhase::Start, 200.0, 100.0),
            ])
            .is_empty()
        );
        assert_eq!(f.count(), 2);
        // One slow frame: both fingers spread and move up, then lift.
        let steps = f.feed(&[
            touch(1, TouchPhase::Move, 40.0, 60.0),
            touch(2, TouchPhase::Move, 240.0, 60.0),
            touch(1, TouchPhase::End, 40.0, 60.0),
            touch(2, TouchPhase::End, 240.0, 60.0),
        ]);
        assert_eq!(f.count(), 0);
        let pan = steps.iter().fold(Vec2::ZERO, |a, s| a + s.pan);
        let zoom: f64 = steps.iter().map(|s| s.zoom).product();
        assert_eq!(pan, egui::vec2(-10.0, -40.0));
        assert!((zoom - 2.0).abs() < 1e-6, "{zoom}");
        assert_eq!(steps.last().map(|s| s.about), Some(pos2(140.0, 60.0)));
    }

    #[test]
    fn one_finger_or_three_make_no_steps() {
        let mut f = Fingers::default();
        let one = f.feed(&[
            touch(1, TouchPhase::Start, 0.0, 0.0),
            touch(1, TouchPhase::Move, 50.0, 0.0),
        ]);
        assert!(one.is_empty());
        let three = f.feed(&[
            touch(2, TouchPhase::Start, 10.0, 0.0),
            touch(3, TouchPhase::Start, 20.0, 0.0),
            touch(2, TouchPhase::Move, 30.0, 0.0),
        ]);
        assert!(three.is_empty());
        assert_eq!(f.count(), 3);
    }
}
