//! The uniform block of schema v2 surfaces (noise background, paper and pigment grain)
//! read by `shaders/surface.wgsl`: `#[repr(C)]` + bytemuck mirrors of the WGSL structs,
//! checked against naga by tests/it/layout.rs.

use marbling_core::image_background::{ImagePixels, fit_map};
use marbling_core::surface::MAX_PALETTE_STOPS;
use marbling_core::{Design, GrainKind, ImageFit, NoiseLayer};
use marbling_noise::noise_gpu::NoiseGpu;
use marbling_noise::wgsl::{NoiseKind, NoiseKinds};

/// `SurfaceParams::flags` bit: the background is noise.
pub const SURFACE_BACKGROUND: u32 = 1;
/// `SurfaceParams::flags` bit: pigment grain.
pub const SURFACE_PIGMENT: u32 = 2;
/// `SurfaceParams::flags` bit: paper grain.
pub const SURFACE_PAPER: u32 = 4;
/// `SurfaceParams::flags` bit (with [`SURFACE_BACKGROUND`]): the background is the
/// image bound at binding 3, not noise.
pub const SURFACE_IMAGE: u32 = 8;
/// Index in [`SurfaceParams::layers`] of the background noise.
pub const LAYER_BACKGROUND: usize = 0;
/// Index in [`SurfaceParams::layers`] of pigment grain.
pub const LAYER_PIGMENT: usize = 1;
/// Index in [`SurfaceParams::layers`] of paper grain.
pub const LAYER_PAPER: usize = 2;

/// How one layer's noise becomes an intensity. Keep in sync with `struct SurfaceLayer`
/// in shaders/surface.wgsl. The noise itself lives in [`SurfaceParams::noises`]: WebGL2
/// rejects structs nested more than 4 deep, and [`NoiseGpu`] is already 3 deep.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct LayerParams {
    /// Threshold transfer centre, noise units.
    pub threshold: f32,
    /// Threshold transfer width, noise units.
    pub width: f32,
    /// 0: `0.5 + n/6` clamped; 1: threshold; 2: inverted threshold.
    pub transfer: u32,
    /// Overlay strength in [0, 1] (unused for the background).
    pub strength: f32,
}

/// Schema v2 surface of a design. Keep in sync with `struct SurfaceParams` in
/// shaders/surface.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct SurfaceParams {
    /// `SURFACE_*` bits; 0 for a plain background without overlays.
    pub flags: u32,
    /// Palette stops in use.
    pub stop_count: u32,
    /// Always 3, the shader's loop bound over `layers` (a uniform, so the loop holding
    /// the one call of the noise dispatcher is not unrolled).
    pub layer_count: u32,
    /// Padding.
    pub _pad: u32,
    /// Palette stops, sRGB in [0, 1] (w unused).
    pub stops: [[f32; 4]; MAX_PALETTE_STOPS],
    /// Background noise, pigment grain (sampled where the walk ended), paper grain
    /// (sampled at the output design point), evaluated at design pixels: see `LAYER_*`.
    pub noises: [NoiseGpu; 3],
    /// The transfer and strength of each of `noises`.
    pub layers: [LayerParams; 3],
    /// Image background ([`SURFACE_IMAGE`]): image pixel u = (x − [0])·[2],
    /// v = (y − [1])·[3] at design point (x, y) (`marbling_core::image_background::ImageMap`).
    pub image_map: [f32; 4],
    /// Image width, height (pixels), 1 when letterboxed (contain) else 0, unused.
    pub image_size: [f32; 4],
    /// The paper around a letterboxed image, linear r, g, b (w unused).
    pub paper: [f32; 4],
}

fn layer(noise: &NoiseLayer, strength: f64) -> (NoiseGpu, LayerParams) {
    // Parsing a NoiseLayer already checked that its spec has a WGSL form.
    let gpu = NoiseGpu::from_spec(noise.spec(), 1).unwrap_or_default();
    let (threshold, width, transfer) = match noise.threshold() {
        None => (0.0, 0.0, 0),
        Some(t) => (t.threshold, t.width, if t.invert { 2 } else { 1 }),
    };
    let params = LayerParams {
        threshold,
        width,
        transfer,
        strength: strength as f32,
    };
    (gpu, params)
}

impl SurfaceParams {
    /// The surface of `design` (all zero flags for a plain v1 design). The GPU draws at
    /// most one overlay of each kind; the schema allows no more.
    pub fn new(design: &Design) -> Self {
        let mut p = Self {
            flags: 0,
            stop_count: 2,
            layer_count: 3,
            _pad: 0,
            stops: [[0.0; 4]; MAX_PALETTE_STOPS],
            noises: [NoiseGpu::default(); 3],
            layers: [LayerParams::default(); 3],
            image_map: [0.0; 4],
            image_size: [0.0; 4],
            paper: [0.0; 4],
        };
        if let Some(img) = &design.background_image {
            p.set_image(img.pixels(), img.fit, design);
        }
        if let Some(bg) = &design.background_noise {
            p.flags |= SURFACE_BACKGROUND;
            (p.noises[LAYER_BACKGROUND], p.layers[LAYER_BACKGROUND]) = layer(&bg.noise, 0.0);
            let stops = bg.palette.srgb_stops();
            p.stop_count = stops.len().clamp(2, MAX_PALETTE_STOPS) as u32;
            for (slot, s) in p.stops.iter_mut().zip(&stops) {
                *slot = [s[0], s[1], s[2], 1.0];
            }
        }
        for o in &design.overlays {
            match o.kind {
                GrainKind::Paper => {
                    p.flags |= SURFACE_PAPER;
                    (p.noises[LAYER_PAPER], p.layers[LAYER_PAPER]) = layer(&o.noise, o.strength);
                }
                GrainKind::Pigment => {
                    p.flags |= SURFACE_PIGMENT;
                    (p.noises[LAYER_PIGMENT], p.layers[LAYER_PIGMENT]) =
                        layer(&o.noise, o.strength);
                }
            }
        }
        p
    }

    /// Whether drawing needs the noise code (`surface.wgsl`): a noise background or a
    /// grain overlay. An image background alone is drawn by every variant.
    pub fn needs_noise(&self) -> bool {
        let noise_background =
            self.flags & SURFACE_BACKGROUND != 0 && self.flags & SURFACE_IMAGE == 0;
        noise_background || self.flags & (SURFACE_PIGMENT | SURFACE_PAPER) != 0
    }

    /// The noise types drawn: those of the noise layers in use.
    pub fn noise_kinds(&self) -> NoiseKinds {
        let used = [
            (
                LAYER_BACKGROUND,
                self.flags & SURFACE_BACKGROUND != 0 && self.flags & SURFACE_IMAGE == 0,
            ),
            (LAYER_PIGMENT, self.flags & SURFACE_PIGMENT != 0),
            (LAYER_PAPER, self.flags & SURFACE_PAPER != 0),
        ];
        used.into_iter()
            .filter(|(_, on)| *on)
            .filter_map(|(i, _)| NoiseKind::of(self.noises[i].noise_type))
            .fold(NoiseKinds::NONE, NoiseKinds::with)
    }

    /// Makes the background `pixels` laid on `design`'s sheet by `fit` (the design's
    /// own image, or a live video frame standing in for it).
    pub fn set_image(&mut self, pixels: &ImagePixels, fit: ImageFit, design: &Design) {
        let map = fit_map(
            fit,
            (pixels.width, pixels.height),
            (design.width, design.height),
        );
        self.flags |= SURFACE_BACKGROUND | SURFACE_IMAGE;
        self.image_map = [
            map.origin.0 as f32,
            map.origin.1 as f32,
            map.scale.0 as f32,
            map.scale.1 as f32,
        ];
        self.image_size = [
            pixels.width as f32,
            pixels.height as f32,
            if map.letterbox { 1.0 } else { 0.0 },
            0.0,
        ];
        let [r, g, b] = design.background.to_linear();
        self.paper = [r, g, b, 1.0];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{NoiseBackground, Overlay, Palette, Rgb8};

    fn layer(json: &str) -> NoiseLayer {
        NoiseLayer::from_json(json).expect("valid noise")
    }

    #[test]
    fn the_noise_kinds_are_those_of_the_layers_in_use() {
        let mut d = Design::new(40, 30, Rgb8::new(200, 190, 180));
        assert_eq!(SurfaceParams::new(&d).noise_kinds(), NoiseKinds::NONE);
        d.set_background_noise(Some(NoiseBackground::new(
            layer(r#"{"type":"worley","frequency":0.05,"seed":1}"#),
            Palette::named("ocean").expect("palette"),
        )));
        let worley = NoiseKinds::NONE.with(NoiseKind::Worley);
        assert_eq!(SurfaceParams::new(&d).noise_kinds(), worley);
        d.overlays = vec![Overlay::paper_grain(
            layer(r#"{"type":"value","frequency":0.2,"octaves":3,"seed":8}"#),
            0.25,
        )];
        assert_eq!(
            SurfaceParams::new(&d).noise_kinds(),
            worley.with(NoiseKind::Fbm)
        );
    }
}
