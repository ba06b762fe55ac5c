//! The contour method: outlines of ink regions read off the exact label raster
//! ([`LabelGrid`]) by marching squares, for regions whose forward tracing would cost
//! more vertices than their picture needs.
//!
//! Region k is drawn as the samples labelled k, grown by `reach` samples into ink that
//! is newer than k (never into older ink or the background). Newer ink is painted over
//! it, so the growth is hidden, and two abutting regions never leave an antialiased
//! seam of whatever lies under both: the older one continues under the newer one.
//!
//! Marching squares runs on the binary mask of each region, tile by tile, with every
//! crossing at the midpoint of its grid edge; segments are directed so that the inside
//! is always on the same side, hence every ring of a region has the same orientation
//! relative to its inside, and holes wind the other way (nonzero fill). Crossings are
//! keyed by their grid edge, so the segments of neighbouring tiles join exactly.

use crate::cellhash::CellHasher;
use crate::dense::take_dense_pixels;
use crate::labels::{LabelGrid, LabelWalk, OUTSIDE};
use crate::simplify::simplify_ring;
use crate::surface_layers::{Channels, RasterLayer};
use crate::{Method, Outline, TraceOptions, TraceStats, VectorError};
use kurbo::Point;
use marbling_core::color::linear_to_srgb;
use marbling_core::{CompiledOp, Design, Rgb8, RgbaImage, output_size};
use rayon::prelude::*;
use std::collections::HashMap;
use std::hash::BuildHasherDefault;

/// Most samples of a label raster (128 MiB of labels); a finer spacing is coarsened to
/// fit.
pub const MAX_SAMPLES: f64 = 32.0 * 1024.0 * 1024.0;

/// What the contour method gives: outlines, the patch of dense pixels, and counts.
pub struct Contoured {
    /// Outlines of the handed regions that show, oldest first.
    pub outlines: Vec<Outline>,
    /// The dense pixels ([`crate::dense`]) as a patch over the outlines, if any.
    pub dense: Option<RasterLayer>,
    /// What it cost.
    pub stats: TraceStats,
}

/// The outlines of the regions `handed` (indices into the compiled `ops`) by the
/// contour method: a label raster of spacing `contour_step`·T, the dense pixels taken
/// out as a raster patch, rings grown `contour_reach` under newer ink (and under the
/// patch) and simplified within one spacing. `underlay` colours the background
/// of the patch for designs with a noise background.
pub fn contour_outlines(
    design: &Design,
    ops: &[CompiledOp],
    handed: &[usize],
    opts: &TraceOptions,
    underlay: Option<&RgbaImage>,
) -> Result<Contoured, VectorError> {
    let grid = label_walk(design, ops, handed, opts).finish_now();
    let mut job = ContourJob::new(grid, design, ops, handed, opts, underlay)?;
    while !job.step(usize::MAX) {}
    Ok(job.finish())
}

/// The label raster that the contour method reads the regions `handed` off: spacing
/// `contour_step`·T, coarsened to at most [`MAX_SAMPLES`] samples.
pub fn label_walk(
    design: &Design,
    ops: &[CompiledOp],
    handed: &[usize],
    opts: &TraceOptions,
) -> LabelWalk {
    let area = f64::from(design.width) * f64::from(design.height);
    let step = (opts.spacing() * opts.contour_step).max((area / MAX_SAMPLES).sqrt());
    LabelWalk::new(design, step, wanted(ops, handed))
}

/// Which labels are handed regions: label j + 1 for each compiled op j in `handed`.
fn wanted(ops: &[CompiledOp], handed: &[usize]) -> Vec<bool> {
    let mut wanted = vec![false; ops.len() + 1];
    for &j in handed {
        wanted[j + 1] = true;
    }
    wanted
}

/// Where a visible crossing between two labels sits ([`srgb_blend_shift`] in grid
/// steps, within ±[`MAX_SHIFT`]).
struct Shift {
    /// Colour of each label: the background, then each compiled op's ink.
    palette: Vec<Rgb8>,
    /// A noise or image underlay: edges against the background do not move.
    underlay: bool,
    /// Output pixels per grid step.
    step_px: f64,
}

impl Shift {
    fn at(&self, inner: u32, out: u32) -> f64 {
        let (Some(a), Some(b)) = (
            self.palette.get(inner as usize),
            self.palette.get(out as usize),
        ) else {
            return 0.0;
        };
        if self.underlay && (inner == 0 || out == 0) {
            return 0.0;
        }
        (srgb_blend_shift(*a, *b) / self.step_px).clamp(-MAX_SHIFT, MAX_SHIFT)
    }
}

/// The contour method on a finished label raster, a few tiles or regions at a time
/// ([`ContourJob::step`]): marching squares tile by tile, then each region's rings
/// linked and simplified.
pub struct ContourJob {
    grid: LabelGrid,
    wanted: Vec<bool>,
    reach: usize,
    shift: Shift,
    /// Ink of each compiled op (None: it lays none).
    inks: Vec<Option<Rgb8>>,
    /// Simplification bounds, design pixels: visible parts, parts under newer paint.
    epsilon: f64,
    hidden_epsilon: f64,
    tiles: Vec<(isize, isize)>,
    next_tile: usize,
    by_label: HashMap<u32, Vec<Segment>>,
    /// Labels with segments, ascending (set once every tile is done).
    labels: Vec<u32>,
    next_label: usize,
    outlines: Vec<Outline>,
    dense: Option<RasterLayer>,
    stats: TraceStats,
}

impl ContourJob {
    /// Takes the dense pixels out of `grid` (the raster of [`label_walk`], complete)
    /// and readies marching squares for the regions `handed`.
    pub fn new(
        mut grid: LabelGrid,
        design: &Design,
        ops: &[CompiledOp],
        handed: &[usize],
        opts: &TraceOptions,
        underlay: Option<&RgbaImage>,
    ) -> Result<Self, VectorError> {
        let step = grid.step;
        let size = output_size(design, opts.scale)?;
        let mut palette = vec![design.background];
        palette.extend(ops.iter().map(|o| o.ink().unwrap_or(design.background)));
        let (patch, dense_pixels) =
            take_dense_pixels(&mut grid, opts.scale, size, &palette, underlay);
        let dense = if dense_pixels > 0 {
            Some(RasterLayer::new(patch, Channels::Rgba)?)
        } else {
            None
        };
        let reach = (opts.contour_reach / opts.scale / step).ceil() as usize;
        // Visible parts may move by one grid step (T/4 by default); hidden parts lie
        // `reach` inside newer paint: they may move by half that.
        let epsilon = step;
        let hidden_epsilon = (reach as f64 * step / 2.0).max(epsilon);
        let stats = TraceStats {
            regions: handed.len(),
            contour_regions: handed.len(),
            contour_samples: grid.walked,
            contour_step: step * opts.scale,
            dense_pixels,
            ..TraceStats::default()
        };
        Ok(Self {
            tiles: tiles(&grid),
            grid,
            wanted: wanted(ops, handed),
            reach,
            shift: Shift {
                palette,
                underlay: underlay.is_some(),
                step_px: step * opts.scale,
            },
            inks: ops.iter().map(CompiledOp::ink).collect(),
            epsilon,
            hidden_epsilon,
            next_tile: 0,
            by_label: HashMap::new(),
            labels: Vec::new(),
            next_label: 0,
            outlines: Vec::new(),
            dense,
            stats,
        })
    }

    /// Tiles and regions done, and in all (regions are counted once the tiles are done).
    pub fn parts(&self) -> (usize, usize) {
        (
            self.next_tile + self.next_label,
            self.tiles.len() + self.labels.len(),
        )
    }

    /// Runs marching squares on up to `count` tiles, or once every tile is done, links
    /// and simplifies up to `count` regions; true when every region is done.
    pub fn step(&mut self, count: usize) -> bool {
        if self.next_tile < self.tiles.len() {
            let to = self.next_tile.saturating_add(count).min(self.tiles.len());
            let is_wanted =
                |l: u32| l != OUTSIDE && self.wanted.get(l as usize).copied().unwrap_or(false);
            let shift = |a: u32, b: u32| self.shift.at(a, b);
            let pieces: Vec<Vec<(u32, Vec<Segment>)>> = self.tiles[self.next_tile..to]
                .par_iter()
                .map(|&tile| {
                    tile_segments(&self.grid, tile, self.reach as isize, &is_wanted, &shift)
                })
                .collect();
            gather(&mut self.by_label, pieces);
            self.next_tile = to;
            if to == self.tiles.len() {
                self.labels = self.by_label.keys().copied().collect();
                self.labels.sort_unstable();
            }
            return false;
        }
        let to = self.next_label.saturating_add(count).min(self.labels.len());
        let segments: Vec<(u32, Vec<Segment>)> = self.labels[self.next_label..to]
            .iter()
            .map(|l| (*l, self.by_label.remove(l).unwrap_or_default()))
            .collect();
        let traced: Vec<(Outline, usize)> = segments
            .into_par_iter()
            .filter_map(|(label, segments)| self.outline(label, &link(&segments)))
            .collect();
        for (outline, refined) in traced {
            self.stats.refined_vertices += refined;
            self.stats.vertices += outline.vertices();
            self.stats.rings += outline.rings.len();
            self.outlines.push(outline);
        }
        self.next_label = to;
        to == self.labels.len()
    }

    /// The outlines, the dense patch and the counts, once [`ContourJob::step`] is done.
    pub fn finish(mut self) -> Contoured {
        self.stats.culled = self.stats.regions - self.outlines.len();
        Contoured {
            outlines: self.outlines,
            dense: self.dense,
            stats: self.stats,
        }
    }

    /// The simplified outline of region `label` from its `rings`, and the vertices
    /// before simplification; None when nothing of it is left.
    fn outline(&self, label: u32, rings: &[Ring]) -> Option<(Outline, usize)> {
        let op_index = label as usize - 1;
        let refined = rings.iter().map(Vec::len).sum();
        let rings: Vec<Vec<Point>> = rings
            .iter()
            .map(|ring| {
                let (points, hidden): (Vec<Point>, Vec<bool>) = ring.iter().copied().unzip();
                simplify_ring(&points, &hidden, self.epsilon, self.hidden_epsilon)
            })
            .filter(|ring| ring.len() >= 3)
            .collect();
        let color = (*self.inks.get(op_index)?)?;
        (!rings.is_empty()).then_some((
            Outline {
                op_index,
                color,
                method: Method::Contour,
                rings,
            },
            refined,
        ))
    }
}

/// Cells per tile side.
const TILE: isize = 64;

/// A grid edge: `(m, n, vertical)`, the edge from sample (m, n) to (m + 1, n), or to
/// (m, n + 1) when vertical; packed into one integer.
type EdgeKey = u64;

/// A directed segment: from, to, whether paint laid later covers its start, and where
/// its start lies.
type Segment = (EdgeKey, EdgeKey, bool, Point);

/// A ring of crossing points, each marked hidden when paint laid later covers it.
pub type Ring = Vec<(Point, bool)>;

fn key(m: isize, n: isize, vertical: bool) -> EdgeKey {
    (((n + 1) as u64) << 33) | (((m + 1) as u64) << 1) | u64::from(vertical)
}

/// Rings of every region whose label `wanted` holds, in design pixels (not simplified):
/// `(label, rings)`, sorted by label. A crossing is hidden when the sample outside it
/// holds newer ink (or the dense patch), which is painted over it. A visible crossing
/// lies between its two samples, moved from the midpoint towards the outside one by
/// `shift(inside label, outside label)` grid steps (in (−½, ½); positive: the inside
/// grows).
pub fn contours(
    grid: &LabelGrid,
    wanted: &[bool],
    reach: usize,
    shift: &(impl Fn(u32, u32) -> f64 + Sync),
) -> Vec<(u32, Vec<Ring>)> {
    let is_wanted = |l: u32| l != OUTSIDE && wanted.get(l as usize).copied().unwrap_or(false);
    let pieces: Vec<Vec<(u32, Vec<Segment>)>> = tiles(grid)
        .par_iter()
        .map(|&tile| tile_segments(grid, tile, reach as isize, &is_wanted, shift))
        .collect();
    let mut by_label = HashMap::new();
    gather(&mut by_label, pieces);
    let mut out: Vec<(u32, Vec<Ring>)> = by_label
        .into_par_iter()
        .map(|(label, segments)| (label, link(&segments)))
        .collect();
    out.sort_by_key(|(label, _)| *label);
    out
}

/// The corners (x0, y0) of the tiles of `grid`'s cells. Cells (m, n) run from −1 to
/// nx − 1 (and ny − 1): their corners include one sample of padding on every side, so
/// every ring closes.
fn tiles(grid: &LabelGrid) -> Vec<(isize, isize)> {
    let (nx, ny) = (grid.nx as isize, grid.ny as isize);
    (-1..ny)
        .step_by(TILE as usize)
        .flat_map(|y| (-1..nx).step_by(TILE as usize).map(move |x| (x, y)))
        .collect()
}

/// Adds the segments of some tiles to those gathered by label.
fn gather(by_label: &mut HashMap<u32, Vec<Segment>>, pieces: Vec<Vec<(u32, Vec<Segment>)>>) {
    for tile in pieces {
        for (label, segments) in tile {
            by_label.entry(label).or_default().extend(segments);
        }
    }
}

/// Segments of every wanted region in the cells of the tile at `(x0, y0)` (cell (m, n)
/// has corners (m, n) to (m + 1, n + 1)).
fn tile_segments(
    grid: &LabelGrid,
    (x0, y0): (isize, isize),
    reach: isize,
    is_wanted: &(impl Fn(u32) -> bool + Sync),
    shift: &(impl Fn(u32, u32) -> f64 + Sync),
) -> Vec<(u32, Vec<Segment>)> {
    let (x1, y1) = (
        (x0 + TILE).min(grid.nx as isize),
        (y0 + TILE).min(grid.ny as isize),
    );
    // The window of samples the masks need: the cell corners, grown by `reach`.
    let (wx0, wy0, wx1, wy1) = (x0 - reach, y0 - reach, x1 + 1 + reach, y1 + 1 + reach);
    let (ww, wh) = ((wx1 - wx0) as usize, (wy1 - wy0) as usize);
    let window: Vec<u32> = (wy0..wy1)
        .flat_map(|n| (wx0..wx1).map(move |m| grid.at(m, n)))
        .collect();
    let mut labels: Vec<u32> = window.iter().copied().filter(|&l| is_wanted(l)).collect();
    labels.sort_unstable();
    labels.dedup();
    let mut out = Vec::with_capacity(labels.len());
    let mut grown = vec![false; ww * wh];
    let mut rows = vec![false; ww * wh];
    for label in labels {
        // Square dilation of "holds `label`" by `reach`, separably: rows, then columns.
        for y in 0..wh {
            let row = &window[y * ww..(y + 1) * ww];
            running_any(
                |i| row[i] == label,
                ww,
                reach as usize,
                &mut rows[y * ww..(y + 1) * ww],
            );
        }
        for x in 0..ww {
            let mut column = vec![false; wh];
            running_any(|i| rows[i * ww + x], wh, reach as usize, &mut column);
            for (y, v) in column.into_iter().enumerate() {
                grown[y * ww + x] = v;
            }
        }
        let at = |m: isize, n: isize| (n - wy0) as usize * ww + (m - wx0) as usize;
        let inside = |m: isize, n: isize| {
            let i = at(m, n);
            let l = window[i];
            l == label || (grown[i] && l > label && l != OUTSIDE)
        };
        let step = grid.step;
        let crossing = |(om, on): (isize, isize), (im, il): (isize, isize)| {
            let (out, inner) = (window[at(om, on)], window[at(im, il)]);
            let hidden = out > label && out != OUTSIDE;
            let t = if hidden { 0.5 } else { 0.5 - shift(inner, out) };
            let p =
                |m: isize, n: isize| Point::new((m as f64 + 0.5) * step, (n as f64 + 0.5) * step);
            (p(om, on).lerp(p(im, il), t), hidden)
        };
        let mut segments = Vec::new();
        for n in y0..y1 {
            for m in x0..x1 {
                cell_segments(m, n, &inside, &crossing, &mut segments);
            }
        }
        if !segments.is_empty() {
            out.push((label, segments));
        }
    }
    out
}

/// Furthest a visible crossing moves from the midpoint of its grid edge, as a fraction
/// of the grid spacing.
const MAX_SHIFT: f64 = 0.45;

/// How far (output pixels) an edge between `inner` and `outer` ink moves into the
/// darker side so that an SVG renderer, which blends an edge pixel's coverage on sRGB
/// codes, shows about the colour a linear-light average gives: at half coverage the
/// renderer needs the lighter ink to cover f = (S − D)/(L − D) of the pixel, where S is
/// the sRGB code of the linear mean (summed over channels), so the edge moves by f − ½
/// (positive: `inner` grows).
pub fn srgb_blend_shift(inner: Rgb8, outer: Rgb8) -> f64 {
    let sum = |c: Rgb8| u32::from(c.r) + u32::from(c.g) + u32::from(c.b);
    let (light, dark, inner_light) = if sum(inner) >= sum(outer) {
        (inner, outer, true)
    } else {
        (outer, inner, false)
    };
    let (l, d) = (light.to_linear(), dark.to_linear());
    let (ls, ds) = ([light.r, light.g, light.b], [dark.r, dark.g, dark.b]);
    let (mut num, mut den) = (0.0, 0.0);
    for ch in 0..3 {
        let mean = linear_to_srgb(0.5 * (l[ch] + d[ch]));
        num += f64::from(mean) - f64::from(ds[ch]);
        den += f64::from(ls[ch]) - f64::from(ds[ch]);
    }
    if den <= 0.0 {
        return 0.0;
    }
    let grow = num / den - 0.5;
    if inner_light { grow } else { -grow }
}

/// `out[i]` = whether `f(j)` holds for some j within `r` of i (0 ≤ j < len).
fn running_any(f: impl Fn(usize) -> bool, len: usize, r: usize, out: &mut [bool]) {
    let mut count = 0usize;
    for j in 0..r.min(len) {
        count += usize::from(f(j));
    }
    for (i, o) in out.iter_mut().enumerate().take(len) {
        if i + r < len {
            count += usize::from(f(i + r));
        }
        if i > r {
            count -= usize::from(f(i - r - 1));
        }
        *o = count > 0;
    }
}

/// The directed segments of cell (m, n): corners clockwise on screen (y down) from the
/// top left; each run of inside corners gives one segment from the crossing where the
/// boundary (walked clockwise) enters the inside to the crossing where it leaves.
fn cell_segments(
    m: isize,
    n: isize,
    inside: &impl Fn(isize, isize) -> bool,
    crossing: &impl Fn((isize, isize), (isize, isize)) -> (Point, bool),
    out: &mut Vec<Segment>,
) {
    let corners = [(m, n), (m + 1, n), (m + 1, n + 1), (m, n + 1)];
    let corner = corners.map(|(x, y)| inside(x, y));
    if corner.iter().all(|&c| c == corner[0]) {
        return;
    }
    // Edge i runs from corner i to corner i + 1.
    let edges = [
        key(m, n, false),
        key(m + 1, n, true),
        key(m, n + 1, false),
        key(m, n, true),
    ];
    for entry in 0..4 {
        if corner[entry] || !corner[(entry + 1) % 4] {
            continue;
        }
        let exit = (1..4)
            .map(|d| (entry + d) % 4)
            .find(|&e| corner[e] && !corner[(e + 1) % 4])
            .unwrap_or(entry);
        // The entry crossing lies between outside corner `entry` and the next corner.
        let (p, hidden) = crossing(corners[entry], corners[(entry + 1) % 4]);
        out.push((edges[entry], edges[exit], hidden, p));
    }
}

/// Joins directed segments (each crossing starts exactly one and ends exactly one) into
/// closed rings of crossing points.
fn link(segments: &[Segment]) -> Vec<Ring> {
    let mut next: HashMap<EdgeKey, (EdgeKey, bool, Point), BuildHasherDefault<CellHasher>> =
        HashMap::with_capacity_and_hasher(segments.len(), BuildHasherDefault::default());
    for &(a, b, hidden, p) in segments {
        next.insert(a, (b, hidden, p));
    }
    let mut rings = Vec::new();
    for &(start, ..) in segments {
        let Some((mut at, hidden, p)) = next.remove(&start) else {
            continue;
        };
        let mut ring = vec![(p, hidden)];
        while at != start {
            match next.remove(&at) {
                Some((b, hidden, p)) => {
                    ring.push((p, hidden));
                    at = b;
                }
                None => break,
            }
        }
        rings.push(ring);
    }
    rings
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A hand-made grid: `rows` of label digits.
    fn grid(rows: &[&str]) -> LabelGrid {
        let labels: Vec<u32> = rows
            .iter()
            .flat_map(|r| r.bytes().map(|b| u32::from(b - b'0')))
            .collect();
        LabelGrid {
            nx: rows[0].len(),
            ny: rows.len(),
            step: 1.0,
            labels,
            walked: 0,
        }
    }

    /// Signed area (shoelace; positive clockwise on screen with y down).
    fn area(ring: &[(Point, bool)]) -> f64 {
        let n = ring.len();
        (0..n)
            .map(|i| {
                let (a, b) = (ring[i].0, ring[(i + 1) % n].0);
                a.x * b.y - b.x * a.y
            })
            .sum::<f64>()
            / 2.0
    }

    #[test]
    fn a_ring_with_a_hole_winds_both_ways() {
        let g = grid(&["00000", "01110", "01010", "01110", "00000"]);
        let mut wanted = vec![false; 2];
        wanted[1] = true;
        let out = contours(&g, &wanted, 0, &|_, _| 0.0);
        assert_eq!(out.len(), 1);
        let rings = &out[0].1;
        assert_eq!(rings.len(), 2, "outer ring and hole");
        let mut areas: Vec<f64> = rings.iter().map(|r| area(r)).collect();
        areas.sort_by(|a, b| b.abs().total_cmp(&a.abs()));
        // Marching squares cuts the corners: the outer 3×3 square less four triangles
        // of ⅛ (8.5), the hole a diamond of area ½, wound the other way.
        assert!((areas[0].abs() - 8.5).abs() < 1e-9, "{areas:?}");
        assert!((areas[1].abs() - 0.5).abs() < 1e-9, "{areas:?}");
        assert!(
            areas[0] * areas[1] < 0.0,
            "opposite orientations: {areas:?}"
        );
    }

    #[test]
    fn a_region_grows_under_newer_ink_only() {
        // Region 1 between older ink 0 (left) and newer ink 2 (right): with reach 2 it
        // extends two samples into 2 but none into 0.
        let g = grid(&["0011222", "0011222", "0011222"]);
        let mut wanted = vec![false; 3];
        wanted[1] = true;
        let xs = |reach| {
            let out = contours(&g, &wanted, reach, &|_, _| 0.0);
            let ring = &out[0].1[0];
            let min = ring.iter().map(|p| p.0.x).fold(f64::INFINITY, f64::min);
            let max = ring.iter().map(|p| p.0.x).fold(f64::NEG_INFINITY, f64::max);
            (min, max)
        };
        assert_eq!(xs(0), (2.0, 4.0));
        assert_eq!(xs(2), (2.0, 6.0));
    }
}
