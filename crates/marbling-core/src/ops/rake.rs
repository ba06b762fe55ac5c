//! Rake: evenly spaced parallel tines.

use super::OpType;
use super::rounding as round;
use crate::caption::arrow;
use crate::caption::{heading, num};
use crate::explain::{Formula, TINE_FORWARD, TINE_INVERSE, TINE_SYMBOLS, unit};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};

/// Parallel tines `spacing` apart, one through `origin`, all moving along `direction`.
///
/// As [`crate::Tine`] with d replaced by d' = s/2 − |fmod(d, s) − s/2|, the distance to
/// the nearest tine.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rake {
    /// A point on one tine line, design pixels.
    pub origin: Point,
    /// Direction of motion (non-zero).
    pub direction: Vec2,
    /// Distance between neighbouring tines, design pixels, > 0.
    pub spacing: f64,
    /// Shift at a tine line, design pixels.
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Rake {
    /// The displacement applied at `p` (constant along M).
    pub fn shift(&self, p: Point) -> Vec2 {
        let m = self.direction.normalize();
        let n = Vec2::new(-m.y, m.x);
        let d = (p - self.origin).dot(n).abs();
        let s = self.spacing;
        let d = s / 2.0 - ((d % s) - s / 2.0).abs();
        m * (self.alpha * self.lambda / (d + self.lambda))
    }

    /// Moves `p` along the rake.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Rake::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}

impl OpType for Rake {
    const FIELDS: &'static [&'static str] =
        &["type", "origin", "direction", "spacing", "alpha", "lambda"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (origin, direction) = (r.point("origin"), r.vector("direction"));
        let spacing = r.number("spacing");
        let (alpha, lambda) = (r.number("alpha"), r.number("lambda"));
        Some(Rake {
            origin: origin?,
            direction: direction?,
            spacing: spacing?,
            alpha: alpha?,
            lambda: lambda?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("origin", self.origin);
        w.vector("direction", self.direction);
        w.number("spacing", self.spacing);
        w.number("alpha", self.alpha);
        w.number("lambda", self.lambda);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("origin", self.origin);
        c.direction("direction", self.direction);
        c.positive("spacing", self.spacing);
        c.finite("alpha", self.alpha);
        c.positive("lambda", self.lambda);
    }

    fn round(&mut self) {
        self.origin = round::point(self.origin);
        self.direction = round::direction(self.direction);
        self.spacing = round::positive(self.spacing);
        self.alpha = round::length(self.alpha);
        self.lambda = round::positive(self.lambda);
    }

    fn scale(&mut self, s: f64) {
        self.alpha *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "rake drawn {}: tines {} px apart, shift {} px, decay {} px",
            heading(self.direction * self.alpha.signum()),
            num(self.spacing),
            num(self.alpha.abs()),
            num(self.lambda)
        )
    }

    fn label(&self, _tag: &str) -> String {
        format!("rake {} (whole sheet)", arrow(self.direction))
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: format!(
                "{TINE_FORWARD}, d = distance to the nearest tine line (lines every s along N)"
            ),
            inverse: TINE_INVERSE.into(),
            values: format!(
                "α = {}, λ = {}, s = {}, M = {}",
                num(self.alpha),
                num(self.lambda),
                num(self.spacing),
                unit(self.direction)
            ),
            symbols: format!(
                "O: a point on one tine's line, s: the spacing of the lines (px), d: P's distance \
                 from the nearest (px), {TINE_SYMBOLS}"
            ),
            area_preserving: true,
        }
    }
}
