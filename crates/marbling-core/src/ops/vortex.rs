//! Vortex: a swirl that is strongest at its centre.

use super::OpType;
use super::rotation::rotate_about;
use super::rounding as round;
use crate::caption::{at, num};
use crate::explain::{Formula, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
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

impl OpType for Vortex {
    const FIELDS: &'static [&'static str] = &["type", "center", "alpha", "lambda"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let center = r.point("center");
        let (alpha, lambda) = (r.number("alpha"), r.number("lambda"));
        Some(Vortex {
            center: center?,
            alpha: alpha?,
            lambda: lambda?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("center", self.center);
        w.number("alpha", self.alpha);
        w.number("lambda", self.lambda);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("center", self.center);
        c.finite("alpha", self.alpha);
        c.positive("lambda", self.lambda);
    }

    fn round(&mut self) {
        self.center = round::point(self.center);
        self.alpha = round::length(self.alpha);
        self.lambda = round::positive(self.lambda);
    }

    fn scale(&mut self, s: f64) {
        self.alpha *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "swirl at {}: strength {} px, decay {} px",
            at(self.center),
            num(self.alpha),
            num(self.lambda)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "vortex".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = C + R(θ)(P − C), θ = α·λ/(ρ + λ)/ρ, ρ = |P − C|".into(),
            inverse: "P = C + R(−θ)(P′ − C)".into(),
            values: format!(
                "C = {}, α = {}, λ = {}",
                pt(self.center),
                num(self.alpha),
                num(self.lambda)
            ),
            symbols: "C: the centre, ρ: P's distance from C (px), θ: the angle P turns, \
                 R(θ): the turn by θ, α: the swirl's strength (px), λ: how fast it fades (px)"
                .into(),
            area_preserving: true,
        }
    }
}
