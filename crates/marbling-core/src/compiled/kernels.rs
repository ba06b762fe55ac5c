//! The per-kind kernels of the compiled walk: each maps (x, y) through one compiled op,
//! forward (`sign` = 1) or inverse (−1), and is the identity for other kinds. The CPU
//! walk ([`crate::Walker`]) calls them op-major; [`CompiledOp::forward`] and
//! [`CompiledOp::inverse`] one point at a time.

use super::CompiledOp;
use super::trig::{self, floor_small};
use crate::ops::rotate;
use kurbo::Vec2;

/// A finite comb's shift at (x, y) times `sign` (constant along m, so −1 inverts
/// exactly). Identity for other ops.
#[inline(always)]
pub(crate) fn tines_shift(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    let CompiledOp::Tines {
        ax,
        ay,
        mx,
        my,
        al,
        lambda,
        ref offsets,
    } = *s
    else {
        return (x, y);
    };
    let along = (x - ax) * -my + (y - ay) * mx;
    let d = offsets
        .iter()
        .map(|o| (along - o).abs())
        .fold(f64::INFINITY, f64::min);
    let f = sign * al / (d + lambda);
    (x + f * mx, y + f * my)
}

/// Inverse of a drop outside its disc: P = C + (P' − C)·√(1 − r²/ρ²), given
/// (dx, dy) = P' − C and d2 = ρ².
#[inline(always)]
pub(crate) fn drop_back(cx: f64, cy: f64, r2: f64, dx: f64, dy: f64, d2: f64) -> (f64, f64) {
    let f = (1.0 - r2 / d2).sqrt();
    (cx + dx * f, cy + dy * f)
}

/// Distance to the nearest rake tine: s/2 − |fmod(d, s) − s/2| for d ≥ 0, given
/// `inv_s` = 1/s (d·(1/s) is within 2 ulp of d/s: the distance within 2e-16·d).
#[inline(always)]
pub(crate) fn rake_distance(d: f64, s: f64, inv_s: f64) -> f64 {
    let q = d * inv_s;
    // fract(q) = q − floor(q) without a call or an integer conversion, so it vectorises;
    // beyond 2⁵¹ (where `floor_small` stops) the fraction is taken as 0.
    let fr = if q < 2.0e15 { q - floor_small(q) } else { 0.0 };
    s * (0.5 - (fr - 0.5).abs())
}

/// A tine (`spacing` = 0) or rake: shift αλ/(d + λ) along the unit motion m, where d
/// is the distance to the (nearest) tine line measured along the unit normal n.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CombKernel {
    /// Origin x.
    pub ax: f64,
    /// Origin y.
    pub ay: f64,
    /// Unit motion x.
    pub mx: f64,
    /// Unit motion y.
    pub my: f64,
    /// Unit normal x (−m.y).
    pub nx: f64,
    /// Unit normal y (m.x).
    pub ny: f64,
    /// α·λ, design px².
    pub al: f64,
    /// λ, design px.
    pub lambda: f64,
    /// Tine spacing of a rake, design px; 0 for a single tine.
    pub spacing: f64,
    /// 1 / spacing (a product in the walk instead of a second division).
    pub inv_spacing: f64,
}

impl CombKernel {
    /// The shift at (x, y) times `sign` (+1 forward, −1 inverse: the shift is constant
    /// along m, so subtracting it inverts exactly); `RAKE` when `spacing` > 0.
    #[inline(always)]
    pub(crate) fn shift<const RAKE: bool>(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let mut d = ((x - self.ax) * self.nx + (y - self.ay) * self.ny).abs();
        if RAKE {
            d = rake_distance(d, self.spacing, self.inv_spacing);
        }
        let f = sign * self.al / (d + self.lambda);
        (x + f * self.mx, y + f * self.my)
    }

    /// [`CombKernel::shift`] for a tine or a rake, whichever this is.
    #[inline(always)]
    pub(crate) fn apply(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        if self.spacing > 0.0 {
            self.shift::<true>(x, y, sign)
        } else {
            self.shift::<false>(x, y, sign)
        }
    }
}

/// A wavy comb: shift A·sin(k·(P·n) + φ) along m = (cos t, sin t), n = (sin t, −cos t).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveKernel {
    /// Unit motion x (cos t).
    pub mx: f64,
    /// Unit motion y (sin t).
    pub my: f64,
    /// Unit normal x (sin t).
    pub nx: f64,
    /// Unit normal y (−cos t).
    pub ny: f64,
    /// Amplitude A, design px.
    pub amp: f64,
    /// 2π / wavelength, radians per design px.
    pub k: f64,
    /// Phase φ, radians.
    pub phase: f64,
}

impl WaveKernel {
    /// The shift at (x, y) times `sign` (constant along m).
    #[inline(always)]
    pub(crate) fn shift(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let f = sign * self.amp * trig::sin(self.k * (x * self.nx + y * self.ny) + self.phase);
        (x + f * self.mx, y + f * self.my)
    }
}

/// A circular comb (d = |ρ − r|) or vortex (d = ρ): rotation by αλ/(d + λ)/ρ radians
/// about C.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SwirlKernel {
    /// Centre x.
    pub cx: f64,
    /// Centre y.
    pub cy: f64,
    /// Radius r of the circular comb (unused by a vortex).
    pub r: f64,
    /// α·λ, design px².
    pub al: f64,
    /// λ, design px.
    pub lambda: f64,
    /// A vortex rather than a circular comb.
    pub vortex: bool,
}

impl SwirlKernel {
    /// The rotation of (x, y) by `sign` times its angle (the angle depends on ρ only,
    /// which a rotation about C keeps, so −1 inverts exactly); `VORTEX` as `vortex`.
    /// The centre itself stays (selected, not branched to, so a loop vectorises).
    #[inline(always)]
    pub(crate) fn turn<const VORTEX: bool>(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let (dx, dy) = (x - self.cx, y - self.cy);
        let rho = (dx * dx + dy * dy).sqrt();
        let d = if VORTEX { rho } else { (rho - self.r).abs() };
        // One division: αλ / ((d + λ)·ρ), within 1 ulp of αλ / (d + λ) / ρ.
        let theta = sign * self.al / ((d + self.lambda) * rho);
        let (sn, cs) = trig::sin_cos(if rho == 0.0 { 0.0 } else { theta });
        let turned = (self.cx + dx * cs - dy * sn, self.cy + dx * sn + dy * cs);
        if rho == 0.0 { (x, y) } else { turned }
    }

    /// [`SwirlKernel::turn`] for a vortex or a circular comb, whichever this is.
    #[inline(always)]
    pub(crate) fn apply(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        if self.vortex {
            self.turn::<true>(x, y, sign)
        } else {
            self.turn::<false>(x, y, sign)
        }
    }
}

/// A shift or turn: P′ = C + R(θ)(P − C) + o.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RigidKernel {
    /// Centre x.
    pub cx: f64,
    /// Centre y.
    pub cy: f64,
    /// sin θ.
    pub sin: f64,
    /// cos θ.
    pub cos: f64,
    /// Offset x.
    pub ox: f64,
    /// Offset y.
    pub oy: f64,
}

impl RigidKernel {
    /// The move of (x, y): forward (`sign` = 1) or inverse (−1).
    #[inline(always)]
    pub(crate) fn apply(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let (cx, cy) = (self.cx, self.cy);
        if sign > 0.0 {
            let r = rotate(Vec2::new(x - cx, y - cy), self.sin, self.cos);
            (cx + r.x + self.ox, cy + r.y + self.oy)
        } else {
            let r = rotate(
                Vec2::new(x - self.ox - cx, y - self.oy - cy),
                -self.sin,
                self.cos,
            );
            (cx + r.x, cy + r.y)
        }
    }
}
