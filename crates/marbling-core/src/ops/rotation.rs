//! Rotation about a centre by an angle that depends only on the distance to it.

use kurbo::{Point, Vec2};

/// Rotates `p` about `c` by the angle `theta_of(ρ)`, leaving `c` fixed.
pub(crate) fn rotate_about(c: Point, p: Point, sign: f64, theta_of: impl Fn(f64) -> f64) -> Point {
    let v = p - c;
    let rho = v.hypot();
    if rho == 0.0 {
        return p;
    }
    let (s, co) = (sign * theta_of(rho)).sin_cos();
    c + Vec2::new(v.x * co - v.y * s, v.x * s + v.y * co)
}
