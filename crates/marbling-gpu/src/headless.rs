//! Headless exact renders to an [`RgbaImage`], tiled when the output is larger than one
//! tile (at most the device's texture side), with progress per tile. Native only.

use crate::compute::ComputeExact;
use crate::deep::DeepView;
use crate::exact::{ExactRenderer, PreparedDesign, View};
use crate::target::{RenderTarget, copy_to_buffer, read_buffer};
use crate::tile_grid;
use crate::{GpuContext, GpuError};
use marbling_core::{Antialias, Design, Op, Point, RenderOptions, RgbaImage, Window, output_size};

/// Default tile side, pixels (smaller when the device's texture limit is smaller).
/// Large enough that 1080p and 4K frames are one or a few draws, small enough that a
/// print render shows progress and no single draw runs for too long.
pub const DEFAULT_TILE_SIDE: u32 = 4096;

/// The format of headless renders: the shader encodes sRGB itself, like the CPU.
pub const OUTPUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Renders designs exactly on one device: the GPU twin of `marbling_core::render`.
#[derive(Debug)]
pub struct GpuRenderer {
    ctx: GpuContext,
    exact: ExactRenderer,
    /// The compute path, where the device has one (else the fragment pipeline draws).
    compute: Option<ComputeExact>,
    tile_side: u32,
}

impl GpuRenderer {
    /// A renderer on `ctx` producing RGBA8 sRGB images.
    pub fn new(ctx: GpuContext) -> Self {
        let exact = ExactRenderer::new(&ctx.device, OUTPUT_FORMAT);
        let compute =
            ComputeExact::supported(&ctx.device).then(|| ComputeExact::new(&ctx.device, &exact));
        let tile_side = DEFAULT_TILE_SIDE.min(ctx.max_texture_side());
        Self {
            ctx,
            exact,
            compute,
            tile_side,
        }
    }

    /// Draws with the fragment pipeline even where compute exists (the path the app and
    /// WebGL2 use; for comparisons and benchmarks).
    pub fn with_fragment_path(mut self) -> Self {
        self.compute = None;
        self
    }

    /// `"compute"` or `"fragment"`: how exact frames are drawn.
    pub fn path(&self) -> &'static str {
        if self.compute.is_some() {
            "compute"
        } else {
            "fragment"
        }
    }

    /// A `width × height` target of [`OUTPUT_FORMAT`] that [`GpuRenderer::draw`] can draw
    /// into on this renderer's path.
    pub fn target(&self, width: u32, height: u32) -> RenderTarget {
        let extra = if self.compute.is_some() {
            wgpu::TextureUsages::STORAGE_BINDING
        } else {
            wgpu::TextureUsages::empty()
        };
        RenderTarget::with_usage(&self.ctx.device, width, height, OUTPUT_FORMAT, extra)
    }

    /// Records the exact render of `design` into `target` on this renderer's path.
    fn record(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        design: &PreparedDesign,
        target: &RenderTarget,
    ) {
        match &self.compute {
            Some(c) => c.dispatch(&self.ctx.device, encoder, design, target),
            None => {
                let mut pass = target.begin_pass(encoder);
                self.exact.draw(&mut pass, design);
            }
        }
    }

    /// Uses tiles of at most `side` × `side` pixels (clamped to 1..=the device limit).
    pub fn with_tile_side(mut self, side: u32) -> Self {
        self.tile_side = side.clamp(1, self.ctx.max_texture_side());
        self
    }

    /// The tile side in use, pixels.
    pub fn tile_side(&self) -> u32 {
        self.tile_side
    }

    /// The device this renderer draws on.
    pub fn context(&self) -> &GpuContext {
        &self.ctx
    }

    /// The exact pipeline (for drawing into caller-owned targets of [`OUTPUT_FORMAT`]).
    pub fn exact(&self) -> &ExactRenderer {
        &self.exact
    }

    /// Uploads `design` for [`GpuRenderer::draw`].
    pub fn prepare(&self, design: &Design) -> Result<PreparedDesign, GpuError> {
        self.ctx.checked(|| {
            self.exact
                .prepare(&self.ctx.device, &self.ctx.queue, design)
        })?
    }

    /// Draws `design` into `target` (made by [`GpuRenderer::target`]) with `view` and
    /// submits; call [`GpuRenderer::wait`] to wait for the GPU.
    pub fn draw(&self, design: &mut PreparedDesign, target: &RenderTarget, view: &View) {
        design.set_view(&self.ctx.queue, view);
        self.record_draw(design, target);
    }

    /// Draws `design` into `target` with the view it holds (set with
    /// [`PreparedDesign::set_view`] or [`ExactRenderer::set_deep_view`]) and submits.
    pub fn record_draw(&self, design: &PreparedDesign, target: &RenderTarget) {
        let mut encoder = self
            .ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        self.record(&mut encoder, design, target);
        self.ctx.queue.submit([encoder.finish()]);
    }

    /// Blocks until all submitted work has finished.
    pub fn wait(&self) -> Result<(), GpuError> {
        self.ctx
            .device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
            .map_err(|e| GpuError::Wgpu(e.to_string()))
    }

    /// Renders the 3D view of `design` (the twin of `marbling_core::view3d::render_3d`,
    /// in f32, on the fragment path); the frame must fit one texture.
    pub fn render_3d(
        &self,
        design: &Design,
        view: &marbling_core::view3d::View3d,
    ) -> Result<RgbaImage, GpuError> {
        self.render_3d_styled(design, view, None)
    }

    /// [`GpuRenderer::render_3d`] with a style's overlay (of the view's size) blended in
    /// by the shader, as `StyleFrame::composite` blends it on the CPU.
    pub fn render_3d_styled(
        &self,
        design: &Design,
        view: &marbling_core::view3d::View3d,
        style: Option<&marbling_core::view3d::style::StyleFrame>,
    ) -> Result<RgbaImage, GpuError> {
        let side = self.ctx.max_texture_side();
        if view.width > side || view.height > side {
            return Err(GpuError::Wgpu(format!(
                "a 3D frame of {}×{} is larger than this device's textures ({side})",
                view.width, view.height
            )));
        }
        let mut prepared = self.prepare(design)?;
        let mut renderer = crate::View3dRenderer::new(&self.ctx.device, &self.exact);
        let mut image = RgbaImage::filled(view.width, view.height, [0, 0, 0, 255]);
        self.ctx.checked(|| -> Result<(), GpuError> {
            let (device, queue) = (&self.ctx.device, &self.ctx.queue);
            if let Some(side) = view.texture {
                renderer.bake(device, queue, &self.exact, &mut prepared, side);
            }
            renderer.set_style(device, queue, style);
            renderer.set_view(queue, &mut prepared, design, view);
            let target = self.target(view.width, view.height);
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            {
                let mut pass = target.begin_pass(&mut encoder);
                renderer.draw(device, &mut pass, &prepared);
            }
            let (buffer, padded) = copy_to_buffer(device, &mut encoder, &target);
            queue.submit([encoder.finish()]);
            let row_bytes = view.width as usize * 4;
            read_buffer(
                &self.ctx,
                &buffer,
                padded,
                view.width,
                view.height,
                |y, bytes| {
                    let start = y as usize * row_bytes;
                    image.pixels[start..start + bytes.len()].copy_from_slice(bytes);
                },
            )
        })??;
        Ok(image)
    }

    /// Renders `design` exactly (same output size, sample positions and colour handling
    /// as `marbling_core::render`, in f32).
    pub fn render(&self, design: &Design, opts: &RenderOptions) -> Result<RgbaImage, GpuError> {
        self.render_with_progress(design, opts, &|_, _| {})
    }

    /// [`GpuRenderer::render`], calling `progress(done, total)` after each tile.
    pub fn render_with_progress(
        &self,
        design: &Design,
        opts: &RenderOptions,
        progress: &dyn Fn(usize, usize),
    ) -> Result<RgbaImage, GpuError> {
        let mut prepared = self.prepare(design)?;
        self.render_prepared(&mut prepared, design, opts, progress)
    }

    /// The frame at time `t` of `turbulence` over `design` (the twin of
    /// `marbling_core::turbulence::Turbulence::render`, in f32): each sample walks back
    /// through the flow for each layer's time, then through the ops, the layers blended
    /// in linear light.
    pub fn render_turbulence(
        &self,
        design: &Design,
        turbulence: &marbling_core::turbulence::Turbulence,
        t: f64,
        opts: &RenderOptions,
    ) -> Result<RgbaImage, GpuError> {
        let mut flowed = design.clone();
        flowed
            .ops
            .push(Op::Flow(turbulence.flow(turbulence.period)));
        let mut prepared = self.prepare(&flowed)?;
        prepared.set_turbulence(&self.ctx.queue, Some(turbulence.layers(t)));
        self.render_prepared(&mut prepared, design, opts, &|_, _| {})
    }

    /// Renders `window` of `design` by the deep walk (one f64 reference per 64-pixel
    /// tile, each sample walking its offset from it in f32): the twin of
    /// `marbling_core::render_window` at any depth, where the plain f32 walk turns to
    /// blocks past about 10⁴×.
    pub fn render_window(
        &self,
        design: &Design,
        window: &Window,
        antialias: Antialias,
    ) -> Result<RgbaImage, GpuError> {
        window.check()?;
        let mut prepared = self.prepare(design)?;
        self.render_tiles(
            &mut prepared,
            [window.width, window.height],
            &|_, _| {},
            |p, x0, y0, w, h| {
                let view = DeepView {
                    origin: Point::new(
                        window.x0 + f64::from(x0) / window.scale,
                        window.y0 + f64::from(y0) / window.scale,
                    ),
                    scale: window.scale,
                    size: [w, h],
                    antialias,
                };
                self.exact
                    .set_deep_view(&self.ctx.device, &self.ctx.queue, p, &view)
            },
        )
    }

    /// [`GpuRenderer::render_window`] by the plain f32 walk (samples placed in f32 from
    /// the window's offset in output pixels): what shallow views draw with, and the
    /// baseline that shows where f32 fails.
    pub fn render_window_f32(
        &self,
        design: &Design,
        window: &Window,
        antialias: Antialias,
    ) -> Result<RgbaImage, GpuError> {
        window.check()?;
        let mut prepared = self.prepare(design)?;
        self.render_tiles(
            &mut prepared,
            [window.width, window.height],
            &|_, _| {},
            |p, x0, y0, _, _| {
                let view = View {
                    scale: window.scale,
                    offset: [
                        window.x0 * window.scale + f64::from(x0),
                        window.y0 * window.scale + f64::from(y0),
                    ],
                    antialias,
                };
                p.set_view(&self.ctx.queue, &view);
                Ok(())
            },
        )
    }

    /// Renders `prepared` (an upload of `design`) in tiles.
    fn render_prepared(
        &self,
        prepared: &mut PreparedDesign,
        design: &Design,
        opts: &RenderOptions,
        progress: &dyn Fn(usize, usize),
    ) -> Result<RgbaImage, GpuError> {
        let (width, height) = output_size(design, opts.scale)?;
        self.render_tiles(prepared, [width, height], progress, |p, x0, y0, _, _| {
            let view = View {
                scale: opts.scale,
                offset: [f64::from(x0), f64::from(y0)],
                antialias: opts.antialias,
            };
            p.set_view(&self.ctx.queue, &view);
            Ok(())
        })
    }

    /// Renders `prepared` into an image of `size` pixels, tile by tile: `set_view(prepared,
    /// x0, y0, w, h)` aims it at each tile before its draw.
    fn render_tiles(
        &self,
        prepared: &mut PreparedDesign,
        [width, height]: [u32; 2],
        progress: &dyn Fn(usize, usize),
        mut set_view: impl FnMut(&mut PreparedDesign, u32, u32, u32, u32) -> Result<(), GpuError>,
    ) -> Result<RgbaImage, GpuError> {
        let mut image = RgbaImage::filled(width, height, [0, 0, 0, 255]);
        let tiles = tile_grid(width, height, self.tile_side);
        for (done, &(x0, y0, w, h)) in tiles.iter().enumerate() {
            self.ctx.checked(|| -> Result<(), GpuError> {
                let target = self.target(w, h);
                set_view(prepared, x0, y0, w, h)?;
                let mut encoder = self
                    .ctx
                    .device
                    .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
                self.record(&mut encoder, prepared, &target);
                let (buffer, padded) = copy_to_buffer(&self.ctx.device, &mut encoder, &target);
                self.ctx.queue.submit([encoder.finish()]);
                let row_bytes = width as usize * 4;
                read_buffer(&self.ctx, &buffer, padded, w, h, |y, bytes| {
                    let start = (y0 + y) as usize * row_bytes + x0 as usize * 4;
                    image.pixels[start..start + bytes.len()].copy_from_slice(bytes);
                })
            })??;
            progress(done + 1, tiles.len());
        }
        Ok(image)
    }
}
