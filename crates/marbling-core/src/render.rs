//! The exact CPU reference renderer: every sample of every output pixel walks back
//! through all ops (no intermediate image is ever resampled), in parallel over bands of
//! tiles with rayon.

use crate::sampling::Sample;
use crate::surface::Surface;
use crate::walk::{Batch, Traced, Walker};
use crate::{Antialias, Design, Rgb8, RgbaImage};
use kurbo::Point;
use rayon::prelude::*;
use std::sync::atomic::{AtomicUsize, Ordering};

/// Largest output side, pixels.
pub const MAX_OUTPUT_SIDE: u32 = 65_536;
/// Largest output area, pixels (16384², i.e. 1 GiB of RGBA).
pub const MAX_OUTPUT_PIXELS: u64 = 16_384 * 16_384;
/// Side of the square pixel tiles the renderer works on.
const TILE: u32 = 32;

/// How to render a design.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// Output pixels per design pixel (> 0): pixel (i, j) samples design point
    /// ((i + 0.5)/s, (j + 0.5)/s) and nearby points for antialiasing.
    pub scale: f64,
    /// Antialiasing pattern.
    pub antialias: Antialias,
}

impl Default for RenderOptions {
    fn default() -> Self {
        Self {
            scale: 1.0,
            antialias: Antialias::Rgss,
        }
    }
}

/// Why a render cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum RenderError {
    /// The scale is not a positive finite number.
    #[error("scale must be a finite number > 0, got {0}")]
    BadScale(f64),
    /// The window's origin is not finite or a side is 0.
    #[error("the window {0:?} needs a finite origin and sides of at least 1 pixel")]
    BadWindow(Window),
    /// The output would be too big.
    #[error(
        "output of {width}×{height} pixels is too large (at most {MAX_OUTPUT_SIDE} per side and {MAX_OUTPUT_PIXELS} pixels)"
    )]
    TooLarge {
        /// Requested width, pixels.
        width: f64,
        /// Requested height, pixels.
        height: f64,
    },
}

/// The output size in pixels of `design` at `scale`: each side rounded, at least 1.
pub fn output_size(design: &Design, scale: f64) -> Result<(u32, u32), RenderError> {
    if !(scale.is_finite() && scale > 0.0) {
        return Err(RenderError::BadScale(scale));
    }
    let w = (f64::from(design.width) * scale).round().max(1.0);
    let h = (f64::from(design.height) * scale).round().max(1.0);
    let side = f64::from(MAX_OUTPUT_SIDE);
    if w > side || h > side || w * h > MAX_OUTPUT_PIXELS as f64 {
        return Err(RenderError::TooLarge {
            width: w,
            height: h,
        });
    }
    Ok((w as u32, h as u32))
}

/// Renders `design` exactly.
pub fn render(design: &Design, opts: &RenderOptions) -> Result<RgbaImage, RenderError> {
    render_with_progress(design, opts, &|_, _| {})
}

/// Renders `design` exactly, calling `progress(done, total)` (in bands of pixel rows,
/// from any thread) as work finishes.
pub fn render_with_progress(
    design: &Design,
    opts: &RenderOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<RgbaImage, RenderError> {
    let (width, height) = output_size(design, opts.scale)?;
    let window = Window {
        x0: 0.0,
        y0: 0.0,
        scale: opts.scale,
        width,
        height,
    };
    let shader = Shader::new(design);
    let mut image = RgbaImage::filled(width, height, [0, 0, 0, 255]);
    let bands = height.div_ceil(TILE) as usize;
    let done = AtomicUsize::new(0);
    image
        .pixels
        .par_chunks_mut(window.band_bytes())
        .enumerate()
        .for_each_init(TileScratch::default, |scratch, (band, rows)| {
            shader.band(&window, opts.antialias, band as u32 * TILE, rows, scratch);
            progress(done.fetch_add(1, Ordering::Relaxed) + 1, bands);
        });
    Ok(image)
}

/// A window of the design plane as output pixels: pixel (i, j) covers the design
/// square from (x0 + i/scale, y0 + j/scale) to (x0 + (i + 1)/scale, y0 + (j + 1)/scale).
/// The window may reach past the sheet: the design goes on there (its inks walked back
/// like any other point), which is what a print's bleed shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// Design x of the window's left edge, design pixels.
    pub x0: f64,
    /// Design y of the window's top edge, design pixels.
    pub y0: f64,
    /// Output pixels per design pixel (> 0).
    pub scale: f64,
    /// Width, output pixels (≥ 1).
    pub width: u32,
    /// Height, output pixels (≥ 1).
    pub height: u32,
}

impl Window {
    /// Bytes of one band of [`TILE`] RGBA rows.
    fn band_bytes(&self) -> usize {
        self.width as usize * 4 * TILE as usize
    }

    /// The `width × height` window at `scale` whose centre shows design point `centre`
    /// (a view of any depth: f64 keeps a pixel's design size of 10⁻⁶ on a 1,000-px sheet
    /// about 10⁷ times larger than the last bit of its position).
    pub fn centred(centre: Point, scale: f64, width: u32, height: u32) -> Self {
        Self {
            x0: centre.x - f64::from(width) / (2.0 * scale),
            y0: centre.y - f64::from(height) / (2.0 * scale),
            scale,
            width,
            height,
        }
    }

    /// The design point at the window's centre.
    pub fn centre(&self) -> Point {
        Point::new(
            self.x0 + f64::from(self.width) / (2.0 * self.scale),
            self.y0 + f64::from(self.height) / (2.0 * self.scale),
        )
    }

    /// Checks the numbers: a finite origin, a positive finite scale, sides ≥ 1.
    pub fn check(&self) -> Result<(), RenderError> {
        if !(self.scale.is_finite() && self.scale > 0.0) {
            return Err(RenderError::BadScale(self.scale));
        }
        if !(self.x0.is_finite() && self.y0.is_finite()) || self.width == 0 || self.height == 0 {
            return Err(RenderError::BadWindow(*self));
        }
        Ok(())
    }
}

/// Renders `window` of `design` exactly, band by band of rows, top first, handing each
/// band to `sink(first row, RGBA bytes of whole rows)` in order: two bands of 32 rows
/// per rayon thread are held at once, so an output of any height streams in bounded
/// memory. `progress(done, total)` counts rows.
pub fn render_window_rows<E>(
    design: &Design,
    window: &Window,
    antialias: Antialias,
    progress: &(dyn Fn(usize, usize) + Sync),
    mut sink: impl FnMut(u32, &[u8]) -> Result<(), E>,
) -> Result<(), E>
where
    E: From<RenderError>,
{
    window.check()?;
    let shader = Shader::new(design);
    let parallel = (rayon::current_num_threads() * 2).max(1) as u32;
    let mut buffer = Vec::new();
    let mut y0 = 0;
    while y0 < window.height {
        let rows = (parallel * TILE).min(window.height - y0);
        buffer.clear();
        buffer.resize(window.width as usize * 4 * rows as usize, 255);
        buffer
            .par_chunks_mut(window.band_bytes())
            .enumerate()
            .for_each_init(TileScratch::default, |scratch, (band, rows)| {
                shader.band(window, antialias, y0 + band as u32 * TILE, rows, scratch);
            });
        sink(y0, &buffer)?;
        y0 += rows;
        progress(y0 as usize, window.height as usize);
    }
    Ok(())
}

/// Renders `window` of `design` exactly into one image (see [`render_window_rows`]).
pub fn render_window(
    design: &Design,
    window: &Window,
    antialias: Antialias,
) -> Result<RgbaImage, RenderError> {
    window.check()?;
    let (w, h) = (f64::from(window.width), f64::from(window.height));
    if w * h > MAX_OUTPUT_PIXELS as f64 {
        return Err(RenderError::TooLarge {
            width: w,
            height: h,
        });
    }
    let mut image = RgbaImage::filled(window.width, window.height, [0, 0, 0, 255]);
    let row_bytes = window.width as usize * 4;
    render_window_rows(design, window, antialias, &|_, _| {}, |y0, rows| {
        let start = y0 as usize * row_bytes;
        image.pixels[start..start + rows.len()].copy_from_slice(rows);
        Ok::<(), RenderError>(())
    })?;
    Ok(image)
}

/// A rectangle of output pixels.
struct Tile {
    x0: u32,
    y0: u32,
    w: u32,
    h: u32,
}

/// Buffers reused from tile to tile on one thread.
#[derive(Default)]
struct TileScratch {
    batch: Batch,
    traced: Vec<Traced>,
    /// Palette index of each traced sample.
    colors: Vec<u32>,
    refine: Vec<u32>,
    /// Output design point of each sample (designs with a surface only).
    starts: Vec<Point>,
    /// Where each sample's walk ended (designs with a surface only).
    ends: Vec<Point>,
    /// Linear colour of each sample (designs with a surface only).
    linear: Vec<[f32; 3]>,
}

/// Turns traced samples into colours.
struct Shader {
    walker: Walker,
    /// sRGB colour of each op's ink (background colour for ops without ink), then the
    /// background colour at index `ops.len()`.
    srgb: Vec<Rgb8>,
    /// The same palette in linear light.
    linear: Vec<[f32; 3]>,
    /// Noise background and overlays; `None` keeps the plain palette fast path.
    surface: Option<Surface>,
}

impl Shader {
    fn new(design: &Design) -> Self {
        let walker = Walker::new(&design.ops);
        let mut srgb: Vec<Rgb8> = walker
            .steps()
            .iter()
            .map(|o| o.ink().unwrap_or(design.background))
            .collect();
        srgb.push(design.background);
        let linear = srgb.iter().map(|c| c.to_linear()).collect();
        Self {
            walker,
            srgb,
            linear,
            surface: Surface::new(design),
        }
    }

    /// Palette index of a traced sample.
    fn index(&self, t: Traced) -> u32 {
        match t {
            Traced::Ink(k) => k as u32,
            Traced::Background(_) => (self.srgb.len() - 1) as u32,
        }
    }

    /// Weighted average of palette entries in linear light, encoded back to sRGB.
    /// Samples of one colour keep that exact colour.
    fn average(&self, idx: &[u32], samples: &[Sample]) -> Rgb8 {
        let first = self.srgb[idx[0] as usize];
        if idx.iter().all(|&i| self.srgb[i as usize] == first) {
            return first;
        }
        let mut acc = [0.0f32; 3];
        for (&i, s) in idx.iter().zip(samples) {
            let lin = self.linear[i as usize];
            for ch in 0..3 {
                acc[ch] += s.weight * lin[ch];
            }
        }
        let e = crate::color::linear_to_srgb;
        Rgb8::new(e(acc[0]), e(acc[1]), e(acc[2]))
    }

    /// Traces `samples` for each listed pixel (local tile index) into `scratch.colors`,
    /// laid out pixel-major.
    fn trace(
        &self,
        tile: &Tile,
        pixels: impl Iterator<Item = u32>,
        samples: &[Sample],
        window: &Window,
        scratch: &mut TileScratch,
    ) {
        let inv = 1.0 / window.scale;
        scratch.batch.clear();
        let mut n = 0u32;
        for p in pixels {
            let (px, py) = (
                f64::from(tile.x0 + p % tile.w),
                f64::from(tile.y0 + p / tile.w),
            );
            for s in samples {
                scratch.batch.push(
                    window.x0 + (px + s.dx) * inv,
                    window.y0 + (py + s.dy) * inv,
                    n,
                );
                n += 1;
            }
        }
        scratch.traced.clear();
        scratch.traced.resize(n as usize, Traced::Ink(0));
        if let Some(surface) = &self.surface {
            scratch.starts.clear();
            scratch.starts.extend(
                scratch
                    .batch
                    .xs
                    .iter()
                    .zip(&scratch.batch.ys)
                    .map(|(&x, &y)| Point::new(x, y)),
            );
            scratch.ends.clear();
            scratch.ends.resize(n as usize, Point::ZERO);
            self.walker.trace_batch_with_ends(
                &mut scratch.batch,
                &mut scratch.traced,
                &mut scratch.ends,
            );
            scratch.linear.clear();
            for i in 0..n as usize {
                let (start, end) = (scratch.starts[i], scratch.ends[i]);
                let base = match scratch.traced[i] {
                    Traced::Ink(k) => self.linear[k],
                    Traced::Background(p) => surface.background(p.x, p.y),
                };
                scratch
                    .linear
                    .push(surface.overlay(base, (start.x, start.y), (end.x, end.y)));
            }
        } else {
            self.walker
                .trace_batch(&mut scratch.batch, &mut scratch.traced);
        }
        scratch.colors.clear();
        scratch
            .colors
            .extend(scratch.traced.iter().map(|&t| self.index(t)));
    }

    /// Renders the band of rows from `y0` of `window` into `rows` (RGBA, whole rows of
    /// the window, at most [`TILE`] of them), tile by tile.
    fn band(
        &self,
        window: &Window,
        antialias: Antialias,
        y0: u32,
        rows: &mut [u8],
        scratch: &mut TileScratch,
    ) {
        let width = window.width;
        let h = (rows.len() / (width as usize * 4)) as u32;
        for x0 in (0..width).step_by(TILE as usize) {
            let w = TILE.min(width - x0);
            let tile = Tile { x0, y0, w, h };
            self.tile(&tile, window, antialias, scratch, |x, y, rgb| {
                let i = (y as usize * width as usize + (x0 + x) as usize) * 4;
                rows[i..i + 3].copy_from_slice(&[rgb.r, rgb.g, rgb.b]);
            });
        }
    }

    /// Renders one tile, handing each pixel's colour to `put(local x, local y, colour)`.
    fn tile(
        &self,
        tile: &Tile,
        window: &Window,
        antialias: Antialias,
        scratch: &mut TileScratch,
        mut put: impl FnMut(u32, u32, Rgb8),
    ) {
        if self.surface.is_some() {
            return self.tile_textured(tile, window, antialias, scratch, put);
        }
        let samples = antialias.samples();
        let count = tile.w * tile.h;
        self.trace(tile, 0..count, samples, window, scratch);
        let k = samples.len();
        scratch.refine.clear();
        for p in 0..count {
            let cs = &scratch.colors[p as usize * k..(p as usize + 1) * k];
            if antialias.refinement().is_some()
                && cs
                    .iter()
                    .any(|&c| self.srgb[c as usize] != self.srgb[cs[0] as usize])
            {
                scratch.refine.push(p);
                continue;
            }
            put(p % tile.w, p / tile.w, self.average(cs, samples));
        }
        if let Some(fine) = antialias.refinement() {
            let refine = std::mem::take(&mut scratch.refine);
            self.trace(tile, refine.iter().copied(), fine, window, scratch);
            for (i, &p) in refine.iter().enumerate() {
                let cs = &scratch.colors[i * fine.len()..(i + 1) * fine.len()];
                put(p % tile.w, p / tile.w, self.average(cs, fine));
            }
            scratch.refine = refine;
        }
    }

    /// Weighted average of per-sample linear colours `lin`, encoded to sRGB (designs
    /// with a surface: colours vary within one source, so no exact-colour shortcut).
    fn average_linear(lin: &[[f32; 3]], samples: &[Sample]) -> Rgb8 {
        let mut acc = [0.0f32; 3];
        for (c, s) in lin.iter().zip(samples) {
            for ch in 0..3 {
                acc[ch] += s.weight * c[ch];
            }
        }
        let e = crate::color::linear_to_srgb;
        Rgb8::new(e(acc[0]), e(acc[1]), e(acc[2]))
    }

    /// [`Shader::tile`] for designs with a noise background or overlays: every sample's
    /// colour comes from [`Surface`]; the adaptive mode refines where the first samples
    /// sources (ink colours, or the plain background colour) differ, as on the GPU.
    fn tile_textured(
        &self,
        tile: &Tile,
        window: &Window,
        antialias: Antialias,
        scratch: &mut TileScratch,
        mut put: impl FnMut(u32, u32, Rgb8),
    ) {
        let samples = antialias.samples();
        let count = tile.w * tile.h;
        self.trace(tile, 0..count, samples, window, scratch);
        let k = samples.len();
        scratch.refine.clear();
        for p in 0..count {
            let range = p as usize * k..(p as usize + 1) * k;
            let cs = &scratch.colors[range.clone()];
            if antialias.refinement().is_some()
                && cs
                    .iter()
                    .any(|&c| self.srgb[c as usize] != self.srgb[cs[0] as usize])
            {
                scratch.refine.push(p);
                continue;
            }
            put(
                p % tile.w,
                p / tile.w,
                Self::average_linear(&scratch.linear[range], samples),
            );
        }
        if let Some(fine) = antialias.refinement() {
            let refine = std::mem::take(&mut scratch.refine);
            self.trace(tile, refine.iter().copied(), fine, window, scratch);
            for (i, &p) in refine.iter().enumerate() {
                let lin = &scratch.linear[i * fine.len()..(i + 1) * fine.len()];
                put(p % tile.w, p / tile.w, Self::average_linear(lin, fine));
            }
            scratch.refine = refine;
        }
    }
}
