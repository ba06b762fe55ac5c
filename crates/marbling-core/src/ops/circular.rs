//! Circular comb: tines moving on circles about a centre.

use super::OpType;
use super::rotation::rotate_about;
use super::rounding as round;
use crate::caption::{at, num};
use crate::explain::{Formula, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
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

impl OpType for Circular {
    const FIELDS: &'static [&'static str] = &["type", "center", "radius", "alpha", "lambda"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (center, radius) = (r.point("center"), r.number("radius"));
        let (alpha, lambda) = (r.number("alpha"), r.number("lambda"));
        Some(Circular {
            center: center?,
            radius: radius?,
            alpha: alpha?,
            lambda: lambda?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("center", self.center);
        w.number("radius", self.radius);
        w.number("alpha", self.alpha);
        w.number("lambda", self.lambda);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("center", self.center);
        c.positive("radius", self.radius);
        c.finite("alpha", self.alpha);
        c.positive("lambda", self.lambda);
    }

    fn round(&mut self) {
        self.center = round::point(self.center);
        self.radius = round::positive(self.radius);
        self.alpha = round::length(self.alpha);
        self.lambda = round::positive(self.lambda);
    }

    fn scale(&mut self, s: f64) {
        self.alpha *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "circular comb around {}: {} px along the circle of radius {} px, decay {} px",
            at(self.center),
            num(self.alpha),
            num(self.radius),
            num(self.lambda)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "circular comb".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = C + R(θ)(P − C), θ = α·λ/(|ρ − r| + λ)/ρ, ρ = |P − C|".into(),
            inverse: "P = C + R(−θ)(P′ − C) (ρ is the same before and after)".into(),
            values: format!(
                "C = {}, r = {}, α = {}, λ = {}",
                pt(self.center),
                num(self.radius),
                num(self.alpha),
                num(self.lambda)
            ),
            symbols: "C: the centre, r: the circular tine's radius (px), ρ: P's distance \
                 from C (px), θ: the angle P turns, R(θ): the turn by θ, α: how far ink on the \
                 tine's circle moves along it (px), λ: how fast that fades (px)"
                .into(),
            area_preserving: true,
        }
    }
}
