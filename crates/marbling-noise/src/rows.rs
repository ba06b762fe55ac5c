//! Row kernels: Perlin and Worley noise along one row of points (one y, many x), equal
//! bit for bit to [`perlin2_periodic`](crate::perlin2_periodic) and [`worley2`] at each
//! point, and several times faster on a grid. A row's lattice hashes are computed once
//! per cell into a small table (a cell spans many points at the usual frequencies), and
//! the per-point arithmetic runs in chunks of [`LANES`] points that the compiler turns
//! into vector code — 8 f32 lanes with AVX2 when the processor has it (chosen at run
//! time), SSE2's 4 otherwise, 4 in `simd128` on the web. A chunk whose points share one cell
//! reads that cell's numbers once; a chunk that crosses cells reads them per point.
//!
//! Rows whose x values spread over far more cells than they have points (a huge
//! frequency, a scattered row) fall back to the point functions.

use crate::hash::{CellRng, PRIME_X, PRIME_Y, floor_i32, lattice_hash_premul, wrap_cell};
use crate::perlin::{GRADIENTS, fade};
use crate::worley::{Metric, worley2};

/// Points per chunk: one AVX2 register of f32; on the web one `simd128` register (4),
/// which also keeps the module small (the chunk loops are unrolled per lane).
pub const LANES: usize = if cfg!(target_arch = "wasm32") { 4 } else { 8 };

/// Runs `$imp` compiled for AVX2 when the processor has it (checked at run time), as
/// compiled for the build's baseline otherwise; the arguments are named with their types.
macro_rules! on_widest_unit {
    ($imp:ident($($arg:ident: $ty:ty),*)) => {{
        #[cfg(target_arch = "x86_64")]
        {
            #[target_feature(enable = "avx2")]
            fn avx2($($arg: $ty),*) {
                $imp($($arg),*)
            }
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: the processor has AVX2 (checked above), all `avx2` needs.
                #[allow(unsafe_code)]
                unsafe {
                    avx2($($arg),*)
                };
                return;
            }
        }
        $imp($($arg),*)
    }};
}

/// `out[i] = perlin2_periodic(xs[i], y, seed, period)` for every i (bit for bit).
///
/// # Panics
/// When `out` is shorter than `xs`.
pub fn perlin2_row(xs: &[f32], y: f32, seed: u32, period: [i32; 2], out: &mut [f32]) {
    assert!(out.len() >= xs.len(), "perlin2_row: out shorter than xs");
    on_widest_unit!(perlin2_row_impl(xs: &[f32], y: f32, seed: u32, period: [i32; 2], out: &mut [f32]))
}

/// `f1[i], f2[i] = worley2(xs[i], y, seed, metric, period)` for every i (bit for bit).
///
/// # Panics
/// When `f1` or `f2` is shorter than `xs`.
pub fn worley2_row(
    xs: &[f32],
    y: f32,
    seed: u32,
    metric: Metric,
    period: [i32; 2],
    f1: &mut [f32],
    f2: &mut [f32],
) {
    assert!(
        f1.len() >= xs.len() && f2.len() >= xs.len(),
        "worley2_row: outputs shorter than xs"
    );
    on_widest_unit!(worley2_row_impl(
        xs: &[f32],
        y: f32,
        seed: u32,
        metric: Metric,
        period: [i32; 2],
        f1: &mut [f32],
        f2: &mut [f32]
    ))
}

/// The cells a row's points fall in, `[lo, hi]`, or `None` when a table over them would
/// cost more than evaluating each point (more than two cells per point, plus slack).
fn cell_span(xs: &[f32]) -> Option<(i32, i32)> {
    let (mut lo, mut hi) = (i32::MAX, i32::MIN);
    for &x in xs {
        let i = floor_i32(x);
        lo = lo.min(i);
        hi = hi.max(i);
    }
    let span = i64::from(hi) - i64::from(lo);
    (lo <= hi && span <= 2 * xs.len() as i64 + 64 && lo > i32::MIN + 2 && hi < i32::MAX - 2)
        .then_some((lo, hi))
}

/// Most cells a chunk may cross and still have its lattice numbers chosen by selects
/// (one pass per cell) rather than read per lane.
const FEW: usize = 3;

/// Which cells a chunk's points fall in.
enum Cells {
    /// All lanes in cell `ix`.
    One(i32),
    /// Lane k in cell `ix + step[k]`, steps in 0..=`span` (span ≤ [`FEW`]).
    Few {
        ix: i32,
        span: usize,
        step: [f32; LANES],
    },
    /// Scattered (or NaN): read per lane.
    Many,
}

/// The position of each point of a chunk in its cell, and its cells. `x − ⌊x⌋` equals
/// the point functions' `x − (⌊x⌋ as i32) as f32` for every x whose cell [`cell_span`]
/// admits (|⌊x⌋| < 2³¹, where the integer converts back exactly), and NaN for NaN;
/// comparing floors in f32 keeps the loop free of conversions to integers.
#[inline(always)]
fn chunk_cells(xs: &[f32; LANES]) -> ([f32; LANES], Cells) {
    let mut step = [0_f32; LANES];
    let mut fx = [0_f32; LANES];
    let base = xs[0].floor();
    let (mut inside, mut span) = (true, 0.0_f32);
    for k in 0..LANES {
        let floor = xs[k].floor();
        fx[k] = xs[k] - floor;
        step[k] = floor - base;
        inside &= step[k] >= 0.0 && step[k] <= FEW as f32;
        span = span.max(step[k]);
    }
    let cells = if !inside {
        Cells::Many
    } else if span == 0.0 {
        Cells::One(floor_i32(xs[0]))
    } else {
        Cells::Few {
            ix: floor_i32(xs[0]),
            span: span as usize,
            step,
        }
    };
    (fx, cells)
}

/// The gradients of a row's two lattice lines: entry c − lo holds those of corner column
/// c (wrapped when periodic) on the line below (`*0`) and above (`*1`) the row.
struct GradientTable {
    gx0: Vec<f32>,
    gy0: Vec<f32>,
    gx1: Vec<f32>,
    gy1: Vec<f32>,
}

impl GradientTable {
    fn new(lo: i32, hi: i32, iy: i32, seed: u32, period: [i32; 2]) -> Self {
        let (y0, y1) = if period[0] > 0 || period[1] > 0 {
            (wrap_cell(iy, period[1]), wrap_cell(iy + 1, period[1]))
        } else {
            (iy, iy + 1)
        };
        let yp0 = (y0 as u32).wrapping_mul(PRIME_Y);
        let yp1 = (y1 as u32).wrapping_mul(PRIME_Y);
        let n = (hi - lo + 2) as usize;
        let mut t = Self {
            gx0: Vec::with_capacity(n),
            gy0: Vec::with_capacity(n),
            gx1: Vec::with_capacity(n),
            gy1: Vec::with_capacity(n),
        };
        for c in lo..=hi + 1 {
            let x = if period[0] > 0 || period[1] > 0 {
                wrap_cell(c, period[0])
            } else {
                c
            };
            let xp = (x as u32).wrapping_mul(PRIME_X);
            let g0 = GRADIENTS[(lattice_hash_premul(xp, yp0, seed) >> 29) as usize];
            let g1 = GRADIENTS[(lattice_hash_premul(xp, yp1, seed) >> 29) as usize];
            t.gx0.push(g0[0]);
            t.gy0.push(g0[1]);
            t.gx1.push(g1[0]);
            t.gy1.push(g1[1]);
        }
        t
    }
}

/// The four corner gradients of each lane: `[g00, g10, g01, g11]`, each `[x; LANES]`
/// then `[y; LANES]` (the order of `perlin_from`'s corners).
type Corners = [[[f32; LANES]; 2]; 4];

/// Perlin noise of a chunk from its positions in the cells (`fx`, `fy`), the row's
/// `v = fade(fy)` and corner gradients `g(corner, axis, lane)`: the same operations in
/// the same order as `perlin_from`.
#[inline(always)]
fn perlin_chunk(
    fx: &[f32; LANES],
    fy: f32,
    v: f32,
    g: impl Fn(usize, usize, usize) -> f32,
) -> [f32; LANES] {
    let mut out = [0.0; LANES];
    for k in 0..LANES {
        let f = fx[k];
        let a = g(0, 0, k) * f + g(0, 1, k) * fy;
        let b = g(1, 0, k) * (f - 1.0) + g(1, 1, k) * fy;
        let c = g(2, 0, k) * f + g(2, 1, k) * (fy - 1.0);
        let d = g(3, 0, k) * (f - 1.0) + g(3, 1, k) * (fy - 1.0);
        let u = fade(f);
        let ab = a + u * (b - a);
        let cd = c + u * (d - c);
        out[k] = ab + v * (cd - ab);
    }
    out
}

#[inline(always)]
fn perlin2_row_impl(xs: &[f32], y: f32, seed: u32, period: [i32; 2], out: &mut [f32]) {
    let Some((lo, hi)) = cell_span(xs) else {
        for (o, &x) in out.iter_mut().zip(xs) {
            *o = crate::perlin::perlin2_periodic(x, y, seed, period);
        }
        return;
    };
    let iy = floor_i32(y);
    let fy = y - iy as f32;
    let v = fade(fy);
    let t = GradientTable::new(lo, hi, iy, seed, period);
    let mut chunks = xs.chunks_exact(LANES);
    let mut outs = out.chunks_exact_mut(LANES);
    for (x, o) in (&mut chunks).zip(&mut outs) {
        let x: &[f32; LANES] = x.try_into().unwrap_or(&[0.0; LANES]);
        let (fx, cells) = chunk_cells(x);
        // The gradients of corner `corner` (0..4, `perlin_from`'s order) of cell c − lo.
        let grad = |c: usize, corner: usize| {
            let c = c + (corner & 1);
            if corner < 2 {
                [t.gx0[c], t.gy0[c]]
            } else {
                [t.gx1[c], t.gy1[c]]
            }
        };
        let r = match cells {
            Cells::One(ix) => {
                let c = (ix - lo) as usize;
                let g: [[f32; 2]; 4] = std::array::from_fn(|corner| grad(c, corner));
                perlin_chunk(&fx, fy, v, |corner, axis, _| g[corner][axis])
            }
            Cells::Few { ix, span, step } => {
                let c = (ix - lo) as usize;
                let mut g: Corners = [[[0.0; LANES]; 2]; 4];
                for j in 0..=span {
                    for (corner, gc) in g.iter_mut().enumerate() {
                        let here = grad(c + j, corner);
                        for (axis, ga) in gc.iter_mut().enumerate() {
                            for k in 0..LANES {
                                ga[k] = if step[k] == j as f32 {
                                    here[axis]
                                } else {
                                    ga[k]
                                };
                            }
                        }
                    }
                }
                perlin_chunk(&fx, fy, v, |corner, axis, k| g[corner][axis][k])
            }
            Cells::Many => {
                let mut g: Corners = [[[0.0; LANES]; 2]; 4];
                for (k, &x) in x.iter().enumerate() {
                    let c = (floor_i32(x) - lo) as usize;
                    for (corner, gc) in g.iter_mut().enumerate() {
                        let here = grad(c, corner);
                        gc[0][k] = here[0];
                        gc[1][k] = here[1];
                    }
                }
                perlin_chunk(&fx, fy, v, |corner, axis, k| g[corner][axis][k])
            }
        };
        o[..LANES].copy_from_slice(&r);
    }
    for (o, &x) in outs.into_remainder().iter_mut().zip(chunks.remainder()) {
        *o = crate::perlin::perlin2_periodic(x, y, seed, period);
    }
}

/// The feature points of a row's three lattice lines: entry (c − lo + 1) of line dj + 1
/// holds the two uniforms cell (c, iy + dj) draws for its point (wrapped when periodic).
struct FeatureTable {
    rx: [Vec<f32>; 3],
    ry: [Vec<f32>; 3],
}

impl FeatureTable {
    fn new(lo: i32, hi: i32, iy: i32, seed: u32, period: [i32; 2]) -> Self {
        let n = (hi - lo + 3) as usize;
        let line = |dj: i32| {
            let mut rx = Vec::with_capacity(n);
            let mut ry = Vec::with_capacity(n);
            for c in lo - 1..=hi + 1 {
                let mut rng =
                    CellRng::new(wrap_cell(c, period[0]), wrap_cell(iy + dj, period[1]), seed);
                rx.push(rng.next_f32());
                ry.push(rng.next_f32());
            }
            (rx, ry)
        };
        let (l0, l1, l2) = (line(-1), line(0), line(1));
        Self {
            rx: [l0.0, l1.0, l2.0],
            ry: [l0.1, l1.1, l2.1],
        }
    }
}

#[inline(always)]
fn worley2_row_impl(
    xs: &[f32],
    y: f32,
    seed: u32,
    metric: Metric,
    period: [i32; 2],
    f1: &mut [f32],
    f2: &mut [f32],
) {
    // Euclidean chunks compare squared distances and take the roots at the end: the
    // order statistics of √ are those of the squares and √ is correctly rounded, so the
    // result equals the point function's (f32::MAX, the value of no point, stays).
    let root = |m: f32| if m == f32::MAX { m } else { m.sqrt() };
    let rows = (xs, y, seed, metric, period);
    match metric {
        Metric::Euclidean => worley_rows(rows, f1, f2, |dx, dy| dx * dx + dy * dy, root),
        Metric::Manhattan => worley_rows(rows, f1, f2, |dx, dy| dx.abs() + dy.abs(), |m| m),
        Metric::Chebyshev => {
            worley_rows(rows, f1, f2, |dx, dy| dx.abs().max(dy.abs()), |m| m);
        }
    }
}

/// The row walk of [`worley2_row_impl`] for one distance function `dist` whose chunk
/// minima `finish` turns into distances.
#[inline(always)]
fn worley_rows(
    (xs, y, seed, metric, period): (&[f32], f32, u32, Metric, [i32; 2]),
    f1: &mut [f32],
    f2: &mut [f32],
    dist: impl Fn(f32, f32) -> f32 + Copy,
    finish: impl Fn(f32) -> f32 + Copy,
) {
    let point = |x: f32, a: &mut f32, b: &mut f32| {
        [*a, *b] = worley2(x, y, seed, metric, period);
    };
    let Some((lo, hi)) = cell_span(xs) else {
        for ((a, b), &x) in f1.iter_mut().zip(f2.iter_mut()).zip(xs) {
            point(x, a, b);
        }
        return;
    };
    let iy = floor_i32(y);
    let fy = y - iy as f32;
    let t = FeatureTable::new(lo, hi, iy, seed, period);
    let mut chunks = xs.chunks_exact(LANES);
    let mut o1 = f1.chunks_exact_mut(LANES);
    let mut o2 = f2.chunks_exact_mut(LANES);
    for ((x, a), b) in (&mut chunks).zip(&mut o1).zip(&mut o2) {
        let x: &[f32; LANES] = x.try_into().unwrap_or(&[0.0; LANES]);
        let (fx, cells) = chunk_cells(x);
        let (m1, m2) = match cells {
            Cells::One(ix) => {
                let c = (ix - lo) as usize;
                let p: [[(f32, f32); 3]; 3] = std::array::from_fn(|dj| {
                    std::array::from_fn(|di| (t.rx[dj][c + di], t.ry[dj][c + di]))
                });
                worley_chunk(&fx, fy, dist, |dj, di, _| p[dj][di])
            }
            Cells::Few { ix, span, step } => {
                let c = (ix - lo) as usize;
                let mut p = [[([0.0; LANES], [0.0; LANES]); 3]; 3];
                for j in 0..=span {
                    for (dj, row) in p.iter_mut().enumerate() {
                        for (di, (px, py)) in row.iter_mut().enumerate() {
                            let (rx, ry) = (t.rx[dj][c + j + di], t.ry[dj][c + j + di]);
                            for k in 0..LANES {
                                let here = step[k] == j as f32;
                                px[k] = if here { rx } else { px[k] };
                                py[k] = if here { ry } else { py[k] };
                            }
                        }
                    }
                }
                worley_chunk(&fx, fy, dist, |dj, di, k| (p[dj][di].0[k], p[dj][di].1[k]))
            }
            Cells::Many => {
                let mut cells = [0_usize; LANES];
                for (c, &x) in cells.iter_mut().zip(x) {
                    *c = (floor_i32(x) - lo) as usize;
                }
                worley_chunk(&fx, fy, dist, |dj, di, k| {
                    (t.rx[dj][cells[k] + di], t.ry[dj][cells[k] + di])
                })
            }
        };
        for k in 0..LANES {
            a[k] = finish(m1[k]);
            b[k] = finish(m2[k]);
        }
    }
    let (r1, r2) = (o1.into_remainder(), o2.into_remainder());
    for ((a, b), &x) in r1.iter_mut().zip(r2.iter_mut()).zip(chunks.remainder()) {
        point(x, a, b);
    }
}

/// The two smallest distances `dist` of each lane of a chunk to the feature points of
/// its 3×3 cells, `r(dj, di, lane)` the two uniforms of cell (di − 1, dj − 1) from the
/// lane's cell: the candidates in `worley2`'s order, its updates written as selects.
#[inline(always)]
fn worley_chunk(
    fx: &[f32; LANES],
    fy: f32,
    dist: impl Fn(f32, f32) -> f32,
    r: impl Fn(usize, usize, usize) -> (f32, f32),
) -> ([f32; LANES], [f32; LANES]) {
    let mut m1 = [f32::MAX; LANES];
    let mut m2 = [f32::MAX; LANES];
    for dj in 0..3 {
        let py = (dj as i32 - 1) as f32;
        for di in 0..3 {
            let ox = (di as i32 - 1) as f32;
            for k in 0..LANES {
                let (rx, ry) = r(dj, di, k);
                // As `worley2`: the point (di + r₁, dj + r₂) in cell units.
                let d = dist((ox + rx) - fx[k], (py + ry) - fy);
                let below1 = d < m1[k];
                m2[k] = if below1 {
                    m1[k]
                } else if d < m2[k] {
                    d
                } else {
                    m2[k]
                };
                m1[k] = if below1 { d } else { m1[k] };
            }
        }
    }
    (m1, m2)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::perlin::perlin2_periodic;

    /// Rows that exercise every path: shared-cell chunks, chunks across cells, negative
    /// cells, a remainder, a periodic wrap, a scattered row (the point fallback).
    fn rows() -> Vec<(Vec<f32>, f32, [i32; 2])> {
        let grid = |n: usize, x0: f32, step: f32| (0..n).map(|i| x0 + i as f32 * step).collect();
        vec![
            (grid(203, 0.005, 0.01), 3.217, [0, 0]),
            (grid(101, -7.3, 0.37), -2.5, [0, 0]),
            (grid(64, -40.0, 1.9), 0.0, [0, 0]),
            (grid(77, 0.3, 0.21), 11.9, [5, 7]),
            (grid(19, 1e4, 997.0), 4.4, [0, 0]),
            (
                vec![f32::NAN, 1.5, -0.0, 2.0, 3.0, 1e9, -1e9, 0.5, 0.25],
                1.0,
                [0, 0],
            ),
        ]
    }

    #[test]
    fn the_perlin_row_equals_the_point_function() {
        for (xs, y, period) in rows() {
            let mut out = vec![0.0; xs.len()];
            perlin2_row(&xs, y, 9, period, &mut out);
            for (&x, &o) in xs.iter().zip(&out) {
                let want = perlin2_periodic(x, y, 9, period);
                assert!(
                    o.to_bits() == want.to_bits() || o == want || (o.is_nan() && want.is_nan()),
                    "x {x} y {y} {period:?}: row {o} point {want}"
                );
            }
        }
    }

    #[test]
    fn the_worley_row_equals_the_point_function() {
        for metric in [Metric::Euclidean, Metric::Manhattan, Metric::Chebyshev] {
            for (xs, y, period) in rows() {
                let (mut a, mut b) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
                worley2_row(&xs, y, 4, metric, period, &mut a, &mut b);
                for (i, &x) in xs.iter().enumerate() {
                    let want = worley2(x, y, 4, metric, period);
                    let same = |p: f32, q: f32| p == q || (p.is_nan() && q.is_nan());
                    assert!(
                        same(a[i], want[0]) && same(b[i], want[1]),
                        "{metric:?} x {x} y {y} {period:?}: row {} {} point {want:?}",
                        a[i],
                        b[i]
                    );
                }
            }
        }
    }

    #[test]
    fn the_comparison_notices_a_changed_value() {
        let xs: Vec<f32> = (0..40).map(|i| i as f32 * 0.05).collect();
        let mut out = vec![0.0; xs.len()];
        perlin2_row(&xs, 0.7, 1, [0, 0], &mut out);
        let other = perlin2_periodic(xs[13], 0.7, 2, [0, 0]);
        assert_ne!(out[13], other, "another seed gives another value");
    }
}
