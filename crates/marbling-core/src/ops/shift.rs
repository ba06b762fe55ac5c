//! Shift: the whole tank moves by one offset (P′ = P + offset).

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
