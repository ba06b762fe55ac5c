//! Deep zoom by perturbation: a reference point R walked back through every op in f64,
//! recording at each op what a point R + δ a tiny distance away needs to follow R in
//! float32 by exact differences, δ' = g(R + δ) − g(R), without ever forming R + δ (in
//! f32 the two would be equal once δ is below R's last bit, past about 10⁴× zoom on a
//! 1,000-px sheet). The GPU's deep walk (marbling-gpu's `shaders/deep.wgsl`) reads these
//! steps; its formulas are stated there.
//!
//! Each kind's difference is algebraically exact (no linearisation) except the stylus
//! and the flow, which follow the reference's Jacobian while |δ| stays within
//! [`LINEAR_REACH`] of the field's length scale. A comb's distance |s − kink| is exact
//! across the nearest kink of the distance (a tine, or the midpoint between two); the
//! step's `reach` says how far δ may move s before another kink could be crossed. Past a
//! reach the walk goes on in absolute f32 from the step's `at`.

use crate::compiled::{CombKernel, CompiledOp, SwirlKernel, WaveKernel, drop_back};
use crate::walk::Walker;
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// The linearised steps (stylus, flow) hold while |δ| ≤ this × the field's length scale
/// (the stylus's wake L, the flow's finest wavelength 1/f): the relative error of the
/// linear step is then about this small.
pub const LINEAR_REACH: f64 = 1e-3;

/// How far a covered reference is moved outside its drop's disc, relative to the radius
/// (the rebased point's distance to the rim is about 10⁻⁹ r).
const REBASE: f64 = 1e-9;

/// A reach that is never exceeded.
pub const UNBOUNDED: f64 = 1e30;

/// What a point δ from the reference needs at one op (one stylus segment) of the walk
/// back. `at` is the reference before the op is undone (the point after it), design
/// pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RefStep {
    /// A drop or spray. When the reference lies in the disc it is moved just outside
    /// (along the ray from C) and `rebase` = old − new is added to δ; then `d` = R − C
    /// and `excess` = |R − C|² − r² ≥ 0 of the moved reference.
    Disc {
        /// The reference before the op (not moved).
        at: Point,
        /// R − C of the (moved) reference.
        d: Vec2,
        /// |R − C|² − r², design px².
        excess: f64,
        /// Added to δ before the step.
        rebase: Vec2,
    },
    /// A tine, rake or finite comb: along the normal coordinate s the tine distance is
    /// d(s) = d(kink) + shape·|s − s_kink| near the kink nearest the reference.
    Comb {
        /// The reference before the op.
        at: Point,
        /// d at the reference, design pixels.
        distance: f64,
        /// s_R − s_kink, design pixels.
        kink: f64,
        /// +1 where d has a minimum at the kink (a tine), −1 a maximum (between tines).
        shape: f64,
        /// The formula holds while |kink + Δs| ≤ reach.
        reach: f64,
    },
    /// A wavy comb: its sine's argument θ = k(R·n) + phase, reduced to [0, 2π).
    Wave {
        /// The reference before the op.
        at: Point,
        /// θ, radians.
        theta: f64,
    },
    /// A circular comb or vortex: D = R − C, the signed ring distance (ρ − r, or ρ for a
    /// vortex; the tine distance is its absolute value) and the turn θ mod 2π.
    Swirl {
        /// The reference before the op.
        at: Point,
        /// R − C.
        d: Vec2,
        /// ρ − r (circular) or ρ (vortex), design pixels.
        ring: f64,
        /// The turn αλ/((|ring| + λ)ρ) reduced to [0, 2π), radians.
        theta: f64,
    },
    /// A shift or turn (linear in δ: nothing more is needed).
    Rigid {
        /// The reference before the op.
        at: Point,
    },
    /// A jiggle: the phase φ solving φ + kA·sin φ = t at the reference (t reduced to
    /// [0, 2π)).
    Jiggle {
        /// The reference before the op.
        at: Point,
        /// φ, radians.
        phi: f64,
    },
    /// A stylus segment or flow: δ' = J·δ (J row-major: ∂x/∂x, ∂x/∂y, ∂y/∂x, ∂y/∂y of
    /// the inverse at the reference) while |δ| ≤ `reach`.
    Linear {
        /// The reference before the op.
        at: Point,
        /// The inverse's Jacobian at the reference.
        jacobian: [f64; 4],
        /// Largest |δ| the linear step serves, design pixels.
        reach: f64,
    },
}

impl RefStep {
    /// The reference before the op.
    pub fn at(&self) -> Point {
        match *self {
            Self::Disc { at, .. }
            | Self::Comb { at, .. }
            | Self::Wave { at, .. }
            | Self::Swirl { at, .. }
            | Self::Rigid { at }
            | Self::Jiggle { at, .. }
            | Self::Linear { at, .. } => at,
        }
    }
}

/// The reference walk of design point `p`: one step per compiled op (one per segment of
/// a stylus), oldest first, and where the (rebased) reference ends.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceWalk {
    /// The steps, oldest first (a stylus op has one per segment).
    pub steps: Vec<RefStep>,
    /// The reference after walking back through every op.
    pub end: Point,
}

impl ReferenceWalk {
    /// Walks `p` back through every op of `walker` in f64.
    pub fn new(walker: &Walker, p: Point) -> Self {
        let mut steps = Vec::with_capacity(walker.len());
        let mut r = p;
        for op in walker.steps().iter().rev() {
            r = step_back(op, r, &mut steps);
        }
        steps.reverse();
        Self { steps, end: r }
    }
}

/// Undoes `op` at `r`, pushing its steps (newest first; a stylus's segments in walk
/// order) and returning the reference before it.
fn step_back(op: &CompiledOp, r: Point, out: &mut Vec<RefStep>) -> Point {
    match *op {
        CompiledOp::Disc {
            cx, cy, r2, deform, ..
        } => {
            let mut d = r - Point::new(cx, cy);
            let rho2 = d.hypot2();
            if rho2 < r2 {
                let outside = r2.sqrt() * (1.0 + REBASE);
                d = if rho2 > 0.0 {
                    d * (outside / rho2.sqrt())
                } else {
                    Vec2::new(outside, 0.0)
                };
            }
            let moved = Point::new(cx, cy) + d;
            let excess = (d.hypot2() - r2).max(0.0);
            out.push(RefStep::Disc {
                at: r,
                d,
                excess,
                rebase: r - moved,
            });
            if deform {
                let (x, y) = drop_back(cx, cy, r2, d.x, d.y, d.hypot2());
                Point::new(x, y)
            } else {
                moved
            }
        }
        CompiledOp::Comb(CombKernel {
            ax,
            ay,
            nx,
            ny,
            spacing,
            ..
        }) => {
            let s = (r.x - ax) * nx + (r.y - ay) * ny;
            out.push(if spacing > 0.0 {
                rake_step(r, s, spacing)
            } else {
                kink_step(r, s.abs(), s, 1.0, UNBOUNDED)
            });
            inverse(op, r)
        }
        CompiledOp::Tines {
            ax,
            ay,
            mx,
            my,
            ref offsets,
            ..
        } => {
            let s = (r.x - ax) * -my + (r.y - ay) * mx;
            out.push(tines_step(r, s, offsets));
            inverse(op, r)
        }
        CompiledOp::Wave(WaveKernel {
            nx, ny, k, phase, ..
        }) => {
            let theta = (k * (r.x * nx + r.y * ny) + phase).rem_euclid(TAU);
            out.push(RefStep::Wave { at: r, theta });
            inverse(op, r)
        }
        CompiledOp::Swirl(SwirlKernel {
            cx,
            cy,
            r: ring_radius,
            al,
            lambda,
            vortex,
        }) => {
            let d = r - Point::new(cx, cy);
            let rho = d.hypot();
            let ring = if vortex { rho } else { rho - ring_radius };
            let theta = if rho > 0.0 {
                (al / (ring.abs() + lambda) / rho).rem_euclid(TAU)
            } else {
                0.0
            };
            out.push(RefStep::Swirl {
                at: r,
                d,
                ring,
                theta,
            });
            inverse(op, r)
        }
        CompiledOp::Rigid { .. } => {
            out.push(RefStep::Rigid { at: r });
            inverse(op, r)
        }
        CompiledOp::Jiggle(ref j) => {
            // One solve serves the reference step and the move.
            let phi = j.phase_before(r.x, r.y);
            out.push(RefStep::Jiggle { at: r, phi });
            Point::from(j.back_by(r.x, r.y, phi))
        }
        CompiledOp::Stylus { ref segments } => {
            let mut r = r;
            for s in segments.iter().rev() {
                out.push(linear_step(r, s.wake, |p| s.inverse(p)));
                r = s.inverse(r);
            }
            r
        }
        CompiledOp::Flow { ref field } => {
            let finest = field.octaves().iter().map(|o| o.0).fold(0.0_f64, f64::max);
            let scale = if finest > 0.0 { 1.0 / finest } else { 1.0 };
            out.push(linear_step(r, scale, |p| field.inverse(p)));
            field.inverse(r)
        }
    }
}

/// `op`'s inverse at `r` (ops that lay no ink).
fn inverse(op: &CompiledOp, r: Point) -> Point {
    op.inverse(r).unwrap_or(r)
}

fn kink_step(at: Point, distance: f64, kink: f64, shape: f64, reach: f64) -> RefStep {
    RefStep::Comb {
        at,
        distance,
        kink,
        shape,
        reach,
    }
}

/// A rake of spacing S: d(s) has tines (minima) at multiples of S and maxima halfway,
/// so the kink nearest s is j·S/2, j = round(2s/S), and the next lie S/2 further.
fn rake_step(at: Point, s: f64, spacing: f64) -> RefStep {
    let half = 0.5 * spacing;
    let j = (s / half).round();
    let kink = s - j * half;
    let shape = if j.rem_euclid(2.0) == 0.0 { 1.0 } else { -1.0 };
    let distance = crate::compiled::rake_distance(s.abs(), spacing, 1.0 / spacing);
    kink_step(at, distance, kink, shape, half)
}

/// A finite comb with tines at `offsets` (any order): d(s) = minᵢ |s − oᵢ| has minima at
/// the tines and maxima halfway between neighbours.
fn tines_step(at: Point, s: f64, offsets: &[f64]) -> RefStep {
    let mut sorted: Vec<f64> = offsets.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    // The nearest tine i, then the kinks around s: tine i and the midpoint on s's side.
    let i = match sorted.binary_search_by(|o| o.total_cmp(&s)) {
        Ok(i) => i,
        Err(0) => 0,
        Err(k) if k >= n => n - 1,
        Err(k) => {
            if s - sorted[k - 1] <= sorted[k] - s {
                k - 1
            } else {
                k
            }
        }
    };
    let o = sorted[i];
    let distance = (s - o).abs();
    let gap_below = if i > 0 { o - sorted[i - 1] } else { UNBOUNDED };
    let gap_above = if i + 1 < n {
        sorted[i + 1] - o
    } else {
        UNBOUNDED
    };
    let gap = if s >= o { gap_above } else { gap_below };
    let mid = if s >= o { o + 0.5 * gap } else { o - 0.5 * gap };
    if gap < UNBOUNDED && (s - mid).abs() < distance {
        kink_step(at, distance, s - mid, -1.0, 0.5 * gap)
    } else {
        kink_step(at, distance, s - o, 1.0, 0.5 * gap_below.min(gap_above))
    }
}

/// The Jacobian of `inverse` at `at` by central differences (h = 10⁻³ of the field's
/// length scale: the truncation error is about 10⁻⁶ of the scale's curvature, the
/// rounding about 10⁻¹³ of |at|/h).
fn linear_step(at: Point, scale: f64, inverse: impl Fn(Point) -> Point) -> RefStep {
    let h = 1e-3 * scale;
    let dx = inverse(at + Vec2::new(h, 0.0)) - inverse(at - Vec2::new(h, 0.0));
    let dy = inverse(at + Vec2::new(0.0, h)) - inverse(at - Vec2::new(0.0, h));
    let k = 0.5 / h;
    RefStep::Linear {
        at,
        jacobian: [dx.x * k, dy.x * k, dx.y * k, dy.y * k],
        reach: LINEAR_REACH * scale,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};

    /// d(s) of a comb step near its kink, as the GPU evaluates it.
    fn distance_after(step: &RefStep, ds: f64) -> Option<f64> {
        let RefStep::Comb {
            distance,
            kink,
            shape,
            reach,
            ..
        } = *step
        else {
            return None;
        };
        ((kink + ds).abs() <= reach).then(|| distance + shape * ((kink + ds).abs() - kink.abs()))
    }

    #[test]
    fn a_finite_combs_kink_formula_matches_the_minimum_distance_within_its_reach() {
        let offsets = [30.0, -20.0, 0.0, 5.0, 60.0];
        let d = |s: f64| {
            offsets
                .iter()
                .map(|o| (s - o).abs())
                .fold(f64::MAX, f64::min)
        };
        let mut checked = 0;
        for k in -400..=400 {
            let s = f64::from(k) * 0.237;
            let step = tines_step(Point::ZERO, s, &offsets);
            for ds in [-3.0, -0.7, -0.01, 0.0, 0.02, 0.9, 2.5] {
                if let Some(got) = distance_after(&step, ds) {
                    assert!(
                        (got - d(s + ds)).abs() < 1e-9,
                        "s {s} ds {ds}: {got} vs {}",
                        d(s + ds)
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 2000, "only {checked} cases within reach");
    }

    #[test]
    fn a_rakes_kink_formula_matches_the_folded_distance_within_its_reach() {
        let spacing = 17.0;
        let d = |s: f64| crate::compiled::rake_distance(s.abs(), spacing, 1.0 / spacing);
        for k in -300..=300 {
            let s = f64::from(k) * 0.731;
            let step = rake_step(Point::ZERO, s, spacing);
            for ds in [-4.0, -0.3, 0.0, 0.25, 3.9] {
                let got = distance_after(&step, ds);
                assert!(
                    got.is_some_and(|got| (got - d(s + ds)).abs() < 1e-9),
                    "s {s} ds {ds}: {got:?} vs {}",
                    d(s + ds)
                );
            }
        }
    }

    #[test]
    fn the_reference_walk_ends_where_the_plain_walk_does_outside_ink() {
        let design = random_design(7, 640, 480, 120, Mix::AllTypes);
        let walker = Walker::new(&design.ops);
        let mut compared = 0;
        for k in 0..200 {
            let p = Point::new(
                f64::from(k % 20) * 31.7 + 3.0,
                f64::from(k / 20) * 43.1 + 5.0,
            );
            let walk = ReferenceWalk::new(&walker, p);
            let segments: usize = walker
                .steps()
                .iter()
                .map(|s| match s {
                    CompiledOp::Stylus { segments } => segments.len(),
                    _ => 1,
                })
                .sum();
            assert_eq!(walk.steps.len(), segments);
            if let crate::Traced::Background(end) = walker.trace(p) {
                assert!(
                    (end - walk.end).hypot() < 1e-9,
                    "{p:?}: {end:?} vs {:?}",
                    walk.end
                );
                compared += 1;
            }
        }
        assert!(compared > 5, "too few background samples: {compared}");
    }
}
