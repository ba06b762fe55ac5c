//! The canvas's GPU side: the exact render (or, while a tool is dragged, the live
//! preview) is drawn into an offscreen texture only when the design or the view changes;
//! egui then shows that texture like any image, so hovering never re-walks the ops.

use eframe::egui_wgpu;
use marbling_core::{Antialias, Design, Op};
use marbling_gpu::{
    ExactRenderer, PreparedDesign, PreviewCache, PreviewRenderer, RenderTarget, View,
};
use std::sync::{Arc, Mutex};

/// The canvas texture's format (what egui-wgpu expects of native textures); the renderer
/// sRGB-encodes into it itself, exactly as the CPU reference does.
pub const CANVAS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// What the next canvas frame must show.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameRequest {
    /// Changes whenever the committed (shown) design changes.
    pub design_key: u64,
    /// Texture size in physical pixels.
    pub size: [u32; 2],
    /// Physical pixels per design pixel.
    pub scale: f64,
    /// Design point at the texture's top-left corner.
    pub origin: [f64; 2],
    /// Antialiasing of exact frames.
    pub antialias: Antialias,
    /// The op being dragged, drawn with the live preview; `None` for the exact render.
    pub pending: Option<Op>,
}

/// What the GPU side reports back to the UI (shared with the paint callback).
#[derive(Debug, Default)]
pub struct CanvasStatus {
    /// The request whose frame is in the texture.
    pub drawn: Option<FrameRequest>,
    /// The last GPU-side error (e.g. more ops than the device's texture can hold).
    pub error: Option<String>,
    /// The design key whose live-preview cache is built (it is built in the frame after
    /// the exact frame, so the first drag frame does not have to wait for it).
    pub cache_ready: Option<u64>,
    /// The design key whose preview cache the GPU has finished rendering (set from the
    /// queue's work-done callback; 0 = none).
    pub cache_done: Arc<std::sync::atomic::AtomicU64>,
    /// How much GPU work the canvas has recorded: exact frames, preview frames and
    /// preview caches (for `data-gpu-work`: hovering must not add to any of them).
    pub work: GpuWork,
}

/// Counts of the canvas's GPU passes since start.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuWork {
    /// Exact renders of the design.
    pub exact: u64,
    /// Live-preview frames.
    pub preview: u64,
    /// Preview caches built.
    pub caches: u64,
}

/// GPU resources kept in egui-wgpu's callback resources between frames.
pub struct CanvasGpu {
    exact: ExactRenderer,
    preview: PreviewRenderer,
    target: Option<RenderTarget>,
    texture_id: Option<egui::TextureId>,
    prepared: Option<(u64, PreparedDesign)>,
    cache: Option<(u64, PreviewCache)>,
    caches_built: u64,
}

impl CanvasGpu {
    /// Builds the pipelines for `device`.
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            exact: ExactRenderer::new(device, CANVAS_FORMAT),
            preview: PreviewRenderer::new(device, CANVAS_FORMAT),
            target: None,
            texture_id: None,
            prepared: None,
            cache: None,
            caches_built: 0,
        }
    }

    /// The egui texture showing the canvas, (re)created at `size` physical pixels.
    pub fn texture_for(
        &mut self,
        device: &wgpu::Device,
        renderer: &mut egui_wgpu::Renderer,
        size: [u32; 2],
    ) -> egui::TextureId {
        let fits = self
            .target
            .as_ref()
            .is_some_and(|t| [t.width, t.height] == size);
        match (fits, self.texture_id) {
            (true, Some(id)) => id,
            (_, old) => {
                let target = RenderTarget::new(device, size[0], size[1], CANVAS_FORMAT);
                let id = match old {
                    Some(id) => {
                        renderer.update_egui_texture_from_wgpu_texture(
                            device,
                            &target.view,
                            wgpu::FilterMode::Nearest,
                            id,
                        );
                        id
                    }
                    None => renderer.register_native_texture(
                        device,
                        &target.view,
                        wgpu::FilterMode::Nearest,
                    ),
                };
                self.texture_id = Some(id);
                self.target = Some(target);
                id
            }
        }
    }

    /// Builds the live-preview cache of `design` for `req`'s scale unless it exists. The
    /// cache is rendered without antialiasing: at [`marbling_gpu::CACHE_FACTOR`] = 2 its
    /// 2 × 2 samples per screen pixel already smooth the preview, at a quarter of the
    /// cost of an RGSS cache (it matters on slow GPUs, where building it is the pause
    /// before a drag can start).
    fn ensure_cache(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
        req: &FrameRequest,
    ) -> Result<(), String> {
        let stale = self
            .cache
            .as_ref()
            .is_none_or(|(k, c)| *k != req.design_key || !c.covers(req.scale));
        if stale {
            self.caches_built += 1;
            self.cache = None;
            let cache = self
                .preview
                .build_cache(device, queue, design, req.scale, Antialias::None)
                .map_err(|e| e.to_string())?;
            self.cache = Some((req.design_key, cache));
        }
        Ok(())
    }

    /// Draws `req` into the canvas texture, recording into `encoder`.
    fn draw(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        design: &Design,
        req: &FrameRequest,
    ) -> Result<(), String> {
        if self
            .target
            .as_ref()
            .is_none_or(|t| [t.width, t.height] != req.size)
        {
            return Ok(());
        }
        if req.pending.is_some() {
            self.ensure_cache(device, queue, design, req)?;
        }
        let Some(target) = &self.target else {
            return Ok(());
        };
        if self
            .prepared
            .as_ref()
            .is_none_or(|(k, _)| *k != req.design_key)
        {
            self.prepared = None;
            let prepared = self
                .exact
                .prepare(device, queue, design)
                .map_err(|e| e.to_string())?;
            self.prepared = Some((req.design_key, prepared));
        }
        match &req.pending {
            None => {
                let Some((_, prepared)) = &mut self.prepared else {
                    return Ok(());
                };
                let offset = [req.origin[0] * req.scale, req.origin[1] * req.scale];
                prepared.set_view(
                    queue,
                    &View {
                        scale: req.scale,
                        offset,
                        antialias: req.antialias,
                    },
                );
                let mut pass = target.begin_pass(encoder);
                self.exact.draw(&mut pass, prepared);
            }
            Some(op) => {
                let Some((_, cache)) = &mut self.cache else {
                    return Ok(());
                };
                cache.set_frame(queue, Some(op), req.origin, req.scale, req.antialias);
                let mut pass = target.begin_pass(encoder);
                self.preview.draw(&mut pass, cache);
            }
        }
        Ok(())
    }
}

/// The per-frame paint callback: renders into the canvas texture when the request
/// differs from what is drawn there.
pub struct CanvasCallback {
    /// The committed design shown (without the pending op).
    pub design: Arc<Design>,
    /// What to draw.
    pub request: FrameRequest,
    /// Where the outcome is reported.
    pub status: Arc<Mutex<CanvasStatus>>,
    /// Woken when GPU work the UI waits for has finished.
    pub ctx: egui::Context,
}

impl egui_wgpu::CallbackTrait for CanvasCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Ok(mut status) = self.status.lock() else {
            return Vec::new();
        };
        let Some(gpu) = resources.get_mut::<CanvasGpu>() else {
            return Vec::new();
        };
        if status.drawn.as_ref() == Some(&self.request) {
            // The exact frame is on screen: use the idle frame to get the preview ready.
            if self.request.pending.is_none()
                && status.cache_ready != Some(self.request.design_key)
                && status.error.is_none()
            {
                match gpu.ensure_cache(device, queue, &self.design, &self.request) {
                    Ok(()) => {
                        status.cache_ready = Some(self.request.design_key);
                        let done = status.cache_done.clone();
                        let key = self.request.design_key;
                        let ctx = self.ctx.clone();
                        queue.on_submitted_work_done(move || {
                            done.store(key, std::sync::atomic::Ordering::SeqCst);
                            ctx.request_repaint();
                        });
                    }
                    Err(e) => status.error = Some(e),
                }
                status.work.caches = gpu.caches_built;
            }
            return Vec::new();
        }
        let outcome = gpu.draw(device, queue, encoder, &self.design, &self.request);
        if self.request.pending.is_some() {
            status.work.preview += 1;
        } else {
            status.work.exact += 1;
        }
        status.work.caches = gpu.caches_built;
        match outcome {
            Ok(()) => {
                status.drawn = Some(self.request.clone());
                status.error = None;
            }
            Err(e) => {
                status.drawn = Some(self.request.clone());
                status.error = Some(e);
            }
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        _pass: &mut wgpu::RenderPass<'static>,
        _resources: &egui_wgpu::CallbackResources,
    ) {
    }
}
