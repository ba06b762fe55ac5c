//! Showing a rendered texture 1:1 inside someone else's render pass (the app's canvas,
//! in egui's pass): texels are copied with `textureLoad`, pixels outside the sheet get a
//! flat background, nothing is filtered or blended (shaders/present.wgsl). The exact
//! bytes of the render reach the screen, and on software GPUs (SwiftShader) one such
//! pass over the canvas costs a fraction of egui's textured, blended image plus the
//! fills around it (docs/BENCHMARKS.md, "Where the time goes"). While the live preview
//! draws the sheet, [`Presenter::draw_frame`] draws only the background around it, in
//! one draw.

use crate::bindings;
use crate::params::PresentParams;
use crate::shaders::PRESENT_WGSL;

/// The present pipeline for one target format.
#[derive(Debug)]
pub struct Presenter {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
    /// `vs_frame` + `fs_background`: the background around the sheet.
    frame_pipeline: wgpu::RenderPipeline,
    linear_target: bool,
}

/// One texture ready to be presented, with the placement of the next draw.
#[derive(Debug)]
pub struct PresentSource {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    linear_target: bool,
    /// The target size of the last placement, pixels.
    target_size: [f32; 2],
}

/// Where a texture goes in the target, in target pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Target pixel of the texture's texel (0, 0) (whole pixels).
    pub origin: [f32; 2],
    /// The sheet: min x, min y, max x, max y. Pixels whose centres lie inside show the
    /// texture; the others show `background`.
    pub sheet: [f32; 4],
    /// The colour outside the sheet: sRGB bytes.
    pub background: [u8; 3],
    /// The size of the target, pixels ([`Presenter::draw_frame`] covers all of it but
    /// the sheet, within the pass's scissor rectangle).
    pub target_size: [u32; 2],
}

impl Presenter {
    /// Builds the pipeline drawing into targets of `format`.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("marbling present.wgsl"),
            source: wgpu::ShaderSource::Wgsl(PRESENT_WGSL.into()),
        });
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling present"),
            entries: &[
                bindings::uniform::<PresentParams>(0, fragment | wgpu::ShaderStages::VERTEX),
                bindings::texture_2d(1, fragment, false),
            ],
        });
        let pipeline_layout = bindings::pipeline_layout(device, "marbling present", &layout);
        let pipeline = crate::fullscreen::pipeline(
            device,
            "marbling present",
            &pipeline_layout,
            &module,
            format,
        );
        let frame_pipeline = crate::fullscreen::pipeline_with(
            device,
            "marbling present (frame)",
            &pipeline_layout,
            &module,
            ["vs_frame", "fs_background"],
            format,
        );
        Self {
            layout,
            pipeline,
            frame_pipeline,
            linear_target: format.is_srgb(),
        }
    }

    /// Binds `view` (a texture holding sRGB-encoded values in a `…Unorm` format, such as
    /// a render of [`crate::ExactRenderer`] into an `Rgba8Unorm` target) for presenting.
    pub fn source(&self, device: &wgpu::Device, view: &wgpu::TextureView) -> PresentSource {
        let uniform = bindings::uniform_buffer::<PresentParams>(device, "marbling present params");
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("marbling present"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(view),
                },
            ],
        });
        PresentSource {
            uniform,
            bind_group,
            linear_target: self.linear_target,
            target_size: [0.0; 2],
        }
    }

    /// Records a draw of `source` into `pass` (a target of this presenter's format). It
    /// covers the pass's viewport and scissor rectangle.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, source: &PresentSource) {
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &source.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }

    /// Records one draw of the background around the sheet of `source`'s placement into
    /// `pass`: every pixel of the target that [`Presenter::draw`] would give the
    /// background, within the pass's scissor rectangle, and no pixel of the sheet. It sets
    /// the pass's viewport to the whole target.
    pub fn draw_frame(&self, pass: &mut wgpu::RenderPass<'_>, source: &PresentSource) {
        let [w, h] = source.target_size;
        if w <= 0.0 || h <= 0.0 {
            return;
        }
        pass.set_viewport(0.0, 0.0, w, h, 0.0, 1.0);
        pass.set_pipeline(&self.frame_pipeline);
        pass.set_bind_group(0, &source.bind_group, &[]);
        pass.draw(0..24, 0..1);
    }
}

impl PresentSource {
    /// Places the texture for the next draws.
    pub fn place(&mut self, queue: &wgpu::Queue, placement: &Placement) {
        self.target_size = placement.target_size.map(|v| v as f32);
        queue.write_buffer(
            &self.uniform,
            0,
            bytemuck::bytes_of(&placement.params(self.linear_target)),
        );
    }
}

impl Placement {
    /// The uniform block for a target that is (`linear_target`) or is not `…UnormSrgb`.
    pub fn params(&self, linear_target: bool) -> PresentParams {
        let bg = self.background.map(|b| {
            if linear_target {
                marbling_core::color::srgb_to_linear(b)
            } else {
                f32::from(b) / 255.0
            }
        });
        PresentParams {
            origin: self.origin,
            linear_target: u32::from(linear_target),
            _pad: 0,
            sheet: self.sheet,
            background: [bg[0], bg[1], bg[2], 1.0],
            target_size: self.target_size.map(|v| v as f32),
            _pad2: [0; 2],
        }
    }
}
