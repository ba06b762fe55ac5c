//! Ink drop: a disc of new ink that pushes all older ink radially outwards.

use super::MIN_SCALED_RADIUS;
use super::OpType;
use super::rounding as round;
use crate::Rgb8;
use crate::caption::{at, num};
use crate::explain::{DROP_FORWARD, DROP_INVERSE, DROP_SYMBOLS, Formula, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::Point;

/// An ink drop of radius `radius` (design pixels) at `center`.
///
/// Forward: P' = C + (P − C)·√(1 + r²/ρ²), ρ = |P − C|. The centre itself has no
/// image (it becomes the whole circle); it is returned unchanged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drop {
    /// Centre in design pixels.
    pub center: Point,
    /// Radius in design pixels, > 0.
    pub radius: f64,
    /// Ink colour.
    pub color: Rgb8,
}

impl Drop {
    /// Pushes an older point outwards (area preserving outside the centre).
    pub fn forward(&self, p: Point) -> Point {
        let v = p - self.center;
        let rho2 = v.hypot2();
        if rho2 == 0.0 {
            return p;
        }
        self.center + v * (1.0 + self.radius * self.radius / rho2).sqrt()
    }

    /// Maps a point back to where it was before the drop; `None` inside the drop
    /// (ρ < r), where the point shows this drop's ink.
    pub fn inverse(&self, p: Point) -> Option<Point> {
        let v = p - self.center;
        let rho2 = v.hypot2();
        let r2 = self.radius * self.radius;
        if rho2 < r2 {
            return None;
        }
        Some(self.center + v * (1.0 - r2 / rho2).sqrt())
    }
}

impl OpType for Drop {
    const FIELDS: &'static [&'static str] = &["type", "center", "radius", "color"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (center, radius, color) = (r.point("center"), r.number("radius"), r.color("color"));
        Some(Drop {
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
            "a drop of {}, radius {} px, at {}",
            self.color,
            num(self.radius),
            at(self.center)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "drop".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: DROP_FORWARD.into(),
            inverse: DROP_INVERSE.into(),
            values: format!("C = {}, r = {}", pt(self.center), num(self.radius)),
            symbols: DROP_SYMBOLS.into(),
            area_preserving: true,
        }
    }
}
