//! The jiggle's compiled kernel: P′ = P + A·sin φ·u + B·cos φ·v, φ = k(P·u) + φ₀, and
//! its inverse, which solves φ + kA·sin φ = t for each point (Kepler's equation).
//!
//! The inverse's solver takes safeguarded Newton steps on [`trig::sin_cos`] (no calls,
//! no branches but selects) and stops a point when a step changes φ by at most
//! 1e-15·(1 + |φ|). The batch form runs [`LANES`] points at once, each lane frozen by a
//! select once it has stopped, so every point gets the same φ as the one-point form,
//! bit for bit, whichever walk asks.

use super::trig::{self, floor_small};
use kurbo::Point;
use std::f64::consts::TAU;

/// Points the batch inverse solves at once (four f64 lanes of AVX2).
const LANES: usize = 4;

/// Most Newton steps per point (the same cap as [`crate::ops::solve_kepler`]'s).
const MAX_STEPS: usize = 60;

/// A jiggle: P′ = P + A·sin φ·u + B·cos φ·v, φ = k(P·u) + φ₀, v = (−u.y, u.x).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JiggleKernel {
    /// u x (cos θ).
    pub ux: f64,
    /// u y (sin θ).
    pub uy: f64,
    /// k = 2π / wavelength, radians per design px.
    pub k: f64,
    /// Amplitude A along u, design px (|kA| < 1).
    pub along: f64,
    /// Amplitude B along v, design px.
    pub across: f64,
    /// Phase φ₀, radians.
    pub phase: f64,
}

/// One point's solver state: φ, its bracket [lo, hi] and whether it has stopped.
#[derive(Clone, Copy)]
struct Solve {
    phi: f64,
    lo: f64,
    hi: f64,
    done: bool,
}

impl JiggleKernel {
    /// The phase t = k(P·u) + φ₀ at (x, y).
    #[inline(always)]
    fn t(&self, x: f64, y: f64) -> f64 {
        self.k * (x * self.ux + y * self.uy) + self.phase
    }

    /// P moved by the phase φ: P ± (A·sin φ·u + B·cos φ·v).
    #[inline(always)]
    fn moved(&self, x: f64, y: f64, sign: f64, (sn, cs): (f64, f64)) -> (f64, f64) {
        (
            x + sign * (self.along * sn * self.ux - self.across * cs * self.uy),
            y + sign * (self.along * sn * self.uy + self.across * cs * self.ux),
        )
    }

    /// Where (x, y) goes forward.
    pub(crate) fn forward(&self, p: Point) -> Point {
        let (x, y) = self.moved(p.x, p.y, 1.0, self.t(p.x, p.y).sin_cos());
        Point::new(x, y)
    }

    /// The solver's start for t reduced to [0, 2π) (which sine and cosine do not see):
    /// φ₀ = t − c·sin t, bracketed by t ± |c|.
    #[inline(always)]
    fn start(&self, x: f64, y: f64) -> (f64, Solve) {
        let t = self.t(x, y);
        let t = t - floor_small(t * (1.0 / TAU)) * TAU;
        let c = self.k * self.along;
        let s = Solve {
            phi: t - c * trig::sin(t),
            lo: t - c.abs(),
            hi: t + c.abs(),
            done: false,
        };
        (t, s)
    }

    /// One safeguarded Newton step of φ + c·sin φ = t (a stopped point stays).
    #[inline(always)]
    fn step(&self, t: f64, s: Solve) -> Solve {
        let c = self.k * self.along;
        let (sn, cs) = trig::sin_cos(s.phi);
        let f = s.phi + c * sn - t;
        let above = f > 0.0;
        let hi = if above { s.phi } else { s.hi };
        let lo = if above { s.lo } else { s.phi };
        let newton = s.phi - f / (1.0 + c * cs);
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let exact = f == 0.0;
        let settled = (next - s.phi).abs() <= 1e-15 * (1.0 + s.phi.abs());
        let stepped = Solve {
            phi: if exact { s.phi } else { next },
            lo,
            hi,
            done: exact || settled,
        };
        if s.done { s } else { stepped }
    }

    /// The phase φ that (x, y) had before the jiggle: the root of φ + kA·sin φ = t, t
    /// the phase at (x, y) reduced to [0, 2π).
    #[inline(always)]
    pub(crate) fn phase_before(&self, x: f64, y: f64) -> f64 {
        let (t, mut s) = self.start(x, y);
        for _ in 0..MAX_STEPS {
            s = self.step(t, s);
            if s.done {
                break;
            }
        }
        s.phi
    }

    /// Where (x, y) was before the jiggle, given its [`JiggleKernel::phase_before`].
    #[inline(always)]
    pub(crate) fn back_by(&self, x: f64, y: f64, phi: f64) -> (f64, f64) {
        self.moved(x, y, -1.0, trig::sin_cos(phi))
    }

    /// Where (x, y) was before the jiggle.
    #[inline(always)]
    pub(crate) fn back(&self, x: f64, y: f64) -> (f64, f64) {
        self.back_by(x, y, self.phase_before(x, y))
    }

    /// [`JiggleKernel::back`] of every point, [`LANES`] at a time: each group steps
    /// until all its points have stopped.
    #[inline(always)]
    pub(crate) fn back_all(&self, xs: &mut [f64], ys: &mut [f64]) {
        let mut xc = xs.chunks_exact_mut(LANES);
        let mut yc = ys.chunks_exact_mut(LANES);
        for (x, y) in (&mut xc).zip(&mut yc) {
            // Structure of arrays, so that each step's lane loop vectorises.
            let mut t = [0.0; LANES];
            let (mut phi, mut lo, mut hi) = ([0.0; LANES], [0.0; LANES], [0.0; LANES]);
            let mut done = [false; LANES];
            for k in 0..LANES {
                let s;
                (t[k], s) = self.start(x[k], y[k]);
                (phi[k], lo[k], hi[k]) = (s.phi, s.lo, s.hi);
            }
            for _ in 0..MAX_STEPS {
                for k in 0..LANES {
                    let s = Solve {
                        phi: phi[k],
                        lo: lo[k],
                        hi: hi[k],
                        done: done[k],
                    };
                    let s = self.step(t[k], s);
                    (phi[k], lo[k], hi[k], done[k]) = (s.phi, s.lo, s.hi, s.done);
                }
                if done.iter().all(|&d| d) {
                    break;
                }
            }
            for k in 0..LANES {
                (x[k], y[k]) = self.back_by(x[k], y[k], phi[k]);
            }
        }
        for (x, y) in xc.into_remainder().iter_mut().zip(yc.into_remainder()) {
            (*x, *y) = self.back(*x, *y);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ops::solve_kepler;
    use crate::synth::SplitMix64;

    fn kernel(rng: &mut SplitMix64) -> JiggleKernel {
        let angle = rng.range(0.0, TAU);
        let wavelength = rng.range(5.0, 500.0);
        let k = TAU / wavelength;
        JiggleKernel {
            ux: angle.cos(),
            uy: angle.sin(),
            k,
            // |kA| up to 0.99: the hardest cases of the solver.
            along: rng.range(-0.99, 0.99) / k,
            across: rng.range(-40.0, 40.0),
            phase: rng.range(0.0, TAU),
        }
    }

    #[test]
    fn the_solver_matches_libms_and_inverts_the_forward_map() {
        let mut rng = SplitMix64(11);
        let mut worst = 0.0_f64;
        for _ in 0..200 {
            let j = kernel(&mut rng);
            for _ in 0..50 {
                let p = Point::new(rng.range(-2000.0, 3000.0), rng.range(-2000.0, 3000.0));
                let (t, _) = j.start(p.x, p.y);
                let (_, mut s) = j.start(p.x, p.y);
                for _ in 0..MAX_STEPS {
                    s = j.step(t, s);
                }
                let want = solve_kepler(t, j.k * j.along);
                assert!((s.phi - want).abs() <= 1e-12, "φ {} libm {want}", s.phi);
                let q = j.forward(Point::from(j.back(p.x, p.y)));
                worst = worst.max((q - p).hypot() / (1.0 + p.to_vec2().hypot()));
            }
        }
        assert!(worst < 1e-12, "round trip {worst:e}");
    }

    #[test]
    fn the_batch_equals_the_one_point_form_bit_for_bit() {
        let mut rng = SplitMix64(5);
        for _ in 0..40 {
            let j = kernel(&mut rng);
            let n = 4 * 9 + 3;
            let mut xs: Vec<f64> = (0..n).map(|_| rng.range(-500.0, 1500.0)).collect();
            let mut ys: Vec<f64> = (0..n).map(|_| rng.range(-500.0, 1500.0)).collect();
            let want: Vec<(f64, f64)> = xs.iter().zip(&ys).map(|(&x, &y)| j.back(x, y)).collect();
            j.back_all(&mut xs, &mut ys);
            for (i, w) in want.iter().enumerate() {
                assert_eq!(
                    (xs[i].to_bits(), ys[i].to_bits()),
                    (w.0.to_bits(), w.1.to_bits())
                );
            }
        }
    }
}
