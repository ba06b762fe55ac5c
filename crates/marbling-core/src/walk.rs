//! The inverse walk: every sample goes back through the ops newest → oldest until an ink
//! drop or spray covers it or it reaches the background. This is the hot path of the CPU
//! reference renderer, so ops are precompiled into [`CompiledOp`]s and samples are
//! processed op-major in batches (one op over many samples, which keeps the op's
//! constants in registers and lets the compiler vectorise the kernels: they have no
//! calls and no branches but selects, `compiled/trig.rs` giving sine and cosine).
//!
//! On x86-64 the batch walk is compiled twice, for the baseline (SSE2: two f64 lanes) and
//! for AVX2 (four), and the AVX2 one runs where the processor has it
//! ([`vector_width`]); the web build walks two lanes of WebAssembly SIMD (`simd128`,
//! enabled for the wasm32 target in `.cargo/config.toml`).

use crate::Op;
use crate::compiled::{CompiledOp, drop_back, tines_shift};
use kurbo::Point;
use std::sync::atomic::{AtomicBool, Ordering};

/// Maps every sample (x, y) of `xs`, `ys` to `$e`, written in the loop itself (no
/// closure call per sample), so the kernel inlines and vectorises in each build.
macro_rules! each {
    ($xs:ident, $ys:ident, |$x:ident, $y:ident| $e:expr) => {
        for (px, py) in $xs.iter_mut().zip($ys.iter_mut()) {
            let ($x, $y) = (*px, *py);
            (*px, *py) = $e;
        }
    };
}

/// Set by [`set_wide_kernels`]: false keeps the baseline walk (a benchmark's control).
static WIDE_KERNELS: AtomicBool = AtomicBool::new(true);

/// Lets the batch walk use the widest vector unit found (true, the default) or keeps it
/// to the build's baseline (false: `marbling bench --simd off`, to compare the two in one
/// run). Results agree to rounding (≤ 1e-12 relative per point).
pub fn set_wide_kernels(on: bool) {
    WIDE_KERNELS.store(on, Ordering::Relaxed);
}

/// f64 lanes the batch walk processes at once here: 4 with AVX2, 2 otherwise (SSE2 on
/// x86-64, `simd128` on the web).
pub fn vector_width() -> usize {
    if avx2() { 4 } else { 2 }
}

/// True when the batch walk runs its AVX2 build.
fn avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        WIDE_KERNELS.load(Ordering::Relaxed) && std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

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
    /// Scratch: where a drop moves each sample, before the covered ones leave.
    moved: (Vec<f64>, Vec<f64>),
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
                CompiledOp::Comb(ref c) => (x, y) = c.apply(x, y, -1.0),
                CompiledOp::Wave(ref w) => (x, y) = w.shift(x, y, -1.0),
                CompiledOp::Swirl(ref w) => (x, y) = w.apply(x, y, -1.0),
                CompiledOp::Rigid(ref r) => (x, y) = r.apply(x, y, -1.0),
                CompiledOp::Tines { .. } => (x, y) = tines_shift(x, y, s, -1.0),
                CompiledOp::Jiggle(ref j) => (x, y) = j.back(x, y),
                CompiledOp::Stylus { .. } | CompiledOp::Flow { .. } => {
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
        self.trace_batch_any::<false>(batch, out, &mut []);
    }

    /// As [`Walker::trace_batch`], and also writes to `ends[id]` the design point where
    /// each walk ended: the back-traced point for the background, or the point (in the
    /// coordinates just after that op) that the covering drop or spray's ink holds.
    /// Pigment grain is sampled there, so it moves with the ink.
    pub fn trace_batch_with_ends(&self, batch: &mut Batch, out: &mut [Traced], ends: &mut [Point]) {
        self.trace_batch_any::<true>(batch, out, ends);
    }

    /// The batch walk on the widest vector unit allowed (see the module doc).
    fn trace_batch_any<const ENDS: bool>(
        &self,
        batch: &mut Batch,
        out: &mut [Traced],
        ends: &mut [Point],
    ) {
        #[cfg(target_arch = "x86_64")]
        if avx2() {
            // SAFETY: the processor has AVX2 (checked by `avx2`), all the AVX2 build needs.
            #[allow(unsafe_code)]
            unsafe {
                self.trace_batch_avx2::<ENDS>(batch, out, ends)
            };
            return;
        }
        self.trace_batch_impl::<ENDS>(batch, out, ends);
    }

    /// [`Walker::trace_batch_impl`] compiled for AVX2 (four f64 lanes).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    fn trace_batch_avx2<const ENDS: bool>(
        &self,
        batch: &mut Batch,
        out: &mut [Traced],
        ends: &mut [Point],
    ) {
        self.trace_batch_impl::<ENDS>(batch, out, ends);
    }

    #[inline(always)]
    fn trace_batch_impl<const ENDS: bool>(
        &self,
        batch: &mut Batch,
        out: &mut [Traced],
        ends: &mut [Point],
    ) {
        let Batch {
            xs,
            ys,
            ids,
            moved: (mx, my),
        } = batch;
        for (k, s) in self.steps.iter().enumerate().rev() {
            if ids.is_empty() {
                break;
            }
            match *s {
                CompiledOp::Disc {
                    cx, cy, r2, deform, ..
                } => {
                    // Most discs cover no sample of a batch: count the covered ones first
                    // (a loop that vectorises), and where there are none move every
                    // sample in place (vectorised too) instead of compacting.
                    let covered: u32 = xs
                        .iter()
                        .zip(ys.iter())
                        .map(|(x, y)| {
                            let (dx, dy) = (x - cx, y - cy);
                            u32::from(dx * dx + dy * dy < r2)
                        })
                        .sum();
                    if covered == 0 {
                        if deform {
                            each!(xs, ys, |x, y| {
                                let (dx, dy) = (x - cx, y - cy);
                                drop_back(cx, cy, r2, dx, dy, dx * dx + dy * dy)
                            });
                        }
                        continue;
                    }
                    // Some are covered: every sample's move first, in a loop that
                    // vectorises (a covered one's is not a number, and is not used), then
                    // the batch compacted, covered samples leaving with this op's ink.
                    let n = ids.len();
                    if deform {
                        // Grown, never shrunk: no zeroing of what is written next.
                        if mx.len() < n {
                            mx.resize(n, 0.0);
                            my.resize(n, 0.0);
                        }
                        let moves = mx[..n].iter_mut().zip(my[..n].iter_mut());
                        for ((x, y), (m, w)) in xs.iter().zip(ys.iter()).zip(moves) {
                            let (dx, dy) = (x - cx, y - cy);
                            (*m, *w) = drop_back(cx, cy, r2, dx, dy, dx * dx + dy * dy);
                        }
                    }
                    let mut j = 0;
                    for i in 0..n {
                        let (dx, dy) = (xs[i] - cx, ys[i] - cy);
                        if dx * dx + dy * dy < r2 {
                            out[ids[i] as usize] = Traced::Ink(k);
                            if ENDS {
                                ends[ids[i] as usize] = Point::new(xs[i], ys[i]);
                            }
                            continue;
                        }
                        if deform {
                            (xs[j], ys[j]) = (mx[i], my[i]);
                        } else {
                            (xs[j], ys[j]) = (xs[i], ys[i]);
                        }
                        ids[j] = ids[i];
                        j += 1;
                    }
                    xs.truncate(j);
                    ys.truncate(j);
                    ids.truncate(j);
                }
                // The op's constants taken out before the loop, and its variant chosen
                // once: the loop body then has no branch and vectorises.
                CompiledOp::Comb(c) if c.spacing > 0.0 => {
                    each!(xs, ys, |x, y| c.shift::<true>(x, y, -1.0));
                }
                CompiledOp::Comb(c) => each!(xs, ys, |x, y| c.shift::<false>(x, y, -1.0)),
                CompiledOp::Wave(w) => each!(xs, ys, |x, y| w.shift(x, y, -1.0)),
                CompiledOp::Swirl(w) if w.vortex => {
                    each!(xs, ys, |x, y| w.turn::<true>(x, y, -1.0));
                }
                CompiledOp::Swirl(w) => each!(xs, ys, |x, y| w.turn::<false>(x, y, -1.0)),
                CompiledOp::Rigid(r) => each!(xs, ys, |x, y| r.apply(x, y, -1.0)),
                CompiledOp::Tines { .. } => each!(xs, ys, |x, y| tines_shift(x, y, s, -1.0)),
                CompiledOp::Jiggle(j) => j.back_all(xs, ys),
                CompiledOp::Flow { ref field } => each!(xs, ys, |x, y| {
                    let q = field.inverse(Point::new(x, y));
                    (q.x, q.y)
                }),
                CompiledOp::Stylus { ref segments } => {
                    for seg in segments.iter().rev() {
                        each!(xs, ys, |x, y| {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};

    /// Every sample of a `w`×`h` sheet walked by `walk`: where each ended.
    fn walked(
        w: u32,
        h: u32,
        walk: impl Fn(&mut Batch, &mut [Traced], &mut [Point]),
    ) -> (Vec<Traced>, Vec<Point>) {
        let n = (w * h) as usize;
        let (mut out, mut ends) = (vec![Traced::Ink(0); n], vec![Point::ZERO; n]);
        let mut batch = Batch::default();
        for id in 0..w * h {
            batch.push(f64::from(id % w) + 0.5, f64::from(id / w) + 0.5, id);
        }
        walk(&mut batch, &mut out, &mut ends);
        (out, ends)
    }

    /// The AVX2 build of the batch walk gives the baseline's results bit for bit: the
    /// same operations on each lane, none fused or reordered.
    #[test]
    #[allow(unsafe_code)]
    fn the_wide_walk_equals_the_baseline() {
        if !avx2() {
            // Nothing to compare where there is no AVX2 build to run: said, not hidden.
            eprintln!("the_wide_walk_equals_the_baseline: no AVX2 here, only the baseline walks");
            return;
        }
        #[cfg(target_arch = "x86_64")]
        {
            for mix in [Mix::CombHeavy, Mix::Mixed, Mix::AllTypes, Mix::DropHeavy] {
                let design = random_design(3, 96, 64, 150, mix);
                let walker = Walker::new(&design.ops);
                let base = walked(96, 64, |b, o, e| walker.trace_batch_impl::<true>(b, o, e));
                // SAFETY: the processor has AVX2 (checked above).
                let wide = walked(96, 64, |b, o, e| unsafe {
                    walker.trace_batch_avx2::<true>(b, o, e)
                });
                assert!(base == wide, "{mix:?}: the AVX2 walk differs");
                let moved = base.1.iter().filter(|p| p.x.fract() != 0.5).count();
                assert!(moved > 1000, "{mix:?}: the design moves too little to tell");
            }
        }
    }

    /// The batch walk (either build) and the one-point walk agree.
    #[test]
    fn the_batch_walk_equals_the_point_walk() {
        let design = random_design(5, 64, 48, 200, Mix::CombHeavy);
        let walker = Walker::new(&design.ops);
        let (out, _) = walked(64, 48, |b, o, e| walker.trace_batch_with_ends(b, o, e));
        for (id, t) in out.iter().enumerate() {
            let p = Point::new((id % 64) as f64 + 0.5, (id / 64) as f64 + 0.5);
            assert_eq!(*t, walker.trace(p), "sample {id}");
        }
    }
}
