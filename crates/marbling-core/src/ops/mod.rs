//! The marbling operations (Lu, Jaffer, Jin, Zhao & Mao 2012): the seven of schema v1,
//! the seven schema v3 adds (shift, turn, comb, drops, sprays, jiggle, stylus) and the
//! flow of schema v4, each with its forward map and its inverse, in f64 design pixels.

mod circular;
mod comb;
mod drop;
mod drops;
mod flow;
mod jiggle;
mod midpoint;
mod op_type;
mod rake;
mod rotation;
mod rounding;
mod shift;
mod spray;
mod stylus;
mod tine;
mod turn;
mod vortex;
mod wavy;

pub use circular::Circular;
pub use comb::{Comb, MAX_COMB_TINES};
pub use drop::Drop;
pub use drops::{DropSet, MAX_DROPS, Radii};
pub use flow::{FLOW_STEP_PX, Flow, FlowField, MAX_FLOW_STEPS, flow_noise};
pub use jiggle::Jiggle;
#[cfg(test)]
pub(crate) use jiggle::solve_kepler;
pub(crate) use op_type::OpType;
pub use rake::Rake;
pub use rounding::{ANGLE_STEP, LENGTH_STEP, TIME_STEP};
pub use shift::Shift;
pub use spray::Spray;
pub use stylus::{
    MAX_STYLUS_POINTS, MAX_STYLUS_TIPS, MAX_STYLUS_WORK, Stylus, StylusSegment, WAKE_REACH,
    sub_steps_of,
};
pub use tine::Tine;
pub use turn::Turn;
pub(crate) use turn::rotate;
pub use vortex::Vortex;
pub use wavy::Wavy;

use crate::Rgb8;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::Point;

/// One operation of a design's history.
#[derive(Clone, Debug, PartialEq)]
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
    /// The whole tank moved (schema v3).
    Shift(Shift),
    /// The whole tank rotated about a centre (schema v3).
    Turn(Turn),
    /// A finite comb of tines moving together (schema v3).
    Comb(Comb),
    /// Many drops in order (schema v3).
    Drops(DropSet),
    /// Many spray droplets in order (schema v3).
    Sprays(DropSet),
    /// A wave of motion along and across a direction (schema v3; not area preserving
    /// when `along` ≠ 0).
    Jiggle(Jiggle),
    /// A free-hand stroke of one or more tips (schema v3).
    Stylus(Stylus),
    /// The tank streaming along a curl noise for a while (schema v4).
    Flow(Flow),
}

/// Smallest radius of a drop scaled toward 0 ([`Op::scaled`]), design pixels: it stays
/// > 0 so the scaled op is still valid.
pub(crate) const MIN_SCALED_RADIUS: f64 = 1e-6;

/// Walk cost of one segment of a stylus path, in simple ops ([`Op::walk_cost`]).
pub const STYLUS_SEGMENT_COST: u64 = 8;
/// Walk cost of a jiggle, in simple ops ([`Op::walk_cost`]).
pub const JIGGLE_COST: u64 = 8;
/// Walk cost of one sub-step of a flow per octave of its noise, in simple ops
/// ([`Op::walk_cost`]): measured on the CPU, one flow of 286 sub-steps and 3 octaves
/// takes as long per sample as 27,000 tines (docs/BENCHMARKS.md).
pub const FLOW_OCTAVE_STEP_COST: u64 = 32;

/// Result of walking one point back through one operation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Back {
    /// The point came from here before the operation.
    Moved(Point),
    /// The point lies in ink laid by the operation; the walk stops with this colour.
    Ink(Rgb8),
}

/// The op types schema v4 adds.
pub(crate) const OP_TYPES_V4: [&str; 1] = ["flow"];

/// The op types schema v3 adds.
pub(crate) const OP_TYPES_V3: [&str; 7] = [
    "shift", "turn", "comb", "drops", "sprays", "jiggle", "stylus",
];

/// The one table of op types: each `"type"` tag with its [`Op`] variant and the type
/// holding its fields (an [`OpType`]). Everything that goes by an op's type (its tag,
/// its fields, reading, writing, value rules, rounding, scaling and caption) is made
/// from this table, in this order (schema v1's seven, then v3's).
macro_rules! op_types {
    ($($tag:literal => $variant:ident($ty:ty),)*) => {
        /// Every op type name, in the order used by summaries: schema v1's seven, then v3's.
        pub const OP_TYPES: &[&str] = &[$($tag),*];

        /// Field names of op type `kind`, `type` first, in the order they are written.
        pub(crate) fn op_fields(kind: &str) -> Option<&'static [&'static str]> {
            match kind {
                $($tag => Some(<$ty as OpType>::FIELDS),)*
                _ => None,
            }
        }

        impl Op {
            /// The `"type"` tag of the op in design documents.
            pub fn type_name(&self) -> &'static str {
                match self {
                    $(Op::$variant(_) => $tag,)*
                }
            }

            /// Reads an op of type `kind` from its fields (`None` after reporting).
            pub(crate) fn read(kind: &str, r: &mut FieldReader<'_>) -> Option<Op> {
                match kind {
                    $($tag => <$ty as OpType>::read(r).map(Op::$variant),)*
                    _ => None,
                }
            }

            /// Writes the op's fields after `type`.
            pub(crate) fn write(&self, w: &mut FieldWriter) {
                match self {
                    $(Op::$variant(o) => o.write(w),)*
                }
            }

            /// Reports every value rule the op breaks.
            pub(crate) fn check(&self, c: &mut OpCheck<'_>) {
                match self {
                    $(Op::$variant(o) => o.check(c),)*
                }
            }

            /// This op with its parameters rounded as `ops/rounding.rs` says (idempotent).
            pub fn rounded(&self) -> Op {
                let mut op = self.clone();
                match &mut op {
                    $(Op::$variant(o) => o.round(),)*
                }
                op
            }

            /// This op at fraction `s` (0..=1) of its strength or radius (a stroke: the
            /// first fraction `s` of its path).
            pub fn scaled(&self, s: f64) -> Op {
                let mut op = self.clone();
                match &mut op {
                    $(Op::$variant(o) => o.scale(s),)*
                }
                op
            }

            /// Its forward and inverse maps with its numbers (see [`crate::explain::formula`]).
            pub(crate) fn type_formula(&self) -> crate::explain::Formula {
                match self {
                    $(Op::$variant(o) => o.formula($tag),)*
                }
            }

            /// A short name for lists (the history): "tine →", "12 drops", "stylus stroke".
            pub fn label(&self) -> String {
                match self {
                    $(Op::$variant(o) => o.label($tag),)*
                }
            }

            /// The op in plain language with its numbers: "a drop of #1f3a5f, radius
            /// 40 px, at (120, 80)".
            pub fn caption(&self) -> String {
                match self {
                    $(Op::$variant(o) => o.caption($tag),)*
                }
            }
        }
    };
}

op_types! {
    "drop" => Drop(Drop),
    "spray" => Spray(Spray),
    "tine" => Tine(Tine),
    "rake" => Rake(Rake),
    "wavy" => Wavy(Wavy),
    "circular" => Circular(Circular),
    "vortex" => Vortex(Vortex),
    "shift" => Shift(Shift),
    "turn" => Turn(Turn),
    "comb" => Comb(Comb),
    "drops" => Drops(DropSet),
    "sprays" => Sprays(DropSet),
    "jiggle" => Jiggle(Jiggle),
    "stylus" => Stylus(Stylus),
    "flow" => Flow(Flow),
}

impl Op {
    /// Whether the op is one schema v3 adds (a design holding one is written as v3).
    pub fn is_v3(&self) -> bool {
        OP_TYPES_V3.contains(&self.type_name())
    }

    /// Whether the op is one schema v4 adds (a design holding one is written as v4).
    pub fn is_v4(&self) -> bool {
        OP_TYPES_V4.contains(&self.type_name())
    }

    /// Whether the GPU walk needs the v3 code for this op: every v3 and v4 type but the
    /// drop and spray patterns, which compile to plain discs (see
    /// [`crate::CompiledOp::push`]).
    pub fn walks_v3(&self) -> bool {
        (self.is_v3() && !matches!(self, Op::Drops(_) | Op::Sprays(_))) || self.is_v4()
    }

    /// How many ops this one counts as toward [`crate::MAX_OPS`]: every drop of a
    /// drop pattern counts, every other op counts once.
    pub fn counted_ops(&self) -> usize {
        match self {
            Op::Drops(d) | Op::Sprays(d) => d.len(),
            _ => 1,
        }
    }

    /// What walking one point back through this op costs, in units of a simple op:
    /// the sum of [`crate::CompiledOp::walk_cost`] over its compiled forms (a drop
    /// pattern one per drop, a finite comb one per tine, a stylus eight per segment of
    /// its path, a jiggle eight). Renderers size their work by it.
    pub fn walk_cost(&self) -> u64 {
        match self {
            Op::Drops(d) | Op::Sprays(d) => d.len() as u64,
            Op::Comb(c) => c.tines.len() as u64,
            Op::Stylus(s) => STYLUS_SEGMENT_COST * s.path.len().saturating_sub(1) as u64,
            Op::Jiggle(_) => JIGGLE_COST,
            Op::Flow(f) => flow_cost(f.field().steps, f.noise.octaves),
            _ => 1,
        }
    }

    /// The ink colour this op lays down first, if it lays any.
    pub fn ink(&self) -> Option<Rgb8> {
        match self {
            Op::Drop(d) => Some(d.color),
            Op::Spray(s) => Some(s.color),
            Op::Drops(d) | Op::Sprays(d) => d.colors.first().copied(),
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
            Op::Shift(s) => s.forward(p),
            Op::Turn(t) => t.forward(p),
            Op::Comb(c) => c.forward(p),
            Op::Drops(d) => d.expand(false).fold(p, |p, op| op.forward(p)),
            Op::Sprays(_) => p,
            Op::Jiggle(j) => j.forward(p),
            Op::Stylus(s) => s.forward(p),
            Op::Flow(f) => f.forward(p),
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
            Op::Shift(s) => Back::Moved(s.inverse(p)),
            Op::Turn(t) => Back::Moved(t.inverse(p)),
            Op::Comb(c) => Back::Moved(c.inverse(p)),
            Op::Drops(d) => back_through(d.expand(false), p),
            Op::Sprays(d) => back_through(d.expand(true), p),
            Op::Jiggle(j) => Back::Moved(j.inverse(p)),
            Op::Stylus(s) => Back::Moved(s.inverse(p)),
            Op::Flow(f) => Back::Moved(f.inverse(p)),
        }
    }
}

/// The walk cost of a flow of `steps` sub-steps over `octaves` octaves.
pub(crate) fn flow_cost(steps: u32, octaves: u32) -> u64 {
    (FLOW_OCTAVE_STEP_COST * u64::from(steps) * u64::from(octaves)).max(1)
}

/// Walks `p` back through `ops` (oldest first), newest first.
fn back_through(ops: impl DoubleEndedIterator<Item = Op>, p: Point) -> Back {
    let mut p = p;
    for op in ops.rev() {
        match op.inverse(p) {
            Back::Moved(q) => p = q,
            ink => return ink,
        }
    }
    Back::Moved(p)
}
