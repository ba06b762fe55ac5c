//! The colour of single design points, for renderers that do not sample a regular grid
//! (the 3D view): the same walk and the same surface rules as [`crate::render`].

use crate::surface::Surface;
use crate::walk::{Batch, Traced, Walker};
use crate::{Design, Point};

/// Source id of a sample that reached the background (ink samples use the index of
/// the op whose ink covered them).
pub const SOURCE_BACKGROUND: u32 = u32::MAX - 1;

/// A design prepared for colouring design points.
#[derive(Clone, Debug)]
pub struct PointColors {
    walker: Walker,
    /// Linear colour of each compiled op's ink (the background's for ops without).
    linear: Vec<[f32; 3]>,
    background: [f32; 3],
    surface: Option<Surface>,
}

/// Scratch buffers reused between calls on one thread.
#[derive(Debug)]
pub struct PointScratch {
    batch: Batch,
    traced: [Traced; 1],
    ends: [Point; 1],
}

impl Default for PointScratch {
    fn default() -> Self {
        Self {
            batch: Batch::default(),
            traced: [Traced::Ink(0)],
            ends: [Point::ZERO],
        }
    }
}

impl PointColors {
    /// Prepares `design`.
    pub fn new(design: &Design) -> Self {
        let walker = Walker::new(&design.ops);
        let linear = walker
            .steps()
            .iter()
            .map(|o| o.ink().unwrap_or(design.background).to_linear())
            .collect();
        Self {
            walker,
            linear,
            background: design.background.to_linear(),
            surface: Surface::new(design),
        }
    }

    /// The linear colour design point `p` shows (noise or image background and grain
    /// included) and its source: the covering op's index, or [`SOURCE_BACKGROUND`].
    pub fn at(&self, p: Point, scratch: &mut PointScratch) -> ([f32; 3], u32) {
        let Some(surface) = &self.surface else {
            return match self.walker.trace(p) {
                Traced::Ink(k) => (self.linear[k], k as u32),
                Traced::Background(_) => (self.background, SOURCE_BACKGROUND),
            };
        };
        scratch.batch.clear();
        scratch.batch.push(p.x, p.y, 0);
        self.walker.trace_batch_with_ends(
            &mut scratch.batch,
            &mut scratch.traced,
            &mut scratch.ends,
        );
        let end = scratch.ends[0];
        let (base, source) = match scratch.traced[0] {
            Traced::Ink(k) => (self.linear[k], k as u32),
            Traced::Background(q) => (surface.background(q.x, q.y), SOURCE_BACKGROUND),
        };
        (surface.overlay(base, (p.x, p.y), (end.x, end.y)), source)
    }
}
