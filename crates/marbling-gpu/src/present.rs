//! Showing a rendered texture 1:1 inside someone else's render pass (the app's canvas,
//! in egui's pass): texels are copied with `textureLoad`, pixels outside the sheet get a
//! flat background, nothing is filtered or blended (shaders/present.wgsl). The exact
//! bytes of the render reach the screen, and on software GPUs (SwiftShader) one such
//! pass over the canvas costs a fraction of egui's textured, blended image plus the
//! fills around it (docs/BENCHMARKS.md, "Where the time goes").

use crate::bindings;
use crate::params::PresentParams;
use crate::shaders::PRESENT_WGSL;

/// The present pipeline for one target format.
#[derive(Debug)]
pub struct Presenter {
    layout: wgpu::BindGroupLayout,
    pipeline: wgpu::RenderPipeline,
    /// `fs_copy`: texels that need no conversion, without the sheet test.
    copy_pipeline: wgpu::RenderPipeline,
    linear_target: bool,
}

/// One texture ready to be presented, with the placement of the next draw.
#[derive(Debug)]
pub struct PresentSource {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// The target is `…UnormSrgb` (the background goes to it in linear light).
    linear_target: bool,
    /// The texels are sRGB-encoded values the shader decodes for the target; false when
    /// they reach it as they are (a `…Unorm` target, or a texture in the target's format).
    decode_texels: bool,
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
        let copy_pipeline = crate::fullscreen::pipeline_with(
            device,
            "marbling present (copy)",
            &pipeline_layout,
            &module,
            ["vs_main", "fs_copy"],
            format,
        );
        Self {
            layout,
            pipeline,
            copy_pipeline,
            linear_target: format.is_srgb(),
        }
    }

    /// Binds `view` (a texture holding sRGB-encoded values in a `…Unorm` format, such as
    /// a render of [`crate::ExactRenderer`] into an `Rgba8Unorm` target) for presenting.
    pub fn source(&self, device: &wgpu::Device, view: &wgpu::TextureView) -> PresentSource {
        self.bind(device, view, self.linear_target)
    }

    /// Binds `view`, a texture of this presenter's own target format, for presenting: its
    /// texels reach the target as they are (an `…UnormSrgb` view decodes them on load and
    /// the target encodes them again on store).
    pub fn source_in_target_format(
        &self,
        device: &wgpu::Device,
        view: &wgpu::TextureView,
    ) -> PresentSource {
        self.bind(device, view, false)
    }

    fn bind(
        &self,
        device: &wgpu::Device,
        view: &wgpu::TextureView,
        decode_texels: bool,
    ) -> PresentSource {
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
            decode_texels,
        }
    }

    /// Records a draw of `source` into `pass` (a target of this presenter's format): the
    /// texels in the sheet, the background around it. It covers the pass's viewport and
    /// scissor rectangle.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, source: &PresentSource) {
        self.draw_with(pass, source, &self.pipeline);
    }

    /// Records a draw of only `source`'s texels into `pass`, whose scissor rectangle must
    /// lie within the sheet. Where the texels need no conversion, this is a straight copy
    /// (`fs_copy`): a software GPU runs every branch of the full shader for every pixel,
    /// the sRGB decode included, so this is several times cheaper there.
    pub fn draw_texels(&self, pass: &mut wgpu::RenderPass<'_>, source: &PresentSource) {
        let pipeline = if source.decode_texels {
            &self.pipeline
        } else {
            &self.copy_pipeline
        };
        self.draw_with(pass, source, pipeline);
    }

    fn draw_with(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        source: &PresentSource,
        pipeline: &wgpu::RenderPipeline,
    ) {
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &source.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

impl PresentSource {
    /// Places the texture for the next draws.
    pub fn place(&mut self, queue: &wgpu::Queue, placement: &Placement) {
        queue.write_buffer(
            &self.uniform,
            0,
            bytemuck::bytes_of(&placement.params(self.linear_target, self.decode_texels)),
        );
    }
}

impl Placement {
    /// The uniform block for a target that is (`linear_target`) or is not `…UnormSrgb`,
    /// and texels the shader decodes from sRGB (`decode_texels`) or copies as they are.
    pub fn params(&self, linear_target: bool, decode_texels: bool) -> PresentParams {
        let bg = self.background.map(|b| {
            if linear_target {
                marbling_core::color::srgb_to_linear(b)
            } else {
                f32::from(b) / 255.0
            }
        });
        PresentParams {
            origin: self.origin,
            linear_target: u32::from(decode_texels),
            _pad: 0,
            sheet: self.sheet,
            background: [bg[0], bg[1], bg[2], 1.0],
        }
    }
}
