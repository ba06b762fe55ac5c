//! Rake: evenly spaced parallel tines.

use kurbo::{Point, Vec2};

/// Parallel tines `spacing` apart, one through `origin`, all moving along `direction`.
///
/// As [`crate::Tine`] with d replaced by d' = s/2 − |fmod(d, s) − s/2|, the distance to
/// the nearest tine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rake {
    /// A point on one tine line, design pixels.
    pub origin: Point,
    /// Direction of motion (non-zero).
    pub direction: Vec2,
    /// Distance between neighbouring tines, design pixels, > 0.
    pub spacing: f64,
    /// Shift at a tine line, design pixels.
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Rake {
    /// The displacement applied at `p` (constant along M).
    pub fn shift(&self, p: Point) -> Vec2 {
        let m = self.direction.normalize();
        let n = Vec2::new(-m.y, m.x);
        let d = (p - self.origin).dot(n).abs();
        let s = self.spacing;
        let d = s / 2.0 - ((d % s) - s / 2.0).abs();
        m * (self.alpha * self.lambda / (d + self.lambda))
    }

    /// Moves `p` along the rake.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Rake::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}
