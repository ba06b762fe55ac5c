//! Deep zoom on the GPU: the per-tile reference records that `shaders/deep.wgsl` walks
//! samples from (layout stated there), made from marbling-core's f64 reference walks
//! ([`ReferenceWalk`]), one per tile of the target.

use crate::encode::{GpuOp, OpLayout, compiled_records};
use marbling_core::deep::{RefStep, ReferenceWalk, UNBOUNDED};
use marbling_core::{Antialias, CompiledOp, Op, Point, Walker};

/// Side of the square tiles that share one reference, output pixels (doubled while the
/// records of every tile would not fit the device's textures).
pub const DEEP_TILE: u32 = 64;

/// Largest error of a sample's position the plain f32 walk may make, output pixels.
pub const F32_TOLERANCE: f64 = 0.05;

/// True when a view at `scale` output pixels per design pixel of a sheet whose longest
/// side is `extent` design pixels needs the deep walk: the f32 walk rounds a sample's
/// design position by up to half an f32 step there, ulp(extent)/2, and beyond
/// [`F32_TOLERANCE`] of a pixel that shows (from about 1,600× on a 640-px sheet, 200×
/// on a 4,096-px one).
pub fn needs_deep(extent: f64, scale: f64) -> bool {
    let ulp = extent.max(1.0).log2().floor().exp2() * f64::from(f32::EPSILON);
    0.5 * ulp * scale > F32_TOLERANCE
}

/// Where a target's pixels lie in the design, in f64: its top-left corner shows design
/// point `origin`, `scale` output pixels per design pixel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeepView {
    /// The design point at the target's top-left corner, design pixels.
    pub origin: Point,
    /// Output pixels per design pixel (> 0).
    pub scale: f64,
    /// The target's width and height, pixels.
    pub size: [u32; 2],
    /// Antialiasing pattern.
    pub antialias: Antialias,
}

/// The reference records of a view, ready to upload.
#[derive(Clone, Debug, PartialEq)]
pub struct DeepRecords {
    /// Tile side, output pixels.
    pub side: u32,
    /// Tiles per row of the target.
    pub tiles_per_row: u32,
    /// Records per tile: the op records and one for the reference's end.
    pub per_tile: u32,
    /// Every tile's records, tile-major.
    pub records: Vec<GpuOp>,
    /// The texture layout they fill.
    pub layout: OpLayout,
}

/// The header record of each reference step of `ops` (one per compiled op; one per
/// segment of a stylus) in the op records [`crate::encode::records`] makes.
pub fn step_slots(ops: &[Op]) -> Vec<usize> {
    let mut slots = Vec::new();
    let mut scratch = Vec::new();
    for op in ops {
        for c in CompiledOp::of(op) {
            let start = scratch.len();
            compiled_records(&c, &mut scratch);
            match &c {
                CompiledOp::Stylus { segments } => {
                    // Tip records, then (H2, H1) per segment.
                    let tips = scratch.len() - start - 2 * segments.len();
                    slots.extend((0..segments.len()).map(|k| start + tips + 2 * k + 1));
                }
                _ => slots.push(scratch.len() - 1),
            }
        }
    }
    slots
}

/// The record of one reference step.
fn step_record(step: &RefStep) -> GpuOp {
    let f = |v: f64| v as f32;
    let at = step.at();
    let mut b = [f(at.x), f(at.y), 0.0, 0.0];
    let a = match *step {
        RefStep::Disc {
            d, excess, rebase, ..
        } => {
            b[2] = f(rebase.x);
            b[3] = f(rebase.y);
            [f(excess), f(d.x), f(d.y), 0.0]
        }
        RefStep::Comb {
            distance,
            kink,
            shape,
            reach,
            ..
        } => [f(distance), f(kink), f(shape), f(reach.min(UNBOUNDED))],
        RefStep::Wave { theta, .. } => [f(theta), 0.0, 0.0, 0.0],
        RefStep::Swirl { d, ring, theta, .. } => [f(d.x), f(d.y), f(ring), f(theta)],
        RefStep::Rigid { .. } => [0.0; 4],
        RefStep::Jiggle { phi, .. } => [f(phi), 0.0, 0.0, 0.0],
        RefStep::Linear {
            jacobian, reach, ..
        } => {
            b[2] = f(reach);
            jacobian.map(f)
        }
    };
    GpuOp { a, b }
}

/// The reference records of `view` over `ops` (whose op records number
/// `op_records`), with tiles as small as `max_side`-texel textures allow; `None` when
/// even one reference per target does not fit.
pub fn deep_records(
    ops: &[Op],
    op_records: usize,
    view: &DeepView,
    max_side: u32,
) -> Option<DeepRecords> {
    let walker = Walker::new(ops);
    let slots = step_slots(ops);
    let per_tile = op_records + 1;
    let [width, height] = view.size;
    let mut side = DEEP_TILE;
    let (cols, rows, layout) = loop {
        let (cols, rows) = (width.div_ceil(side), height.div_ceil(side));
        let total = cols as usize * rows as usize * per_tile;
        if let Some(layout) = OpLayout::for_capacity(total, max_side) {
            break (cols, rows, layout);
        }
        if side >= width.max(height) {
            return None;
        }
        side *= 2;
    };
    let zero = GpuOp {
        a: [0.0; 4],
        b: [0.0; 4],
    };
    let mut records = vec![zero; cols as usize * rows as usize * per_tile];
    let half = 0.5 * f64::from(side) / view.scale;
    for ty in 0..rows {
        for tx in 0..cols {
            let start = Point::new(
                view.origin.x + f64::from(tx * side) / view.scale + half,
                view.origin.y + f64::from(ty * side) / view.scale + half,
            );
            let walk = ReferenceWalk::new(&walker, start);
            let tile = &mut records[(ty * cols + tx) as usize * per_tile..][..per_tile];
            for (step, &slot) in walk.steps.iter().zip(&slots) {
                tile[slot] = step_record(step);
            }
            tile[op_records] = GpuOp {
                a: [walk.end.x as f32, walk.end.y as f32, 0.0, 0.0],
                b: [start.x as f32, start.y as f32, 0.0, 0.0],
            };
        }
    }
    Some(DeepRecords {
        side,
        tiles_per_row: cols,
        per_tile: per_tile as u32,
        records,
        layout,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::records;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn every_step_lands_on_its_ops_header_record() {
        let design = random_design(5, 300, 200, 80, Mix::AllTypes);
        let mut recs = Vec::new();
        for op in &design.ops {
            records(op, &mut recs);
        }
        let slots = step_slots(&design.ops);
        let walk = ReferenceWalk::new(&Walker::new(&design.ops), Point::new(150.0, 100.0));
        assert_eq!(slots.len(), walk.steps.len());
        for (&slot, step) in slots.iter().zip(&walk.steps) {
            let kind = recs[slot].kind();
            let expected = match step {
                RefStep::Disc { .. } => "drop or spray",
                RefStep::Comb { .. } => "comb or tines",
                RefStep::Wave { .. } => "wave",
                RefStep::Swirl { .. } => "swirl",
                RefStep::Rigid { .. } => "rigid",
                RefStep::Jiggle { .. } => "jiggle",
                RefStep::Linear { .. } => "stylus or flow",
            };
            use marbling_core::OpKind as K;
            let ok = matches!(
                (expected, kind),
                ("drop or spray", Some(K::Drop | K::Spray))
                    | ("comb or tines", Some(K::Comb | K::Tines))
                    | ("wave", Some(K::Wave))
                    | ("swirl", Some(K::Circular | K::Vortex))
                    | ("rigid", Some(K::Rigid))
                    | ("jiggle", Some(K::Jiggle))
                    | ("stylus or flow", Some(K::Stylus | K::Flow))
            );
            assert!(ok, "record {slot}: a {expected} step on a {kind:?} record");
        }
    }

    #[test]
    fn deep_starts_where_f32_steps_pass_a_twentieth_of_a_pixel() {
        assert!(!needs_deep(640.0, 1600.0) && needs_deep(640.0, 1700.0));
        assert!(!needs_deep(4096.0, 200.0) && needs_deep(4096.0, 210.0));
        assert!(!needs_deep(640.0, 1.0));
    }

    #[test]
    fn tiles_grow_until_the_records_fit() {
        let design = random_design(6, 300, 200, 50, Mix::Mixed);
        let mut recs = Vec::new();
        for op in &design.ops {
            records(op, &mut recs);
        }
        let view = DeepView {
            origin: Point::new(10.0, 10.0),
            scale: 1e5,
            size: [640, 480],
            antialias: Antialias::None,
        };
        let roomy = deep_records(&design.ops, recs.len(), &view, 8192);
        let tight = deep_records(&design.ops, recs.len(), &view, 64);
        assert_eq!(roomy.as_ref().map(|r| r.side), Some(DEEP_TILE));
        assert!(
            tight.as_ref().is_some_and(|r| r.side > DEEP_TILE),
            "{:?}",
            tight.map(|r| r.side)
        );
    }
}
