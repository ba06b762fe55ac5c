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
//!   n₃ at 2.2× the frequency and bandwidth (capped at their ranges).
//!
//! and `opacity` scales it.

mod fibres;
mod marks;
mod scene;

pub use fibres::{BACKDROP_CELL, FIBRE_LIST, Fibre, MAX_SPLITS};
pub use marks::{DEPTH_TOLERANCE_RADII, Layer};

use super::{View3d, View3dError};
use crate::{Design, RgbaImage};
use marbling_noise::{GaborKind, StyleKind, StyleSpec, smoothstep, style};
use scene::Scene;
use std::f64::consts::PI;

/// A style's overlay for one frame.
#[derive(Clone, Debug)]
pub struct StyleFrame {
    /// Frame width, pixels.
    pub width: u32,
    /// Frame height, pixels.
    pub height: u32,
    /// Ink colour, sRGB bytes.
    pub ink: [u8; 3],
    /// Coverage per pixel in [0, 1], rows top to bottom.
    pub coverage: Vec<f32>,
    /// The first noise layer per pixel (unit variance; NaN off the object); empty for
    /// the fibre styles.
    pub noise: Vec<f32>,
    /// Kernels drawn, all layers (0 for the naive anchorings and the fibre styles).
    pub kernels: usize,
    /// The fibres drawn (empty for the mark styles).
    pub fibres: Vec<Fibre>,
}

impl StyleFrame {
    /// The overlay as straight-alpha sRGBA bytes (ink, coverage).
    pub fn rgba(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.coverage.len() * 4);
        for &c in &self.coverage {
            out.extend_from_slice(&self.ink);
            out.push((c.clamp(0.0, 1.0) * 255.0).round() as u8);
        }
        out
    }

    /// Lays the overlay over `image` (the same size): base + (ink − base)·coverage in
    /// sRGB.
    pub fn composite(&self, image: &mut RgbaImage) {
        for (px, &c) in image.pixels.chunks_exact_mut(4).zip(&self.coverage) {
            for (channel, &ink) in px[..3].iter_mut().zip(&self.ink) {
                let (b, i) = (f32::from(*channel), f32::from(ink));
                *channel = (b + (i - b) * c.clamp(0.0, 1.0)).round() as u8;
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
    match spec.kind {
        StyleKind::Hatching => vec![layer(GaborKind::Anisotropic, 0.0, 0)],
        StyleKind::Stipple => vec![layer(GaborKind::Isotropic, 0.0, 0)],
        StyleKind::Crosshatch => vec![
            layer(GaborKind::Anisotropic, 0.0, 0),
            layer(GaborKind::Anisotropic, PI / 2.0, 1),
        ],
        StyleKind::Graphite => {
            let mut grain = layer(GaborKind::Isotropic, 0.0, 2);
            grain.marks.frequency = (2.2 * marks.frequency).min(style::MARK_FREQUENCY.hi as f32);
            grain.marks.bandwidth = (2.2 * marks.bandwidth).min(style::MARK_BANDWIDTH.hi as f32);
            vec![layer(GaborKind::Anisotropic, 0.0, 0), grain]
        }
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
    let scene = Scene::new(design, view);
    let ink = spec.ink.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8);
    let (width, height) = (view.width, view.height);
    if spec.kind.is_fibres() {
        let fibres = fibres::fibres(&scene, spec);
        let coverage = fibres::draw(&fibres, f64::from(spec.opacity), width, height);
        return Ok(StyleFrame {
            width,
            height,
            ink,
            coverage,
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
    let coverage = (0..scene.depth.len())
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
                _ => 1.0 - white(n(0)),
            };
            c * spec.opacity
        })
        .collect();
    Ok(StyleFrame {
        width,
        height,
        ink,
        coverage,
        noise: noises.into_iter().next().unwrap_or_default(),
        kernels,
        fibres: Vec::new(),
    })
}

/// The 3D render of `design` with `spec`'s overlay composited over `image` (a render of
/// the same view by either backend).
pub fn apply_style(
    design: &Design,
    view: &View3d,
    spec: &StyleSpec,
    image: &mut RgbaImage,
) -> Result<StyleFrame, View3dError> {
    let frame = style_frame(design, view, spec)?;
    frame.composite(image);
    Ok(frame)
}
