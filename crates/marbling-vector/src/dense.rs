//! Output pixels where three or more inks (or inks and the background) meet: detail
//! finer than an output pixel, which no stack of antialiased vector fills can
//! reproduce. An antialiased fill blends by coverage as if it were spread evenly
//! over what lies beneath, which holds for two colours in a pixel (the older one grown
//! under the newer) but not for three. Such pixels are exported as one raster patch at
//! the output size, coloured from the label raster exactly as the reference's 4×4
//! supersampling colours them, and the contour method does not trace inside them.

use crate::labels::{LabelGrid, OUTSIDE};
use marbling_core::color::{linear_to_srgb, srgb_to_linear};
use marbling_core::{Rgb8, RgbaImage};

/// Label given to samples of dense pixels before contouring: newer than every ink, so
/// regions grow under the patch, and never traced itself.
pub const DENSE: u32 = OUTSIDE - 1;

/// Finds the dense pixels of a `w × h` output (`scale` output pixels per design pixel)
/// on `grid`, relabels their samples [`DENSE`], and returns the patch (opaque where
/// dense, transparent elsewhere) and the number of dense pixels. `palette[l]` is the
/// colour of label l; `underlay`, where given, colours the background's samples.
pub fn take_dense_pixels(
    grid: &mut LabelGrid,
    scale: f64,
    (w, h): (u32, u32),
    palette: &[Rgb8],
    underlay: Option<&RgbaImage>,
) -> (RgbaImage, usize) {
    let pixel_of = |i: usize| ((i as f64 + 0.5) * grid.step * scale).floor() as i64;
    let columns: Vec<i64> = (0..grid.nx).map(pixel_of).collect();
    let rows: Vec<i64> = (0..grid.ny).map(pixel_of).collect();
    let (wu, hu) = (w as usize, h as usize);
    // Up to three distinct labels per pixel; the third marks it dense.
    let mut seen = vec![[OUTSIDE; 3]; wu * hu];
    let pixel = |m: usize, n: usize| {
        let (x, y) = (columns[m], rows[n]);
        (x >= 0 && y >= 0 && (x as usize) < wu && (y as usize) < hu)
            .then(|| y as usize * wu + x as usize)
    };
    for n in 0..grid.ny {
        for m in 0..grid.nx {
            let Some(p) = pixel(m, n) else { continue };
            let l = grid.labels[n * grid.nx + m];
            let s = &mut seen[p];
            if let Some(slot) = s.iter_mut().find(|v| **v == OUTSIDE || **v == l) {
                *slot = l;
            }
        }
    }
    let junction: Vec<bool> = seen.iter().map(|s| s[2] != OUTSIDE).collect();
    let dense = with_neighbours(&junction, wu, hu);
    let linear: Vec<[f32; 3]> = palette.iter().map(|c| c.to_linear()).collect();
    let mut sums = vec![([0.0f32; 3], 0u32); wu * hu];
    for n in 0..grid.ny {
        for m in 0..grid.nx {
            let Some(p) = pixel(m, n) else { continue };
            if !dense[p] {
                continue;
            }
            let i = n * grid.nx + m;
            let l = grid.labels[i] as usize;
            let c = match underlay {
                Some(u) if l == 0 => {
                    let q = &u.pixels[p * 4..p * 4 + 3];
                    [q[0], q[1], q[2]].map(srgb_to_linear)
                }
                _ => linear[l],
            };
            let s = &mut sums[p];
            for (acc, v) in s.0.iter_mut().zip(c) {
                *acc += v;
            }
            s.1 += 1;
            grid.labels[i] = DENSE;
        }
    }
    let mut patch = RgbaImage::filled(w, h, [0, 0, 0, 0]);
    let mut count = 0;
    for (p, (sum, k)) in sums.iter().enumerate() {
        if *k == 0 {
            continue;
        }
        count += 1;
        let c = sum.map(|v| quantised(linear_to_srgb(v / *k as f32)));
        patch.pixels[p * 4..p * 4 + 4].copy_from_slice(&[c[0], c[1], c[2], 255]);
    }
    (patch, count)
}

/// Pixels with three or more labels, and those with at least [`JOINING`] such
/// neighbours (of 8): next to a junction two-ink pixels carry edges too short to be
/// worth their vertices, and the patch colours them exactly.
fn with_neighbours(junction: &[bool], w: usize, h: usize) -> Vec<bool> {
    let mut dense = junction.to_vec();
    for y in 0..h {
        for x in 0..w {
            if junction[y * w + x] {
                continue;
            }
            let mut k = 0;
            for yy in y.saturating_sub(1)..(y + 2).min(h) {
                for xx in x.saturating_sub(1)..(x + 2).min(w) {
                    k += usize::from(junction[yy * w + xx]);
                }
            }
            dense[y * w + x] = k >= JOINING;
        }
    }
    dense
}

/// Junction neighbours that bring a pixel into the patch.
const JOINING: usize = 3;

/// A patch colour code rounded to the middle of its group of 4 (error ≤ 2/255), which
/// makes the PNG about a fifth smaller.
fn quantised(v: u8) -> u8 {
    (v & !3) | 2
}
