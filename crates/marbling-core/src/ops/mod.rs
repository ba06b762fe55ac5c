//! The seven marbling operations of schema v1 (Lu, Jaffer, Jin, Zhao & Mao 2012),
//! each with its forward map and its inverse, in f64 design pixels.

mod circular;
mod drop;
mod rake;
mod rotation;
mod rounding;
mod spray;
mod tine;
mod vortex;
mod wavy;

pub use circular::Circular;
pub use drop::Drop;
pub use rake::Rake;
pub use rounding::{ANGLE_STEP, LENGTH_STEP};
pub use spray::Spray;
pub use tine::Tine;
pub use vortex::Vortex;
pub use wavy::Wavy;

use crate::Rgb8;
use kurbo::Point;

/// One operation of a design's history.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// An ink drop that pushes older ink outwards.
    Drop(Drop),
    /// A droplet laid on top without deformation.
    Spray(Spray),
    /// One straight tine.
    Tine(Tine),
    /// Evenly spaced parallel tines.
    Rake(Rake),
    /// A sinusoidal comb.
    Wavy(Wavy),
    /// Tines on circles about a centre.
    Circular(Circular),
    /// A swirl, strongest at its centre.
    Vortex(Vortex),
}

/// Result of walking one point back through one operation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Back {
    /// The point came from here before the operation.
    Moved(Point),
    /// The point lies in ink laid by the operation; the walk stops with this colour.
    Ink(Rgb8),
}

/// Every op type name of schema v1, in the order used by summaries.
pub const OP_TYPES: [&str; 7] = [
    "drop", "spray", "tine", "rake", "wavy", "circular", "vortex",
];

impl Op {
    /// The `"type"` tag of the op in design documents.
    pub fn type_name(&self) -> &'static str {
        match self {
            Op::Drop(_) => "drop",
            Op::Spray(_) => "spray",
            Op::Tine(_) => "tine",
            Op::Rake(_) => "rake",
            Op::Wavy(_) => "wavy",
            Op::Circular(_) => "circular",
            Op::Vortex(_) => "vortex",
        }
    }

    /// The ink colour this op lays down, if it lays any.
    pub fn ink(&self) -> Option<Rgb8> {
        match self {
            Op::Drop(d) => Some(d.color),
            Op::Spray(s) => Some(s.color),
            _ => None,
        }
    }

    /// Where a point of older ink ends up after this op (a spray moves nothing).
    pub fn forward(&self, p: Point) -> Point {
        match self {
            Op::Drop(d) => d.forward(p),
            Op::Spray(_) => p,
            Op::Tine(t) => t.forward(p),
            Op::Rake(r) => r.forward(p),
            Op::Wavy(w) => w.forward(p),
            Op::Circular(c) => c.forward(p),
            Op::Vortex(v) => v.forward(p),
        }
    }

    /// Walks a point back through this op: where it was before, or the ink covering it.
    pub fn inverse(&self, p: Point) -> Back {
        match self {
            Op::Drop(d) => d.inverse(p).map_or(Back::Ink(d.color), Back::Moved),
            Op::Spray(s) if s.covers(p) => Back::Ink(s.color),
            Op::Spray(_) => Back::Moved(p),
            Op::Tine(t) => Back::Moved(t.inverse(p)),
            Op::Rake(r) => Back::Moved(r.inverse(p)),
            Op::Wavy(w) => Back::Moved(w.inverse(p)),
            Op::Circular(c) => Back::Moved(c.inverse(p)),
            Op::Vortex(v) => Back::Moved(v.inverse(p)),
        }
    }
}
