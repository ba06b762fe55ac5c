//! Tine: one straight tine drawn across the tank.

use super::OpType;
use super::rounding as round;
use crate::caption::arrow;
use crate::caption::{at, heading, num};
use crate::explain::{Formula, TINE_FORWARD, TINE_INVERSE, TINE_SYMBOLS, pt, unit};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};

/// A tine through `origin` moving along `direction`.
///
/// M = direction/|direction|, N = (−M.y, M.x), d = |(P − A)·N|;
/// forward P' = P + αλ/(d + λ)·M. `alpha` is the largest shift (design pixels, at the
/// tine line) and `lambda` (> 0) how fast the shift decays with distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tine {
    /// A point on the tine line, design pixels.
    pub origin: Point,
    /// Direction of motion (non-zero; its length does not matter).
    pub direction: Vec2,
    /// Shift at the tine line, design pixels (negative moves against `direction`).
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Tine {
    /// The displacement applied at `p`; it is constant along M, so the map inverts exactly.
    pub fn shift(&self, p: Point) -> Vec2 {
        let m = self.direction.normalize();
        let n = Vec2::new(-m.y, m.x);
        let d = (p - self.origin).dot(n).abs();
        m * (self.alpha * self.lambda / (d + self.lambda))
    }

    /// Moves `p` along the tine.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Tine::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}

impl OpType for Tine {
    const FIELDS: &'static [&'static str] = &["type", "origin", "direction", "alpha", "lambda"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (origin, direction) = (r.point("origin"), r.vector("direction"));
        let (alpha, lambda) = (r.number("alpha"), r.number("lambda"));
        Some(Tine {
            origin: origin?,
            direction: direction?,
            alpha: alpha?,
            lambda: lambda?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("origin", self.origin);
        w.vector("direction", self.direction);
        w.number("alpha", self.alpha);
        w.number("lambda", self.lambda);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("origin", self.origin);
        c.direction("direction", self.direction);
        c.finite("alpha", self.alpha);
        c.positive("lambda", self.lambda);
    }

    fn round(&mut self) {
        self.origin = round::point(self.origin);
        self.direction = round::direction(self.direction);
        self.alpha = round::length(self.alpha);
        self.lambda = round::positive(self.lambda);
    }

    fn scale(&mut self, s: f64) {
        self.alpha *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "a tine drawn {} through {}: shift {} px, decay {} px",
            heading(self.direction),
            at(self.origin),
            num(self.alpha),
            num(self.lambda)
        )
    }

    fn label(&self, _tag: &str) -> String {
        format!("tine {}", arrow(self.direction))
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: format!("{TINE_FORWARD}, d = |(P − O)·N|"),
            inverse: TINE_INVERSE.into(),
            values: format!(
                "α = {}, λ = {}, O = {}, M = {}",
                num(self.alpha),
                num(self.lambda),
                pt(self.origin),
                unit(self.direction)
            ),
            symbols: format!(
                "O: a point on the tine's line, d: P's distance from that line (px), {TINE_SYMBOLS}"
            ),
            area_preserving: true,
        }
    }
}
