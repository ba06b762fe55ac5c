//! Forward tracing of a whole design, op by op: every drop and spray becomes a region
//! whose rings are carried through each later op, refined where that op stretched or
//! bent them, and (the lossy step) pinched apart and thinned out where they became
//! thinner than the tolerance allows to matter.

use crate::contour::contour_outlines;
use crate::curve::Curve;
use crate::pinch::{Pinch, PinchCount};
use crate::ring::{Node, Refine, RefineCount, carry, initial_ring, reanchor};
use crate::simplify::simplify_outline;
use crate::surface_layers::surface_layers;
use crate::{
    Canvas, MARGIN_PX, Method, Outline, TraceOptions, TraceStats, VectorDesign, VectorError,
    initial_sides,
};
use marbling_core::{CompiledOp, Design, Point, Rgb8, Traced, Walker};
use rayon::prelude::*;

/// Checks that `design` has a canvas to trace on. Every design can be exported: drops
/// and sprays become regions, the deformations forward maps, and a schema v2 noise
/// background or grain overlay becomes a raster layer ([`crate::surface_layers`]).
pub fn check_traceable(design: &Design) -> Result<(), VectorError> {
    if design.width == 0 || design.height == 0 {
        return Err(VectorError::Untraceable(format!(
            "empty canvas {}×{}",
            design.width, design.height
        )));
    }
    Ok(())
}

/// Traces every drop and spray of `design` forward through all later ops.
pub fn trace(design: &Design, opts: &TraceOptions) -> Result<VectorDesign, VectorError> {
    trace_with_progress(design, opts, &|_, _| {})
}

/// One drop or spray being traced.
struct Region {
    /// Index of the op that laid the ink.
    op_index: usize,
    /// Ink colour.
    color: Rgb8,
    /// Source curves of its rings' segments: the rim, then cuts.
    curves: Vec<Curve>,
    /// Closed rings; the region is their union under the nonzero rule.
    rings: Vec<Vec<Node>>,
    /// The op after which its segments were last re-anchored (or the ink was laid).
    anchored_at: usize,
    /// Vertices when the lossy step last ran on this region.
    pinched_at: usize,
    /// Vertices of the initial n-gon.
    initial: usize,
    /// What refinement did.
    refined: RefineCount,
    /// What the lossy step did.
    pinched: PinchCount,
}

impl Region {
    fn vertices(&self) -> usize {
        self.rings.iter().map(Vec::len).sum()
    }

    /// Carries the rings through op `j` and refines them; re-anchors them when `anchor`
    /// ops (> 0) have passed since the last time.
    fn advance(&mut self, j: usize, refine: &Refine, anchor: usize) {
        let op = &refine.ops[j];
        for ring in &mut self.rings {
            carry(ring, op);
            *ring = refine.refine(&self.curves, ring, j, &mut self.refined);
        }
        if anchor > 0 && j >= self.anchored_at + anchor {
            self.curves = reanchor(&mut self.rings, j);
            self.anchored_at = j;
        }
    }

    /// The lossy step on every ring, when the vertex count grew by half since it
    /// last ran (or `force`).
    fn pinch(&mut self, pinch: Option<&Pinch>, force: bool) {
        let Some(pinch) = pinch else { return };
        let n = self.vertices();
        if !force && n < 64.max(self.pinched_at + self.pinched_at / 2) {
            return;
        }
        let mut out = Vec::with_capacity(self.rings.len());
        for ring in std::mem::take(&mut self.rings) {
            pinch.apply(ring, &mut self.curves, &mut out, &mut self.pinched);
        }
        self.rings = out;
        self.pinched_at = self.vertices();
    }
}

/// As [`trace`], calling `progress(done, total)` (ops processed, from this thread).
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
    let ops = CompiledOp::compile(&design.ops);
    let spacing = opts.spacing();
    let refine = Refine {
        ops: &ops,
        spacing: spacing * opts.chord,
        deviation: spacing * opts.deviation,
        canvas: opts.simplify.then_some(canvas),
        min_fraction: 0.5f64.powi(opts.max_depth as i32) / 8.0,
    };
    // Finer tolerances need more vertices for the same picture: the budget grows as 1/T
    // below T = 1.
    let budget = (opts.max_live as f64 / opts.tolerance.min(1.0)).min(usize::MAX as f64) as usize;
    let pinch = (opts.thin > 0.0).then(|| {
        let width = spacing * opts.thin;
        Pinch {
            width,
            separation: (4.0 * width).max(2.0 * spacing * opts.chord),
            reach: spacing * opts.chord,
            op: 0,
        }
    });
    let mut regions: Vec<Region> = Vec::new();
    // Regions handed to the contour method, by compiled op index: all of them when the
    // label raster is cheap (the contour method is the more faithful: it grows older
    // ink under newer and places edges for sRGB blending).
    let mut handed: Vec<usize> = Vec::new();
    let contour_all = raster_cost(design, &ops, opts) <= opts.contour_all;
    if contour_all {
        handed.extend(
            ops.iter()
                .enumerate()
                .filter_map(|(j, op)| op.ink().map(|_| j)),
        );
    }
    let mut peak = 0;
    // Compiled ops: a drop pattern is one disc per drop, each a region of its own.
    for (j, op) in ops.iter().enumerate().filter(|_| !contour_all) {
        let pinch_j = pinch.map(|p| Pinch { op: j, ..p });
        regions.par_iter_mut().with_max_len(1).for_each(|r| {
            r.advance(j, &refine, opts.anchor as usize);
            r.pinch(pinch_j.as_ref(), false);
        });
        if let CompiledOp::Disc {
            cx, cy, r2, color, ..
        } = *op
        {
            let (center, radius) = (Point::new(cx, cy), r2.sqrt());
            let rim = Curve::Circle {
                center,
                radius,
                op: j,
            };
            let sides = initial_sides(radius * opts.scale, opts.tolerance);
            let mut region = Region {
                op_index: j,
                color,
                curves: vec![rim],
                rings: vec![initial_ring(&rim, 0, sides)],
                anchored_at: j,
                pinched_at: 0,
                initial: sides,
                refined: RefineCount::default(),
                pinched: PinchCount::default(),
            };
            region.rings[0] =
                refine.refine(&region.curves, &region.rings[0], j, &mut region.refined);
            regions.push(region);
        }
        let mut total = regions.iter().map(Region::vertices).sum::<usize>();
        peak = peak.max(total);
        // Finishing costs the vertices held times the ops left: near the end a design
        // may hold more before regions are handed over.
        let left = ops.len() - j;
        let budget = budget.saturating_mul((TAIL / left).max(1));
        if total > budget {
            // The costliest regions go to the contour method until half the budget is
            // held: their raster outlines cost what their visible boundary costs.
            regions.sort_by_key(|r| std::cmp::Reverse(r.vertices()));
            let mut hand = 0;
            while hand < regions.len() && total > budget / 2 {
                total -= regions[hand].vertices();
                hand += 1;
            }
            handed.extend(regions.drain(..hand).map(|r| r.op_index));
            regions.sort_by_key(|r| r.op_index);
        }
        check_total(peak, opts)?;
        progress(j + 1, ops.len());
    }
    let last = ops.len().saturating_sub(1);
    let epsilon = opts.spacing() * opts.epsilon;
    let traced: Vec<(Option<Outline>, TraceStats)> = regions
        .into_par_iter()
        .with_max_len(1)
        .map(|mut r| {
            r.pinch(pinch.map(|p| Pinch { op: last, ..p }).as_ref(), true);
            finish(r, opts, &canvas, epsilon)
        })
        .collect();
    let mut stats = TraceStats {
        peak_vertices: peak,
        ..TraceStats::default()
    };
    let mut outlines = Vec::with_capacity(traced.len() + handed.len());
    for (outline, s) in traced {
        stats += s;
        outlines.extend(outline);
    }
    let (underlay, grain) = surface_layers(design, opts.scale)?;
    let mut dense = None;
    if !handed.is_empty() {
        let underlay = underlay.as_ref().map(|l| &l.image);
        let contoured = contour_outlines(design, &ops, &handed, opts, underlay)?;
        stats += contoured.stats;
        outlines.extend(contoured.outlines);
        outlines.sort_by_key(|o| o.op_index);
        dense = contoured.dense;
    }
    Ok(VectorDesign {
        width: design.width,
        height: design.height,
        background: design.background,
        outlines,
        underlay,
        dense,
        grain,
        tolerance: opts.tolerance,
        scale: opts.scale,
        stats,
    })
}

/// The op-samples the contour method's label raster would cost if every grid point
/// were walked: grid points times the mean cost of a walk, measured on a 64 × 64
/// lattice of probes (a walk ends at the newest ink covering it; a finite comb costs one
/// unit per tine, a stylus eight per segment, a jiggle eight, any other op one).
fn raster_cost(design: &Design, ops: &[CompiledOp], opts: &TraceOptions) -> f64 {
    let step = opts.spacing() * opts.contour_step;
    let (w, h) = (f64::from(design.width), f64::from(design.height));
    let samples = w * h / (step * step);
    // cost[k]: the units of walking ops k.. (newest first down to k).
    let mut cost = vec![0.0; ops.len() + 1];
    for (k, op) in ops.iter().enumerate().rev() {
        let units = match op {
            CompiledOp::Tines { offsets, .. } => offsets.len() as f64,
            CompiledOp::Stylus { segments } => 8.0 * segments.len() as f64,
            CompiledOp::Jiggle { .. } => 8.0,
            _ => 1.0,
        };
        cost[k] = cost[k + 1] + units;
    }
    let walker = Walker::new(&design.ops);
    const PROBES: usize = 64;
    let total: f64 = (0..PROBES * PROBES)
        .into_par_iter()
        .map(|i| {
            let (x, y) = ((i % PROBES) as f64 + 0.5, (i / PROBES) as f64 + 0.5);
            let p = Point::new(x * w / PROBES as f64, y * h / PROBES as f64);
            match walker.trace(p) {
                Traced::Ink(k) => cost[k],
                Traced::Background(_) => cost[0],
            }
        })
        .sum();
    samples * total / (PROBES * PROBES) as f64
}

/// Ops before the end from which the vertex budget grows as `TAIL` / ops left.
const TAIL: usize = 16;

/// Refuses a design once its rings hold more than `opts.max_vertices` vertices.
fn check_total(total: usize, opts: &TraceOptions) -> Result<(), VectorError> {
    if total > opts.max_vertices {
        return Err(VectorError::TooComplex {
            limit: opts.max_vertices,
        });
    }
    Ok(())
}

/// Simplifies a traced region's rings; `None` when nothing of it is visible.
fn finish(
    r: Region,
    opts: &TraceOptions,
    canvas: &Canvas,
    epsilon: f64,
) -> (Option<Outline>, TraceStats) {
    let refined = r.vertices();
    let rings: Vec<Vec<kurbo::Point>> = r
        .rings
        .iter()
        .map(|ring| {
            let points: Vec<kurbo::Point> = ring.iter().map(|n| n.p).collect();
            if opts.simplify {
                simplify_outline(&points, canvas, epsilon)
            } else {
                points
            }
        })
        .filter(|ring| ring.len() >= 3)
        .collect();
    let vertices = rings.iter().map(Vec::len).sum();
    let stats = TraceStats {
        regions: 1,
        culled: usize::from(rings.is_empty()),
        initial_vertices: r.initial,
        refined_vertices: refined,
        vertices,
        rings: rings.len(),
        capped: r.refined.capped,
        mapped_points: r.refined.mapped,
        dropped_pieces: r.pinched.dropped,
        dropped_area: r.pinched.area,
        cuts: r.pinched.cuts,
        ..TraceStats::default()
    };
    let outline = (!rings.is_empty()).then_some(Outline {
        op_index: r.op_index,
        color: r.color,
        method: Method::Forward,
        rings,
    });
    (outline, stats)
}
