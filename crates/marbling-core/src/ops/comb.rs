//! Comb: a finite comb whose tines move together along one direction.

use super::OpType;
use super::rounding as round;
use crate::caption::arrow;
use crate::caption::{heading, num, plural, range};
use crate::explain::{Formula, TINE_FORWARD, TINE_INVERSE, TINE_SYMBOLS, unit};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};
use std::sync::Arc;

/// Most tines of one comb.
pub const MAX_COMB_TINES: usize = 256;

/// Tines at signed offsets `tines` across the line through `origin` along `direction`,
/// all moving along it: M = unit direction, N = (−M.y, M.x), s = (P − A)·N,
/// d = minᵢ |s − oᵢ|, P′ = P + αλ/(d + λ)·M. The shift is constant along M, so the map
/// inverts exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Comb {
    /// A point on the line the tine offsets are measured from, design pixels.
    pub origin: Point,
    /// Direction of motion (non-zero; its length does not matter).
    pub direction: Vec2,
    /// Offsets of the tines along N, design pixels; 1..=[`MAX_COMB_TINES`] of them.
    pub tines: Arc<[f64]>,
    /// Shift at a tine, design pixels (negative moves against `direction`).
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Comb {
    /// The displacement applied at `p`.
    pub fn shift(&self, p: Point) -> Vec2 {
        let m = self.direction.normalize();
        let n = Vec2::new(-m.y, m.x);
        let s = (p - self.origin).dot(n);
        let d = self
            .tines
            .iter()
            .map(|o| (s - o).abs())
            .fold(f64::INFINITY, f64::min);
        m * (self.alpha * self.lambda / (d + self.lambda))
    }

    /// Moves `p` with the comb.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Comb::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}

impl OpType for Comb {
    const FIELDS: &'static [&'static str] =
        &["type", "origin", "direction", "tines", "alpha", "lambda"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (origin, direction) = (r.point("origin"), r.vector("direction"));
        let tines = r.numbers("tines");
        let (alpha, lambda) = (r.number("alpha"), r.number("lambda"));
        Some(Comb {
            origin: origin?,
            direction: direction?,
            tines: tines?,
            alpha: alpha?,
            lambda: lambda?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.point("origin", self.origin);
        w.vector("direction", self.direction);
        w.numbers("tines", &self.tines);
        w.number("alpha", self.alpha);
        w.number("lambda", self.lambda);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("origin", self.origin);
        c.direction("direction", self.direction);
        if c.count("tines", self.tines.len(), 1, MAX_COMB_TINES, "tine offsets") {
            for (k, &o) in self.tines.iter().enumerate() {
                c.finite(&format!("tines[{k}]"), o);
            }
        }
        c.finite("alpha", self.alpha);
        c.positive("lambda", self.lambda);
    }

    fn round(&mut self) {
        self.origin = round::point(self.origin);
        self.direction = round::direction(self.direction);
        self.tines = self.tines.iter().map(|&o| round::length(o)).collect();
        self.alpha = round::length(self.alpha);
        self.lambda = round::positive(self.lambda);
    }

    fn scale(&mut self, s: f64) {
        self.alpha *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        let n = self.tines.len();
        let gaps: Vec<f64> = self.tines.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
        let apart = if gaps.is_empty() {
            String::new()
        } else {
            let lo = gaps.iter().cloned().fold(f64::INFINITY, f64::min);
            let hi = gaps.iter().cloned().fold(0.0, f64::max);
            format!(", {} px apart", range(lo, hi))
        };
        format!(
            "comb drawn {}: {}{apart}, shift {} px, decay {} px",
            heading(self.direction * self.alpha.signum()),
            plural(n, "tine", "tines"),
            num(self.alpha.abs()),
            num(self.lambda)
        )
    }

    fn label(&self, _tag: &str) -> String {
        format!(
            "comb of {} tines {}",
            self.tines.len(),
            arrow(self.direction)
        )
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: format!("{TINE_FORWARD}, d = min over i of |(P − O)·N − t_i|"),
            inverse: TINE_INVERSE.into(),
            values: format!(
                "α = {}, λ = {}, {} tines, M = {}",
                num(self.alpha),
                num(self.lambda),
                self.tines.len(),
                unit(self.direction)
            ),
            symbols: format!(
                "O: the comb's origin, t_i: tine i's offset from O along N (px), d: P's distance \
                 from the nearest tine's line (px), {TINE_SYMBOLS}"
            ),
            area_preserving: true,
        }
    }
}
