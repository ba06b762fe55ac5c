//! The exact renderer's pipeline (shaders/render.wgsl) and a design uploaded for it.
//! Pipelines are created once per device and target format; designs are uploaded into
//! their own op texture and uniform buffer, so an app can keep several.

use crate::DesignPrefix;
use crate::GpuError;
use crate::bindings;
use crate::encode::{GpuOp, OpLayout, records};
use crate::params::RenderParams;
use crate::shaders::{ExactVariant, RENDER_PLAIN_WGSL};
use crate::surface::SurfaceParams;
use crate::variants::Variants;
use marbling_core::ImageFit;
use marbling_core::image_background::ImagePixels;
use marbling_core::turbulence::Layer;
use marbling_core::{Antialias, Design, Op};
use marbling_noise::wgsl::NoiseKinds;
use std::sync::Arc;
use textures::{image_texture, op_texture, write_records};

mod deep_view;
mod textures;

/// The exact render pipeline for one target format, in [`ExactVariant`]s: plain (every
/// v1 design; no noise or stylus code) built at once, the others (with the noise types
/// of a design's schema v2 surfaces, with finite combs and styli, with both) on the
/// first design that needs them. Clones share the pipelines (the preview cache's
/// renderer and the canvas's compile each variant once).
#[derive(Clone, Debug)]
pub struct ExactRenderer {
    layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: Arc<Variants<wgpu::RenderPipeline>>,
    format: wgpu::TextureFormat,
}

/// A design uploaded to the GPU: its op texture, uniform buffers and bind group. It can
/// be brought up to another design or prefix with [`ExactRenderer::update`], which
/// writes only the ops that differ (the texture keeps room to grow).
#[derive(Debug)]
pub struct PreparedDesign {
    ops_texture: wgpu::Texture,
    layout: OpLayout,
    /// The ops in the texture, oldest first (all of them are walked).
    uploaded: Vec<Op>,
    /// The number of records after each uploaded op.
    record_ends: Vec<usize>,
    /// The records in the texture, oldest first.
    records: Vec<GpuOp>,
    /// Records written into the texture since it was prepared.
    written: u64,
    surface: wgpu::Buffer,
    surface_params: SurfaceParams,
    /// What a sample's noise costs beyond the walk ([`Design::surface_cost`]).
    surface_cost: u64,
    /// The image background's pixels (1×1 when there is none), bound at binding 3.
    image_texture: wgpu::Texture,
    /// The pixels in `image_texture` (compared by pointer to skip re-uploads).
    image_uploaded: Option<Arc<ImagePixels>>,
    /// A live picture (a video frame) shown instead of the design's background.
    live_image: Option<(Arc<ImagePixels>, ImageFit)>,
    /// Whether the design needs the surface variant of the pipeline.
    textured: bool,
    /// Whether it holds ops only the v3 walk knows ([`Op::walks_v3`]).
    v3: bool,
    /// Whether it holds a flow ([`Op::is_v4`]).
    flow: bool,
    /// The layers of a looping turbulence whose flow is the last uploaded op
    /// ([`PreparedDesign::set_turbulence`]).
    turbulence: Option<[Layer; 2]>,
    /// Deep zoom's reference records (`shaders/deep.wgsl`; 1×1 when not deep), bound
    /// at binding 4.
    deep_texture: wgpu::Texture,
    /// The deep walk's parameters ([`RenderParams::deep`]) while a deep view is set.
    deep: Option<[u32; 4]>,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    params: RenderParams,
    view: View,
    background: marbling_core::Rgb8,
    width: u32,
    height: u32,
}

/// Op-texture room for `n` ops with space to grow: appending ops seldom needs a new
/// texture. Falls back to exactly `n` where the rounded-up room would not fit.
fn room_for(n: usize, max_side: u32) -> Option<OpLayout> {
    const MIN_ROOM: usize = 64;
    OpLayout::for_capacity(n.max(MIN_ROOM).next_power_of_two(), max_side)
        .or_else(|| OpLayout::for_capacity(n, max_side))
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
                bindings::texture_2d(3, visibility, false),
                bindings::texture_2d(4, visibility, false),
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
        let pipelines = Arc::new(Variants::default());
        pipelines.get_or_init(ExactVariant::PLAIN, || pipeline);
        Self {
            layout,
            pipeline_layout,
            pipelines,
            format,
        }
    }

    /// The pipeline of `variant`, compiled on first use.
    fn variant_pipeline(
        &self,
        device: &wgpu::Device,
        variant: ExactVariant,
    ) -> wgpu::RenderPipeline {
        self.pipelines.get_or_init(variant, || {
            let label = format!("marbling render ({})", variant.name());
            let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(&label),
                source: wgpu::ShaderSource::Wgsl(variant.render_wgsl().into()),
            });
            crate::fullscreen::pipeline(device, &label, &self.pipeline_layout, &module, self.format)
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

    /// Uploads `design` (op texture rows at most the device's texture side).
    pub fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
    ) -> Result<PreparedDesign, GpuError> {
        self.prepare_prefix(device, queue, design.into())
    }

    /// Uploads what `shown` walks.
    pub fn prepare_prefix(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        shown: DesignPrefix<'_>,
    ) -> Result<PreparedDesign, GpuError> {
        let max_side = device.limits().max_texture_dimension_2d;
        let layout = room_for(shown.op_count(), max_side).ok_or(GpuError::TooManyOps {
            ops: shown.op_count(),
            max_side,
        })?;
        let ops_texture = op_texture(device, layout);
        let uniform = bindings::uniform_buffer::<RenderParams>(device, "marbling render params");
        let surface = bindings::uniform_buffer::<SurfaceParams>(device, "marbling surface params");
        let image_texture = image_texture(device, 1, 1);
        let deep_texture = op_texture(device, OpLayout::SMALLEST);
        let bind_group = self.bind_group(
            device,
            &uniform,
            &ops_texture,
            &surface,
            [&image_texture, &deep_texture],
        );
        let design = shown.design;
        let view = View {
            scale: 1.0,
            offset: [0.0; 2],
            antialias: Antialias::None,
        };
        let mut prepared = PreparedDesign {
            ops_texture,
            layout,
            uploaded: Vec::new(),
            record_ends: Vec::new(),
            records: Vec::new(),
            written: 0,
            surface_params: SurfaceParams::new(design),
            surface_cost: design.surface_cost(),
            surface,
            image_texture,
            image_uploaded: None,
            live_image: None,
            textured: false,
            v3: false,
            flow: false,
            turbulence: None,
            deep_texture,
            deep: None,
            uniform,
            bind_group,
            params: RenderParams::new(
                design.background,
                0,
                layout.ops_per_row,
                view.antialias,
                view.scale,
                view.offset,
                !self.format.is_srgb(),
            ),
            view,
            background: design.background,
            width: design.width,
            height: design.height,
        };
        queue.write_buffer(
            &prepared.surface,
            0,
            bytemuck::bytes_of(&prepared.surface_params),
        );
        self.update(device, queue, &mut prepared, shown)?;
        Ok(prepared)
    }

    /// Brings `prepared` up to `shown`: writes the ops from the first one that differs
    /// from what the texture holds (a longer prefix or a gesture's new ops write only
    /// those; a shorter prefix writes nothing), the paper and the surface. A new texture
    /// is made only when the ops outgrow the old one. Applies to command buffers
    /// submitted after this call.
    pub fn update(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        prepared: &mut PreparedDesign,
        shown: DesignPrefix<'_>,
    ) -> Result<(), GpuError> {
        let same = prepared
            .uploaded
            .iter()
            .zip(shown.ops())
            .take_while(|(a, b)| a == b)
            .count();
        let mut start = same.checked_sub(1).map_or(0, |k| prepared.record_ends[k]);
        prepared.uploaded.truncate(same);
        prepared.record_ends.truncate(same);
        prepared.records.truncate(start);
        for op in shown.ops().skip(same) {
            records(op, &mut prepared.records);
            prepared.uploaded.push(op.clone());
            prepared.record_ends.push(prepared.records.len());
        }
        let n = prepared.records.len();
        if n > prepared.layout.capacity() {
            let max_side = device.limits().max_texture_dimension_2d;
            let Some(layout) = room_for(n, max_side) else {
                prepared.uploaded.clear();
                prepared.record_ends.clear();
                prepared.records.clear();
                return Err(GpuError::TooManyOps { ops: n, max_side });
            };
            prepared.ops_texture = op_texture(device, layout);
            prepared.layout = layout;
            self.rebind(device, prepared);
            start = 0;
        }
        write_records(queue, prepared, start..n);
        let design = shown.design;
        prepared.surface_cost = design.surface_cost();
        let mut surface_params = SurfaceParams::new(design);
        let image = match &prepared.live_image {
            Some((pixels, fit)) => Some((pixels.clone(), *fit)),
            None => design
                .background_image
                .as_ref()
                .map(|b| (b.pixels_arc().clone(), b.fit)),
        };
        if let Some((pixels, fit)) = &image {
            surface_params.set_image(pixels, *fit, design);
        }
        self.upload_image(device, queue, prepared, image.map(|(pixels, _)| pixels));
        if surface_params != prepared.surface_params {
            queue.write_buffer(&prepared.surface, 0, bytemuck::bytes_of(&surface_params));
            prepared.surface_params = surface_params;
        }
        prepared.textured = surface_params.needs_noise();
        prepared.v3 = prepared.uploaded.iter().any(Op::walks_v3);
        prepared.flow = prepared.uploaded.iter().any(Op::is_v4);
        self.variant_pipeline(device, prepared.variant());
        prepared.background = design.background;
        (prepared.width, prepared.height) = (design.width, design.height);
        prepared.write_params(queue);
        Ok(())
    }

    /// Shows `pixels` (a live video frame, laid on the sheet by `fit`) as the
    /// background of `prepared` instead of the design's own, or the design's own again
    /// with `None`; `shown` is what `prepared` holds. Uploads the pixels (a new texture
    /// only when their size changes).
    pub fn set_live_image(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        prepared: &mut PreparedDesign,
        shown: DesignPrefix<'_>,
        live: Option<(Arc<ImagePixels>, ImageFit)>,
    ) -> Result<(), GpuError> {
        prepared.live_image = live;
        self.update(device, queue, prepared, shown)
    }

    /// Puts `image` (or nothing) into `prepared`'s image texture, re-binding when the
    /// texture is replaced.
    fn upload_image(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        prepared: &mut PreparedDesign,
        image: Option<Arc<ImagePixels>>,
    ) {
        let same = match (&image, &prepared.image_uploaded) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            _ => false,
        };
        if same {
            return;
        }
        let (w, h) = image.as_ref().map_or((1, 1), |p| (p.width, p.height));
        let size = prepared.image_texture.size();
        if (size.width, size.height) != (w, h) {
            prepared.image_texture = image_texture(device, w, h);
            self.rebind(device, prepared);
        }
        if let Some(p) = &image {
            queue.write_texture(
                prepared.image_texture.as_image_copy(),
                &p.rgba,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(4 * w),
                    rows_per_image: Some(h),
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: 1,
                },
            );
        }
        prepared.image_uploaded = image;
    }

    /// Makes `prepared`'s bind group anew after one of its textures was replaced.
    fn rebind(&self, device: &wgpu::Device, prepared: &mut PreparedDesign) {
        prepared.bind_group = self.bind_group(
            device,
            &prepared.uniform,
            &prepared.ops_texture,
            &prepared.surface,
            [&prepared.image_texture, &prepared.deep_texture],
        );
    }

    /// Bind group 0 over a design's buffers, op texture, image and deep-reference textures.
    fn bind_group(
        &self,
        device: &wgpu::Device,
        uniform: &wgpu::Buffer,
        ops: &wgpu::Texture,
        surface: &wgpu::Buffer,
        [image, deep]: [&wgpu::Texture; 2],
    ) -> wgpu::BindGroup {
        let view = ops.create_view(&wgpu::TextureViewDescriptor::default());
        let image_view = image.create_view(&wgpu::TextureViewDescriptor::default());
        let deep_view = deep.create_view(&wgpu::TextureViewDescriptor::default());
        crate::bindings::bind_group(
            device,
            "marbling render",
            &self.layout,
            &[
                uniform.as_entire_binding(),
                wgpu::BindingResource::TextureView(&view),
                surface.as_entire_binding(),
                wgpu::BindingResource::TextureView(&image_view),
                wgpu::BindingResource::TextureView(&deep_view),
            ],
        )
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
        // `update` built the variant of every design it uploaded.
        let Some(pipeline) = self.pipelines.get(design.variant()) else {
            return;
        };
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &design.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

impl PreparedDesign {
    /// Sets the view of the next draws (written to the uniform buffer through `queue`, so
    /// it applies to command buffers submitted after this call).
    pub fn set_view(&mut self, queue: &wgpu::Queue, view: &View) {
        self.view = *view;
        self.deep = None;
        self.write_params(queue);
    }

    /// Shows the uploaded ops as a looping turbulence's frame
    /// (`marbling_core::turbulence`): the last uploaded op must be a flow (of any time;
    /// its noise and strength are the turbulence's), and each sample walks back through
    /// it for each layer's time, then through the ops before it, the layers blended by
    /// their weights. `None`, or a last op that is no flow: the ops as they are.
    pub fn set_turbulence(&mut self, queue: &wgpu::Queue, layers: Option<[Layer; 2]>) {
        self.turbulence = layers;
        self.write_params(queue);
    }

    /// The flow the turbulence layers follow: the last uploaded op, when one is set.
    fn turbulence_flow(&self) -> Option<(&marbling_core::Flow, [Layer; 2])> {
        match (self.uploaded.last(), self.turbulence) {
            (Some(Op::Flow(flow)), Some(layers)) => Some((flow, layers)),
            _ => None,
        }
    }

    fn write_params(&mut self, queue: &wgpu::Queue) {
        let mut op_count = self.records.len() as u32;
        let mut layers = [[0.0; 4]; 2];
        if let Some((flow, turbulence)) = self.turbulence_flow() {
            let header = self.records.len() - 1;
            let before = self.uploaded.len().checked_sub(2);
            op_count = before.map_or(0, |k| self.record_ends[k]) as u32;
            for (slot, layer) in layers.iter_mut().zip(turbulence) {
                let field = marbling_core::Flow {
                    time: layer.time,
                    ..flow.clone()
                }
                .field();
                *slot = [
                    field.dt as f32,
                    field.steps as f32,
                    layer.weight as f32,
                    header as f32,
                ];
            }
        }
        self.params = RenderParams::new(
            self.background,
            op_count,
            self.layout.ops_per_row,
            self.view.antialias,
            self.view.scale,
            self.view.offset,
            self.params.encode_srgb == 1,
        );
        self.params.layers = layers;
        self.params.deep = self.deep.unwrap_or([0; 4]);
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&self.params));
    }

    /// The design's canvas size, design pixels.
    pub fn design_size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Number of records walked (one per op for most ops; see [`crate::encode`]).
    pub fn op_count(&self) -> usize {
        self.records.len()
    }

    /// What one sample costs, in simple ops: its walk back through every op
    /// ([`Op::walk_cost`]) and the noise it reads ([`Design::surface_cost`]); renderers
    /// size their tiles by it.
    pub fn walk_cost(&self) -> u64 {
        let ops: u64 = self.uploaded.iter().map(Op::walk_cost).sum();
        // A turbulence walks twice: the two layers' flow times add up to less than
        // 1.5 periods, the flow's own time being one.
        let walks = if self.turbulence_flow().is_some() {
            2
        } else {
            1
        };
        walks * ops + self.surface_cost
    }

    /// Records written into the op texture since it was prepared (an update that only
    /// appends writes only the new ones; one record per op for most ops).
    pub fn ops_written(&self) -> u64 {
        self.written
    }

    /// The exact-renderer variant the design needs.
    pub(crate) fn variant(&self) -> ExactVariant {
        ExactVariant {
            noises: if self.textured {
                self.surface_params.noise_kinds()
            } else {
                NoiseKinds::NONE
            },
            v3: self.v3,
            flow: self.flow,
            deep: self.deep.is_some(),
        }
    }

    /// Bind group 0 of the exact pipelines.
    pub(crate) fn bind_group(&self) -> &wgpu::BindGroup {
        &self.bind_group
    }
}
