//! Spray droplet: a small disc of ink laid on top without deforming anything.

use crate::Rgb8;
use kurbo::Point;

/// A droplet of radius `radius` at `center` that covers what is under it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spray {
    /// Centre in design pixels.
    pub center: Point,
    /// Radius in design pixels, > 0.
    pub radius: f64,
    /// Ink colour.
    pub color: Rgb8,
}

impl Spray {
    /// True when `p` lies strictly inside the droplet (ρ < r).
    pub fn covers(&self, p: Point) -> bool {
        (p - self.center).hypot2() < self.radius * self.radius
    }
}
