//! Styles of the 3D view: marks (Bénard et al. 2010) or fibres (Kaplan & Cohen 2005) laid
//! over the exact render, flat on the screen yet moving with the object.
//!
//! A style is an overlay: one ink colour and a coverage per pixel, composited over the
//! render in sRGB, out = base + (ink − base)·coverage. The overlay is computed on the CPU
//! from one ray per pixel centre (what shows where, how far, how lit) whichever backend
//! drew the render, so the CLI's CPU and GPU renders and the playground carry the same
//! marks.
//!
//! Coverage of the marks: each style thresholds unit-variance noise layers
//! ([`marks`]) with a smoothstep of the spec's `softness` around
//! t = `tone` + `shading`·(d − ½), d = 1 − the headlight's cosine (darker: more ink):
//! - hatching: c = 1 − S(n₁), n₁ anisotropic;
//! - stipple: the same with isotropic noise;
//! - crosshatch: c = 1 − S(n₁)·S(n₂), n₂ anisotropic a right angle from n₁ (the product
//!   of the two papers left white);
//! - graphite: hatching times a fine isotropic grain, c = (1 − S(n₁))·smoothstep(−1, 1, n₃),
//!   n₃ at 2.2× the frequency and bandwidth (capped at their ranges);
//! - felt: c = (1 − S(n₁))·(0.7 + 0.3·smoothstep(−1, 1, n₂)), n₂ an isotropic grain at 3×,
//!   multiplied into the colour ([`StyleBlend::Multiply`]);
//!
//! and `opacity` scales it. Watercolor and painterly lay no ink: they overlay a grey g
//! ([`StyleBlend::Overlay`], g = ½ leaves the colour), watercolor's
//! g = ½ + opacity·(0.16·n₁ + 0.08·n₂) (pigment n₁, isotropic; paper n₂, isotropic at
//! 3.5×), painterly's g = ½ + 0.25·opacity·(L·∇h)/(2πF₀) with the relief
//! h = n₁ + 0.35·n₂ (strokes n₁; brush fibres n₂, anisotropic along them at 4× the
//! frequency and 2× the bandwidth), ∇h by central differences on the pixel grid and
//! L = (0.6, 0.8) (screen pixels, y down: slopes facing the upper left are lit).
//!
//! The overlay reaches the colour through [`StyleFrame::field`], bytes that the CPU's
//! [`StyleFrame::composite`] and the GPU's 3D shader (marbling-gpu's view3d.wgsl,
//! `styled`) both decode and blend by [`blend_pixel`].

mod fibres;
mod marks;
mod scene;
pub mod stretch;

pub use fibres::{BACKDROP_CELL, FIBRE_LIST, Fibre, MAX_SPLITS};
pub use marks::{DEPTH_TOLERANCE_RADII, Layer};

use super::{View3d, View3dError};
use crate::walk::Walker;
use crate::{Design, RgbaImage};
use marbling_noise::{Follow, GaborKind, StyleBlend, StyleKind, StyleSpec, smoothstep, style};
use scene::Scene;
use std::f64::consts::PI;

/// The screen direction painterly's relief is lit along (unit, y down).
pub const RELIEF_LIGHT: [f32; 2] = [0.6, 0.8];

/// The field byte of the overlay grey g: 128 + round(127·(2g − 1)), so ½ is 128 exactly.
pub fn grey_byte(g: f32) -> u8 {
    (128.0 + (127.0 * (2.0 * g.clamp(0.0, 1.0) - 1.0)).round()).clamp(1.0, 255.0) as u8
}

/// The overlay grey of a field byte: ½ + (b − 128)/254.
pub fn byte_grey(b: u8) -> f32 {
    0.5 + (f32::from(b) - 128.0) / 254.0
}

/// One pixel's colour under a style: `base` and `ink` sRGB in [0, 1], coverage `c`,
/// overlay grey `g` (see [`StyleBlend`]).
pub fn blend_pixel(base: [f32; 3], c: f32, g: f32, ink: [f32; 3], blend: StyleBlend) -> [f32; 3] {
    let c = c.clamp(0.0, 1.0);
    std::array::from_fn(|i| {
        let b = base[i];
        match blend {
            StyleBlend::Ink => b + (ink[i] - b) * c,
            StyleBlend::Multiply => b * (1.0 - c + c * ink[i]),
            StyleBlend::Overlay if b < 0.5 => 2.0 * b * g,
            StyleBlend::Overlay => 1.0 - 2.0 * (1.0 - b) * (1.0 - g),
        }
    })
}

/// A style's overlay for one frame.
#[derive(Clone, Debug)]
pub struct StyleFrame {
    /// Frame width, pixels.
    pub width: u32,
    /// Frame height, pixels.
    pub height: u32,
    /// Ink colour, sRGB bytes.
    pub ink: [u8; 3],
    /// How the overlay meets the render's colour.
    pub blend: StyleBlend,
    /// Coverage per pixel in [0, 1], rows top to bottom (0 for the overlay blend).
    pub coverage: Vec<f32>,
    /// Overlay grey per pixel in [0, 1] (½ off the object); empty unless the blend is
    /// [`StyleBlend::Overlay`].
    pub grey: Vec<f32>,
    /// The first noise layer per pixel (unit variance; NaN off the object); empty for
    /// the fibre styles.
    pub noise: Vec<f32>,
    /// Kernels drawn, all layers (0 for the naive anchorings and the fibre styles).
    pub kernels: usize,
    /// The fibres drawn (empty for the mark styles).
    pub fibres: Vec<Fibre>,
}

impl StyleFrame {
    /// The overlay as the renderers read it, four bytes per pixel: coverage·255, the
    /// overlay grey's [`grey_byte`], 0, 255.
    pub fn field(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.coverage.len() * 4);
        for (i, &c) in self.coverage.iter().enumerate() {
            let g = self.grey.get(i).map_or(128, |&g| grey_byte(g));
            out.extend_from_slice(&[(c.clamp(0.0, 1.0) * 255.0).round() as u8, g, 0, 255]);
        }
        out
    }

    /// The ink as sRGB in [0, 1].
    pub fn ink_unit(&self) -> [f32; 3] {
        self.ink.map(|b| f32::from(b) / 255.0)
    }

    /// Lays the overlay over `image` (the same size) by [`blend_pixel`], from the
    /// [`StyleFrame::field`] bytes the GPU reads too.
    pub fn composite(&self, image: &mut RgbaImage) {
        let ink = self.ink_unit();
        for (px, f) in image
            .pixels
            .chunks_exact_mut(4)
            .zip(self.field().chunks_exact(4))
        {
            let base = [px[0], px[1], px[2]].map(|b| f32::from(b) / 255.0);
            let out = blend_pixel(
                base,
                f32::from(f[0]) / 255.0,
                byte_grey(f[1]),
                ink,
                self.blend,
            );
            for (channel, v) in px[..3].iter_mut().zip(out) {
                *channel = (v.clamp(0.0, 1.0) * 255.0).round() as u8;
            }
        }
    }
}

/// The noise layers of a mark style.
pub fn layers(spec: &StyleSpec) -> Vec<Layer> {
    let marks = spec.marks;
    let layer = |kind, turn, seed_step: u32| Layer {
        kind,
        marks,
        turn,
        seed: spec.seed.wrapping_add(seed_step.wrapping_mul(0x9E37_79B9)),
    };
    // A finer layer: frequency and bandwidth times `f` and `a` (capped at their ranges).
    let finer = |kind, f: f32, a: f32, seed_step| {
        let mut l = layer(kind, 0.0, seed_step);
        l.marks.frequency = (f * marks.frequency).min(style::MARK_FREQUENCY.hi as f32);
        l.marks.bandwidth = (a * marks.bandwidth).min(style::MARK_BANDWIDTH.hi as f32);
        l
    };
    let strokes = layer(GaborKind::Anisotropic, 0.0, 0);
    match spec.kind {
        StyleKind::Hatching => vec![strokes],
        StyleKind::Stipple => vec![layer(GaborKind::Isotropic, 0.0, 0)],
        StyleKind::Crosshatch => vec![strokes, layer(GaborKind::Anisotropic, PI / 2.0, 1)],
        StyleKind::Graphite => vec![strokes, finer(GaborKind::Isotropic, 2.2, 2.2, 2)],
        StyleKind::Felt => vec![strokes, finer(GaborKind::Isotropic, 3.0, 3.0, 2)],
        StyleKind::Watercolor => vec![
            layer(GaborKind::Isotropic, 0.0, 0),
            finer(GaborKind::Isotropic, 3.5, 3.5, 3),
        ],
        StyleKind::Painterly => vec![strokes, finer(GaborKind::Anisotropic, 4.0, 2.0, 4)],
        StyleKind::Paper | StyleKind::Canvas => Vec::new(),
    }
}

/// The overlay of `spec` on the 3D view of `design`.
pub fn style_frame(
    design: &Design,
    view: &View3d,
    spec: &StyleSpec,
) -> Result<StyleFrame, View3dError> {
    view.check(design)?;
    let mut scene = Scene::new(design, view);
    if spec.marks.follow == Follow::Stretch {
        scene.walker = Some(Walker::new(&design.ops));
    }
    let ink = spec.ink.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    let (width, height) = (view.width, view.height);
    let blend = spec.kind.blend();
    if spec.kind.is_fibres() {
        let fibres = fibres::fibres(&scene, spec);
        let coverage = fibres::draw(&fibres, f64::from(spec.opacity), width, height);
        return Ok(StyleFrame {
            width,
            height,
            ink,
            blend,
            coverage,
            grey: Vec::new(),
            noise: Vec::new(),
            kernels: 0,
            fibres,
        });
    }
    let mut kernels = 0;
    let noises: Vec<Vec<f32>> = layers(spec)
        .iter()
        .map(|layer| {
            let (n, k) = marks::noise(&scene, layer, spec.anchoring, spec.depth_test);
            kernels += k;
            n
        })
        .collect();
    let m = &spec.marks;
    let n_pixels = scene.depth.len();
    let (coverage, grey) = if blend == StyleBlend::Overlay {
        let grey = match spec.kind {
            StyleKind::Painterly => relief(&scene, &noises, spec),
            _ => (0..n_pixels)
                .map(|i| {
                    let wash = 0.16 * noises[0][i] + 0.08 * noises[1][i];
                    if wash.is_finite() {
                        0.5 + spec.opacity * wash
                    } else {
                        0.5
                    }
                })
                .collect(),
        };
        (vec![0.0; n_pixels], grey)
    } else {
        let coverage = (0..n_pixels)
            .map(|i| {
                if !scene.depth[i].is_finite() {
                    return 0.0;
                }
                let t = m.tone + m.shading * (0.5 - scene.light[i]);
                let white = |n: f32| smoothstep(t - 0.5 * m.softness, t + 0.5 * m.softness, n);
                let n = |k: usize| noises[k][i];
                let c = match spec.kind {
                    StyleKind::Crosshatch => 1.0 - white(n(0)) * white(n(1)),
                    StyleKind::Graphite => (1.0 - white(n(0))) * smoothstep(-1.0, 1.0, n(1)),
                    StyleKind::Felt => {
                        (1.0 - white(n(0))) * (0.7 + 0.3 * smoothstep(-1.0, 1.0, n(1)))
                    }
                    _ => 1.0 - white(n(0)),
                };
                c * spec.opacity
            })
            .collect();
        (coverage, Vec::new())
    };
    Ok(StyleFrame {
        width,
        height,
        ink,
        blend,
        coverage,
        grey,
        noise: noises.into_iter().next().unwrap_or_default(),
        kernels,
        fibres: Vec::new(),
    })
}

/// Painterly's overlay grey: the relief h = n₁ + 0.35·n₂ lit along [`RELIEF_LIGHT`].
fn relief(scene: &Scene, noises: &[Vec<f32>], spec: &StyleSpec) -> Vec<f32> {
    let (w, h) = (scene.width as usize, scene.height as usize);
    let height: Vec<f32> = (0..w * h)
        .map(|i| noises[0][i] + 0.35 * noises[1][i])
        .collect();
    let at = |x: usize, y: usize| height[y * w + x];
    // A central difference, one-sided at the object's edge, 0 across it.
    let slope = |lo: Option<f32>, mid: f32, hi: Option<f32>| match (
        lo.filter(|v| v.is_finite()),
        hi.filter(|v| v.is_finite()),
    ) {
        (Some(a), Some(b)) => 0.5 * (b - a),
        (Some(a), None) => mid - a,
        (None, Some(b)) => b - mid,
        (None, None) => 0.0,
    };
    let k = 0.25 * spec.opacity / (2.0 * std::f32::consts::PI * spec.marks.frequency);
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let mid = height[i];
            if !mid.is_finite() {
                return 0.5;
            }
            let gx = slope(
                (x > 0).then(|| at(x - 1, y)),
                mid,
                (x + 1 < w).then(|| at(x + 1, y)),
            );
            let gy = slope(
                (y > 0).then(|| at(x, y - 1)),
                mid,
                (y + 1 < h).then(|| at(x, y + 1)),
            );
            0.5 + k * (RELIEF_LIGHT[0] * gx + RELIEF_LIGHT[1] * gy)
        })
        .collect()
}
