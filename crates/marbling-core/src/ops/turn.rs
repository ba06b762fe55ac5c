//! Turn: the whole tank rotates about a centre (P′ = C + R(θ)(P − C)).

use super::OpType;
use super::rounding as round;
use crate::caption::{at, num};
use crate::explain::{Formula, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};

/// A rigid rotation by `angle` about `center`, with
/// R(θ) = [[cos θ, −sin θ], [sin θ, cos θ]] (y down, so a positive angle turns clockwise
/// on screen, as the circular comb does).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turn {
    /// Centre of rotation, design pixels.
    pub center: Point,
    /// Angle θ, radians.
    pub angle: f64,
}

/// R(θ)·v for θ given by its sine and cosine.
pub(crate) fn rotate(v: Vec2, sin: f64, cos: f64) -> Vec2 {
    Vec2::new(v.x * cos - v.y * sin, v.x * sin + v.y * cos)
}

impl Turn {
    /// Rotates `p` about the centre.
    pub fn forward(&self, p: Point) -> Point {
        let (s, c) = self.angle.sin_cos();
        self.center + rotate(p - self.center, s, c)
    }

    /// Undoes [`Turn::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        let (s, c) = self.angle.sin_cos();
        self.center + rotate(p - self.center, -s, c)
    }
}

impl OpType for Turn {
    const FIELDS: &'static [&'static str] = &["type", "center", "angle"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (center, angle) = (r.point("center"), r.number("angle"));
        Some(Turn {
            center: center?,
            angle: angle?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("center", self.center);
        w.number("angle", self.angle);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("center", self.center);
        c.finite("angle", self.angle);
    }

    fn round(&mut self) {
        self.center = round::point(self.center);
        self.angle = round::angle(self.angle);
    }

    fn scale(&mut self, s: f64) {
        self.angle *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "the tank turned {}° about {}",
            num(self.angle.to_degrees()),
            at(self.center)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "turn".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = C + R(θ)(P − C)".into(),
            inverse: "P = C + R(−θ)(P′ − C)".into(),
            values: format!(
                "C = {}, θ = {}°",
                pt(self.center),
                num(self.angle.to_degrees())
            ),
            symbols: "C: the centre, θ: the angle, R(θ): the turn by θ".into(),
            area_preserving: true,
        }
    }
}
