//! The inverse walk: every sample goes back through the ops newest → oldest until an ink
//! drop or spray covers it or it reaches the background. This is the hot path of the CPU
//! reference renderer, so ops are precompiled into [`CompiledOp`]s and samples are
//! processed op-major in batches (one op over many samples, which keeps the op's
//! constants in registers and lets the compiler vectorise the combs).

use crate::Op;
use crate::compiled::{
    CompiledOp, comb_shift, drop_back, jiggle_back, rigid_move, swirl_turn, tines_shift, wave_shift,
};
use kurbo::Point;

/// Where a sample's walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Traced {
    /// Covered by the ink of compiled op number `usize` (an index into
    /// [`Walker::steps`]; the same as into `Design::ops` for designs without drop
    /// patterns).
    Ink(usize),
    /// Reached the background at this (back-traced) design point.
    Background(Point),
}

/// A design's ops compiled for fast inverse walks.
#[derive(Clone, Debug)]
pub struct Walker {
    steps: Vec<CompiledOp>,
}

/// Samples of one batch, structure-of-arrays; `ids` name each sample's slot in the
/// caller's output. Reused between batches to avoid allocation.
#[derive(Default, Debug)]
pub struct Batch {
    /// Design x of each live sample.
    pub xs: Vec<f64>,
    /// Design y of each live sample.
    pub ys: Vec<f64>,
    /// Output slot of each live sample.
    pub ids: Vec<u32>,
}

impl Batch {
    /// Empties the batch, keeping its memory.
    pub fn clear(&mut self) {
        self.xs.clear();
        self.ys.clear();
        self.ids.clear();
    }

    /// Adds a sample at design point (x, y) whose result goes to slot `id`.
    pub fn push(&mut self, x: f64, y: f64, id: u32) {
        self.xs.push(x);
        self.ys.push(y);
        self.ids.push(id);
    }
}

impl Walker {
    /// Compiles `ops` (oldest first).
    pub fn new(ops: &[Op]) -> Self {
        Self {
            steps: CompiledOp::compile(ops),
        }
    }

    /// The compiled ops, oldest first (a drop pattern has one per drop).
    pub fn steps(&self) -> &[CompiledOp] {
        &self.steps
    }

    /// Number of compiled ops.
    pub fn len(&self) -> usize {
        self.steps.len()
    }

    /// True when there are no ops.
    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    /// Walks one design point back through every op.
    pub fn trace(&self, p: Point) -> Traced {
        let (mut x, mut y) = (p.x, p.y);
        for (k, s) in self.steps.iter().enumerate().rev() {
            match *s {
                CompiledOp::Disc {
                    cx, cy, r2, deform, ..
                } => {
                    let (dx, dy) = (x - cx, y - cy);
                    let d2 = dx * dx + dy * dy;
                    if d2 < r2 {
                        return Traced::Ink(k);
                    }
                    if deform {
                        (x, y) = drop_back(cx, cy, r2, dx, dy, d2);
                    }
                }
                CompiledOp::Comb { .. } => (x, y) = comb_shift(x, y, s, -1.0),
                CompiledOp::Wave { .. } => (x, y) = wave_shift(x, y, s, -1.0),
                CompiledOp::Swirl { .. } => (x, y) = swirl_turn(x, y, s, -1.0),
                CompiledOp::Rigid { .. } => (x, y) = rigid_move(x, y, s, -1.0),
                CompiledOp::Tines { .. } => (x, y) = tines_shift(x, y, s, -1.0),
                CompiledOp::Jiggle { .. } | CompiledOp::Stylus { .. } | CompiledOp::Flow { .. } => {
                    let q = s.inverse(Point::new(x, y)).unwrap_or_default();
                    (x, y) = (q.x, q.y);
                }
            }
        }
        Traced::Background(Point::new(x, y))
    }

    /// Walks every sample of `batch` back through every op, op-major, writing each
    /// result to `out[id]`. The batch is consumed (left empty).
    pub fn trace_batch(&self, batch: &mut Batch, out: &mut [Traced]) {
        self.trace_batch_impl::<false>(batch, out, &mut []);
    }

    /// As [`Walker::trace_batch`], and also writes to `ends[id]` the design point where
    /// each walk ended: the back-traced point for the background, or the point (in the
    /// coordinates just after that op) that the covering drop or spray's ink holds.
    /// Pigment grain is sampled there, so it moves with the ink.
    pub fn trace_batch_with_ends(&self, batch: &mut Batch, out: &mut [Traced], ends: &mut [Point]) {
        self.trace_batch_impl::<true>(batch, out, ends);
    }

    #[inline(always)]
    fn trace_batch_impl<const ENDS: bool>(
        &self,
        batch: &mut Batch,
        out: &mut [Traced],
        ends: &mut [Point],
    ) {
        let Batch { xs, ys, ids } = batch;
        for (k, s) in self.steps.iter().enumerate().rev() {
            if ids.is_empty() {
                break;
            }
            match *s {
                CompiledOp::Disc {
                    cx, cy, r2, deform, ..
                } => {
                    // Compact the batch: covered samples leave it with this op's ink.
                    let mut j = 0;
                    for i in 0..ids.len() {
                        let (dx, dy) = (xs[i] - cx, ys[i] - cy);
                        let d2 = dx * dx + dy * dy;
                        if d2 < r2 {
                            out[ids[i] as usize] = Traced::Ink(k);
                            if ENDS {
                                ends[ids[i] as usize] = Point::new(xs[i], ys[i]);
                            }
                            continue;
                        }
                        let (x, y) = if deform {
                            drop_back(cx, cy, r2, dx, dy, d2)
                        } else {
                            (xs[i], ys[i])
                        };
                        xs[j] = x;
                        ys[j] = y;
                        ids[j] = ids[i];
                        j += 1;
                    }
                    xs.truncate(j);
                    ys.truncate(j);
                    ids.truncate(j);
                }
                CompiledOp::Comb { .. } => apply(xs, ys, |x, y| comb_shift(x, y, s, -1.0)),
                CompiledOp::Wave { .. } => apply(xs, ys, |x, y| wave_shift(x, y, s, -1.0)),
                CompiledOp::Swirl { .. } => apply(xs, ys, |x, y| swirl_turn(x, y, s, -1.0)),
                CompiledOp::Rigid { .. } => apply(xs, ys, |x, y| rigid_move(x, y, s, -1.0)),
                CompiledOp::Tines { .. } => apply(xs, ys, |x, y| tines_shift(x, y, s, -1.0)),
                CompiledOp::Jiggle { .. } => apply(xs, ys, |x, y| {
                    let q = jiggle_back(Point::new(x, y), s);
                    (q.x, q.y)
                }),
                CompiledOp::Flow { ref field } => apply(xs, ys, |x, y| {
                    let q = field.inverse(Point::new(x, y));
                    (q.x, q.y)
                }),
                CompiledOp::Stylus { ref segments } => {
                    for seg in segments.iter().rev() {
                        apply(xs, ys, |x, y| {
                            let q = seg.inverse(Point::new(x, y));
                            (q.x, q.y)
                        });
                    }
                }
            }
        }
        for i in 0..ids.len() {
            out[ids[i] as usize] = Traced::Background(Point::new(xs[i], ys[i]));
            if ENDS {
                ends[ids[i] as usize] = Point::new(xs[i], ys[i]);
            }
        }
        batch.clear();
    }
}

#[inline(always)]
fn apply(xs: &mut [f64], ys: &mut [f64], f: impl Fn(f64, f64) -> (f64, f64)) {
    for (x, y) in xs.iter_mut().zip(ys.iter_mut()) {
        (*x, *y) = f(*x, *y);
    }
}
