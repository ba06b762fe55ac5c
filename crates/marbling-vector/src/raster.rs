//! Raster preview of traced outlines with tiny-skia (antialiased, any scale).

use crate::{TraceOptions, VectorDesign, VectorError, trace};
use marbling_core::color::{linear_to_srgb, srgb_to_linear};
use marbling_core::sampling::Sample;
use marbling_core::{Antialias, Design, Rgb8, RgbaImage, output_size};
use rayon::prelude::*;
use tiny_skia::{Color, FillRule, Mask, Paint, Path, PathBuilder, Pixmap, Transform};

/// How a preview is antialiased.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Blend {
    /// Point samples at exactly the positions (and weights) the CPU reference renderer
    /// uses for this pattern (the adaptive pattern uses its fine samples everywhere):
    /// one non-antialiased tiny-skia fill per sample offset, each sample taking the
    /// colour of the topmost region covering it, averaged in linear light. Abutting
    /// regions show no background seams. `Linear(Antialias::Rgss)` is the default and
    /// what `marbling render --backend vector` uses.
    Linear(Antialias),
    /// tiny-skia's analytic antialiasing, region after region, blended on sRGB-encoded
    /// values: what browsers, resvg and librsvg do with the exported SVG (including the
    /// faint seams where two antialiased edges abut).
    Srgb,
}

impl Default for Blend {
    fn default() -> Self {
        Self::Linear(Antialias::Rgss)
    }
}

/// Rasterises `vector` at `scale` output pixels per design pixel, with the same output
/// size and pixel convention as the CPU reference renderer (pixel (i, j) covers the
/// design square [i/s, (i+1)/s) × [j/s, (j+1)/s)). Regions are filled in painter's
/// order, nonzero rule, antialiased as `blend` says.
pub fn rasterize(
    vector: &VectorDesign,
    scale: f64,
    blend: Blend,
) -> Result<RgbaImage, VectorError> {
    let probe = Design::new(vector.width, vector.height, vector.background);
    let (w, h) = output_size(&probe, scale)?;
    let transform = Transform::from_scale(scale as f32, scale as f32);
    let paths = vector
        .outlines
        .iter()
        .filter_map(|o| Some((path(&o.rings)?, o.color)));
    let underlay = vector.underlay.as_ref().map(|l| resized(&l.image, w, h));
    let mut image = match blend {
        Blend::Srgb => srgb(w, h, vector.background, underlay, paths, transform)?,
        Blend::Linear(aa) => sampled(
            w,
            h,
            vector.background,
            underlay.as_ref(),
            paths.collect(),
            scale,
            aa.refinement().unwrap_or(aa.samples()),
        ),
    };
    if let Some(dense) = &vector.dense {
        let dense = resized(&dense.image, w, h);
        for (px, d) in image
            .pixels
            .chunks_exact_mut(4)
            .zip(dense.pixels.chunks_exact(4))
        {
            if d[3] != 0 {
                px.copy_from_slice(d);
            }
        }
    }
    if let Some(grain) = &vector.grain {
        let grain = resized(&grain.image, w, h);
        for (px, g) in image
            .pixels
            .chunks_exact_mut(4)
            .zip(grain.pixels.chunks_exact(4))
        {
            for v in px.iter_mut().take(3) {
                *v = match blend {
                    // What SVG renderers do: multiply the encoded values.
                    Blend::Srgb => ((u16::from(*v) * u16::from(g[0]) + 127) / 255) as u8,
                    Blend::Linear(_) => linear_to_srgb(srgb_to_linear(*v) * srgb_to_linear(g[0])),
                };
            }
        }
    }
    Ok(image)
}

/// `image` at `w × h` pixels (itself when it already is; else nearest pixels).
fn resized(image: &RgbaImage, w: u32, h: u32) -> RgbaImage {
    if image.width == w && image.height == h {
        return image.clone();
    }
    let mut out = RgbaImage::filled(w, h, [0, 0, 0, 255]);
    for y in 0..h {
        let sy = (u64::from(y) * u64::from(image.height) / u64::from(h)) as u32;
        for x in 0..w {
            let sx = (u64::from(x) * u64::from(image.width) / u64::from(w)) as u32;
            out.set_pixel(x, y, image.pixel(sx, sy));
        }
    }
    out
}

/// Traces `design` at `opts` and rasterises it at `opts.scale` in linear light: the
/// `--backend vector` render.
pub fn render_vector(design: &Design, opts: &TraceOptions) -> Result<RgbaImage, VectorError> {
    rasterize(&trace(design, opts)?, opts.scale, Blend::default())
}

/// A tiny-skia path of closed subpaths through `rings` (design pixels); `None` if
/// degenerate.
fn path(rings: &[Vec<kurbo::Point>]) -> Option<Path> {
    let n: usize = rings.iter().map(Vec::len).sum();
    let mut pb = PathBuilder::with_capacity(n + rings.len(), n);
    for ring in rings {
        let Some((first, rest)) = ring.split_first() else {
            continue;
        };
        pb.move_to(first.x as f32, first.y as f32);
        for p in rest {
            pb.line_to(p.x as f32, p.y as f32);
        }
        pb.close();
    }
    pb.finish()
}

/// Plain tiny-skia painting on an sRGB pixmap.
fn srgb(
    w: u32,
    h: u32,
    background: Rgb8,
    underlay: Option<RgbaImage>,
    paths: impl Iterator<Item = (Path, Rgb8)>,
    transform: Transform,
) -> Result<RgbaImage, VectorError> {
    let mut pixmap = Pixmap::new(w, h).ok_or(VectorError::BadScale(f64::from(w)))?;
    match underlay {
        Some(image) => pixmap.data_mut().copy_from_slice(&image.pixels),
        None => pixmap.fill(Color::from_rgba8(
            background.r,
            background.g,
            background.b,
            255,
        )),
    }
    let mut paint = Paint {
        anti_alias: true,
        ..Paint::default()
    };
    for (path, c) in paths {
        paint.set_color(Color::from_rgba8(c.r, c.g, c.b, 255));
        pixmap.fill_path(&path, &paint, FillRule::Winding, transform, None);
    }
    Ok(RgbaImage {
        width: w,
        height: h,
        pixels: pixmap.take(),
    })
}

/// Output rows per band of the sampled preview.
const BAND_ROWS: u32 = 16;

/// Point-sampled rendering: for each band of output rows and each sample offset, every
/// region's non-antialiased tiny-skia mask (which fills the pixels whose centres are
/// inside) writes its palette index into that sample's buffer; each output pixel then
/// averages its samples in linear light. Samples of the background take the
/// underlay's pixel where there is one.
fn sampled(
    w: u32,
    h: u32,
    background: Rgb8,
    underlay: Option<&RgbaImage>,
    regions: Vec<(Path, Rgb8)>,
    scale: f64,
    samples: &[Sample],
) -> RgbaImage {
    let to_px = Transform::from_scale(scale as f32, scale as f32);
    let mut srgb = vec![background];
    srgb.extend(regions.iter().map(|(_, c)| *c));
    let palette: Vec<[f32; 3]> = srgb.iter().map(|c| c.to_linear()).collect();
    // Pixel bounds of each region, one pixel wider than its path on every side (sample
    // offsets shift it by less than a pixel), clamped to the image: x0, y0, x1, y1.
    let bounds: Vec<Option<[u32; 4]>> = regions
        .iter()
        .map(|(path, _)| {
            let b = path.bounds().transform(to_px)?;
            let x0 = (b.left().floor() - 1.0).max(0.0) as u32;
            let y0 = (b.top().floor() - 1.0).max(0.0) as u32;
            let x1 = ((b.right().ceil() + 1.0).max(0.0) as u32).min(w);
            let y1 = ((b.bottom().ceil() + 1.0).max(0.0) as u32).min(h);
            (x0 < x1 && y0 < y1).then_some([x0, y0, x1, y1])
        })
        .collect();
    let n = samples.len();
    let mut pixels = vec![255u8; w as usize * h as usize * 4];
    let band_bytes = w as usize * 4 * BAND_ROWS as usize;
    pixels
        .par_chunks_mut(band_bytes)
        .enumerate()
        .for_each(|(band, out)| {
            let rows = (out.len() / (w as usize * 4)) as u32;
            let (by0, by1) = (band as u32 * BAND_ROWS, band as u32 * BAND_ROWS + rows);
            // index[(row · w + x) · n + sample]
            let mut index = vec![0u32; (w * rows) as usize * n];
            for (k, ((path, _), b)) in regions.iter().zip(&bounds).enumerate() {
                let Some([x0, y0, x1, y1]) = *b else { continue };
                let (y0, y1) = (y0.max(by0), y1.min(by1));
                if y0 >= y1 {
                    continue;
                }
                let Some(mut mask) = Mask::new(x1 - x0, y1 - y0) else {
                    continue;
                };
                let mw = (x1 - x0) as usize;
                for (si, sample) in samples.iter().enumerate() {
                    // Pixel (i, j) of the mask has its centre at sample (dx, dy) of
                    // output pixel (x0 + i, y0 + j).
                    let local = to_px.post_translate(
                        (0.5 - sample.dx) as f32 - x0 as f32,
                        (0.5 - sample.dy) as f32 - y0 as f32,
                    );
                    mask.clear();
                    mask.fill_path(path, FillRule::Winding, false, local);
                    for (row, cov) in mask.data().chunks_exact(mw).enumerate() {
                        let start = ((y0 - by0) as usize + row) * w as usize + x0 as usize;
                        for (x, &c) in cov.iter().enumerate() {
                            if c != 0 {
                                index[(start + x) * n + si] = k as u32 + 1;
                            }
                        }
                    }
                }
            }
            for (p, idx) in index.chunks_exact(n).enumerate() {
                let o = p * 4;
                let first = idx[0];
                let under = underlay.map(|u| {
                    let q = (by0 as usize * w as usize) * 4 + o;
                    let c = &u.pixels[q..q + 3];
                    [c[0], c[1], c[2]]
                });
                if idx.iter().all(|&i| {
                    i == first || (under.is_none() && srgb[i as usize] == srgb[first as usize])
                }) {
                    let c = srgb[first as usize];
                    let c = match under {
                        Some(u) if first == 0 => u,
                        _ => [c.r, c.g, c.b],
                    };
                    out[o..o + 3].copy_from_slice(&c);
                    continue;
                }
                let under_linear = under.map(|u| u.map(srgb_to_linear));
                let mut acc = [0.0f32; 3];
                for (&i, sample) in idx.iter().zip(samples) {
                    let c = match under_linear {
                        Some(u) if i == 0 => u,
                        _ => palette[i as usize],
                    };
                    for ch in 0..3 {
                        acc[ch] += sample.weight * c[ch];
                    }
                }
                for ch in 0..3 {
                    out[o + ch] = linear_to_srgb(acc[ch]);
                }
            }
        });
    RgbaImage {
        width: w,
        height: h,
        pixels,
    }
}
