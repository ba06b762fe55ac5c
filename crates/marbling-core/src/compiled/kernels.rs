//! The per-kind kernels of the compiled walk: each maps (x, y) through one compiled op,
//! forward (`sign` = 1) or inverse (−1), and is the identity for other kinds. The CPU
//! walk ([`crate::Walker`]) calls them op-major; [`CompiledOp::forward`] and
//! [`CompiledOp::inverse`] one point at a time.

use super::CompiledOp;
use super::trig::{self, floor_small};
use crate::ops::{rotate, solve_kepler};
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// A shift or turn of (x, y): forward (`sign` = 1) or inverse (−1). Identity for
/// other ops.
#[inline(always)]
pub(crate) fn rigid_move(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    let CompiledOp::Rigid {
        cx,
        cy,
        sin,
        cos,
        ox,
        oy,
    } = *s
    else {
        return (x, y);
    };
    if sign > 0.0 {
        let r = rotate(Vec2::new(x - cx, y - cy), sin, cos);
        (cx + r.x + ox, cy + r.y + oy)
    } else {
        let r = rotate(Vec2::new(x - ox - cx, y - oy - cy), -sin, cos);
        (cx + r.x, cy + r.y)
    }
}

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

/// A jiggle's move at `p` for the phase `phase_of(t)`, t = k(p·u) + φ₀: P ± (A·sin φ·u +
/// B·cos φ·v), v = (−u.y, u.x). Identity for other ops.
pub(super) fn jiggle_move(
    p: Point,
    s: &CompiledOp,
    sign: f64,
    phase_of: impl Fn(f64, f64) -> f64,
) -> Point {
    let CompiledOp::Jiggle {
        ux,
        uy,
        k,
        along,
        across,
        phase,
    } = *s
    else {
        return p;
    };
    let (sn, cs) = phase_of(k * (p.x * ux + p.y * uy) + phase, k * along).sin_cos();
    Point::new(
        p.x + sign * (along * sn * ux - across * cs * uy),
        p.y + sign * (along * sn * uy + across * cs * ux),
    )
}

/// The jiggle's forward map: φ = t.
pub(super) fn jiggle_forward(p: Point, s: &CompiledOp) -> Point {
    jiggle_move(p, s, 1.0, |t, _| t)
}

/// The jiggle's inverse: φ solves φ + kA·sin φ = t (t reduced to [0, 2π), which sine and
/// cosine do not see). Identity for other ops.
pub(crate) fn jiggle_back(p: Point, s: &CompiledOp) -> Point {
    jiggle_move(p, s, -1.0, |t, ka| {
        solve_kepler(t - (t / TAU).floor() * TAU, ka)
    })
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

/// A comb's constants out of its [`CompiledOp::Comb`], for a loop over samples (which
/// then has no enum to look into and vectorises).
#[derive(Clone, Copy, Debug)]
pub(crate) struct CombK {
    ax: f64,
    ay: f64,
    mx: f64,
    my: f64,
    nx: f64,
    ny: f64,
    al: f64,
    lambda: f64,
    /// Rake spacing, design px; 0 for a single tine.
    pub spacing: f64,
    /// 1 / spacing (a product in the loop instead of a second division).
    inv_spacing: f64,
}

impl CombK {
    /// The comb's constants, or `None` for another op.
    #[inline(always)]
    pub fn of(s: &CompiledOp) -> Option<Self> {
        let CompiledOp::Comb {
            ax,
            ay,
            mx,
            my,
            nx,
            ny,
            al,
            lambda,
            spacing,
        } = *s
        else {
            return None;
        };
        Some(Self {
            ax,
            ay,
            mx,
            my,
            nx,
            ny,
            al,
            lambda,
            spacing,
            inv_spacing: 1.0 / spacing,
        })
    }

    /// The shift at (x, y) times `sign` (+1 forward, −1 inverse: the shift is constant
    /// along m, so subtracting it inverts exactly); `RAKE` when `spacing` > 0.
    #[inline(always)]
    pub fn shift<const RAKE: bool>(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let mut d = ((x - self.ax) * self.nx + (y - self.ay) * self.ny).abs();
        if RAKE {
            d = rake_distance(d, self.spacing, self.inv_spacing);
        }
        let f = sign * self.al / (d + self.lambda);
        (x + f * self.mx, y + f * self.my)
    }
}

/// A comb's shift at (x, y) times `sign` ([`CombK::shift`]). Identity for other ops.
#[inline(always)]
pub(crate) fn comb_shift(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    match CombK::of(s) {
        Some(c) if c.spacing > 0.0 => c.shift::<true>(x, y, sign),
        Some(c) => c.shift::<false>(x, y, sign),
        None => (x, y),
    }
}

/// A wavy comb's constants out of its [`CompiledOp::Wave`] (see [`CombK`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct WaveK {
    mx: f64,
    my: f64,
    nx: f64,
    ny: f64,
    amp: f64,
    k: f64,
    phase: f64,
}

impl WaveK {
    /// The wavy comb's constants, or `None` for another op.
    #[inline(always)]
    pub fn of(s: &CompiledOp) -> Option<Self> {
        let CompiledOp::Wave {
            mx,
            my,
            nx,
            ny,
            amp,
            k,
            phase,
        } = *s
        else {
            return None;
        };
        Some(Self {
            mx,
            my,
            nx,
            ny,
            amp,
            k,
            phase,
        })
    }

    /// The shift at (x, y) times `sign` (constant along m).
    #[inline(always)]
    pub fn shift(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let f = sign * self.amp * trig::sin(self.k * (x * self.nx + y * self.ny) + self.phase);
        (x + f * self.mx, y + f * self.my)
    }
}

/// A wavy comb's shift at (x, y) times `sign`. Identity for other ops.
#[inline(always)]
pub(crate) fn wave_shift(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    WaveK::of(s).map_or((x, y), |w| w.shift(x, y, sign))
}

/// A circular comb's or vortex's constants out of its [`CompiledOp::Swirl`] (see
/// [`CombK`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SwirlK {
    cx: f64,
    cy: f64,
    r: f64,
    al: f64,
    lambda: f64,
    /// A vortex (d = ρ) rather than a circular comb (d = |ρ − r|).
    pub vortex: bool,
}

impl SwirlK {
    /// The swirl's constants, or `None` for another op.
    #[inline(always)]
    pub fn of(s: &CompiledOp) -> Option<Self> {
        let CompiledOp::Swirl {
            cx,
            cy,
            r,
            al,
            lambda,
            vortex,
        } = *s
        else {
            return None;
        };
        Some(Self {
            cx,
            cy,
            r,
            al,
            lambda,
            vortex,
        })
    }

    /// The rotation of (x, y) by `sign` times its angle (the angle depends on ρ only,
    /// which a rotation about C keeps, so −1 inverts exactly); `VORTEX` as `vortex`.
    /// The centre itself stays (selected, not branched to, so a loop vectorises).
    #[inline(always)]
    pub fn turn<const VORTEX: bool>(&self, x: f64, y: f64, sign: f64) -> (f64, f64) {
        let (dx, dy) = (x - self.cx, y - self.cy);
        let rho = (dx * dx + dy * dy).sqrt();
        let d = if VORTEX { rho } else { (rho - self.r).abs() };
        // One division: αλ / ((d + λ)·ρ), within 1 ulp of αλ / (d + λ) / ρ.
        let theta = sign * self.al / ((d + self.lambda) * rho);
        let (sn, cs) = trig::sin_cos(if rho == 0.0 { 0.0 } else { theta });
        let turned = (self.cx + dx * cs - dy * sn, self.cy + dx * sn + dy * cs);
        if rho == 0.0 { (x, y) } else { turned }
    }
}

/// A swirl's rotation of (x, y) by `sign` times its angle ([`SwirlK::turn`]). Identity
/// for other ops.
#[inline(always)]
pub(crate) fn swirl_turn(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    match SwirlK::of(s) {
        Some(w) if w.vortex => w.turn::<true>(x, y, sign),
        Some(w) => w.turn::<false>(x, y, sign),
        None => (x, y),
    }
}
