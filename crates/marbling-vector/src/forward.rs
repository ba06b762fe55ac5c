//! Ops compiled for fast forward mapping: constants (unit directions, αλ, 2π/wavelength,
//! sin/cos of a wavy comb's angle) computed once instead of at every point.

use kurbo::Point;
use marbling_core::Op;
use std::f64::consts::TAU;

/// One op's forward map with its constants precomputed. Same formulas as `Op::forward`
/// (results agree to rounding).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ForwardStep {
    /// Drop: P' = C + (P − C)·√(1 + r²/ρ²).
    Drop {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Squared radius.
        r2: f64,
    },
    /// Spray: moves nothing.
    Identity,
    /// Tine (`spacing == 0`) or rake: shift αλ/(d + λ) along the unit direction m.
    Comb {
        /// Origin x.
        ax: f64,
        /// Origin y.
        ay: f64,
        /// Unit direction x.
        mx: f64,
        /// Unit direction y.
        my: f64,
        /// α·λ.
        al: f64,
        /// λ.
        lambda: f64,
        /// Tine spacing of a rake, 0 for a single tine.
        spacing: f64,
    },
    /// Wavy comb: shift A·sin(k·(P·n) + φ) along m = (cos t, sin t), n = (sin t, −cos t).
    Wave {
        /// cos t.
        c: f64,
        /// sin t.
        s: f64,
        /// Amplitude A.
        amp: f64,
        /// 2π / wavelength.
        k: f64,
        /// Phase φ.
        phase: f64,
    },
    /// Circular comb (d = |ρ − r|) or vortex (d = ρ): rotate by αλ/(d + λ)/ρ about C.
    Swirl {
        /// Centre x.
        cx: f64,
        /// Centre y.
        cy: f64,
        /// Radius r of the circular comb (unused by a vortex).
        r: f64,
        /// α·λ.
        al: f64,
        /// λ.
        lambda: f64,
        /// Vortex rather than circular comb.
        vortex: bool,
    },
}

impl ForwardStep {
    /// Compiles one op.
    pub fn new(op: &Op) -> Self {
        match *op {
            Op::Drop(d) => Self::Drop {
                cx: d.center.x,
                cy: d.center.y,
                r2: d.radius * d.radius,
            },
            Op::Spray(_) => Self::Identity,
            Op::Tine(t) => Self::comb(t.origin, t.direction, t.alpha, t.lambda, 0.0),
            Op::Rake(r) => Self::comb(r.origin, r.direction, r.alpha, r.lambda, r.spacing),
            Op::Wavy(w) => {
                let (s, c) = w.angle.sin_cos();
                Self::Wave {
                    c,
                    s,
                    amp: w.amplitude,
                    k: TAU / w.wavelength,
                    phase: w.phase,
                }
            }
            Op::Circular(c) => Self::Swirl {
                cx: c.center.x,
                cy: c.center.y,
                r: c.radius,
                al: c.alpha * c.lambda,
                lambda: c.lambda,
                vortex: false,
            },
            Op::Vortex(v) => Self::Swirl {
                cx: v.center.x,
                cy: v.center.y,
                r: 0.0,
                al: v.alpha * v.lambda,
                lambda: v.lambda,
                vortex: true,
            },
        }
    }

    fn comb(origin: Point, dir: kurbo::Vec2, alpha: f64, lambda: f64, spacing: f64) -> Self {
        let m = dir.normalize();
        Self::Comb {
            ax: origin.x,
            ay: origin.y,
            mx: m.x,
            my: m.y,
            al: alpha * lambda,
            lambda,
            spacing,
        }
    }

    /// Where older ink at `p` ends up after this op.
    #[inline]
    pub fn apply(&self, p: Point) -> Point {
        let (x, y) = (p.x, p.y);
        match *self {
            Self::Drop { cx, cy, r2 } => {
                let (dx, dy) = (x - cx, y - cy);
                let d2 = dx * dx + dy * dy;
                if d2 == 0.0 {
                    return p;
                }
                let f = (1.0 + r2 / d2).sqrt();
                Point::new(cx + dx * f, cy + dy * f)
            }
            Self::Identity => p,
            Self::Comb {
                ax,
                ay,
                mx,
                my,
                al,
                lambda,
                spacing,
            } => {
                // Normal n = (−m.y, m.x).
                let mut d = (-(x - ax) * my + (y - ay) * mx).abs();
                if spacing > 0.0 {
                    let half = spacing / 2.0;
                    d = half - ((d % spacing) - half).abs();
                }
                let f = al / (d + lambda);
                Point::new(x + f * mx, y + f * my)
            }
            Self::Wave {
                c,
                s,
                amp,
                k,
                phase,
            } => {
                let v = x * s - y * c;
                let f = amp * (k * v + phase).sin();
                Point::new(x + f * c, y + f * s)
            }
            Self::Swirl {
                cx,
                cy,
                r,
                al,
                lambda,
                vortex,
            } => {
                let (dx, dy) = (x - cx, y - cy);
                let rho = (dx * dx + dy * dy).sqrt();
                if rho == 0.0 {
                    return p;
                }
                let d = if vortex { rho } else { (rho - r).abs() };
                let (sn, cs) = (al / (d + lambda) / rho).sin_cos();
                Point::new(cx + dx * cs - dy * sn, cy + dx * sn + dy * cs)
            }
        }
    }
}

/// Maps `p` through `steps` in order.
#[inline]
pub fn forward_through(steps: &[ForwardStep], p: Point) -> Point {
    steps.iter().fold(p, |p, s| s.apply(p))
}

/// Compiles every op of a design.
pub fn compile(ops: &[Op]) -> Vec<ForwardStep> {
    ops.iter().map(ForwardStep::new).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, SplitMix64, random_design};

    #[test]
    fn compiled_steps_match_op_forward() {
        let design = random_design(3, 300, 200, 400, Mix::Mixed);
        let mut rng = SplitMix64(9);
        for op in &design.ops {
            let step = ForwardStep::new(op);
            for _ in 0..50 {
                let p = Point::new(rng.range(-100.0, 400.0), rng.range(-100.0, 300.0));
                let (a, b) = (op.forward(p), step.apply(p));
                assert!(
                    (a - b).hypot() <= 1e-9 * (1.0 + a.to_vec2().hypot()),
                    "{op:?}"
                );
            }
        }
    }
}
