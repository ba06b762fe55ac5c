//! Forward tracing of a whole design, op by op: every drop and spray becomes a region
//! whose rings are carried through each later op, refined where that op stretched or
//! bent them, and (the lossy step) pinched apart and thinned out where they became
//! thinner than the tolerance allows to matter.

use crate::contour::{ContourJob, label_walk};
use crate::curve::Curve;
use crate::labels::LabelWalk;
use crate::pinch::{Pinch, PinchCount};
use crate::ring::{Node, Refine, RefineCount, carry, initial_ring, reanchor};
use crate::simplify::simplify_outline;
use crate::surface_layers::RasterLayer;
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

/// As [`trace`], calling `progress(done, total)` (units of work done, from this
/// thread): one unit per op traced forward and per row of the label raster.
pub fn trace_with_progress(
    design: &Design,
    opts: &TraceOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<VectorDesign, VectorError> {
    let mut tracer = Tracer::new(design.clone(), opts)?;
    while !tracer.step()? {
        let (done, total) = tracer.progress();
        progress(done, total);
    }
    tracer.finish()
}

/// A trace of a whole design done a step at a time ([`Tracer::advance`] within a time
/// budget), so that the app's Export SVG keeps the page responsive and can be
/// cancelled by dropping it; [`trace`] runs it whole. A step is one op traced forward,
/// the simplification of every traced region, the raster layers, a batch of label
/// rows, or the contour method's outlines.
pub struct Tracer {
    design: Design,
    opts: TraceOptions,
    ops: Vec<CompiledOp>,
    canvas: Canvas,
    /// Most vertices held at once before the budget's tail growth.
    budget: usize,
    pinch: Option<Pinch>,
    regions: Vec<Region>,
    /// Regions handed to the contour method, by compiled op index.
    handed: Vec<usize>,
    peak: usize,
    /// Ops traced forward: all of them, or none when every region is contoured.
    forward_ops: usize,
    /// Rows of the finished label raster (coarse and fine), and once the contour method
    /// is done, its parts too.
    label_rows: usize,
    outlines: Vec<Outline>,
    stats: TraceStats,
    underlay: Option<RasterLayer>,
    grain: Option<RasterLayer>,
    dense: Option<RasterLayer>,
    stage: Stage,
}

/// Where a [`Tracer`] stands.
enum Stage {
    /// Tracing forward: carrying the regions from `region` on through op `op`.
    Forward {
        op: usize,
        region: usize,
    },
    /// Simplifying the traced regions.
    Finish,
    /// Rendering the noise underlay and grain.
    Layers,
    /// Walking the contour method's label raster.
    Labels(Box<LabelWalk>),
    /// Reading the handed regions' outlines off the finished raster.
    Contour(Box<ContourJob>),
    Done,
}

impl Tracer {
    /// Starts tracing `design`; refuses bad options and an empty canvas at once.
    pub fn new(design: Design, opts: &TraceOptions) -> Result<Self, VectorError> {
        opts.validate()?;
        check_traceable(&design)?;
        let canvas = Canvas::new(
            f64::from(design.width),
            f64::from(design.height),
            MARGIN_PX / opts.scale,
        );
        let ops = CompiledOp::compile(&design.ops);
        let spacing = opts.spacing();
        // Finer tolerances need more vertices for the same picture: the budget grows as
        // 1/T below T = 1.
        let budget =
            (opts.max_live as f64 / opts.tolerance.min(1.0)).min(usize::MAX as f64) as usize;
        let pinch = (opts.thin > 0.0).then(|| {
            let width = spacing * opts.thin;
            Pinch {
                width,
                separation: (4.0 * width).max(2.0 * spacing * opts.chord),
                reach: spacing * opts.chord,
                op: 0,
            }
        });
        // All regions go to the contour method when the label raster is cheap (it is
        // the more faithful: it grows older ink under newer and places edges for sRGB
        // blending).
        let contour_all = raster_cost(&design, &ops, opts) <= opts.contour_all;
        let handed = if contour_all {
            ops.iter()
                .enumerate()
                .filter_map(|(j, op)| op.ink().map(|_| j))
                .collect()
        } else {
            Vec::new()
        };
        let stage = if contour_all || ops.is_empty() {
            Stage::Finish
        } else {
            Stage::Forward { op: 0, region: 0 }
        };
        let forward_ops = if matches!(stage, Stage::Forward { .. }) {
            ops.len()
        } else {
            0
        };
        Ok(Self {
            design,
            opts: *opts,
            ops,
            canvas,
            budget,
            pinch,
            regions: Vec::new(),
            handed,
            peak: 0,
            forward_ops,
            label_rows: 0,
            outlines: Vec::new(),
            stats: TraceStats::default(),
            underlay: None,
            grain: None,
            dense: None,
            stage,
        })
    }

    /// Steps until `now()` passes `budget_ms` from the start (at least one step);
    /// `Ok(true)` when the trace is complete.
    pub fn advance(&mut self, budget_ms: f64, now: impl Fn() -> f64) -> Result<bool, VectorError> {
        let start = now();
        loop {
            if self.step()? {
                return Ok(true);
            }
            if now() - start > budget_ms {
                return Ok(false);
            }
        }
    }

    /// Units of work done and in all as known now (the label raster's rows join the
    /// total when forward tracing hands regions over).
    pub fn progress(&self) -> (usize, usize) {
        let forward = self.forward_ops;
        let done_forward = match self.stage {
            Stage::Forward { op, .. } => op,
            _ => forward,
        };
        let (rows_done, rows) = match &self.stage {
            Stage::Labels(walk) => walk.rows(),
            Stage::Contour(job) => {
                let (done, all) = job.parts();
                (self.label_rows + done, self.label_rows + all)
            }
            Stage::Done => (self.label_rows, self.label_rows),
            _ => (0, usize::from(!self.handed.is_empty())),
        };
        (done_forward + rows_done, forward + rows)
    }

    /// Does one step; `Ok(true)` when the trace is complete.
    pub fn step(&mut self) -> Result<bool, VectorError> {
        match std::mem::replace(&mut self.stage, Stage::Done) {
            Stage::Forward { op, region } => {
                self.stage = if let Some(region) = self.forward(op, region)? {
                    Stage::Forward { op, region }
                } else if op + 1 < self.ops.len() {
                    Stage::Forward {
                        op: op + 1,
                        region: 0,
                    }
                } else {
                    Stage::Finish
                };
            }
            Stage::Finish => {
                self.stage = if self.finish_regions() {
                    Stage::Layers
                } else {
                    Stage::Finish
                };
            }
            Stage::Layers => {
                (self.underlay, self.grain) = surface_layers(&self.design, self.opts.scale)?;
                self.stage = if self.handed.is_empty() {
                    Stage::Done
                } else {
                    Stage::Labels(Box::new(label_walk(
                        &self.design,
                        &self.ops,
                        &self.handed,
                        &self.opts,
                    )))
                };
            }
            Stage::Labels(mut walk) => {
                self.stage = if walk.step() {
                    self.label_rows = walk.rows().1;
                    let underlay = self.underlay.as_ref().map(|l| &l.image);
                    Stage::Contour(Box::new(ContourJob::new(
                        walk.finish_now(),
                        &self.design,
                        &self.ops,
                        &self.handed,
                        &self.opts,
                        underlay,
                    )?))
                } else {
                    Stage::Labels(walk)
                };
            }
            Stage::Contour(mut job) => {
                if job.step(PARTS_PER_STEP * rayon::current_num_threads()) {
                    self.label_rows += job.parts().1;
                    let contoured = job.finish();
                    self.stats += contoured.stats;
                    self.outlines.extend(contoured.outlines);
                    self.outlines.sort_by_key(|o| o.op_index);
                    self.dense = contoured.dense;
                } else {
                    self.stage = Stage::Contour(job);
                }
            }
            Stage::Done => {}
        }
        Ok(matches!(self.stage, Stage::Done))
    }

    /// The traced design; call once [`Tracer::step`] has returned true.
    pub fn finish(self) -> Result<VectorDesign, VectorError> {
        if !matches!(self.stage, Stage::Done) {
            return Err(VectorError::Untraceable("the trace is not complete".into()));
        }
        Ok(VectorDesign {
            width: self.design.width,
            height: self.design.height,
            background: self.design.background,
            outlines: self.outlines,
            underlay: self.underlay,
            dense: self.dense,
            grain: self.grain,
            tolerance: self.opts.tolerance,
            scale: self.opts.scale,
            stats: self.stats,
        })
    }

    /// Carries the regions from `from` on through op `j`, as many as hold about
    /// [`VERTICES_PER_STEP`] vertices per thread, and returns where to go on; after the
    /// last region lays a new one if `j` lays ink and hands the costliest regions to
    /// the contour method when too many vertices are held.
    fn forward(&mut self, j: usize, from: usize) -> Result<Option<usize>, VectorError> {
        let opts = &self.opts;
        let spacing = opts.spacing();
        let refine = Refine {
            ops: &self.ops,
            spacing: spacing * opts.chord,
            deviation: spacing * opts.deviation,
            canvas: opts.simplify.then_some(self.canvas),
            min_fraction: 0.5f64.powi(opts.max_depth as i32) / 8.0,
        };
        let pinch_j = self.pinch.map(|p| Pinch { op: j, ..p });
        let most = VERTICES_PER_STEP * rayon::current_num_threads();
        let mut to = from;
        let mut held = 0;
        while to < self.regions.len() && held < most {
            held += self.regions[to].vertices();
            to += 1;
        }
        self.regions[from..to]
            .par_iter_mut()
            .with_max_len(1)
            .for_each(|r| {
                r.advance(j, &refine, opts.anchor as usize);
                r.pinch(pinch_j.as_ref(), false);
            });
        if to < self.regions.len() {
            return Ok(Some(to));
        }
        // Compiled ops: a drop pattern is one disc per drop, each a region of its own.
        if let CompiledOp::Disc {
            cx, cy, r2, color, ..
        } = self.ops[j]
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
            self.regions.push(region);
        }
        let mut total = self.regions.iter().map(Region::vertices).sum::<usize>();
        self.peak = self.peak.max(total);
        // Finishing costs the vertices held times the ops left: near the end a design
        // may hold more before regions are handed over.
        let left = self.ops.len() - j;
        let budget = self.budget.saturating_mul((TAIL / left).max(1));
        if total > budget {
            // The costliest regions go to the contour method until half the budget is
            // held: their raster outlines cost what their visible boundary costs.
            self.regions
                .sort_by_key(|r| std::cmp::Reverse(r.vertices()));
            let mut hand = 0;
            while hand < self.regions.len() && total > budget / 2 {
                total -= self.regions[hand].vertices();
                hand += 1;
            }
            self.handed
                .extend(self.regions.drain(..hand).map(|r| r.op_index));
            self.regions.sort_by_key(|r| r.op_index);
        }
        check_total(self.peak, opts).map(|()| None)
    }

    /// Simplifies the oldest traced regions, as many as hold about
    /// [`VERTICES_PER_STEP`] vertices per thread, into their outlines; true when none
    /// is left.
    fn finish_regions(&mut self) -> bool {
        let (opts, canvas) = (&self.opts, &self.canvas);
        let last = self.ops.len().saturating_sub(1);
        let epsilon = opts.spacing() * opts.epsilon;
        let pinch = self.pinch;
        let most = VERTICES_PER_STEP * rayon::current_num_threads();
        let (mut count, mut held) = (0, 0);
        while count < self.regions.len() && held < most {
            held += self.regions[count].vertices();
            count += 1;
        }
        let traced: Vec<(Option<Outline>, TraceStats)> = self
            .regions
            .drain(..count)
            .collect::<Vec<_>>()
            .into_par_iter()
            .with_max_len(1)
            .map(|mut r| {
                r.pinch(pinch.map(|p| Pinch { op: last, ..p }).as_ref(), true);
                finish(r, opts, canvas, epsilon)
            })
            .collect();
        self.stats.peak_vertices = self.peak;
        for (outline, s) in traced {
            self.stats += s;
            self.outlines.extend(outline);
        }
        self.regions.is_empty()
    }
}

/// The op-samples the contour method's label raster would cost if every grid point
/// were walked: grid points times the mean cost of a walk, measured on a 64 × 64
/// lattice of probes (a walk ends at the newest ink covering it; each op costs its
/// [`CompiledOp::walk_cost`]).
fn raster_cost(design: &Design, ops: &[CompiledOp], opts: &TraceOptions) -> f64 {
    let step = opts.spacing() * opts.contour_step;
    let (w, h) = (f64::from(design.width), f64::from(design.height));
    let samples = w * h / (step * step);
    // cost[k]: the units of walking ops k.. (newest first down to k).
    let mut cost = vec![0.0; ops.len() + 1];
    for (k, op) in ops.iter().enumerate().rev() {
        cost[k] = cost[k + 1] + op.walk_cost() as f64;
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

/// Vertices carried per step and thread while tracing forward: a few milliseconds of
/// work natively (a region is never split, so a step may hold more).
const VERTICES_PER_STEP: usize = 1_000;

/// Contour tiles (64² cells) or regions per step and thread of the contour method: a
/// few milliseconds of work natively.
const PARTS_PER_STEP: usize = 8;

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
