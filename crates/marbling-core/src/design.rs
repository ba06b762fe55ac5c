//! The design document: canvas size, background and the history of operations.

use crate::{Op, Rgb8};

/// Largest accepted canvas side, design pixels.
pub const MAX_SIDE: u32 = 16_384;
/// Largest accepted number of operations in one design.
pub const MAX_OPS: usize = 100_000;
/// The schema version this crate writes.
pub const CURRENT_VERSION: u64 = 1;
/// Every schema version this crate reads.
pub const SUPPORTED_VERSIONS: &[u64] = &[1];

/// A marbled design: its history of operations, oldest first, on a plain background.
///
/// Coordinates are design pixels, origin top-left, x right, y down; angles in radians.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// Canvas width, design pixels, 1..=[`MAX_SIDE`].
    pub width: u32,
    /// Canvas height, design pixels, 1..=[`MAX_SIDE`].
    pub height: u32,
    /// Colour of the tank before any ink.
    pub background: Rgb8,
    /// Operations, oldest first.
    pub ops: Vec<Op>,
}

impl Design {
    /// An empty design of the given size and background.
    pub fn new(width: u32, height: u32, background: Rgb8) -> Self {
        Self {
            width,
            height,
            background,
            ops: Vec::new(),
        }
    }

    /// How many ops of each type, as `(type, count)` in [`crate::OP_TYPES`] order,
    /// omitting types that do not occur.
    pub fn op_counts(&self) -> Vec<(&'static str, usize)> {
        crate::OP_TYPES
            .iter()
            .map(|&t| (t, self.ops.iter().filter(|o| o.type_name() == t).count()))
            .filter(|&(_, n)| n > 0)
            .collect()
    }
}
