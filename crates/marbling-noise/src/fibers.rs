//! Paper and canvas height fields after Kaplan & Cohen 2005: many short
//! rectangular fibers of a given length and width are "drawn" into a height field (the
//! height counts the fibers covering a point), randomly oriented for paper, along the
//! cardinal directions with weights for woven canvas, with optional impurities (small dark
//! specks). Unlike the paper's global list, fibers are generated per grid cell from the
//! cell's seeded stream (a Poisson count, then three uniforms per fiber), so any region
//! at any zoom is reproducible without generating the rest.
//!
//! Units: output pixels. Fiber coverage is antialiased over one pixel; by Campbell's
//! theorem the height has mean ρ·L·W and variance ρ·(L − ⅓)(W − ⅓) (ρ fibers per
//! pixel², length L ≥ 1, width W ≥ 1), which normalises it to zero mean and unit
//! variance; impurities then subtract `strength` per speck. Keep in sync with
//! `shaders/fibers.wgsl`.

use crate::field::Field;
use crate::hash::{CellRng, floor_i32, poisson_split, wrap_cell};
use std::f32::consts::PI;

/// Most fibers expected per generation cell; cells shrink below the fiber reach to keep
/// the Poisson mean under this.
pub const MAX_FIBERS_PER_CELL: f32 = 48.0;

/// XOR-ed into the seed for the impurity process.
pub const IMPURITY_SEED: u32 = 0x5BD1_E995;

/// Fiber orientations.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FiberLayout {
    /// Uniformly random orientations (paper).
    Paper,
    /// Horizontal or vertical threads, chosen with probabilities proportional to
    /// `[horizontal, vertical]` (woven canvas).
    Canvas {
        /// Relative weights of horizontal and vertical threads (≥ 0, not both 0).
        weights: [f32; 2],
    },
}

/// Small dark specks pressed into the sheet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Impurities {
    /// Specks per pixel².
    pub density: f32,
    /// Speck radius, pixels.
    pub radius: f32,
    /// Depth of a speck in units of the normalised height (standard deviations).
    pub strength: f32,
}

/// Parameters of a paper or canvas height field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FiberParams {
    /// Paper or canvas.
    pub layout: FiberLayout,
    /// Fiber length L, pixels (≥ 1).
    pub length: f32,
    /// Fiber width W, pixels (≥ 1).
    pub width: f32,
    /// ρ, fiber centres per pixel² (e.g. 0.3; Kaplan & Cohen use 0.8–1.5 at 512²).
    pub density: f32,
    /// Seed.
    pub seed: u32,
    /// Tile period in pixels (cells are sized to divide it and wrap).
    pub period: Option<u32>,
    /// Optional impurities.
    pub impurities: Option<Impurities>,
}

/// A grid of generation cells for one Poisson process.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Grid {
    pub(crate) cell: f32,
    pub(crate) reach_cells: i32,
    pub(crate) period_cells: i32,
    pub(crate) exp_neg_part: f32,
    pub(crate) poisson_parts: u32,
}

impl Grid {
    fn new(reach: f32, density: f32, period: Option<u32>) -> Self {
        let mut cell = (2.0 * reach).min((MAX_FIBERS_PER_CELL / density).sqrt());
        let mut period_cells = 0;
        if let Some(p) = period.filter(|&p| p > 0) {
            let cells = ((p as f32 / cell).floor() as i32).max(1);
            cell = p as f32 / cells as f32;
            period_cells = cells;
        }
        let (exp_neg_part, poisson_parts) = poisson_split(density * cell * cell);
        Self {
            cell,
            reach_cells: (reach / cell).ceil() as i32,
            period_cells,
            exp_neg_part,
            poisson_parts,
        }
    }
}

/// A ready-to-evaluate paper or canvas height field.
#[derive(Clone, Debug)]
pub struct Fibers {
    params: FiberParams,
    pub(crate) fibers: Grid,
    pub(crate) specks: Option<Grid>,
    pub(crate) horizontal_probability: f32,
    pub(crate) mean: f32,
    pub(crate) inv_std: f32,
}

impl Fibers {
    /// Precomputes grids and normalisation.
    #[must_use]
    pub fn new(params: FiberParams) -> Self {
        let (half_l, half_w) = (0.5 * params.length + 0.5, 0.5 * params.width + 0.5);
        let reach = (half_l * half_l + half_w * half_w).sqrt();
        let horizontal_probability = match params.layout {
            FiberLayout::Paper => 0.0,
            FiberLayout::Canvas { weights } => weights[0] / (weights[0] + weights[1]),
        };
        let specks = params
            .impurities
            .map(|i| Grid::new(i.radius + 0.5, i.density, params.period));
        Self {
            fibers: Grid::new(reach, params.density, params.period),
            specks,
            horizontal_probability,
            mean: params.density * params.length * params.width,
            inv_std: 1.0
                / (params.density * (params.length - 1.0 / 3.0) * (params.width - 1.0 / 3.0))
                    .sqrt(),
            params,
        }
    }

    /// The parameters.
    #[must_use]
    pub fn params(&self) -> &FiberParams {
        &self.params
    }

    /// Number of fibers covering (x, y), antialiased (the raw height).
    #[must_use]
    pub fn height(&self, x: f32, y: f32) -> f32 {
        let p = &self.params;
        let g = &self.fibers;
        let (half_l, half_w) = (0.5 * p.length + 0.5, 0.5 * p.width + 0.5);
        let mut h = 0.0;
        visit(g, x, y, p.seed, |rng, cx, cy| {
            let ox = (cx + rng.next_f32()) * g.cell;
            let oy = (cy + rng.next_f32()) * g.cell;
            let u = rng.next_f32();
            let (c, s) = match p.layout {
                FiberLayout::Paper => {
                    let a = PI * u;
                    (a.cos(), a.sin())
                }
                FiberLayout::Canvas { .. } => {
                    if u < self.horizontal_probability {
                        (1.0, 0.0)
                    } else {
                        (0.0, 1.0)
                    }
                }
            };
            let (dx, dy) = (x - ox, y - oy);
            let along = (dx * c + dy * s).abs();
            let across = (dy * c - dx * s).abs();
            h += (half_l - along).clamp(0.0, 1.0) * (half_w - across).clamp(0.0, 1.0);
        });
        h
    }

    /// Total speck coverage at (x, y) (0 without impurities).
    #[must_use]
    pub fn specks(&self, x: f32, y: f32) -> f32 {
        let (Some(g), Some(imp)) = (&self.specks, &self.params.impurities) else {
            return 0.0;
        };
        let mut cover = 0.0;
        visit(g, x, y, self.params.seed ^ IMPURITY_SEED, |rng, cx, cy| {
            let ox = (cx + rng.next_f32()) * g.cell;
            let oy = (cy + rng.next_f32()) * g.cell;
            let d = ((x - ox).powi(2) + (y - oy).powi(2)).sqrt();
            cover += (imp.radius + 0.5 - d).clamp(0.0, 1.0);
        });
        cover
    }

    /// The height normalised to zero mean and unit variance, minus impurities.
    #[must_use]
    pub fn eval(&self, x: f32, y: f32) -> f32 {
        let n = (self.height(x, y) - self.mean) * self.inv_std;
        match &self.params.impurities {
            Some(imp) => n - imp.strength * self.specks(x, y),
            None => n,
        }
    }
}

/// Calls `f(rng, cell_x, cell_y)` once per point of the Poisson process of `g` in the
/// cells within reach of (x, y); `rng` is positioned after the count.
#[inline]
fn visit(g: &Grid, x: f32, y: f32, seed: u32, mut f: impl FnMut(&mut CellRng, f32, f32)) {
    let ix = floor_i32(x / g.cell);
    let iy = floor_i32(y / g.cell);
    let k = g.reach_cells;
    for cy in iy - k..=iy + k {
        for cx in ix - k..=ix + k {
            let mut rng = CellRng::new(
                wrap_cell(cx, g.period_cells),
                wrap_cell(cy, g.period_cells),
                seed,
            );
            let count = rng.poisson_parts(g.exp_neg_part, g.poisson_parts);
            for _ in 0..count {
                f(&mut rng, cx as f32, cy as f32);
            }
        }
    }
}

impl Field for Fibers {
    fn sample(&self, x: f32, y: f32) -> f32 {
        self.eval(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalised_moments() {
        let f = Fibers::new(FiberParams {
            layout: FiberLayout::Paper,
            length: 12.0,
            width: 2.0,
            density: 0.2,
            seed: 3,
            period: None,
            impurities: None,
        });
        let (mut s, mut s2) = (0.0_f64, 0.0_f64);
        let n = 200;
        for j in 0..n {
            for i in 0..n {
                let v = f64::from(f.eval(i as f32 * 2.3 + 0.5, j as f32 * 2.3 + 0.5));
                s += v;
                s2 += v * v;
            }
        }
        let c = f64::from(n * n);
        assert!((s / c).abs() < 0.1, "mean {}", s / c);
        assert!((s2 / c - (s / c).powi(2) - 1.0).abs() < 0.12, "var");
    }
}
