//! The inverse walk: every sample goes back through the ops newest → oldest until an ink
//! drop or spray covers it or it reaches the background. This is the hot path of the CPU
//! reference renderer, so ops are precompiled into [`Walker`] steps and samples are
//! processed op-major in batches (one op over many samples, which keeps the op's
//! constants in registers and lets the compiler vectorise the combs).

use crate::Op;
use kurbo::Point;
use std::f64::consts::TAU;

/// Where a sample's walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Traced {
    /// Covered by the ink of op number `usize` (an index into `Design::ops`).
    Ink(usize),
    /// Reached the background at this (back-traced) design point.
    Background(Point),
}

/// One op, precompiled for the inverse walk.
#[derive(Clone, Copy, Debug)]
enum Step {
    /// Drop (`deform`) or spray: centre and squared radius.
    Disc {
        cx: f64,
        cy: f64,
        r2: f64,
        deform: bool,
    },
    /// Tine (`spacing == 0`) or rake: origin, unit motion m, unit normal n, αλ, λ.
    Comb {
        ax: f64,
        ay: f64,
        mx: f64,
        my: f64,
        nx: f64,
        ny: f64,
        al: f64,
        lambda: f64,
        spacing: f64,
    },
    /// Wavy comb: unit motion m, unit normal n, amplitude, 2π/wavelength, phase.
    Wave {
        mx: f64,
        my: f64,
        nx: f64,
        ny: f64,
        amp: f64,
        k: f64,
        phase: f64,
    },
    /// Circular comb (`vortex == false`, strongest at ρ = r) or vortex (d = ρ).
    Swirl {
        cx: f64,
        cy: f64,
        r: f64,
        al: f64,
        lambda: f64,
        vortex: bool,
    },
}

impl Step {
    fn new(op: &Op) -> Step {
        match *op {
            Op::Drop(d) => Step::Disc {
                cx: d.center.x,
                cy: d.center.y,
                r2: d.radius * d.radius,
                deform: true,
            },
            Op::Spray(s) => Step::Disc {
                cx: s.center.x,
                cy: s.center.y,
                r2: s.radius * s.radius,
                deform: false,
            },
            Op::Tine(t) => Self::comb(t.origin, t.direction, t.alpha, t.lambda, 0.0),
            Op::Rake(r) => Self::comb(r.origin, r.direction, r.alpha, r.lambda, r.spacing),
            Op::Wavy(w) => {
                let (s, c) = w.angle.sin_cos();
                Step::Wave {
                    mx: c,
                    my: s,
                    nx: s,
                    ny: -c,
                    amp: w.amplitude,
                    k: TAU / w.wavelength,
                    phase: w.phase,
                }
            }
            Op::Circular(c) => Step::Swirl {
                cx: c.center.x,
                cy: c.center.y,
                r: c.radius,
                al: c.alpha * c.lambda,
                lambda: c.lambda,
                vortex: false,
            },
            Op::Vortex(v) => Step::Swirl {
                cx: v.center.x,
                cy: v.center.y,
                r: 0.0,
                al: v.alpha * v.lambda,
                lambda: v.lambda,
                vortex: true,
            },
        }
    }

    fn comb(origin: Point, dir: kurbo::Vec2, alpha: f64, lambda: f64, spacing: f64) -> Step {
        let m = dir.normalize();
        Step::Comb {
            ax: origin.x,
            ay: origin.y,
            mx: m.x,
            my: m.y,
            nx: -m.y,
            ny: m.x,
            al: alpha * lambda,
            lambda,
            spacing,
        }
    }
}

/// Inverse of a drop outside its disc: P = C + (P' − C)·√(1 − r²/ρ²).
#[inline(always)]
fn drop_back(cx: f64, cy: f64, r2: f64, dx: f64, dy: f64, d2: f64) -> (f64, f64) {
    let f = (1.0 - r2 / d2).sqrt();
    (cx + dx * f, cy + dy * f)
}

/// Distance to the nearest rake tine: s/2 − |fmod(d, s) − s/2| for d ≥ 0.
#[inline(always)]
fn rake_distance(d: f64, s: f64) -> f64 {
    let q = d / s;
    // fract(q) by truncation (fast, vectorisable); beyond 2^52 an f64 has no fraction.
    let fr = if q < 4.0e15 {
        q - (q as i64 as f64)
    } else {
        0.0
    };
    s * (0.5 - (fr - 0.5).abs())
}

#[inline(always)]
fn comb_back(x: f64, y: f64, s: &Step) -> (f64, f64) {
    let Step::Comb {
        ax,
        ay,
        mx,
        my,
        nx,
        ny,
        al,
        lambda,
        spacing,
    } = *s
    else {
        return (x, y);
    };
    let mut d = ((x - ax) * nx + (y - ay) * ny).abs();
    if spacing > 0.0 {
        d = rake_distance(d, spacing);
    }
    let f = al / (d + lambda);
    (x - f * mx, y - f * my)
}

#[inline(always)]
fn wave_back(x: f64, y: f64, s: &Step) -> (f64, f64) {
    let Step::Wave {
        mx,
        my,
        nx,
        ny,
        amp,
        k,
        phase,
    } = *s
    else {
        return (x, y);
    };
    let f = amp * (k * (x * nx + y * ny) + phase).sin();
    (x - f * mx, y - f * my)
}

#[inline(always)]
fn swirl_back(x: f64, y: f64, s: &Step) -> (f64, f64) {
    let Step::Swirl {
        cx,
        cy,
        r,
        al,
        lambda,
        vortex,
    } = *s
    else {
        return (x, y);
    };
    let (dx, dy) = (x - cx, y - cy);
    let rho = (dx * dx + dy * dy).sqrt();
    if rho == 0.0 {
        return (x, y);
    }
    let d = if vortex { rho } else { (rho - r).abs() };
    let theta = al / (d + lambda) / rho;
    let (sn, cs) = (-theta).sin_cos();
    (cx + dx * cs - dy * sn, cy + dx * sn + dy * cs)
}

/// A design's ops compiled for fast inverse walks.
#[derive(Clone, Debug)]
pub struct Walker {
    steps: Vec<Step>,
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
            steps: ops.iter().map(Step::new).collect(),
        }
    }

    /// Number of ops.
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
                Step::Disc { cx, cy, r2, deform } => {
                    let (dx, dy) = (x - cx, y - cy);
                    let d2 = dx * dx + dy * dy;
                    if d2 < r2 {
                        return Traced::Ink(k);
                    }
                    if deform {
                        (x, y) = drop_back(cx, cy, r2, dx, dy, d2);
                    }
                }
                Step::Comb { .. } => (x, y) = comb_back(x, y, s),
                Step::Wave { .. } => (x, y) = wave_back(x, y, s),
                Step::Swirl { .. } => (x, y) = swirl_back(x, y, s),
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
                Step::Disc { cx, cy, r2, deform } => {
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
                Step::Comb { .. } => apply(xs, ys, |x, y| comb_back(x, y, s)),
                Step::Wave { .. } => apply(xs, ys, |x, y| wave_back(x, y, s)),
                Step::Swirl { .. } => apply(xs, ys, |x, y| swirl_back(x, y, s)),
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
