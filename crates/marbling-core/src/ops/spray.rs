//! Spray droplet: a small disc of ink laid on top without deforming anything.

use super::MIN_SCALED_RADIUS;
use super::OpType;
use super::rounding as round;
use crate::Rgb8;
use crate::caption::{at, num};
use crate::explain::{Formula, SPRAY_SYMBOLS, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
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

impl OpType for Spray {
    const FIELDS: &'static [&'static str] = &["type", "center", "radius", "color"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (center, radius, color) = (r.point("center"), r.number("radius"), r.color("color"));
        Some(Spray {
            center: center?,
            radius: radius?,
            color: color?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("center", self.center);
        w.number("radius", self.radius);
        w.color("color", self.color);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("center", self.center);
        c.positive("radius", self.radius);
    }

    fn round(&mut self) {
        self.center = round::point(self.center);
        self.radius = round::positive(self.radius);
    }

    fn scale(&mut self, s: f64) {
        self.radius = (self.radius * s).max(MIN_SCALED_RADIUS);
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "a spray of {}, radius {} px, at {}",
            self.color,
            num(self.radius),
            at(self.center)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "spray droplet".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = P (a spray lays ink on top without moving anything)".into(),
            inverse: "P = P′; inside |P′ − C| < r: this spray's ink".into(),
            values: format!("C = {}, r = {}", pt(self.center), num(self.radius)),
            symbols: SPRAY_SYMBOLS.into(),
            area_preserving: true,
        }
    }
}
