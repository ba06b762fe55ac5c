//! Forward tracing of a whole design: every drop and spray, in parallel over regions.

use crate::forward::{ForwardStep, compile};
use crate::refine::Refiner;
use crate::simplify::simplify_outline;
use crate::{
    Canvas, MARGIN_PX, Outline, TraceOptions, TraceStats, VectorDesign, VectorError, initial_sides,
};
use marbling_core::{Design, Op, Point, Rgb8};
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Checks that `design` is exactly a background rectangle plus traced ink regions.
///
/// Every schema-v1 design is: its background is one plain colour and its seven op types
/// are drops and sprays (regions) and homeomorphic deformations (forward maps). Schema
/// v2 noise backgrounds and grain overlays are refused here with a message naming them
/// ([`VectorError::RasterOnly`]), before anything is traced or written.
pub fn check_traceable(design: &Design) -> Result<(), VectorError> {
    if design.width == 0 || design.height == 0 {
        return Err(VectorError::Untraceable(format!(
            "empty canvas {}×{}",
            design.width, design.height
        )));
    }
    let mut raster_only = Vec::new();
    if design.background_noise.is_some() {
        raster_only.push("a noise background".to_owned());
    }
    if !design.overlays.is_empty() {
        raster_only.push(format!("{} grain overlay(s)", design.overlays.len()));
    }
    if !raster_only.is_empty() {
        return Err(VectorError::RasterOnly(raster_only.join(" and ")));
    }
    Ok(())
}

/// Traces every drop and spray of `design` forward through all later ops.
pub fn trace(design: &Design, opts: &TraceOptions) -> Result<VectorDesign, VectorError> {
    trace_with_progress(design, opts, &|_, _| {})
}

/// As [`trace`], calling `progress(done, total)` (regions, from any thread).
pub fn trace_with_progress(
    design: &Design,
    opts: &TraceOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<VectorDesign, VectorError> {
    opts.validate()?;
    check_traceable(design)?;
    let canvas = Canvas::new(
        f64::from(design.width),
        f64::from(design.height),
        MARGIN_PX / opts.scale,
    );
    let ink: Vec<Ink> = design
        .ops
        .iter()
        .enumerate()
        .filter_map(|(k, op)| match *op {
            Op::Drop(d) => Some((k, d.center, d.radius, d.color)),
            Op::Spray(s) => Some((k, s.center, s.radius, s.color)),
            _ => None,
        })
        .collect();
    let steps = compile(&design.ops);
    let used = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let traced: Vec<(Option<Outline>, TraceStats)> = ink
        .par_iter()
        .with_max_len(1)
        .map(|&ink_op| {
            let r = trace_region(&steps, ink_op, opts, &canvas, &used);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, ink.len());
            r
        })
        .collect::<Result<_, _>>()?;
    let mut stats = TraceStats::default();
    let mut outlines = Vec::with_capacity(traced.len());
    for (outline, s) in traced {
        stats += s;
        outlines.extend(outline);
    }
    Ok(VectorDesign {
        width: design.width,
        height: design.height,
        background: design.background,
        outlines,
        tolerance: opts.tolerance,
        scale: opts.scale,
        stats,
    })
}

/// A drop or spray: op index, centre, radius (design pixels), colour.
type Ink = (usize, Point, f64, Rgb8);

/// Traces one drop or spray of `design`; `None` when it is invisible.
fn trace_region(
    steps: &[ForwardStep],
    (k, center, radius, color): Ink,
    opts: &TraceOptions,
    canvas: &Canvas,
    used: &AtomicUsize,
) -> Result<(Option<Outline>, TraceStats), VectorError> {
    let spacing = opts.spacing();
    let refiner = Refiner {
        ops: &steps[k + 1..],
        center,
        radius,
        spacing,
        deviation: spacing / 4.0,
        canvas: opts.simplify.then_some(*canvas),
        max_depth: opts.max_depth,
        max_vertices: opts.max_vertices,
    };
    let sides = initial_sides(radius * opts.scale, opts.tolerance);
    let refined = refiner.refine(sides)?;
    let total = used.fetch_add(refined.points.len(), Ordering::Relaxed) + refined.points.len();
    if total > opts.max_vertices {
        return Err(VectorError::TooComplex {
            limit: opts.max_vertices,
        });
    }
    let points = if opts.simplify {
        simplify_outline(&refined.points, canvas, spacing / 4.0)
    } else {
        refined.points.clone()
    };
    let stats = TraceStats {
        regions: 1,
        culled: usize::from(points.is_empty()),
        initial_vertices: sides,
        refined_vertices: refined.points.len(),
        vertices: points.len(),
        capped: refined.capped,
        mapped_points: refined.mapped,
    };
    let outline = (!points.is_empty()).then_some(Outline {
        op_index: k,
        color,
        points,
    });
    Ok((outline, stats))
}
