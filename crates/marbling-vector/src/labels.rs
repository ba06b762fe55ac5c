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
        LabelWalk::new(design, step, wanted.to_vec()).finish_now()
    }
}

/// The label raster built a batch of rows at a time ([`LabelWalk::step`]), so that a
/// caller on a UI thread can spread it over frames; [`LabelGrid::new`] runs it whole.
pub struct LabelWalk {
    walker: Walker,
    step: f64,
    nx: usize,
    ny: usize,
    /// Coarse lattice points each way.
    cx: usize,
    cy: usize,
    /// Labels a caller wants outlines of (by label).
    wanted: Vec<bool>,
    /// Coarse rows walked so far.
    coarse: Vec<Vec<u32>>,
    /// Coarse cells walked sample by sample (set once every coarse row is walked).
    mixed: Vec<Vec<bool>>,
    /// Fine labels of the rows done, row-major.
    labels: Vec<u32>,
    walked: usize,
}

/// Rows walked per [`LabelWalk::step`] and thread: one row of a 300-op design is
/// tens of milliseconds of work on one core.
const ROWS_PER_STEP: usize = 2;

/// Rows walked per step: [`ROWS_PER_STEP`] for each thread rayon has.
fn rows_per_step() -> usize {
    ROWS_PER_STEP * rayon::current_num_threads()
}

impl LabelWalk {
    /// A walk of `design`'s labels on a grid of spacing `step` design pixels.
    pub fn new(design: &Design, step: f64, wanted: Vec<bool>) -> Self {
        let nx = ((f64::from(design.width) / step).ceil() as usize).max(1);
        let ny = ((f64::from(design.height) / step).ceil() as usize).max(1);
        Self {
            walker: Walker::new(&design.ops),
            step,
            nx,
            ny,
            // Coarse points at fine indices STRIDE·M, far enough to cover the last sample.
            cx: (nx - 1) / STRIDE + 2,
            cy: (ny - 1) / STRIDE + 2,
            wanted,
            coarse: Vec::new(),
            mixed: Vec::new(),
            labels: Vec::with_capacity(nx * ny),
            walked: 0,
        }
    }

    /// Rows (coarse, then fine) done and in all.
    pub fn rows(&self) -> (usize, usize) {
        (
            self.coarse.len() + self.labels.len() / self.nx,
            self.cy + self.ny,
        )
    }

    /// Walks the next batch of rows; true when the raster is complete.
    pub fn step(&mut self) -> bool {
        if self.coarse.len() < self.cy {
            let from = self.coarse.len();
            let to = (from + rows_per_step()).min(self.cy);
            let cx = self.cx;
            let rows: Vec<Vec<u32>> = (from..to)
                .into_par_iter()
                .map(|my| {
                    let points: Vec<(usize, usize)> =
                        (0..cx).map(|mx| (mx * STRIDE, my * STRIDE)).collect();
                    self.walk(&points)
                })
                .collect();
            self.walked += rows.len() * cx;
            self.coarse.extend(rows);
            if self.coarse.len() == self.cy {
                self.mixed = self.mixed_cells();
            }
            return false;
        }
        let from = self.labels.len() / self.nx;
        let to = (from + rows_per_step()).min(self.ny);
        let rows: Vec<(Vec<u32>, usize)> = (from..to)
            .into_par_iter()
            .map(|n| self.fine_row(n))
            .collect();
        for (row, walked) in rows {
            self.labels.extend(row);
            self.walked += walked;
        }
        to == self.ny
    }

    /// Walks every row left and returns the raster.
    pub fn finish_now(mut self) -> LabelGrid {
        while !self.step() {}
        self.finish()
    }

    /// The finished raster.
    fn finish(self) -> LabelGrid {
        debug_assert_eq!(self.labels.len(), self.nx * self.ny);
        LabelGrid {
            nx: self.nx,
            ny: self.ny,
            step: self.step,
            labels: self.labels,
            walked: self.walked,
        }
    }

    /// The labels of fine samples `points` (indices (m, n)), walked as one batch.
    fn walk(&self, points: &[(usize, usize)]) -> Vec<u32> {
        let mut batch = Batch::default();
        for (i, &(m, n)) in points.iter().enumerate() {
            batch.push(
                (m as f64 + 0.5) * self.step,
                (n as f64 + 0.5) * self.step,
                i as u32,
            );
        }
        let mut traced = vec![Traced::Ink(0); points.len()];
        self.walker.trace_batch(&mut batch, &mut traced);
        traced
            .into_iter()
            .map(|t| match t {
                Traced::Ink(k) => k as u32 + 1,
                Traced::Background(_) => BACKGROUND,
            })
            .collect()
    }

    /// Cells whose corners disagree where a wanted label is among them, and their eight
    /// neighbours (so that a boundary bulging between two coarse corners is found too):
    /// these are walked sample by sample.
    fn mixed_cells(&self) -> Vec<Vec<bool>> {
        let (cx, cy, coarse) = (self.cx, self.cy, &self.coarse);
        let is_wanted = |l: u32| self.wanted.get(l as usize).copied().unwrap_or(false);
        let differs: Vec<Vec<bool>> = (0..cy - 1)
            .map(|my| {
                (0..cx - 1)
                    .map(|mx| {
                        let c = [
                            coarse[my][mx],
                            coarse[my][mx + 1],
                            coarse[my + 1][mx],
                            coarse[my + 1][mx + 1],
                        ];
                        c.iter().any(|&l| l != c[0]) && c.iter().any(|&l| is_wanted(l))
                    })
                    .collect()
            })
            .collect();
        (0..cy - 1)
            .map(|my| {
                (0..cx - 1)
                    .map(|mx| {
                        (my.saturating_sub(1)..(my + 2).min(cy - 1)).any(|y| {
                            (mx.saturating_sub(1)..(mx + 2).min(cx - 1)).any(|x| differs[y][x])
                        })
                    })
                    .collect()
            })
            .collect()
    }

    /// Fine row `n`: each sample walked where its cell (or the cell before, on a coarse
    /// line) is mixed, else its coarse block's label; and how many were walked.
    fn fine_row(&self, n: usize) -> (Vec<u32>, usize) {
        let (cx, cy) = (self.cx, self.cy);
        // Cells holding fine index i along one axis: i / STRIDE, and the one before
        // when i lies on a coarse line.
        let cells_of = |i: usize, cells: usize| {
            let c = (i / STRIDE).min(cells - 1);
            let before = (i.is_multiple_of(STRIDE) && c > 0).then(|| c - 1);
            (c, before)
        };
        let mut row = vec![BACKGROUND; self.nx];
        let mut todo = Vec::new();
        let (ry, ry_before) = cells_of(n, cy - 1);
        for (m, slot) in row.iter_mut().enumerate() {
            if m.is_multiple_of(STRIDE) && n.is_multiple_of(STRIDE) {
                *slot = self.coarse[n / STRIDE][m / STRIDE];
                continue;
            }
            let (rx, rx_before) = cells_of(m, cx - 1);
            let refine = [Some(rx), rx_before].into_iter().flatten().any(|x| {
                [Some(ry), ry_before]
                    .into_iter()
                    .flatten()
                    .any(|y| self.mixed[y][x])
            });
            if refine {
                todo.push((m, n));
            } else {
                *slot = self.coarse[ry][rx];
            }
        }
        let out = self.walk(&todo);
        for (&(m, _), &l) in todo.iter().zip(&out) {
            row[m] = l;
        }
        (row, todo.len())
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
