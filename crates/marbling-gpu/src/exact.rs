//! The exact renderer's pipeline (shaders/render.wgsl) and a design uploaded for it.
//! Pipelines are created once per device and target format; designs are uploaded into
//! their own op texture and uniform buffer, so an app can keep several.

use crate::GpuError;
use crate::bindings;
use crate::encode::layout_ops;
use crate::params::RenderParams;
use crate::shaders::{RENDER_PLAIN_WGSL, render_wgsl};
use crate::surface::SurfaceParams;
use marbling_core::{Antialias, Design};
use std::sync::OnceLock;

/// The exact render pipeline for one target format, in two variants: plain (every v1
/// design; no noise code) and, built on the first design that needs it, with schema v2
/// surfaces (noise background, grain overlays).
#[derive(Debug)]
pub struct ExactRenderer {
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipeline: wgpu::RenderPipeline,
    surface_pipeline: OnceLock<wgpu::RenderPipeline>,
    format: wgpu::TextureFormat,
}

/// A design uploaded to the GPU: its op texture, uniform buffer and bind group.
#[derive(Debug)]
pub struct PreparedDesign {
    _ops: wgpu::Texture,
    _surface: wgpu::Buffer,
    /// Whether the design needs the surface variant of the pipeline.
    textured: bool,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    params: RenderParams,
    background: marbling_core::Rgb8,
    width: u32,
    height: u32,
    op_count: usize,
}

/// Which part of the output a draw covers, and how it is sampled.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Output pixels per design pixel (> 0).
    pub scale: f64,
    /// Output pixel (column, row) that the target's top-left pixel shows; output pixel
    /// (i, j) samples design point ((i + dx)/scale, (j + dy)/scale).
    pub offset: [f64; 2],
    /// Antialiasing pattern (the same sample positions and weights as the CPU).
    pub antialias: Antialias,
}

impl ExactRenderer {
    /// Builds the pipeline drawing into targets of `format`. With an sRGB format the
    /// shader writes linear light and the hardware encodes; with any other (e.g.
    /// `Rgba8Unorm`) the shader encodes sRGB itself, exactly like the CPU renderer.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("marbling render.wgsl (plain)"),
            source: wgpu::ShaderSource::Wgsl(RENDER_PLAIN_WGSL.into()),
        });
        // The compute variant (crate::compute) shares this group where it can run.
        let visibility = if crate::compute::ComputeExact::supported(device) {
            wgpu::ShaderStages::FRAGMENT | wgpu::ShaderStages::COMPUTE
        } else {
            wgpu::ShaderStages::FRAGMENT
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling render"),
            entries: &[
                bindings::uniform::<RenderParams>(0, visibility),
                bindings::texture_2d(1, visibility, false),
                bindings::uniform::<SurfaceParams>(2, visibility),
            ],
        });
        let pipeline_layout = bindings::pipeline_layout(device, "marbling render", &layout);
        let pipeline = crate::fullscreen::pipeline(
            device,
            "marbling render",
            &pipeline_layout,
            &module,
            format,
        );
        Self {
            layout,
            pipeline_layout,
            pipeline,
            surface_pipeline: OnceLock::new(),
            format,
        }
    }

    /// The variant with schema v2 surfaces, compiled on first use.
    fn surface_pipeline(&self, device: &wgpu::Device) -> &wgpu::RenderPipeline {
        self.surface_pipeline.get_or_init(|| {
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("marbling render.wgsl (surface)"),
                source: wgpu::ShaderSource::Wgsl(render_wgsl().into()),
            });
            crate::fullscreen::pipeline(
                device,
                "marbling render (surface)",
                &self.pipeline_layout,
                &module,
                self.format,
            )
        })
    }

    /// The layout of bind group 0 (params, ops, surface), shared with the compute
    /// variant.
    pub(crate) fn bind_group_layout(&self) -> &wgpu::BindGroupLayout {
        &self.layout
    }

    /// The target format this pipeline draws into.
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// Uploads `design`'s ops (op texture rows at most the device's texture side).
    pub fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
    ) -> Result<PreparedDesign, GpuError> {
        let max_side = device.limits().max_texture_dimension_2d;
        let texels = layout_ops(&design.ops, max_side).ok_or(GpuError::TooManyOps {
            ops: design.ops.len(),
            max_side,
        })?;
        let size = wgpu::Extent3d {
            width: texels.width,
            height: texels.height,
            depth_or_array_layers: 1,
        };
        let ops = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("marbling ops"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba32Float,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &ops,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            bytemuck::cast_slice(&texels.texels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(texels.width * 16),
                rows_per_image: Some(texels.height),
            },
            size,
        );
        let params = RenderParams::new(
            design.background,
            texels.op_count,
            texels.ops_per_row,
            Antialias::None,
            1.0,
            [0.0; 2],
            !self.format.is_srgb(),
        );
        let uniform = bindings::uniform_buffer::<RenderParams>(device, "marbling render params");
        queue.write_buffer(&uniform, 0, bytemuck::bytes_of(&params));
        let surface_params = SurfaceParams::new(design);
        if surface_params.flags != 0 {
            self.surface_pipeline(device);
        }
        let surface = bindings::uniform_buffer::<SurfaceParams>(device, "marbling surface params");
        queue.write_buffer(&surface, 0, bytemuck::bytes_of(&surface_params));
        let view = ops.create_view(&wgpu::TextureViewDescriptor::default());
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("marbling render"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&view),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: surface.as_entire_binding(),
                },
            ],
        });
        Ok(PreparedDesign {
            _ops: ops,
            _surface: surface,
            textured: surface_params.flags != 0,
            uniform,
            bind_group,
            params,
            background: design.background,
            width: design.width,
            height: design.height,
            op_count: design.ops.len(),
        })
    }

    /// Records a full-target draw of `design` (its view set with
    /// [`PreparedDesign::set_view`]) into `pass`, whose target has this pipeline's format.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, design: &PreparedDesign) {
        self.draw_full(pass, design);
    }

    /// Records a draw of `design` into the target pixels `[x, y, width, height]` of
    /// `pass` alone (a tile of a progressive render; the rest of the target is left as
    /// it is when the pass keeps its pixels). The pixels drawn are exactly those of a
    /// full draw.
    pub fn draw_rect(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        design: &PreparedDesign,
        rect: [u32; 4],
    ) {
        let [x, y, w, h] = rect;
        pass.set_scissor_rect(x, y, w, h);
        self.draw_full(pass, design);
    }

    fn draw_full(&self, pass: &mut wgpu::RenderPass<'_>, design: &PreparedDesign) {
        let pipeline = match (design.textured, self.surface_pipeline.get()) {
            (true, Some(p)) => p,
            // `prepare` built the surface variant for every design that needs it.
            _ => &self.pipeline,
        };
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &design.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

impl PreparedDesign {
    /// Sets the view of the next draws (written to the uniform buffer through `queue`, so
    /// it applies to command buffers submitted after this call).
    pub fn set_view(&mut self, queue: &wgpu::Queue, view: &View) {
        self.params = RenderParams::new(
            self.background,
            self.params.op_count,
            self.params.ops_per_row,
            view.antialias,
            view.scale,
            view.offset,
            self.params.encode_srgb == 1,
        );
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&self.params));
    }

    /// The design's canvas size, design pixels.
    pub fn design_size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Number of ops uploaded.
    pub fn op_count(&self) -> usize {
        self.op_count
    }

    /// Whether the design needs the surface (schema v2) variant.
    pub(crate) fn textured(&self) -> bool {
        self.textured
    }

    /// Bind group 0 of the exact pipelines.
    pub(crate) fn bind_group(&self) -> &wgpu::BindGroup {
        &self.bind_group
    }
}
