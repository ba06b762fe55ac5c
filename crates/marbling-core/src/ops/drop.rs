//! Ink drop: a disc of new ink that pushes all older ink radially outwards.

use crate::Rgb8;
use kurbo::Point;

/// An ink drop of radius `radius` (design pixels) at `center`.
///
/// Forward: P' = C + (P − C)·√(1 + r²/ρ²), ρ = |P − C|. The centre itself has no
/// image (it becomes the whole circle); it is returned unchanged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drop {
    /// Centre in design pixels.
    pub center: Point,
    /// Radius in design pixels, > 0.
    pub radius: f64,
    /// Ink colour.
    pub color: Rgb8,
}

impl Drop {
    /// Pushes an older point outwards (area preserving outside the centre).
    pub fn forward(&self, p: Point) -> Point {
        let v = p - self.center;
        let rho2 = v.hypot2();
        if rho2 == 0.0 {
            return p;
        }
        self.center + v * (1.0 + self.radius * self.radius / rho2).sqrt()
    }

    /// Maps a point back to where it was before the drop; `None` inside the drop
    /// (ρ < r), where the point shows this drop's ink.
    pub fn inverse(&self, p: Point) -> Option<Point> {
        let v = p - self.center;
        let rho2 = v.hypot2();
        let r2 = self.radius * self.radius;
        if rho2 < r2 {
            return None;
        }
        Some(self.center + v * (1.0 - r2 / rho2).sqrt())
    }
}
