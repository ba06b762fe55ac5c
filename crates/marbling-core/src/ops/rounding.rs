//! Rounding an op's parameters to what can matter, so that an op made by a tool is
//! exactly what its document and share link hold (and links stay short).
//!
//! Lengths, positions, strengths and direction components are rounded to
//! [`LENGTH_STEP`] design pixels, angles and phases to [`ANGLE_STEP`] radians. Moving a
//! point by at most half a step (0.005 px) changes no rendered pixel at any scale a
//! screen or print uses. Values that must stay positive (radius, λ, spacing,
//! wavelength) are at least one step; a direction that would round to zero keeps its
//! angle at unit length.

use kurbo::{Point, Vec2};

/// Step of rounded lengths and positions, design pixels.
pub const LENGTH_STEP: f64 = 0.01;
/// Step of rounded angles and phases, radians.
pub const ANGLE_STEP: f64 = 1e-4;
/// Step of rounded flow times (a flow moves about its strength in px per unit time, so
/// a step moves a point by strength·10⁻⁴ px).
pub const TIME_STEP: f64 = 1e-4;

fn round_to(v: f64, step: f64) -> f64 {
    // Dividing by the reciprocal of the step gives the shortest decimal (12.34, not
    // 12.340000000000002) for every value a design can hold.
    let k = (v / step).round();
    let r = k / (1.0 / step);
    if r == 0.0 { 0.0 } else { r }
}

/// Rounded as the module doc says.
pub(super) fn length(v: f64) -> f64 {
    round_to(v, LENGTH_STEP)
}

/// Rounded as the module doc says.
pub(super) fn positive(v: f64) -> f64 {
    length(v).max(LENGTH_STEP)
}

/// Rounded as the module doc says.
pub(super) fn angle(v: f64) -> f64 {
    round_to(v, ANGLE_STEP)
}

/// A flow's time, rounded to [`TIME_STEP`].
pub(super) fn time(v: f64) -> f64 {
    round_to(v, TIME_STEP)
}

/// Rounded as the module doc says.
pub(super) fn point(p: Point) -> Point {
    Point::new(length(p.x), length(p.y))
}

/// Rounded as the module doc says.
pub(super) fn direction(v: Vec2) -> Vec2 {
    let r = Vec2::new(length(v.x), length(v.y));
    if r.hypot2() > 0.0 || v.hypot2() == 0.0 {
        return r;
    }
    let u = v.normalize();
    Vec2::new(angle(u.x), angle(u.y))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};
    use crate::{Design, Drop, Op, Rgb8, Tine};

    #[test]
    fn rounding_moves_values_by_at_most_half_a_step_and_is_idempotent() {
        let d = random_design(7, 640, 400, 400, Mix::Mixed);
        for op in &d.ops {
            let r = op.rounded();
            assert_eq!(r.rounded(), r, "{op:?}");
            assert_eq!(r.type_name(), op.type_name());
        }
        let mut rounded = d.clone();
        rounded.ops = d.ops.iter().map(Op::rounded).collect();
        assert!(rounded.validate().is_ok());
        // The JSON holds exactly the rounded values: reading it back changes nothing.
        let back = Design::from_json(&rounded.to_json_compact()).expect("valid");
        assert_eq!(back, rounded);
    }

    #[test]
    fn rounded_values_are_short_decimals_within_half_a_step() {
        let op = Op::Drop(Drop {
            center: Point::new(123.456_789, 0.333_333_3),
            radius: 0.000_1,
            color: Rgb8::new(1, 2, 3),
        });
        let Op::Drop(d) = op.rounded() else {
            unreachable!()
        };
        assert_eq!((d.center.x, d.center.y, d.radius), (123.46, 0.33, 0.01));
        let t = Op::Tine(Tine {
            origin: Point::new(-0.004, 5.0),
            direction: Vec2::new(0.001, -0.002),
            alpha: 80.123_4,
            lambda: 8.0,
        });
        let Op::Tine(t) = t.rounded() else {
            unreachable!()
        };
        // -0.004 rounds to 0, not -0; a tiny direction keeps its angle.
        assert_eq!(t.origin.x.to_bits(), 0.0f64.to_bits());
        assert!((t.direction.normalize() - Vec2::new(1.0, -2.0).normalize()).hypot() < 1e-3);
        assert_eq!(t.alpha, 80.12);
        for v in [0.1 + 0.2, 1234.565, -7.005, 99.999] {
            let r = round_to(v, LENGTH_STEP);
            assert!((r - v).abs() <= LENGTH_STEP / 2.0 + 1e-12, "{v} → {r}");
            assert!(r.to_string().len() <= 8, "{v} → {r}");
        }
    }
}
