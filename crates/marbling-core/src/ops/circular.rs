//! Circular comb: tines moving on circles about a centre.

use super::rotation::rotate_about;
use kurbo::Point;

/// Tines moving on circles about `center`, the strongest on the circle of `radius`.
///
/// ρ = |P − C|, d = |ρ − r|, l = αλ/(d + λ), θ = l/ρ; forward rotates P about C by θ
/// (y down, so positive θ turns clockwise on screen). The centre stays put.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circular {
    /// Centre, design pixels.
    pub center: Point,
    /// Radius of the strongest circle, design pixels, > 0.
    pub radius: f64,
    /// Arc length moved on that circle, design pixels.
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Circular {
    /// The rotation angle (radians) at distance `rho` > 0 from the centre.
    pub fn angle(&self, rho: f64) -> f64 {
        let d = (rho - self.radius).abs();
        self.alpha * self.lambda / (d + self.lambda) / rho
    }

    /// Rotates `p` forwards.
    pub fn forward(&self, p: Point) -> Point {
        rotate_about(self.center, p, 1.0, |r| self.angle(r))
    }

    /// Undoes [`Circular::forward`] (ρ is unchanged by the rotation).
    pub fn inverse(&self, p: Point) -> Point {
        rotate_about(self.center, p, -1.0, |r| self.angle(r))
    }
}
