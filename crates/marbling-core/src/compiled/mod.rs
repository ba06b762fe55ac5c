//! Ops compiled once for fast point mapping: unit directions, αλ, 2π/wavelength and the
//! sin/cos of a wavy comb's angle are computed here instead of at every point.
//!
//! This is the one compiled representation of an op. The CPU reference renderer's
//! inverse walk ([`crate::Walker`]), forward tracing of ink outlines (marbling-vector)
//! and the GPU's op record (marbling-gpu's `GpuOp`, built from it) all use it; the
//! formulas are those of [`Op::forward`] and [`Op::inverse`] (results agree to
//! rounding, f64 design pixels).

use crate::ops::{FlowField, StylusSegment};
use crate::{Op, OpKind, Rgb8};
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;
use std::sync::Arc;

mod jiggle;
mod kernels;
mod trig;
pub use jiggle::JiggleKernel;
pub use kernels::{CombKernel, RigidKernel, SwirlKernel, WaveKernel};
pub(crate) use kernels::{drop_back, rake_distance, tines_shift};

/// One op with its constants precomputed. Lengths are design pixels. A drop pattern
/// (`drops`, `sprays`) compiles to one [`CompiledOp::Disc`] per drop; every other op
/// to one compiled op.
#[derive(Clone, Debug, PartialEq)]
pub enum CompiledOp {
    /// Drop (`deform`) or spray (`!deform`): a disc of new ink of centre (cx, cy) and
    /// squared radius r2. A drop maps P ↦ C + (P − C)·√(1 + r²/ρ²); a spray moves nothing.
    Disc {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Squared radius, design px².
        r2: f64,
        /// Whether the disc pushes older ink outwards (drop) or not (spray).
        deform: bool,
        /// The ink.
        color: Rgb8,
    },
    /// Tine or rake.
    Comb(CombKernel),
    /// Wavy comb.
    Wave(WaveKernel),
    /// Circular comb or vortex.
    Swirl(SwirlKernel),
    /// Shift or turn.
    Rigid(RigidKernel),
    /// Finite comb: shift αλ/(d + λ) along the unit motion m, d = minᵢ |s − oᵢ|,
    /// s = (P − A)·n.
    Tines {
        /// Origin x.
        ax: f64,
        /// Origin y.
        ay: f64,
        /// Unit motion x.
        mx: f64,
        /// Unit motion y.
        my: f64,
        /// α·λ, design px².
        al: f64,
        /// λ, design px.
        lambda: f64,
        /// Tine offsets oᵢ along n = (−m.y, m.x), design px.
        offsets: Arc<[f64]>,
    },
    /// Jiggle.
    Jiggle(JiggleKernel),
    /// Stylus: its segments, in order.
    Stylus {
        /// The path's segments of non-zero length.
        segments: Arc<[StylusSegment]>,
    },
    /// Flow along a curl noise: its sub-steps.
    Flow {
        /// The compiled flow.
        field: Arc<FlowField>,
    },
}

impl CompiledOp {
    /// Compiles one op: one compiled op, or one per drop of a drop pattern.
    pub fn of(op: &Op) -> Vec<Self> {
        let mut out = Vec::new();
        Self::push(op, &mut out);
        out
    }

    /// Appends the compiled form of `op` to `out`.
    pub fn push(op: &Op, out: &mut Vec<Self>) {
        match op {
            Op::Drops(d) | Op::Sprays(d) => {
                out.extend(
                    d.expand(matches!(op, Op::Sprays(_)))
                        .map(|o| Self::single(&o)),
                );
            }
            _ => out.push(Self::single(op)),
        }
    }

    fn single(op: &Op) -> Self {
        match op {
            Op::Drop(d) => Self::Disc {
                cx: d.center.x,
                cy: d.center.y,
                r2: d.radius * d.radius,
                deform: true,
                color: d.color,
            },
            Op::Spray(s) => Self::Disc {
                cx: s.center.x,
                cy: s.center.y,
                r2: s.radius * s.radius,
                deform: false,
                color: s.color,
            },
            Op::Tine(t) => Self::comb(t.origin, t.direction, t.alpha, t.lambda, 0.0),
            Op::Rake(r) => Self::comb(r.origin, r.direction, r.alpha, r.lambda, r.spacing),
            Op::Shift(s) => Self::Rigid(RigidKernel {
                cx: 0.0,
                cy: 0.0,
                sin: 0.0,
                cos: 1.0,
                ox: s.offset.x,
                oy: s.offset.y,
            }),
            Op::Turn(t) => {
                let (sin, cos) = t.angle.sin_cos();
                Self::Rigid(RigidKernel {
                    cx: t.center.x,
                    cy: t.center.y,
                    sin,
                    cos,
                    ox: 0.0,
                    oy: 0.0,
                })
            }
            Op::Comb(c) => {
                let m = c.direction.normalize();
                Self::Tines {
                    ax: c.origin.x,
                    ay: c.origin.y,
                    mx: m.x,
                    my: m.y,
                    al: c.alpha * c.lambda,
                    lambda: c.lambda,
                    offsets: c.tines.clone(),
                }
            }
            Op::Jiggle(j) => {
                let (sin, cos) = j.angle.sin_cos();
                Self::Jiggle(JiggleKernel {
                    ux: cos,
                    uy: sin,
                    k: TAU / j.wavelength,
                    along: j.along,
                    across: j.across,
                    phase: j.phase,
                })
            }
            Op::Stylus(s) => Self::Stylus {
                segments: s.segments().into(),
            },
            Op::Flow(f) => Self::Flow {
                field: Arc::new(f.field()),
            },
            Op::Drops(_) | Op::Sprays(_) => {
                unreachable!("drop patterns compile to one disc per drop (CompiledOp::push)")
            }
            Op::Wavy(w) => {
                let (s, c) = w.angle.sin_cos();
                Self::Wave(WaveKernel {
                    mx: c,
                    my: s,
                    nx: s,
                    ny: -c,
                    amp: w.amplitude,
                    k: TAU / w.wavelength,
                    phase: w.phase,
                })
            }
            Op::Circular(c) => Self::Swirl(SwirlKernel {
                cx: c.center.x,
                cy: c.center.y,
                r: c.radius,
                al: c.alpha * c.lambda,
                lambda: c.lambda,
                vortex: false,
            }),
            Op::Vortex(v) => Self::Swirl(SwirlKernel {
                cx: v.center.x,
                cy: v.center.y,
                r: 0.0,
                al: v.alpha * v.lambda,
                lambda: v.lambda,
                vortex: true,
            }),
        }
    }

    fn comb(origin: Point, dir: Vec2, alpha: f64, lambda: f64, spacing: f64) -> Self {
        let m = dir.normalize();
        Self::Comb(CombKernel {
            ax: origin.x,
            ay: origin.y,
            mx: m.x,
            my: m.y,
            nx: -m.y,
            ny: m.x,
            al: alpha * lambda,
            lambda,
            spacing,
            inv_spacing: 1.0 / spacing,
        })
    }

    /// Which formula this op applies (the code of its GPU record).
    pub fn kind(&self) -> OpKind {
        match *self {
            Self::Disc { deform: true, .. } => OpKind::Drop,
            Self::Disc { deform: false, .. } => OpKind::Spray,
            Self::Comb(_) => OpKind::Comb,
            Self::Wave(_) => OpKind::Wave,
            Self::Swirl(SwirlKernel { vortex: false, .. }) => OpKind::Circular,
            Self::Swirl(SwirlKernel { vortex: true, .. }) => OpKind::Vortex,
            Self::Rigid(_) => OpKind::Rigid,
            Self::Tines { .. } => OpKind::Tines,
            Self::Jiggle { .. } => OpKind::Jiggle,
            Self::Stylus { .. } => OpKind::Stylus,
            Self::Flow { .. } => OpKind::Flow,
        }
    }

    /// What walking one point back through this op costs, in units of a simple op (a
    /// comb one per tine, a stylus [`crate::ops::STYLUS_SEGMENT_COST`] per segment, a
    /// jiggle [`crate::ops::JIGGLE_COST`]).
    pub fn walk_cost(&self) -> u64 {
        match self {
            Self::Tines { offsets, .. } => offsets.len() as u64,
            Self::Stylus { segments } => crate::ops::STYLUS_SEGMENT_COST * segments.len() as u64,
            Self::Jiggle { .. } => crate::ops::JIGGLE_COST,
            Self::Flow { field } => {
                crate::ops::flow_cost(field.steps, field.octaves().len() as u32)
            }
            _ => 1,
        }
    }

    /// The ink this op lays, if it lays any.
    pub fn ink(&self) -> Option<Rgb8> {
        match self {
            Self::Disc { color, .. } => Some(*color),
            _ => None,
        }
    }

    /// Compiles every op of a design, oldest first (a drop pattern gives one op per
    /// drop).
    pub fn compile(ops: &[Op]) -> Vec<Self> {
        let mut out = Vec::with_capacity(ops.len());
        for op in ops {
            Self::push(op, &mut out);
        }
        out
    }

    /// Where older ink at `p` ends up after this op (a spray, or a drop's own centre,
    /// moves nothing).
    #[inline]
    pub fn forward(&self, p: Point) -> Point {
        let (x, y) = match *self {
            Self::Disc {
                cx, cy, r2, deform, ..
            } => {
                let (dx, dy) = (p.x - cx, p.y - cy);
                let d2 = dx * dx + dy * dy;
                if !deform || d2 == 0.0 {
                    return p;
                }
                let f = (1.0 + r2 / d2).sqrt();
                (cx + dx * f, cy + dy * f)
            }
            Self::Comb(ref c) => c.apply(p.x, p.y, 1.0),
            Self::Wave(ref w) => w.shift(p.x, p.y, 1.0),
            Self::Swirl(ref w) => w.apply(p.x, p.y, 1.0),
            Self::Rigid(ref r) => r.apply(p.x, p.y, 1.0),
            Self::Tines { .. } => tines_shift(p.x, p.y, self, 1.0),
            Self::Jiggle(ref j) => return j.forward(p),
            Self::Stylus { ref segments } => {
                return segments.iter().fold(p, |p, s| s.forward(p));
            }
            Self::Flow { ref field } => return field.forward(p),
        };
        Point::new(x, y)
    }

    /// Where a point `p` after this op was before it; `None` when `p` lies in the ink
    /// this op lays (ρ < r of a drop or spray).
    #[inline]
    pub fn inverse(&self, p: Point) -> Option<Point> {
        let (x, y) = match *self {
            Self::Disc {
                cx, cy, r2, deform, ..
            } => {
                let (dx, dy) = (p.x - cx, p.y - cy);
                let d2 = dx * dx + dy * dy;
                if d2 < r2 {
                    return None;
                }
                if !deform {
                    return Some(p);
                }
                drop_back(cx, cy, r2, dx, dy, d2)
            }
            Self::Comb(ref c) => c.apply(p.x, p.y, -1.0),
            Self::Wave(ref w) => w.shift(p.x, p.y, -1.0),
            Self::Swirl(ref w) => w.apply(p.x, p.y, -1.0),
            Self::Rigid(ref r) => r.apply(p.x, p.y, -1.0),
            Self::Tines { .. } => tines_shift(p.x, p.y, self, -1.0),
            Self::Jiggle(ref j) => j.back(p.x, p.y),
            Self::Stylus { ref segments } => {
                return Some(segments.iter().rev().fold(p, |p, s| s.inverse(p)));
            }
            Self::Flow { ref field } => return Some(field.inverse(p)),
        };
        Some(Point::new(x, y))
    }
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::Back;
    use crate::synth::{Mix, SplitMix64, random_design};

    #[test]
    fn an_ops_walk_cost_is_that_of_its_compiled_forms() {
        for mix in [Mix::AllTypes, Mix::Stylus] {
            let design = random_design(5, 300, 200, 200, mix);
            for op in &design.ops {
                let compiled: u64 = CompiledOp::of(op).iter().map(CompiledOp::walk_cost).sum();
                assert_eq!(op.walk_cost(), compiled, "{op:?}");
            }
            // The comparison can fail: combs, styli and jiggles cost more than one.
            assert!(design.ops.iter().any(|op| op.walk_cost() > 1));
        }
    }

    fn close(a: Point, b: Point) -> bool {
        (a - b).hypot() <= 1e-9 * (1.0 + a.to_vec2().hypot())
    }

    #[test]
    fn compiled_ops_match_op_forward_and_inverse() {
        let mut rng = SplitMix64(9);
        for mix in [Mix::Mixed, Mix::DropHeavy, Mix::CombHeavy] {
            let design = random_design(3, 300, 200, 300, mix);
            for op in &design.ops {
                let [c] = CompiledOp::of(op).try_into().expect("one compiled op");
                for _ in 0..40 {
                    let p = Point::new(rng.range(-100.0, 400.0), rng.range(-100.0, 300.0));
                    assert!(close(op.forward(p), c.forward(p)), "{op:?}");
                    match (op.inverse(p), c.inverse(p)) {
                        (Back::Moved(a), Some(b)) => assert!(close(a, b), "{op:?}"),
                        (Back::Ink(_), None) => {}
                        (a, b) => panic!("{op:?} at {p:?}: {a:?} vs {b:?}"),
                    }
                }
            }
        }
    }

    #[test]
    fn inverse_undoes_forward() {
        let design = random_design(5, 300, 200, 200, Mix::Mixed);
        let mut rng = SplitMix64(2);
        for op in &design.ops {
            let [c] = CompiledOp::of(op).try_into().expect("one compiled op");
            for _ in 0..40 {
                let p = Point::new(rng.range(-50.0, 350.0), rng.range(-50.0, 250.0));
                match c.inverse(c.forward(p)) {
                    Some(back) => assert!((back - p).hypot() < 1e-6, "{op:?}: {p:?} → {back:?}"),
                    // Only a spray leaves older ink under new ink.
                    None => assert!(matches!(op, Op::Spray(_)), "{op:?} at {p:?}"),
                }
            }
        }
    }
}
