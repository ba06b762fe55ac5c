//! The exact label raster behind the contour method: which ink (or the background)
//! every point of a fine square grid holds, found by walking it back through all ops
//! like the CPU reference renderer does, adaptively.
//!
//! Sample (m, n) sits at design point ((m + ½)·step, (n + ½)·step). Every `STRIDE`-th
//! sample in each direction (the coarse lattice) is walked first; a coarse cell whose
//! four corners hold one label, as do those of its eight neighbours, is filled with it;
//! so is one where only labels the caller does not want meet (there forward-traced
//! outlines draw the picture); every other sample is walked. So only an island or filament that touches no coarse
//! point of a 3×3 block of coarse cells (`STRIDE` samples each) is missed.

use marbling_core::{Batch, Design, Traced, Walker};
use rayon::prelude::*;

/// Label of a sample that holds the background.
pub const BACKGROUND: u32 = 0;
/// Label of the padding outside the grid (never an ink).
pub const OUTSIDE: u32 = u32::MAX;
/// Fine samples per coarse step, each way.
const STRIDE: usize = 4;

/// Labels on a square grid over the canvas: 0 for the background, k + 1 for the ink
/// of compiled op k.
#[derive(Clone, Debug)]
pub struct LabelGrid {
    /// Samples per row.
    pub nx: usize,
    /// Rows.
    pub ny: usize,
    /// Sample spacing, design pixels.
    pub step: f64,
    /// Row-major labels.
    pub labels: Vec<u32>,
    /// Samples walked back through the ops (coarse and refined).
    pub walked: usize,
}

impl LabelGrid {
    /// The label at (m, n), [`OUTSIDE`] beyond the grid.
    #[inline]
    pub fn at(&self, m: isize, n: isize) -> u32 {
        if m < 0 || n < 0 || m >= self.nx as isize || n >= self.ny as isize {
            OUTSIDE
        } else {
            self.labels[n as usize * self.nx + m as usize]
        }
    }

    /// Labels `design` on a grid of spacing `step` design pixels covering the canvas.
    /// Only blocks where a label that `wanted` holds (by label) meets another are
    /// walked finely; elsewhere every sample takes its coarse block's label.
    pub fn new(design: &Design, step: f64, wanted: &[bool]) -> Self {
        let is_wanted = |l: u32| wanted.get(l as usize).copied().unwrap_or(false);
        let walker = Walker::new(&design.ops);
        let nx = ((f64::from(design.width) / step).ceil() as usize).max(1);
        let ny = ((f64::from(design.height) / step).ceil() as usize).max(1);
        // Coarse points at fine indices STRIDE·M, far enough to cover the last sample.
        let (cx, cy) = ((nx - 1) / STRIDE + 2, (ny - 1) / STRIDE + 2);
        let label = |t: Traced| match t {
            Traced::Ink(k) => k as u32 + 1,
            Traced::Background(_) => BACKGROUND,
        };
        let walk = |points: &[(usize, usize)], out: &mut Vec<u32>| {
            let mut batch = Batch::default();
            for (i, &(m, n)) in points.iter().enumerate() {
                batch.push((m as f64 + 0.5) * step, (n as f64 + 0.5) * step, i as u32);
            }
            let mut traced = vec![Traced::Ink(0); points.len()];
            walker.trace_batch(&mut batch, &mut traced);
            out.clear();
            out.extend(traced.into_iter().map(label));
        };
        let coarse: Vec<Vec<u32>> = (0..cy)
            .into_par_iter()
            .map(|my| {
                let points: Vec<(usize, usize)> =
                    (0..cx).map(|mx| (mx * STRIDE, my * STRIDE)).collect();
                let mut out = Vec::new();
                walk(&points, &mut out);
                out
            })
            .collect();
        let corners = |mx: usize, my: usize| {
            [
                coarse[my][mx],
                coarse[my][mx + 1],
                coarse[my + 1][mx],
                coarse[my + 1][mx + 1],
            ]
        };
        // Cells whose corners disagree, and their eight neighbours (so that a boundary
        // bulging between two coarse corners is found too), are walked sample by sample.
        let differs: Vec<Vec<bool>> = (0..cy - 1)
            .map(|my| {
                (0..cx - 1)
                    .map(|mx| {
                        let c = corners(mx, my);
                        c.iter().any(|&l| l != c[0]) && c.iter().any(|&l| is_wanted(l))
                    })
                    .collect()
            })
            .collect();
        let mixed: Vec<Vec<bool>> = (0..cy - 1)
            .map(|my| {
                (0..cx - 1)
                    .map(|mx| {
                        (my.saturating_sub(1)..(my + 2).min(cy - 1)).any(|y| {
                            (mx.saturating_sub(1)..(mx + 2).min(cx - 1)).any(|x| differs[y][x])
                        })
                    })
                    .collect()
            })
            .collect();
        // Cells holding fine index i along one axis: i / STRIDE, and the one before
        // when i lies on a coarse line.
        let cells_of = |i: usize, cells: usize| {
            let c = (i / STRIDE).min(cells - 1);
            let before = (i.is_multiple_of(STRIDE) && c > 0).then(|| c - 1);
            (c, before)
        };
        let rows: Vec<(Vec<u32>, usize)> = (0..ny)
            .into_par_iter()
            .map(|n| {
                let mut row = vec![BACKGROUND; nx];
                let mut todo = Vec::new();
                let (ry, ry_before) = cells_of(n, cy - 1);
                for (m, slot) in row.iter_mut().enumerate() {
                    if m.is_multiple_of(STRIDE) && n.is_multiple_of(STRIDE) {
                        *slot = coarse[n / STRIDE][m / STRIDE];
                        continue;
                    }
                    let (rx, rx_before) = cells_of(m, cx - 1);
                    let refine = [Some(rx), rx_before].into_iter().flatten().any(|x| {
                        [Some(ry), ry_before]
                            .into_iter()
                            .flatten()
                            .any(|y| mixed[y][x])
                    });
                    if refine {
                        todo.push((m, n));
                    } else {
                        *slot = coarse[ry][rx];
                    }
                }
                let mut out = Vec::new();
                walk(&todo, &mut out);
                for (&(m, _), &l) in todo.iter().zip(&out) {
                    row[m] = l;
                }
                (row, todo.len())
            })
            .collect();
        let mut labels = Vec::with_capacity(nx * ny);
        let mut walked = cx * cy;
        for (row, n) in rows {
            labels.extend(row);
            walked += n;
        }
        Self {
            nx,
            ny,
            step,
            labels,
            walked,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{Drop, Op, Point, Rgb8};

    #[test]
    fn labels_match_single_walks_inside_and_outside_a_drop() {
        let mut design = Design::new(40, 30, Rgb8::new(255, 255, 255));
        design.ops.push(Op::Drop(Drop {
            center: Point::new(20.0, 15.0),
            radius: 8.0,
            color: Rgb8::new(200, 0, 0),
        }));
        design.ops.push(Op::Drop(Drop {
            center: Point::new(26.0, 15.0),
            radius: 3.0,
            color: Rgb8::new(0, 0, 200),
        }));
        let grid = LabelGrid::new(&design, 0.5, &[true; 3]);
        let walker = Walker::new(&design.ops);
        for n in 0..grid.ny {
            for m in 0..grid.nx {
                let p = Point::new((m as f64 + 0.5) * 0.5, (n as f64 + 0.5) * 0.5);
                let expected = match walker.trace(p) {
                    Traced::Ink(k) => k as u32 + 1,
                    Traced::Background(_) => BACKGROUND,
                };
                assert_eq!(grid.at(m as isize, n as isize), expected, "sample {m},{n}");
            }
        }
        assert!(
            grid.walked < grid.nx * grid.ny,
            "uniform cells are not walked"
        );
        assert_eq!(grid.at(-1, 0), OUTSIDE);
    }
}
