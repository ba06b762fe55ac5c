//! Wavy comb: every point moves along one direction by a sine of its position across it.

use super::OpType;
use super::rounding as round;
use crate::caption::{heading, num};
use crate::explain::{Formula, num2};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
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

impl OpType for Wavy {
    const FIELDS: &'static [&'static str] = &["type", "angle", "amplitude", "wavelength", "phase"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (angle, amplitude) = (r.number("angle"), r.number("amplitude"));
        let (wavelength, phase) = (r.number("wavelength"), r.number("phase"));
        Some(Wavy {
            angle: angle?,
            amplitude: amplitude?,
            wavelength: wavelength?,
            phase: phase?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.number("angle", self.angle);
        w.number("amplitude", self.amplitude);
        w.number("wavelength", self.wavelength);
        w.number("phase", self.phase);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.finite("angle", self.angle);
        c.finite("amplitude", self.amplitude);
        c.positive("wavelength", self.wavelength);
        c.finite("phase", self.phase);
    }

    fn round(&mut self) {
        self.angle = round::angle(self.angle);
        self.amplitude = round::length(self.amplitude);
        self.wavelength = round::positive(self.wavelength);
        self.phase = round::angle(self.phase);
    }

    fn scale(&mut self, s: f64) {
        self.amplitude *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "wavy comb moving {}: amplitude {} px, wavelength {} px",
            heading(Vec2::new(self.angle.cos(), self.angle.sin())),
            num(self.amplitude),
            num(self.wavelength)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "wavy comb".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = P + A·sin(2π(P·N)/ℓ + φ)·M".into(),
            inverse: "P = P′ − A·sin(2π(P′·N)/ℓ + φ)·M".into(),
            values: format!(
                "A = {}, ℓ = {}, φ = {}, M at {}°",
                num(self.amplitude),
                num(self.wavelength),
                num2(self.phase),
                num(self.angle.to_degrees())
            ),
            symbols: "M: the unit direction ink moves, N: M turned 90°, A: the amplitude \
                 (px), ℓ: the wavelength along N (px), φ: the phase (radians)"
                .into(),
            area_preserving: true,
        }
    }
}
