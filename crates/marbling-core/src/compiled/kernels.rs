//! The per-kind kernels of the compiled walk: each maps (x, y) through one compiled op,
//! forward (`sign` = 1) or inverse (−1), and is the identity for other kinds. The CPU
//! walk ([`crate::Walker`]) calls them op-major; [`CompiledOp::forward`] and
//! [`CompiledOp::inverse`] one point at a time.

use super::CompiledOp;
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

/// Distance to the nearest rake tine: s/2 − |fmod(d, s) − s/2| for d ≥ 0.
#[inline(always)]
pub(crate) fn rake_distance(d: f64, s: f64) -> f64 {
    let q = d / s;
    // fract(q) by truncation (fast, vectorisable); beyond 2^52 an f64 has no fraction.
    let fr = if q < 4.0e15 {
        q - (q as i64 as f64)
    } else {
        0.0
    };
    s * (0.5 - (fr - 0.5).abs())
}

/// A comb's shift at (x, y) times `sign` (+1 forward, −1 inverse: the shift is constant
/// along m, so subtracting it inverts exactly). Identity for other ops.
#[inline(always)]
pub(crate) fn comb_shift(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
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
        return (x, y);
    };
    let mut d = ((x - ax) * nx + (y - ay) * ny).abs();
    if spacing > 0.0 {
        d = rake_distance(d, spacing);
    }
    let f = sign * al / (d + lambda);
    (x + f * mx, y + f * my)
}

/// A wavy comb's shift at (x, y) times `sign` (constant along m). Identity for other ops.
#[inline(always)]
pub(crate) fn wave_shift(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
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
        return (x, y);
    };
    let f = sign * amp * (k * (x * nx + y * ny) + phase).sin();
    (x + f * mx, y + f * my)
}

/// A swirl's rotation of (x, y) by `sign` times its angle (the angle depends on ρ only,
/// which a rotation about C keeps, so −1 inverts exactly). Identity for other ops.
#[inline(always)]
pub(crate) fn swirl_turn(x: f64, y: f64, s: &CompiledOp, sign: f64) -> (f64, f64) {
    let CompiledOp::Swirl {
        cx,
        cy,
        r,
        al,
        lambda,
        vortex,
    } = *s
    else {
        return (x, y);
    };
    let (dx, dy) = (x - cx, y - cy);
    let rho = (dx * dx + dy * dy).sqrt();
    if rho == 0.0 {
        return (x, y);
    }
    let d = if vortex { rho } else { (rho - r).abs() };
    let theta = sign * al / (d + lambda) / rho;
    let (sn, cs) = theta.sin_cos();
    (cx + dx * cs - dy * sn, cy + dx * sn + dy * cs)
}
