//! The fBm of [`crate::Fbm`] in f64 with its gradient and Hessian: the stream function
//! of the marbling `flow` op, whose exact walk solves an implicit step by Newton's
//! method to 1e-12 (f32 noise would stop at 1e-7). The octaves, seeds, lattice hashes
//! and corner gradients are the f32 fBm's own, so the two agree to f32 rounding; only
//! the untiled fBm is served (a flow does not tile). Keep in sync with
//! `crates/marbling-gpu/shaders/flow.wgsl`.

use crate::fbm::{Basis, Fbm};
use crate::hash::{PRIME_X, PRIME_Y, lattice_hash_premul};
use crate::perlin::{PERLIN_GRADIENT_BOUND, gradient};
use crate::value::corner;

/// Bound on |∇n| of value noise in lattice units: 1.875·2, reached at the middle of a
/// cell's edge between corners −1 and 1 (1.875 the largest slope of the quintic fade).
pub const VALUE_GRADIENT_BOUND: f64 = 3.75;

/// A noise value with its first and second derivatives, per output pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Jet {
    /// n.
    pub n: f64,
    /// ∂n/∂x.
    pub dx: f64,
    /// ∂n/∂y.
    pub dy: f64,
    /// ∂²n/∂x².
    pub dxx: f64,
    /// ∂²n/∂x∂y.
    pub dxy: f64,
    /// ∂²n/∂y².
    pub dyy: f64,
}

/// An untiled fBm evaluated in f64 (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Fbm64 {
    basis: Basis,
    /// (frequency, amplitude·1/σ, seed) per octave.
    octaves: Vec<(f64, f64, u32)>,
}

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

fn fade1(t: f64) -> f64 {
    let s = t * (t - 1.0);
    30.0 * s * s
}

fn fade2(t: f64) -> f64 {
    60.0 * t * (t - 1.0) * (2.0 * t - 1.0)
}

/// The cell of `x` (saturating far outside the i32 range, as no design reaches).
fn cell(x: f64) -> (i32, f64) {
    let f = x.floor();
    (f as i32, x - f)
}

impl Fbm64 {
    /// The f64 twin of `fbm` (its period, if any, is ignored).
    #[must_use]
    pub fn new(fbm: &Fbm) -> Self {
        let s = f64::from(fbm.inv_std());
        Self {
            basis: fbm.params().basis,
            octaves: fbm
                .octaves()
                .map(|(f, a, seed)| (f64::from(f), f64::from(a) * s, seed))
                .collect(),
        }
    }

    /// The summed lattice noise.
    #[must_use]
    pub fn basis(&self) -> Basis {
        self.basis
    }

    /// (frequency per output pixel, amplitude/σ, seed) per octave, first octave first.
    #[must_use]
    pub fn octaves(&self) -> &[(f64, f64, u32)] {
        &self.octaves
    }

    /// An upper bound of |∇n| over the plane, per output pixel: Σ aᵢ·fᵢ/σ times the
    /// basis's bound ([`PERLIN_GRADIENT_BOUND`], [`VALUE_GRADIENT_BOUND`]).
    #[must_use]
    pub fn gradient_bound(&self) -> f64 {
        let basis = match self.basis {
            Basis::Perlin => f64::from(PERLIN_GRADIENT_BOUND),
            Basis::Value => VALUE_GRADIENT_BOUND,
        };
        basis * self.octaves.iter().map(|&(f, a, _)| f * a).sum::<f64>()
    }

    /// The fBm at (x, y) in output pixels, unit variance as [`Fbm::eval`], with its
    /// derivatives.
    #[must_use]
    pub fn jet(&self, x: f64, y: f64) -> Jet {
        let mut out = Jet::default();
        for &(f, a, seed) in &self.octaves {
            let j = match self.basis {
                Basis::Perlin => perlin_jet(x * f, y * f, seed),
                Basis::Value => value_jet(x * f, y * f, seed),
            };
            let (a1, a2) = (a * f, a * f * f);
            out.n += a * j.n;
            out.dx += a1 * j.dx;
            out.dy += a1 * j.dy;
            out.dxx += a2 * j.dxx;
            out.dxy += a2 * j.dxy;
            out.dyy += a2 * j.dyy;
        }
        out
    }
}

/// The four corner hashes of the cell (ix, iy): 00, 10, 01, 11.
fn hashes(ix: i32, iy: i32, seed: u32) -> [u32; 4] {
    let xp0 = (ix as u32).wrapping_mul(PRIME_X);
    let xp1 = (ix.wrapping_add(1) as u32).wrapping_mul(PRIME_X);
    let yp0 = (iy as u32).wrapping_mul(PRIME_Y);
    let yp1 = (iy.wrapping_add(1) as u32).wrapping_mul(PRIME_Y);
    [
        lattice_hash_premul(xp0, yp0, seed),
        lattice_hash_premul(xp1, yp0, seed),
        lattice_hash_premul(xp0, yp1, seed),
        lattice_hash_premul(xp1, yp1, seed),
    ]
}

/// Perlin noise (the f32 [`crate::perlin2`]'s lattice) in lattice units, with its
/// derivatives. With a, b, c, d the corner ramps, u = fade(fx), v = fade(fy) and
/// k = a − b − c + d: n = a + u(b − a) + v(c − a) + uv·k.
fn perlin_jet(x: f64, y: f64, seed: u32) -> Jet {
    let (ix, fx) = cell(x);
    let (iy, fy) = cell(y);
    let g = hashes(ix, iy, seed).map(|h| gradient(h).map(f64::from));
    let [g00, g10, g01, g11] = g;
    let a = g00[0] * fx + g00[1] * fy;
    let b = g10[0] * (fx - 1.0) + g10[1] * fy;
    let c = g01[0] * fx + g01[1] * (fy - 1.0);
    let d = g11[0] * (fx - 1.0) + g11[1] * (fy - 1.0);
    let (u, v) = (fade(fx), fade(fy));
    let (u1, v1) = (fade1(fx), fade1(fy));
    let (u2, v2) = (fade2(fx), fade2(fy));
    let k = a - b - c + d;
    // ∇a … ∇d are the corner gradients; ∇k = g00 − g10 − g01 + g11.
    let gk = [
        g00[0] - g10[0] - g01[0] + g11[0],
        g00[1] - g10[1] - g01[1] + g11[1],
    ];
    let ba = [g10[0] - g00[0], g10[1] - g00[1]];
    let ca = [g01[0] - g00[0], g01[1] - g00[1]];
    // ∂n/∂x = a_x + u(b − a)_x + v(c − a)_x + uv·k_x + u′((b − a) + v·k), and in y.
    let ex = (b - a) + v * k;
    let ey = (c - a) + u * k;
    Jet {
        n: a + u * (b - a) + v * (c - a) + u * v * k,
        dx: g00[0] + u * ba[0] + v * ca[0] + u * v * gk[0] + u1 * ex,
        dy: g00[1] + u * ba[1] + v * ca[1] + u * v * gk[1] + v1 * ey,
        dxx: 2.0 * u1 * (ba[0] + v * gk[0]) + u2 * ex,
        dxy: v1 * (ca[0] + u * gk[0]) + u1 * (ba[1] + v * gk[1] + v1 * k),
        dyy: 2.0 * v1 * (ca[1] + u * gk[1]) + v2 * ey,
    }
}

/// Value noise (the f32 [`crate::value2`]'s lattice) in lattice units, with its
/// derivatives: n = a + u(b − a) + v(c − a) + uv·k with corner values a, b, c, d.
fn value_jet(x: f64, y: f64, seed: u32) -> Jet {
    let (ix, fx) = cell(x);
    let (iy, fy) = cell(y);
    let (x1, y1) = (ix.wrapping_add(1), iy.wrapping_add(1));
    let a = f64::from(corner(ix, iy, seed));
    let b = f64::from(corner(x1, iy, seed));
    let c = f64::from(corner(ix, y1, seed));
    let d = f64::from(corner(x1, y1, seed));
    let (u, v) = (fade(fx), fade(fy));
    let (u1, v1) = (fade1(fx), fade1(fy));
    let k = a - b - c + d;
    let ex = (b - a) + v * k;
    let ey = (c - a) + u * k;
    Jet {
        n: a + u * (b - a) + v * (c - a) + u * v * k,
        dx: u1 * ex,
        dy: v1 * ey,
        dxx: fade2(fx) * ex,
        dxy: u1 * v1 * k,
        dyy: fade2(fy) * ey,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fbm::FbmParams;

    fn fbm(basis: Basis, octaves: u32) -> Fbm {
        Fbm::new(FbmParams {
            basis,
            frequency: 1.0 / 37.0,
            octaves,
            seed: 5,
            ..FbmParams::default()
        })
    }

    /// The f64 jet's value and gradient are the f32 fBm's (to f32 rounding), and its
    /// second derivatives are the first derivatives' central differences.
    #[test]
    fn jets_agree_with_the_f32_fbm_and_their_own_differences() {
        for basis in [Basis::Perlin, Basis::Value] {
            let f32_fbm = fbm(basis, 3);
            let f = Fbm64::new(&f32_fbm);
            let h = 1e-5;
            for k in 0..200 {
                let (x, y) = (f64::from(k) * 3.37 - 90.0, f64::from(k) * 2.11 + 0.3);
                let j = f.jet(x, y);
                let n32 = f64::from(f32_fbm.eval(x as f32, y as f32));
                assert!((j.n - n32).abs() < 2e-5, "{basis:?} n {} vs {n32}", j.n);
                if basis == Basis::Perlin {
                    let [_, dx, dy] = f32_fbm.eval_with_gradient(x as f32, y as f32);
                    assert!((j.dx - f64::from(dx)).abs() < 1e-5, "{} {dx}", j.dx);
                    assert!((j.dy - f64::from(dy)).abs() < 1e-5, "{} {dy}", j.dy);
                }
                let (px, mx) = (f.jet(x + h, y), f.jet(x - h, y));
                let (py, my) = (f.jet(x, y + h), f.jet(x, y - h));
                let tol = 1e-6 + 1e-4 * (j.dxx.abs() + j.dyy.abs() + j.dxy.abs());
                assert!(((px.n - mx.n) / (2.0 * h) - j.dx).abs() < 1e-7);
                assert!(((py.n - my.n) / (2.0 * h) - j.dy).abs() < 1e-7);
                assert!(
                    ((px.dx - mx.dx) / (2.0 * h) - j.dxx).abs() < tol,
                    "{basis:?} dxx"
                );
                assert!(
                    ((py.dy - my.dy) / (2.0 * h) - j.dyy).abs() < tol,
                    "{basis:?} dyy"
                );
                assert!(
                    ((py.dx - my.dx) / (2.0 * h) - j.dxy).abs() < tol,
                    "{basis:?} dxy"
                );
                assert!(
                    ((px.dy - mx.dy) / (2.0 * h) - j.dxy).abs() < tol,
                    "{basis:?} dyx"
                );
            }
        }
    }

    /// No point's gradient exceeds the bound, and random points come within 20 % of it
    /// for one octave (so it is not loose).
    #[test]
    fn the_gradient_bound_holds_and_is_tight() {
        for basis in [Basis::Perlin, Basis::Value] {
            let f = Fbm64::new(&fbm(basis, 1));
            let bound = f.gradient_bound();
            let mut most = 0.0_f64;
            for j in 0..700 {
                for i in 0..700 {
                    let g = f.jet(f64::from(i) * 0.731, f64::from(j) * 0.689);
                    most = most.max(g.dx.hypot(g.dy));
                }
            }
            assert!(most <= bound, "{basis:?}: {most} > {bound}");
            assert!(most >= 0.8 * bound, "{basis:?}: {most} ≪ {bound}");
        }
    }
}
