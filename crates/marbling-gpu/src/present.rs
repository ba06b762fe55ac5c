//! Showing a rendered texture 1:1 inside someone else's render pass (the app's canvas and
//! cached panels, in egui's pass): texels are copied, sampled at their centres with a
//! nearest-texel sampler, within the pass's scissor rectangle, nothing is filtered or blended (shaders/present.wgsl). The exact
//! bytes of the render reach the screen, and on software GPUs (SwiftShader) such a draw
//! costs a fraction of egui's textured, blended image (docs/BENCHMARKS.md, "Where the
//! time goes").

use crate::bindings;
use crate::params::PresentParams;
use crate::shaders::PRESENT_WGSL;

/// The present pipelines for one target format.
#[derive(Debug)]
pub struct Presenter {
    layout: wgpu::BindGroupLayout,
    /// `fs_copy`: texels that need no conversion.
    copy_pipeline: wgpu::RenderPipeline,
    /// `fs_decode`: sRGB-encoded texels for an `…UnormSrgb` target.
    decode_pipeline: wgpu::RenderPipeline,
    /// Nearest-texel, clamped to the edge.
    sampler: wgpu::Sampler,
    /// The target is `…UnormSrgb`.
    srgb_target: bool,
}

/// One texture ready to be presented, with the placement of the next draw.
#[derive(Debug)]
pub struct PresentSource {
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// The texels are sRGB-encoded values the shader decodes for the target; false when
    /// they reach it as they are (a `…Unorm` target, or a texture in the target's format).
    decode_texels: bool,
}

/// Where a texture goes in the target, in target pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    /// Target pixel of the texture's texel (0, 0) (whole pixels).
    pub origin: [f32; 2],
}

impl Presenter {
    /// Builds the pipelines drawing into targets of `format`.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("marbling present.wgsl"),
            source: wgpu::ShaderSource::Wgsl(PRESENT_WGSL.into()),
        });
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling present"),
            entries: &[
                bindings::uniform::<PresentParams>(0, fragment),
                bindings::texture_2d(1, fragment, false),
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: fragment,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::NonFiltering),
                    count: None,
                },
            ],
        });
        let pipeline_layout = bindings::pipeline_layout(device, "marbling present", &layout);
        let [copy_pipeline, decode_pipeline] =
            [("copy", "fs_copy"), ("decode", "fs_decode")].map(|(name, entry)| {
                crate::fullscreen::pipeline_with(
                    device,
                    &format!("marbling present ({name})"),
                    &pipeline_layout,
                    &module,
                    ["vs_main", entry],
                    format,
                )
            });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("marbling present"),
            ..Default::default()
        });
        Self {
            layout,
            copy_pipeline,
            decode_pipeline,
            sampler,
            srgb_target: format.is_srgb(),
        }
    }

    /// Binds `view` (a texture holding sRGB-encoded values in a `…Unorm` format, such as
    /// a render of [`crate::ExactRenderer`] into an `Rgba8Unorm` target) for presenting.
    pub fn source(&self, device: &wgpu::Device, view: &wgpu::TextureView) -> PresentSource {
        self.bind(device, view, self.srgb_target)
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
        let bind_group = crate::bindings::bind_group(
            device,
            "marbling present",
            &self.layout,
            &[
                uniform.as_entire_binding(),
                wgpu::BindingResource::TextureView(view),
                wgpu::BindingResource::Sampler(&self.sampler),
            ],
        );
        PresentSource {
            uniform,
            bind_group,
            decode_texels,
        }
    }

    /// Records a draw of `source`'s texels into `pass` (a target of this presenter's
    /// format), covering its viewport and scissor rectangle. Where the texels need no
    /// conversion this is a straight copy (`fs_copy`), else they are decoded from sRGB
    /// (`fs_decode`).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, source: &PresentSource) {
        pass.set_pipeline(if source.decode_texels {
            &self.decode_pipeline
        } else {
            &self.copy_pipeline
        });
        pass.set_bind_group(0, &source.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

impl PresentSource {
    /// Places the texture for the next draws.
    pub fn place(&mut self, queue: &wgpu::Queue, placement: &Placement) {
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&placement.params()));
    }
}

impl Placement {
    /// The uniform block.
    pub fn params(&self) -> PresentParams {
        PresentParams {
            origin: self.origin,
            _pad: [0.0; 2],
        }
    }
}
