//! Shift: the whole tank moves by one offset (P′ = P + offset).

use super::OpType;
use super::rounding as round;
use crate::caption::arrow;
use crate::caption::num;
use crate::explain::Formula;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};

/// A translation of everything by `offset`, design pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shift {
    /// How far everything moves, design pixels.
    pub offset: Vec2,
}

impl Shift {
    /// Moves `p` by the offset.
    pub fn forward(&self, p: Point) -> Point {
        p + self.offset
    }

    /// Undoes [`Shift::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.offset
    }
}

impl OpType for Shift {
    const FIELDS: &'static [&'static str] = &["type", "offset"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        Some(Shift {
            offset: r.vector("offset")?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.vector("offset", self.offset);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        c.point("offset", self.offset.to_point());
    }

    fn round(&mut self) {
        self.offset = Vec2::new(round::length(self.offset.x), round::length(self.offset.y));
    }

    fn scale(&mut self, s: f64) {
        self.offset *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "the tank shifted by ({}, {}) px",
            num(self.offset.x),
            num(self.offset.y)
        )
    }

    fn label(&self, _tag: &str) -> String {
        format!("shift {}", arrow(self.offset))
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "P′ = P + D".into(),
            inverse: "P = P′ − D".into(),
            values: format!("D = ({}, {})", num(self.offset.x), num(self.offset.y)),
            symbols: "D: how far the whole tank moves (px)".into(),
            area_preserving: true,
        }
    }
}
