//! Jiggle: a wave of motion along and across one direction.
//!
//! u = (cos θ, sin θ), v = (−sin θ, cos θ), k = 2π/λ, φ = k(P·u) + φ₀,
//! P′ = P + A·sin φ·u + B·cos φ·v. Invertible when |kA| < 1. It is **not** area
//! preserving when A ≠ 0: its Jacobian is 1 + kA·cos φ. With A = 0 it is a shear, like
//! the wavy comb.

use super::OpType;
use super::rounding as round;
use crate::caption::{heading, num};
use crate::explain::Formula;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};
use std::f64::consts::TAU;

/// A jiggle of the tank (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jiggle {
    /// Angle θ of u, radians.
    pub angle: f64,
    /// Wavelength λ along u, design pixels, > 0.
    pub wavelength: f64,
    /// Amplitude A along u, design pixels; |2πA/λ| < 1.
    pub along: f64,
    /// Amplitude B along v, design pixels.
    pub across: f64,
    /// Phase φ₀, radians.
    pub phase: f64,
}

/// Solves φ + c·sin φ = t for φ (|c| < 1, so the left side is increasing): safeguarded
/// Newton in the bracket [t − |c|, t + |c|], to f64 rounding.
pub(crate) fn solve_kepler(t: f64, c: f64) -> f64 {
    let (mut lo, mut hi) = (t - c.abs(), t + c.abs());
    let mut phi = t - c * t.sin();
    for _ in 0..60 {
        let f = phi + c * phi.sin() - t;
        if f == 0.0 {
            break;
        }
        if f > 0.0 {
            hi = phi;
        } else {
            lo = phi;
        }
        let mut next = phi - f / (1.0 + c * phi.cos());
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - phi).abs() <= 1e-15 * (1.0 + phi.abs()) {
            phi = next;
            break;
        }
        phi = next;
    }
    phi
}

impl Jiggle {
    /// (u, v, k).
    fn frame(&self) -> (Vec2, Vec2, f64) {
        let (s, c) = self.angle.sin_cos();
        (Vec2::new(c, s), Vec2::new(-s, c), TAU / self.wavelength)
    }

    /// kA, which must be below 1 in magnitude.
    pub fn k_along(&self) -> f64 {
        TAU / self.wavelength * self.along
    }

    /// Moves `p` by the jiggle.
    pub fn forward(&self, p: Point) -> Point {
        let (u, v, k) = self.frame();
        let phi = k * p.to_vec2().dot(u) + self.phase;
        let (s, c) = phi.sin_cos();
        p + u * (self.along * s) + v * (self.across * c)
    }

    /// Undoes [`Jiggle::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        let (u, v, k) = self.frame();
        let t = k * p.to_vec2().dot(u) + self.phase;
        // Solve with t reduced to [0, 2π): sin and cos do not see the whole turns.
        let turns = (t / TAU).floor() * TAU;
        let phi = solve_kepler(t - turns, k * self.along);
        let (s, c) = phi.sin_cos();
        p - u * (self.along * s) - v * (self.across * c)
    }

    /// The Jacobian determinant of the forward map at `p`: 1 + kA·cos φ.
    pub fn jacobian(&self, p: Point) -> f64 {
        let (u, _, k) = self.frame();
        let phi = k * p.to_vec2().dot(u) + self.phase;
        1.0 + k * self.along * phi.cos()
    }
}

impl OpType for Jiggle {
    const FIELDS: &'static [&'static str] =
        &["type", "angle", "wavelength", "along", "across", "phase"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (angle, wavelength) = (r.number("angle"), r.number("wavelength"));
        let (along, across, phase) = (r.number("along"), r.number("across"), r.number("phase"));
        Some(Jiggle {
            angle: angle?,
            wavelength: wavelength?,
            along: along?,
            across: across?,
            phase: phase?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.number("angle", self.angle);
        w.number("wavelength", self.wavelength);
        w.number("along", self.along);
        w.number("across", self.across);
        w.number("phase", self.phase);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.finite("angle", self.angle);
        c.positive("wavelength", self.wavelength);
        let along_ok = c.finite("along", self.along);
        c.finite("across", self.across);
        c.finite("phase", self.phase);
        let ka = self.k_along();
        if along_ok && self.wavelength > 0.0 && ka.abs() >= 1.0 {
            c.push(
                "along",
                format!(
                    "must satisfy |2π·along/wavelength| < 1 (the jiggle must not fold the tank), got {:.4} for along {} and wavelength {}; use a smaller along or a longer wavelength",
                    ka.abs(),
                    self.along,
                    self.wavelength
                ),
            );
        }
    }

    fn round(&mut self) {
        self.angle = round::angle(self.angle);
        self.wavelength = round::positive(self.wavelength);
        self.along = round::length(self.along);
        self.across = round::length(self.across);
        self.phase = round::angle(self.phase);
    }

    fn scale(&mut self, s: f64) {
        self.along *= s;
        self.across *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "the tank jiggled {}: wavelength {} px, {} px along, {} px across",
            heading(Vec2::new(self.angle.cos(), self.angle.sin())),
            num(self.wavelength),
            num(self.along),
            num(self.across)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "jiggle".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = P + A·sin φ·u + B·cos φ·v, φ = 2π(P·u)/λ + φ₀".into(),
            inverse:
                "solve P·u = P′·u − A·sin φ for φ (Newton), then P = P′ − A·sin φ·u − B·cos φ·v"
                    .into(),
            values: format!(
                "A = {}, B = {}, λ = {}, u at {}°; area scales by 1 + 2πA/λ·cos φ",
                num(self.along),
                num(self.across),
                num(self.wavelength),
                num(self.angle.to_degrees())
            ),
            symbols: "u: the unit direction of the wave, v: u turned 90°, A: the swing \
                 along u (px), B: the swing across (px), λ: the wavelength (px), φ₀: the phase, \
                 φ: the phase at P"
                .into(),
            area_preserving: self.along == 0.0,
        }
    }
}
