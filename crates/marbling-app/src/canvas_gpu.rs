//! The canvas's GPU side. The exact render is drawn into an offscreen texture only when
//! the design or the view changes, and every frame copies that texture 1:1 into egui's
//! pass over the sheet in one cheap draw (the grey around it is the window's clear
//! colour), so hovering never re-walks the ops. While a tool is dragged, the live
//! preview is drawn straight into egui's pass over the sheet instead: one pass per
//! frame, not two.

use eframe::egui_wgpu;
use egui::{Pos2, Rect};
use marbling_core::{Antialias, Design, Op};
use marbling_gpu::{
    ExactRenderer, Placement, PreparedDesign, PresentSource, Presenter, PreviewCache,
    PreviewRenderer, RenderTarget, View,
};
use std::sync::{Arc, Mutex};

/// The canvas texture's format; the renderer sRGB-encodes into it itself, exactly as the
/// CPU reference does.
pub const CANVAS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// The colour around the sheet (sRGB bytes).
pub const SURROUND: [u8; 3] = [48, 48, 48];

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
    /// The number of the last exact frame the GPU has finished (of [`GpuWork::exact`];
    /// set from the queue's work-done callback, asked for in the frame after the one
    /// that recorded it, when its commands have been submitted).
    pub exact_done: Arc<std::sync::atomic::AtomicU64>,
    /// The exact frame whose completion was asked for.
    pub exact_asked: u64,
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
    /// Draws into egui's target (format of the window's surface).
    preview: PreviewRenderer,
    presenter: Presenter,
    /// The exact frame, and its binding for the present draw.
    target: Option<(RenderTarget, PresentSource)>,
    prepared: Option<(u64, PreparedDesign)>,
    cache: Option<(u64, PreviewCache)>,
    caches_built: u64,
}

impl CanvasGpu {
    /// Builds the pipelines for `device`; egui draws into targets of `surface_format`.
    pub fn new(device: &wgpu::Device, surface_format: wgpu::TextureFormat) -> Self {
        Self {
            exact: ExactRenderer::new(device, CANVAS_FORMAT),
            preview: PreviewRenderer::new(device, surface_format),
            presenter: Presenter::new(device, surface_format),
            target: None,
            prepared: None,
            cache: None,
            caches_built: 0,
        }
    }

    /// (Re)creates the canvas texture at `size` physical pixels unless it has that size.
    fn ensure_target(&mut self, device: &wgpu::Device, size: [u32; 2]) {
        let fits = self
            .target
            .as_ref()
            .is_some_and(|(t, _)| [t.width, t.height] == size);
        if !fits {
            let target = RenderTarget::new(device, size[0], size[1], CANVAS_FORMAT);
            let source = self.presenter.source(device, &target.view);
            self.target = Some((target, source));
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

    /// Draws the exact frame of `req` (no pending op) into the canvas texture,
    /// recording into `encoder`.
    fn draw_exact(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        design: &Design,
        req: &FrameRequest,
    ) -> Result<(), String> {
        self.ensure_target(device, req.size);
        let Some((target, _)) = &self.target else {
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
        Ok(())
    }

    /// Sets up the live preview of `op` over `design`'s cache for `req`, drawn straight
    /// into egui's target with the canvas texture's top-left at `canvas_px`.
    fn set_preview(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        design: &Design,
        req: &FrameRequest,
        op: &Op,
        canvas_px: [f64; 2],
    ) -> Result<(), String> {
        self.ensure_cache(device, queue, design, req)?;
        if let Some((_, cache)) = &mut self.cache {
            // Target pixel (X, Y) shows the design point the texture's pixel
            // (X, Y) − canvas_px would: the same samples as a render into the texture.
            let origin = [
                req.origin[0] - canvas_px[0] / req.scale,
                req.origin[1] - canvas_px[1] / req.scale,
            ];
            cache.set_frame(queue, Some(op), origin, req.scale, req.antialias);
        }
        Ok(())
    }
}

/// Where the canvas lies in egui's target, physical pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CanvasPlacement {
    /// Target pixel of the canvas texture's top-left pixel (whole pixels).
    pub canvas_px: [f64; 2],
    /// The sheet: min x, min y, max x, max y (may extend beyond the canvas).
    pub sheet_px: [f64; 4],
}

impl CanvasPlacement {
    /// Where a canvas at `rect` (points) with the sheet at `sheet` (points) is drawn at
    /// `ppp` physical pixels per point: the canvas corner rounded as egui rounds its
    /// viewport, the sheet relative to it.
    pub fn new(rect: Rect, sheet: Rect, ppp: f64) -> Self {
        let corner = |p: Pos2| [f64::from(p.x) * ppp, f64::from(p.y) * ppp];
        let canvas_px = corner(rect.min).map(f64::round);
        let [x0, y0] = corner(sheet.min);
        let [x1, y1] = corner(sheet.max);
        let [rx, ry] = corner(rect.min);
        let (dx, dy) = (canvas_px[0] - rx, canvas_px[1] - ry);
        Self {
            canvas_px,
            sheet_px: [x0 + dx, y0 + dy, x1 + dx, y1 + dy],
        }
    }

    /// The sheet's pixels (those whose centres lie inside it), as a rectangle of whole
    /// pixels: the pixels the present shader fills from the texture.
    pub fn sheet_pixels(&self) -> Rect {
        let edge = |v: f64| (v - 0.5).ceil() as f32;
        let [x0, y0, x1, y1] = self.sheet_px;
        Rect::from_min_max(Pos2::new(edge(x0), edge(y0)), Pos2::new(edge(x1), edge(y1)))
    }

    /// The present pass's placement in egui's target.
    fn placement(&self) -> Placement {
        Placement {
            origin: self.canvas_px.map(|v| v as f32),
        }
    }
}

/// The per-frame paint callback: renders into the canvas texture when the request
/// differs from what is drawn there.
pub struct CanvasCallback {
    /// The committed design shown (without the pending op).
    pub design: Arc<Design>,
    /// What to draw.
    pub request: FrameRequest,
    /// Where it goes in egui's target.
    pub placement: CanvasPlacement,
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
        let req = &self.request;
        if let Some(op) = &req.pending {
            // Live preview: drawn in `paint`; the texture keeps the last exact frame.
            status.error = gpu
                .set_preview(
                    device,
                    queue,
                    &self.design,
                    req,
                    op,
                    self.placement.canvas_px,
                )
                .err();
            status.work.preview += 1;
            status.work.caches = gpu.caches_built;
        } else if status.drawn.as_ref() == Some(req) {
            // The exact frame was submitted with the previous frame: hear when it is done.
            if status.exact_asked != status.work.exact {
                status.exact_asked = status.work.exact;
                let (done, n, ctx) = (
                    status.exact_done.clone(),
                    status.work.exact,
                    self.ctx.clone(),
                );
                queue.on_submitted_work_done(move || {
                    done.store(n, std::sync::atomic::Ordering::SeqCst);
                    ctx.request_repaint();
                });
            }
            // The exact frame is on screen: use the idle frame to get the preview ready.
            if status.cache_ready != Some(req.design_key) && status.error.is_none() {
                match gpu.ensure_cache(device, queue, &self.design, req) {
                    Ok(()) => {
                        status.cache_ready = Some(req.design_key);
                        let done = status.cache_done.clone();
                        let key = req.design_key;
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
        } else {
            let outcome = gpu.draw_exact(device, queue, encoder, &self.design, req);
            status.work.exact += 1;
            status.work.caches = gpu.caches_built;
            status.error = outcome.err();
            status.drawn = Some(req.clone());
        }
        if let Some((_, source)) = &mut gpu.target {
            source.place(queue, &self.placement.placement());
        }
        Vec::new()
    }

    fn paint(
        &self,
        info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(gpu) = resources.get::<CanvasGpu>() else {
            return;
        };
        let Some((_, source)) = &gpu.target else {
            return;
        };
        // Only the sheet's pixels are drawn: the grey around it is the window's clear
        // colour (`MarblingApp::clear_color`), so no pixel is drawn twice.
        let clip = info.clip_rect_in_pixels();
        let clip = Rect::from_min_size(
            Pos2::new(clip.left_px as f32, clip.top_px as f32),
            egui::vec2(clip.width_px as f32, clip.height_px as f32),
        );
        let sheet = self.placement.sheet_pixels().intersect(clip);
        if !sheet.is_positive() {
            return;
        }
        pass.set_scissor_rect(
            sheet.min.x as u32,
            sheet.min.y as u32,
            sheet.width() as u32,
            sheet.height() as u32,
        );
        let preview = gpu
            .cache
            .as_ref()
            .filter(|(key, _)| self.request.pending.is_some() && *key == self.request.design_key);
        match preview {
            Some((_, cache)) => gpu.preview.draw(pass, cache),
            None => gpu.presenter.draw(pass, source),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
        Rect::from_min_max(Pos2::new(x0, y0), Pos2::new(x1, y1))
    }

    #[test]
    fn the_canvas_corner_is_rounded_and_the_sheet_moves_with_it() {
        // At 1.5 physical pixels per point the canvas corner lands on 100.5 px → 101
        // (as egui rounds its viewport); the sheet keeps its place relative to it.
        let p = CanvasPlacement::new(
            rect(67.0, 10.0, 400.0, 300.0),
            rect(77.0, 20.0, 177.0, 80.0),
            1.5,
        );
        assert_eq!(p.canvas_px, [101.0, 15.0]);
        assert_eq!(p.sheet_px, [116.0, 30.0, 266.0, 120.0]);
    }

    #[test]
    fn sheet_pixels_are_those_whose_centres_lie_inside_the_sheet() {
        let p = CanvasPlacement {
            canvas_px: [0.0, 0.0],
            sheet_px: [10.4, 10.6, 20.5, 20.6],
        };
        // x: centres 10.5 … 19.5 are inside [10.4, 20.5); y: 11.5 … 20.5 inside [10.6, 20.6).
        assert_eq!(p.sheet_pixels(), rect(10.0, 11.0, 20.0, 21.0));
    }
}
