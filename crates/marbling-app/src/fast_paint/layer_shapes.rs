//! The shapes of one egui layer painted so far this pass: how many, a range of them, and
//! replacing a range by one shape (the panel cache's copies, the flat overlay).

use egui::epaint::ClippedShape;
use egui::{LayerId, Rect, Shape};
use std::ops::Range;

/// The number of shapes painted so far this pass on `layer` (the index the next one
/// gets).
pub(crate) fn count(ctx: &egui::Context, layer: LayerId) -> usize {
    ctx.graphics(|g| g.get(layer).map_or(0, |l| l.next_idx().0))
}

/// Copies of the shapes `range` of `layer`.
pub(crate) fn get(ctx: &egui::Context, layer: LayerId, range: Range<usize>) -> Vec<ClippedShape> {
    ctx.graphics(|g| {
        g.get(layer).map_or_else(Vec::new, |list| {
            list.all_entries()
                .skip(range.start)
                .take(range.len())
                .cloned()
                .collect()
        })
    })
}

/// Replaces the shapes `range` of `layer` by `shape` clipped to `clip`, painted where
/// the first of them was.
pub(crate) fn replace(
    ctx: &egui::Context,
    layer: LayerId,
    range: Range<usize>,
    clip: Rect,
    shape: Shape,
) {
    ctx.graphics_mut(|g| {
        let list = g.entry(layer);
        for i in range.clone() {
            list.reset_shape(egui::layers::ShapeIdx(i));
        }
        list.set(egui::layers::ShapeIdx(range.start), clip, shape);
    });
}
