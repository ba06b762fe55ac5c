//! Uniform blocks shared with the WGSL shaders: `#[repr(C)]` + bytemuck mirrors of the
//! WGSL structs (uniform address-space layout; checked against naga by tests/it/layout.rs).

use crate::encode::{GpuOp, color_texel};
use marbling_core::sampling::Sample;
use marbling_core::{Antialias, Rgb8};

/// Most samples the render shader takes per pixel (first pass + refinement:
/// adaptive = 4 RGSS + 16 grid).
pub const MAX_RENDER_SAMPLES: usize = 20;
/// Most samples the preview shader takes per view pixel.
pub const MAX_PREVIEW_SAMPLES: usize = 4;

/// Parameters of the exact render pass.
///
/// Keep in sync with `struct RenderParams` in shaders/render.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct RenderParams {
    /// Background: linear r, g, b and packed sRGB (see [`crate::encode::pack_srgb`]).
    pub background: [f32; 4],
    /// Output pixel (column, row) of the render target's top-left pixel.
    pub offset: [f32; 2],
    /// Design pixels per output pixel.
    pub inv_scale: f32,
    /// Number of ops in the op texture.
    pub op_count: u32,
    /// log2 of the records per row of the op texture (a power of two).
    pub ops_row_shift: u32,
    /// Samples in the first pass.
    pub first_count: u32,
    /// Samples in the refinement pass (0: none).
    pub refine_count: u32,
    /// 1: the shader writes sRGB-encoded values; 0: linear light (sRGB targets).
    pub encode_srgb: u32,
    /// The two layers of a looping turbulence (`marbling_core::turbulence`), each
    /// (Δt, N, weight, record index of the flow's header): every sample walks back N
    /// sub-steps of Δt through the flow whose header is that record, then through the
    /// `op_count` records before the flow. All zero: no turbulence.
    pub layers: [[f32; 4]; 2],
    /// (dx, dy, weight, 0) per sample: first pass, then refinement.
    pub samples: [[f32; 4]; MAX_RENDER_SAMPLES],
    /// Deep zoom (`shaders/deep.wgsl`): tile side, tiles per row, log2 of the
    /// reference records per texture row, records per tile. Zero: not deep.
    pub deep: [u32; 4],
}

/// Parameters of the live-preview pass.
///
/// Keep in sync with `struct PreviewParams` in shaders/preview.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct PreviewParams {
    /// The pending op's first texel (see [`crate::encode::encode_op`]).
    pub pending_a: [f32; 4],
    /// The pending op's second texel.
    pub pending_b: [f32; 4],
    /// Design point at the view target's top-left corner.
    pub view_origin: [f32; 2],
    /// Design pixels per view pixel.
    pub view_inv_scale: f32,
    /// 1 when a pending op is set.
    pub has_pending: u32,
    /// Design width and height, design pixels.
    pub design_size: [f32; 2],
    /// Samples per view pixel.
    pub sample_count: u32,
    /// 1: the shader writes sRGB-encoded values; 0: linear light (sRGB targets).
    pub encode_srgb: u32,
    /// (dx, dy, weight, 0) per sample.
    pub samples: [[f32; 4]; MAX_PREVIEW_SAMPLES],
}

fn sample_texel(s: &Sample) -> [f32; 4] {
    [s.dx as f32, s.dy as f32, s.weight, 0.0]
}

impl RenderParams {
    /// Parameters for drawing ops (count and records per row, a power of two, given) on `background` with
    /// `antialias`, output pixel (0, 0) of the target at output pixel `offset`, `scale`
    /// output pixels per design pixel.
    pub fn new(
        background: Rgb8,
        op_count: u32,
        ops_per_row: u32,
        antialias: Antialias,
        scale: f64,
        offset: [f64; 2],
        encode_srgb: bool,
    ) -> Self {
        let first = antialias.samples();
        let refine = antialias.refinement().unwrap_or(&[]);
        let mut samples = [[0.0; 4]; MAX_RENDER_SAMPLES];
        for (slot, s) in samples.iter_mut().zip(first.iter().chain(refine)) {
            *slot = sample_texel(s);
        }
        Self {
            background: color_texel(background),
            offset: [offset[0] as f32, offset[1] as f32],
            inv_scale: (1.0 / scale) as f32,
            op_count,
            ops_row_shift: ops_per_row.trailing_zeros(),
            first_count: first.len() as u32,
            refine_count: refine.len() as u32,
            encode_srgb: u32::from(encode_srgb),
            layers: [[0.0; 4]; 2],
            samples,
            deep: [0; 4],
        }
    }
}

impl PreviewParams {
    /// Parameters for showing the cache of a `design_size` design with `pending` on top;
    /// the view's top-left corner is design point `view_origin`, `view_scale` view pixels
    /// per design pixel. Modes with more than 4 samples (or a refinement) use RGSS.
    pub fn new(
        design_size: [f64; 2],
        pending: Option<GpuOp>,
        view_origin: [f64; 2],
        view_scale: f64,
        antialias: Antialias,
        encode_srgb: bool,
    ) -> Self {
        let pattern = match antialias.samples() {
            s if s.len() <= MAX_PREVIEW_SAMPLES && antialias.refinement().is_none() => s,
            _ => Antialias::Rgss.samples(),
        };
        let mut samples = [[0.0; 4]; MAX_PREVIEW_SAMPLES];
        for (slot, s) in samples.iter_mut().zip(pattern) {
            *slot = sample_texel(s);
        }
        let GpuOp { a, b } = pending.unwrap_or(GpuOp {
            a: [0.0; 4],
            b: [0.0; 4],
        });
        Self {
            pending_a: a,
            pending_b: b,
            view_origin: [view_origin[0] as f32, view_origin[1] as f32],
            view_inv_scale: (1.0 / view_scale) as f32,
            has_pending: u32::from(pending.is_some()),
            design_size: [design_size[0] as f32, design_size[1] as f32],
            sample_count: pattern.len() as u32,
            encode_srgb: u32::from(encode_srgb),
            samples,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adaptive_fills_first_and_refinement_samples() {
        let p = RenderParams::new(
            Rgb8::new(1, 2, 3),
            0,
            1,
            Antialias::Adaptive,
            2.0,
            [0.0; 2],
            true,
        );
        assert_eq!((p.first_count, p.refine_count), (4, 16));
        assert_eq!(p.samples[0], [0.375, 0.125, 0.25, 0.0]);
        assert_eq!(p.samples[4], [0.125, 0.125, 0.0625, 0.0]);
        assert_eq!(p.inv_scale, 0.5);
    }

    #[test]
    fn preview_falls_back_to_rgss_for_big_patterns() {
        let p = PreviewParams::new([10.0; 2], None, [0.0; 2], 1.0, Antialias::Grid4, true);
        assert_eq!((p.sample_count, p.has_pending), (4, 0));
        assert_eq!(p.samples[1], [0.875, 0.375, 0.25, 0.0]);
    }
}

/// Parameters of the present pass ([`crate::Presenter`]).
/// Keep in sync with `struct PresentParams` in shaders/present.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct PresentParams {
    /// Target pixel (x, y) of the texture's texel (0, 0).
    pub origin: [f32; 2],
    /// Padding to 16 bytes.
    pub _pad: [f32; 2],
}
