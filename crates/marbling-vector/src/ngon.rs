//! The initial regular n-gon of a drop or spray.

/// Fewest sides of an initial polygon.
pub const MIN_SIDES: usize = 8;
/// Most sides of an initial polygon (refinement adds more where needed).
pub const MAX_SIDES: usize = 1 << 16;

/// Sides n of the regular polygon inscribed in a circle of radius `radius_px` output
/// pixels whose sagitta r·(1 − cos(π/n)) is at most `tolerance / 4` output pixels,
/// clamped to [`MIN_SIDES`]..=[`MAX_SIDES`]. Non-positive or non-finite inputs give
/// [`MIN_SIDES`].
pub fn initial_sides(radius_px: f64, tolerance: f64) -> usize {
    let dev = tolerance / 4.0;
    if !(radius_px.is_finite() && dev.is_finite() && radius_px > 0.0 && dev > 0.0) {
        return MIN_SIDES;
    }
    if dev >= radius_px {
        return MIN_SIDES;
    }
    let half_angle = (1.0 - dev / radius_px).acos();
    let n = (std::f64::consts::PI / half_angle).ceil();
    (n as usize).clamp(MIN_SIDES, MAX_SIDES)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sagitta_within_quarter_tolerance() {
        for &(r, t) in &[(40.0, 1.0), (3.0, 0.25), (500.0, 1.0), (1.0, 2.0)] {
            let n = initial_sides(r, t);
            let sag = r * (1.0 - (std::f64::consts::PI / n as f64).cos());
            assert!(sag <= t / 4.0 + 1e-12, "r {r} t {t} n {n} sag {sag}");
            if n > MIN_SIDES {
                let fewer = r * (1.0 - (std::f64::consts::PI / (n - 1) as f64).cos());
                assert!(fewer > t / 4.0, "n {n} is not the fewest");
            }
        }
    }
}
