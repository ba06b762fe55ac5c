//! "Play": the making of a design animated op by op, each op eased in from zero
//! strength (combs, swirls) or zero radius (drops, sprays).

use crate::shown::Shown;
use marbling_core::{Design, Op, Point, Radii};
use std::sync::Arc;

/// Where a playback is: op `index` is `t` (0..=1) of the way in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Playback {
    /// The op being eased in.
    pub index: usize,
    /// Progress of that op, 0..=1.
    pub t: f64,
}

/// Smoothstep easing, 0 → 0 and 1 → 1 with zero slope at both ends.
pub fn ease(t: f64) -> f64 {
    let t = t.clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// `op` at fraction `s` (0..=1) of its strength or radius.
pub fn scaled(op: &Op, s: f64) -> Op {
    let mut op = op.clone();
    // Radii stay > 0 so the scaled op is still valid.
    let tiny = 1e-6;
    match &mut op {
        Op::Drop(d) => d.radius = (d.radius * s).max(tiny),
        Op::Spray(d) => d.radius = (d.radius * s).max(tiny),
        Op::Tine(t) => t.alpha *= s,
        Op::Rake(r) => r.alpha *= s,
        Op::Wavy(w) => w.amplitude *= s,
        Op::Circular(c) => c.alpha *= s,
        Op::Vortex(v) => v.alpha *= s,
        Op::Shift(t) => t.offset *= s,
        Op::Turn(t) => t.angle *= s,
        Op::Comb(c) => c.alpha *= s,
        Op::Drops(d) | Op::Sprays(d) => {
            d.radii = match &d.radii {
                Radii::One(r) => Radii::One((r * s).max(tiny)),
                Radii::Each(list) => Radii::Each(list.iter().map(|r| (r * s).max(tiny)).collect()),
            }
        }
        Op::Jiggle(j) => {
            j.along *= s;
            j.across *= s;
        }
        // A stroke is drawn along its path: the first fraction s of its length.
        Op::Stylus(st) => st.path = path_part(&st.path, s),
    }
    op
}

/// The first fraction `s` (0..=1) of a path's length (at least two points).
fn path_part(path: &[Point], s: f64) -> Arc<[Point]> {
    let total: f64 = path.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
    let mut left = total * s.clamp(0.0, 1.0);
    let mut out = vec![path[0]];
    for w in path.windows(2) {
        let len = (w[1] - w[0]).hypot();
        if left >= len {
            out.push(w[1]);
            left -= len;
        } else {
            out.push(w[0] + (w[1] - w[0]) * (left / len));
            break;
        }
    }
    if out.len() < 2 {
        out.push(path[0]);
    }
    out.into()
}

impl Playback {
    /// Starts at the first op.
    pub fn start() -> Self {
        Self { index: 0, t: 0.0 }
    }

    /// Advances by `dt` seconds at `ops_per_second`; false once past the last op.
    pub fn advance(&mut self, dt: f64, ops_per_second: f64, op_count: usize) -> bool {
        self.t += dt * ops_per_second;
        while self.t >= 1.0 && self.index < op_count {
            self.t -= 1.0;
            self.index += 1;
        }
        self.index < op_count
    }

    /// The design as it looks at this moment of the playback: the ops before the one
    /// being eased in, then that op at its eased strength (a view of `full`, no copy).
    pub fn frame(&self, full: &Arc<Design>) -> Shown {
        Shown {
            design: full.clone(),
            ops: self.index.min(full.ops.len()),
            tail: full
                .ops
                .get(self.index)
                .map(|op| scaled(op, ease(self.t)))
                .into_iter()
                .collect(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn playback_eases_each_op_in_and_ends_on_the_design() {
        let full = Arc::new(random_design(1, 100, 100, 20, Mix::Mixed));
        let mut p = Playback::start();
        let first = p.frame(&full).to_design();
        assert_eq!(first.ops.len(), 1);
        assert!(first.validate().is_ok());
        let mut frames = 0;
        while p.advance(0.1, 3.0, full.ops.len()) {
            let f = p.frame(&full).to_design();
            assert!(f.validate().is_ok());
            assert_eq!(&f.ops[..p.index], &full.ops[..p.index]);
            frames += 1;
        }
        assert_eq!(p.frame(&full), Shown::all(full.clone()));
        assert!(frames >= 60, "{frames}");
        assert_eq!(scaled(&full.ops[3], 1.0), full.ops[3]);
        assert_eq!((ease(0.0), ease(0.5), ease(1.0)), (0.0, 0.5, 1.0));
    }

    #[test]
    fn a_stroke_plays_along_its_path() {
        use marbling_core::Stylus;
        let op = Op::Stylus(Stylus {
            path: Arc::from([
                Point::new(0.0, 0.0),
                Point::new(100.0, 0.0),
                Point::new(100.0, 100.0),
            ]),
            wake: 4.0,
            tips: None,
        });
        let Op::Stylus(half) = scaled(&op, 0.75) else {
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
        let Op::Stylus(none) = scaled(&op, 0.0) else {
            panic!()
        };
        assert_eq!(none.sub_steps(), 0);
        assert_eq!(scaled(&op, 1.0), op);
    }
}
