//! Vortex: a swirl that is strongest at its centre.

use super::rotation::rotate_about;
use kurbo::Point;

/// A vortex: [`crate::Circular`] with d = ρ, strongest at the centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vortex {
    /// Centre, design pixels.
    pub center: Point,
    /// Arc length scale, design pixels.
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Vortex {
    /// The rotation angle (radians) at distance `rho` > 0 from the centre.
    pub fn angle(&self, rho: f64) -> f64 {
        self.alpha * self.lambda / (rho + self.lambda) / rho
    }

    /// Rotates `p` forwards.
    pub fn forward(&self, p: Point) -> Point {
        rotate_about(self.center, p, 1.0, |r| self.angle(r))
    }

    /// Undoes [`Vortex::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        rotate_about(self.center, p, -1.0, |r| self.angle(r))
    }
}
