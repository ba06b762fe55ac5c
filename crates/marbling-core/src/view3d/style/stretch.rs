//! The marbled design's local stretch, for marks that follow the ink (`follow: stretch`,
//! a link no paper has): the ops draw the ink out along the direction in which the
//! forward map's Jacobian J is largest. The walk gives the inverse map, whose Jacobian is
//! J⁻¹; that direction is the eigenvector of J⁻ᵀJ⁻¹ with the smallest eigenvalue.
//! J⁻¹ comes from central differences of the walk ([`STEP`] design pixels), between the
//! points the walk ends at: the background, or the ink of the drop that covers them.

use crate::walk::{Batch, Traced, Walker};
use kurbo::Point;

/// Finite-difference step, design pixels.
pub const STEP: f64 = 0.25;

/// The ink counts as stretched where its ellipse's long axis is at least this many
/// times its short one (√(λ_max/λ_min) of J⁻ᵀJ⁻¹; 1 where the ops left it round).
pub const MIN_STRETCH: f64 = 1.25;

/// The unit direction (design pixels) in which the ink at design point `p` was drawn
/// out, or `None` where it is not stretched by [`MIN_STRETCH`] or the difference points
/// end in different inks.
pub fn direction(walker: &Walker, p: Point) -> Option<(f64, f64)> {
    let offsets = [(STEP, 0.0), (-STEP, 0.0), (0.0, STEP), (0.0, -STEP)];
    let mut batch = Batch::default();
    for (i, (dx, dy)) in offsets.iter().enumerate() {
        batch.push(p.x + dx, p.y + dy, i as u32);
    }
    let mut out = [Traced::Background(Point::ZERO); 4];
    let mut ends = [Point::ZERO; 4];
    walker.trace_batch_with_ends(&mut batch, &mut out, &mut ends);
    let same = |a: Traced, b: Traced| match (a, b) {
        (Traced::Ink(i), Traced::Ink(j)) => i == j,
        (Traced::Background(_), Traced::Background(_)) => true,
        _ => false,
    };
    if !out.iter().all(|&t| same(t, out[0])) {
        return None;
    }
    // Columns of J⁻¹: ∂q/∂x and ∂q/∂y.
    let gx = (
        (ends[0].x - ends[1].x) / (2.0 * STEP),
        (ends[0].y - ends[1].y) / (2.0 * STEP),
    );
    let gy = (
        (ends[2].x - ends[3].x) / (2.0 * STEP),
        (ends[2].y - ends[3].y) / (2.0 * STEP),
    );
    // M = J⁻ᵀJ⁻¹ = [[a, b], [b, c]].
    let a = gx.0 * gx.0 + gx.1 * gx.1;
    let b = gx.0 * gy.0 + gx.1 * gy.1;
    let c = gy.0 * gy.0 + gy.1 * gy.1;
    let mean = 0.5 * (a + c);
    let spread = (0.25 * (a - c) * (a - c) + b * b).sqrt();
    let (lo, hi) = (mean - spread, mean + spread);
    if !(lo > 0.0 && hi.is_finite()) || (hi / lo).sqrt() < MIN_STRETCH {
        return None;
    }
    // The largest eigenvalue's direction is at θ = ½·atan2(2b, a − c); the stretch is a
    // right angle from it.
    let theta = 0.5 * (2.0 * b).atan2(a - c) + std::f64::consts::FRAC_PI_2;
    Some((theta.cos(), theta.sin()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Op, ops::Tine};

    /// A horizontal tine line drags the ink sideways: in its band the ink is sheared
    /// (γ = αλ/(d + λ)² = 10.2 at d = 4), so its streaks run ½·atan(2/γ) = 5.5° from x;
    /// far away nothing is stretched.
    #[test]
    fn a_tine_stretches_the_ink_along_its_line() {
        let tine = Op::Tine(Tine {
            origin: Point::new(0.0, 100.0),
            direction: kurbo::Vec2::new(1.0, 0.0),
            alpha: 200.0,
            lambda: 10.0,
        });
        let walker = Walker::new(&[tine]);
        let (dx, dy) = direction(&walker, Point::new(200.0, 104.0)).expect("stretched");
        let degrees = dy.atan2(dx).to_degrees().rem_euclid(180.0);
        let off = degrees.min(180.0 - degrees);
        assert!((off - 5.5).abs() < 0.5, "({dx}, {dy}): {degrees}°");
        assert_eq!(direction(&walker, Point::new(200.0, 900.0)), None);
        assert_eq!(direction(&Walker::new(&[]), Point::new(5.0, 5.0)), None);
    }
}
