//! Live editing: while the user drags a tool, frames show the committed design from a
//! cache (rendered exactly once at ≥ 2× the view resolution) with only the pending op
//! walked per pixel on top (shaders/preview.wgsl).
//!
//! This is an approximation (the committed design is resampled bilinearly, in gamma
//! space, see [`CACHE_FORMAT`], and points the pending op pulls in from outside the canvas take the canvas
//! edge's colour). It is meant only for frames while dragging: when the op is committed
//! or the view changes, draw the exact render ([`crate::ExactRenderer`]) instead and
//! rebuild the cache for the new committed design (or new zoom, see
//! [`PreviewCache::covers`]).

use crate::bindings;
use crate::encode::encode_op;
use crate::exact::{ExactRenderer, PreparedDesign, View};
use crate::params::PreviewParams;
use crate::preview_kind::PreviewKind;
use crate::shaders::preview_wgsl;
use crate::target::RenderTarget;
use crate::{DesignPrefix, GpuError};
use marbling_core::{Antialias, Design, Op, output_size};

/// The cache's format, holding sRGB-encoded bytes (the exact renderer encodes them, as
/// for the canvas). The preview filters them bilinearly as they are, in gamma space: at
/// 2× the view's resolution the difference from filtering in linear light is a faint
/// darkening of some edge pixels while dragging, and it spares the one-sample preview
/// (slow devices) any sRGB decoding or encoding per pixel (docs/BENCHMARKS.md).
pub const CACHE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// How much finer than the view the cache is rendered, when the device allows.
pub const CACHE_FACTOR: f64 = 2.0;

/// The preview pipelines (per [`PreviewKind`], one taking the antialiasing's samples and
/// one taking a single sample) for one target format, and the exact pipeline that fills
/// caches.
#[derive(Debug)]
pub struct PreviewRenderer {
    layout: wgpu::BindGroupLayout,
    /// Indexed by [`PreviewKind::index`]: `[fs_main, fs_one_sample]`.
    pipelines: Vec<[wgpu::RenderPipeline; 2]>,
    sampler: wgpu::Sampler,
    cache_renderer: ExactRenderer,
    format: wgpu::TextureFormat,
}

/// A committed design cached in a texture, plus the pending op and view of the next frame.
#[derive(Debug)]
pub struct PreviewCache {
    cache: RenderTarget,
    /// The committed design, uploaded for drawing the cache.
    prepared: PreparedDesign,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    design_size: [f64; 2],
    cache_scale: f64,
    /// The largest cache scale the device's texture side allows for this design.
    max_scale: f64,
    encode_srgb: bool,
    /// The pipeline variant the next draw uses (the pending op's kind).
    kind: PreviewKind,
    /// True when the next draw takes one sample per pixel (`fs_one_sample`).
    one_sample: bool,
}

impl PreviewRenderer {
    /// Builds the pipelines; previews are drawn into targets of `format`.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        Self::sharing(device, format, &ExactRenderer::new(device, CACHE_FORMAT))
    }

    /// [`PreviewRenderer::new`] whose caches are drawn with `exact`'s pipelines where it
    /// draws into [`CACHE_FORMAT`] (each exact variant is then compiled once: on a
    /// software GPU a compile of a noise variant takes seconds).
    pub fn sharing(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        exact: &ExactRenderer,
    ) -> Self {
        let fragment = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling preview"),
            entries: &[
                bindings::uniform::<PreviewParams>(0, fragment),
                bindings::texture_2d(1, fragment, true),
                wgpu::BindGroupLayoutEntry {
                    binding: 2,
                    visibility: fragment,
                    ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                    count: None,
                },
            ],
        });
        let pipeline_layout = bindings::pipeline_layout(device, "marbling preview", &layout);
        let pipelines = PreviewKind::ALL
            .into_iter()
            .map(|kind| {
                let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some(&format!("marbling preview.wgsl ({})", kind.name())),
                    source: wgpu::ShaderSource::Wgsl(preview_wgsl(kind, format.is_srgb()).into()),
                });
                ["fs_main", "fs_one_sample"].map(|fragment| {
                    crate::fullscreen::pipeline_with(
                        device,
                        &format!("marbling preview ({}, {fragment})", kind.name()),
                        &pipeline_layout,
                        &module,
                        ["vs_main", fragment],
                        format,
                    )
                })
            })
            .collect();
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("marbling preview cache"),
            address_mode_u: wgpu::AddressMode::ClampToEdge,
            address_mode_v: wgpu::AddressMode::ClampToEdge,
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Self {
            layout,
            pipelines,
            sampler,
            cache_renderer: if exact.format() == CACHE_FORMAT {
                exact.clone()
            } else {
                ExactRenderer::new(device, CACHE_FORMAT)
            },
            format,
        }
    }

    /// The target format previews are drawn into.
    pub fn format(&self) -> wgpu::TextureFormat {
        self.format
    }

    /// Renders `committed` exactly (with `antialias`) into a new cache covering its whole
    /// canvas at [`CACHE_FACTOR`] × `view_scale` output pixels per design pixel, or less
    /// when that would exceed the device's texture side (see [`PreviewCache::cache_scale`]).
    /// The work is submitted in one draw; it need not have finished when this returns.
    pub fn build_cache(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        committed: &Design,
        view_scale: f64,
        antialias: Antialias,
    ) -> Result<PreviewCache, GpuError> {
        let cache = self.new_cache(device, queue, committed.into(), view_scale, antialias)?;
        let (w, h) = cache.cache_size();
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        self.draw_cache_rect(&mut encoder, &cache, [0, 0, w, h]);
        queue.submit([encoder.finish()]);
        Ok(cache)
    }

    /// A cache of `shown` as [`PreviewRenderer::build_cache`] makes it of a design, with
    /// nothing drawn yet: draw it with [`PreviewRenderer::draw_cache_rect`], in as many
    /// tiles as wanted, before showing it.
    pub fn new_cache(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        shown: DesignPrefix<'_>,
        view_scale: f64,
        antialias: Antialias,
    ) -> Result<PreviewCache, GpuError> {
        let max_side = f64::from(device.limits().max_texture_dimension_2d);
        let committed = shown.design;
        let longest = f64::from(committed.width.max(committed.height));
        let max_scale = max_side / longest;
        let cache_scale = (CACHE_FACTOR * view_scale).min(max_scale);
        let (w, h) = output_size(committed, cache_scale)?;
        let cache = RenderTarget::new(device, w, h, CACHE_FORMAT);
        let mut prepared = self.cache_renderer.prepare_prefix(device, queue, shown)?;
        prepared.set_view(
            queue,
            &View {
                scale: cache_scale,
                offset: [0.0; 2],
                antialias,
            },
        );
        let uniform = bindings::uniform_buffer::<PreviewParams>(device, "marbling preview params");
        let bind_group = crate::bindings::bind_group(
            device,
            "marbling preview",
            &self.layout,
            &[
                uniform.as_entire_binding(),
                wgpu::BindingResource::TextureView(&cache.view),
                wgpu::BindingResource::Sampler(&self.sampler),
            ],
        );
        let mut out = PreviewCache {
            cache,
            prepared,
            uniform,
            bind_group,
            design_size: [f64::from(committed.width), f64::from(committed.height)],
            cache_scale,
            max_scale,
            encode_srgb: !self.format.is_srgb(),
            kind: PreviewKind::Idle,
            one_sample: false,
        };
        out.set_frame(queue, None, [0.0; 2], view_scale, antialias);
        Ok(out)
    }

    /// Records the exact render of the cache's pixels `[x, y, width, height]` into
    /// `encoder` (a tile of the cache; the other pixels are kept).
    pub fn draw_cache_rect(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        cache: &PreviewCache,
        rect: [u32; 4],
    ) {
        let mut pass = cache.cache.begin_pass_keeping(encoder);
        self.cache_renderer
            .draw_rect(&mut pass, &cache.prepared, rect);
    }

    /// Records a full-target preview draw of `cache` into `pass` (target of this
    /// renderer's format).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, cache: &PreviewCache) {
        let [sampled, one_sample] = &self.pipelines[cache.kind.index()];
        pass.set_pipeline(if cache.one_sample {
            one_sample
        } else {
            sampled
        });
        pass.set_bind_group(0, &cache.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

impl PreviewCache {
    /// Sets what the next preview draws show: `pending` (the op being dragged, or
    /// `None`) over the cache, the view's top-left corner at design point `view_origin`,
    /// `view_scale` view pixels per design pixel, sampled with `antialias` (patterns of
    /// more than 4 samples fall back to RGSS).
    pub fn set_frame(
        &mut self,
        queue: &wgpu::Queue,
        pending: Option<&Op>,
        view_origin: [f64; 2],
        view_scale: f64,
        antialias: Antialias,
    ) {
        let encoded = pending.and_then(encode_op);
        self.kind = PreviewKind::of(encoded.as_ref());
        let params = PreviewParams::new(
            self.design_size,
            encoded,
            view_origin,
            view_scale,
            antialias,
            self.encode_srgb,
        );
        self.one_sample = params.sample_count == 1;
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&params));
    }

    /// Output pixels per design pixel of the cache.
    pub fn cache_scale(&self) -> f64 {
        self.cache_scale
    }

    /// The cache texture's size, pixels.
    pub fn cache_size(&self) -> (u32, u32) {
        (self.cache.width, self.cache.height)
    }

    /// True while the cache is at least [`CACHE_FACTOR`] times finer than a view of
    /// `view_scale`, or as fine as the device's textures allow (zooming in further calls
    /// for a new cache; at the texture limit a rebuild would give the same cache).
    pub fn covers(&self, view_scale: f64) -> bool {
        self.cache_scale >= (CACHE_FACTOR * view_scale).min(self.max_scale)
    }
}
