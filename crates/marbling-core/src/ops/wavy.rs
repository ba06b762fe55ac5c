//! Wavy comb: every point moves along one direction by a sine of its position across it.

use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// A sinusoidal shift along m = (cos t, sin t) driven by v = P·n, n = (sin t, −cos t):
/// P' = P + A·sin(2πv/wavelength + phase)·m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wavy {
    /// Angle t of the motion direction, radians (x right, y down).
    pub angle: f64,
    /// Amplitude A, design pixels.
    pub amplitude: f64,
    /// Wavelength, design pixels, > 0.
    pub wavelength: f64,
    /// Phase, radians.
    pub phase: f64,
}

impl Wavy {
    /// The displacement applied at `p` (constant along m).
    pub fn shift(&self, p: Point) -> Vec2 {
        let (s, c) = self.angle.sin_cos();
        let m = Vec2::new(c, s);
        let n = Vec2::new(s, -c);
        let v = p.to_vec2().dot(n);
        m * (self.amplitude * (TAU * v / self.wavelength + self.phase).sin())
    }

    /// Moves `p` by the wave.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Wavy::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}
