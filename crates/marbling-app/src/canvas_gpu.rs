//! The canvas's GPU side. The exact render of the design is drawn into an offscreen
//! texture whenever the design or the view changes, in tiles over successive frames
//! (`refine.rs`: as much a frame as keeps frame intervals at their aim, measured from
//! the frames before), so no frame waits for a whole render and input stays live. Until the last
//! tile is drawn, the preview stands in under the tiles already drawn: the preview
//! cache of this design, or of the design just before an edit with the edit's op
//! walked on top (what the last drag frame showed). Every frame then copies the
//! texture 1:1 into egui's pass over the sheet in one cheap draw (the grey around it is
//! the window's clear colour), so hovering never re-walks the ops. Once the exact frame
//! is done, the live-preview cache of the design is brought up to date the same way, in
//! tiles. While a tool is dragged, the live preview is drawn straight into egui's pass
//! over the sheet instead.

use crate::refine::{
    ACTIVE_FRAME_MS, FrameBudget, IDLE_FRAME_MS, MAX_IN_FLIGHT, PixelRect, Refinement, per_pixel,
};
use crate::shown::Shown;
use eframe::egui_wgpu;
use egui::{Pos2, Rect};
use marbling_core::{Antialias, Design, Op};
use marbling_gpu::{
    ExactRenderer, Placement, PreparedDesign, PresentSource, Presenter, PreviewCache,
    PreviewRenderer, RenderTarget, View,
};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
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
    /// What may stand in while the exact frame is drawn in tiles, when this design has
    /// no preview cache yet.
    pub stand_in: Option<StandIn>,
    /// A frame of a gesture in progress (its ops drawn exactly over the design): no
    /// preview cache is built for it.
    pub transient: bool,
}

/// A design close to the requested one whose preview cache can stand in for it.
#[derive(Clone, Debug, PartialEq)]
pub struct StandIn {
    /// That design's key.
    pub key: u64,
    /// The op to walk over its cache (the op just committed), if any.
    pub op: Option<Op>,
}

impl FrameRequest {
    /// What identifies the exact frame this request asks for (the rest says how to get
    /// there or what to show meanwhile).
    fn exact_frame(&self) -> FrameRequest {
        FrameRequest {
            pending: None,
            stand_in: None,
            ..self.clone()
        }
    }
}

/// What the GPU side reports back to the UI (shared with the paint callback).
#[derive(Debug, Default)]
pub struct CanvasStatus {
    /// The exact frame whose tiles are all drawn (submitted) into the texture.
    pub drawn: Option<FrameRequest>,
    /// The fraction of the exact frame drawn so far, while it is being drawn.
    pub progress: Option<f64>,
    /// The last GPU-side error (e.g. more ops than the device's texture can hold).
    pub error: Option<String>,
    /// The design key whose live-preview cache is complete (all its tiles submitted).
    pub cache_ready: Option<u64>,
    /// The design key whose preview cache the GPU has finished rendering (set from the
    /// queue's work-done callback; 0 = none).
    pub cache_done: Arc<AtomicU64>,
    /// How much GPU work the canvas has recorded: exact frames, tiles, preview frames and
    /// preview caches (for `data-gpu-work`: hovering must not add to any of them).
    pub work: GpuWork,
    /// The number of the last exact frame the GPU has finished (of [`GpuWork::exact`];
    /// set from the queue's work-done callback asked for right after its last tile).
    pub exact_done: Arc<AtomicU64>,
}

/// Counts of the canvas's GPU passes since start.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GpuWork {
    /// Exact frames of the design completed (all their tiles drawn).
    pub exact: u64,
    /// Tiles drawn, of exact frames and preview caches.
    pub tiles: u64,
    /// Live-preview frames.
    pub preview: u64,
    /// Preview caches begun.
    pub caches: u64,
    /// Op-samples the frames' tiles may take now (the adaptive budget).
    pub frame_units: u64,
    /// Ops written into the exact renderer's op texture (an edit, a Play frame or a
    /// history view writes only the ops that differ from what it holds).
    pub ops_written: u64,
}

/// What the paint callback shows this frame.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Show {
    /// The canvas texture over the whole sheet.
    Exact,
    /// The live preview (cache + pending op) over the whole sheet.
    Preview,
    /// The exact frame's drawn tiles over the preview standing in for the rest.
    Refining,
}

/// GPU resources kept in egui-wgpu's callback resources between frames.
pub struct CanvasGpu {
    exact: ExactRenderer,
    /// Draws into egui's target (format of the window's surface).
    preview: PreviewRenderer,
    presenter: Presenter,
    /// The exact frame, and its binding for the present draw.
    target: Option<(RenderTarget, PresentSource)>,
    /// The uploaded design, and the key of what it shows (brought to another design
    /// or view of one by writing only the ops that differ).
    prepared: Option<(u64, PreparedDesign)>,
    /// The exact frame in the texture (or being drawn there), and its tiles.
    refining: Option<(FrameRequest, Refinement)>,
    /// The newest complete preview cache.
    cache: Option<(u64, PreviewCache)>,
    /// A preview cache being drawn in tiles.
    building: Option<(u64, PreviewCache, Refinement)>,
    caches_built: u64,
    /// Ops written into the exact op texture so far (all uploads).
    ops_written: u64,
    /// The design whose preview cache could not be made (not tried again).
    cache_failed: Option<u64>,
    budget: FrameBudget,
    /// When the last frame that drew tiles began, ms (its interval steers the budget).
    last_tile_frame_ms: Option<f64>,
    /// Tiles submitted and not heard of yet.
    in_flight: Arc<AtomicUsize>,
    show: Show,
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
            refining: None,
            cache: None,
            building: None,
            caches_built: 0,
            ops_written: 0,
            cache_failed: None,
            budget: FrameBudget::default(),
            last_tile_frame_ms: None,
            in_flight: Arc::default(),
            show: Show::Exact,
        }
    }

    /// Starts drawing the exact frame of `req`: (re)creates the texture at its size
    /// (cleared to the design's paper), brings the uploaded design up to `shown` if it
    /// changed, sets the view. The texture keeps what it showed until tiles replace it.
    fn start_exact(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        shown: &Shown,
        req: &FrameRequest,
    ) -> Result<(), String> {
        let design = &*shown.design;
        self.refining = None;
        let fits = self
            .target
            .as_ref()
            .is_some_and(|(t, _)| [t.width, t.height] == req.size);
        if !fits {
            let target = RenderTarget::new(device, req.size[0], req.size[1], CANVAS_FORMAT);
            let source = self.presenter.source(device, &target.view);
            let c = design.background;
            let [r, g, b] = [c.r, c.g, c.b].map(|v| f64::from(v) / 255.0);
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            drop(target.begin_pass_clearing(&mut encoder, wgpu::Color { r, g, b, a: 1.0 }));
            queue.submit([encoder.finish()]);
            self.target = Some((target, source));
        }
        match &mut self.prepared {
            Some((key, _)) if *key == req.design_key => {}
            Some((key, prepared)) => {
                let before = prepared.ops_written();
                if let Err(e) = self.exact.update(device, queue, prepared, shown.prefix()) {
                    self.prepared = None;
                    return Err(e.to_string());
                }
                self.ops_written += prepared.ops_written() - before;
                *key = req.design_key;
            }
            None => {
                let prepared = self
                    .exact
                    .prepare_prefix(device, queue, shown.prefix())
                    .map_err(|e| e.to_string())?;
                self.ops_written += prepared.ops_written();
                self.prepared = Some((req.design_key, prepared));
            }
        }
        if let Some((_, prepared)) = &mut self.prepared {
            prepared.set_view(
                queue,
                &View {
                    scale: req.scale,
                    offset: [req.origin[0] * req.scale, req.origin[1] * req.scale],
                    antialias: req.antialias,
                },
            );
        }
        let region = sheet_region(design, req);
        self.refining = Some((req.clone(), Refinement::new(region)));
        Ok(())
    }

    /// True when `req`'s design needs a preview cache (for its scale) that is not
    /// complete yet.
    fn cache_wanted(&self, req: &FrameRequest) -> bool {
        let key = req.design_key;
        let complete = self
            .cache
            .as_ref()
            .is_some_and(|(k, c)| *k == key && c.covers(req.scale));
        !req.transient && !complete && self.cache_failed != Some(key)
    }

    /// True when another tile may be submitted.
    fn may_submit(&self) -> bool {
        self.in_flight.load(Ordering::SeqCst) < MAX_IN_FLIGHT
    }

    /// Starts a frame at `now_ms`: a frame that follows one that drew tiles steers the
    /// budget towards `target_ms`.
    fn begin_frame(&mut self, now_ms: f64, target_ms: f64) {
        if let Some(last) = self.last_tile_frame_ms.take() {
            self.budget.record_frame(now_ms - last, target_ms);
        }
    }

    /// The largest tile of a render of `ops` ops with `samples` samples per pixel that
    /// fits a `tiles`-th of this frame's budget, pixels.
    fn tile_pixels(&self, ops: usize, samples: usize, tiles: usize) -> u64 {
        (self.budget.units() / tiles.max(1) as u64 / per_pixel(ops, samples)).max(1)
    }

    /// Draws the next tile of the exact frame, a `tiles`-th of the frame's budget; true
    /// when it was the last.
    fn exact_tile(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        ctx: &egui::Context,
        ops: usize,
        tiles: usize,
    ) -> bool {
        let Some(samples) = self
            .refining
            .as_ref()
            .map(|(req, _)| req.antialias.samples().len())
        else {
            return false;
        };
        let pixels = self.tile_pixels(ops, samples, tiles);
        let (Some((_, refinement)), Some((target, _)), Some((_, prepared))) =
            (&mut self.refining, &self.target, &self.prepared)
        else {
            return false;
        };
        let Some(tile) = refinement.next_tile(pixels) else {
            return false;
        };
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = target.begin_pass_keeping(&mut encoder);
            self.exact.draw_rect(&mut pass, prepared, tile);
        }
        submit_counted(queue, encoder, &self.in_flight, ctx);
        refinement.is_done()
    }

    /// Draws the next tile of the preview cache of `shown` for the key and view scale
    /// of `req`, beginning a new cache first when none is being drawn for them; true
    /// when the cache is then complete.
    fn cache_tile(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        ctx: &egui::Context,
        shown: &Shown,
        req: &FrameRequest,
        tiles: usize,
    ) -> Result<bool, String> {
        let (key, scale) = (req.design_key, req.scale);
        let fresh = self
            .building
            .as_ref()
            .is_some_and(|(k, c, _)| *k == key && c.covers(scale));
        if !fresh {
            self.building = None;
            self.caches_built += 1;
            // Rendered without antialiasing: at CACHE_FACTOR = 2 its 2 × 2 samples per
            // screen pixel already smooth the preview, at a quarter of an RGSS cache's cost.
            let cache = self
                .preview
                .new_cache(device, queue, shown.prefix(), scale, Antialias::None)
                .map_err(|e| e.to_string())?;
            let (w, h) = cache.cache_size();
            self.building = Some((key, cache, Refinement::new([0, 0, w, h])));
        }
        let pixels = self.tile_pixels(shown.op_count(), 1, tiles);
        let Some((_, cache, refinement)) = &mut self.building else {
            return Ok(false);
        };
        if let Some(tile) = refinement.next_tile(pixels) {
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            self.preview.draw_cache_rect(&mut encoder, cache, tile);
            submit_counted(queue, encoder, &self.in_flight, ctx);
        }
        if refinement.is_done() {
            self.cache = self.building.take().map(|(k, c, _)| (k, c));
            return Ok(true);
        }
        Ok(false)
    }

    /// Points the complete preview cache at the view of `req` with `op` walked over it,
    /// drawn into egui's target with the canvas texture's top-left at `canvas_px`.
    fn aim_preview(
        &mut self,
        queue: &wgpu::Queue,
        req: &FrameRequest,
        op: Option<&Op>,
        canvas_px: [f64; 2],
    ) {
        if let Some((_, cache)) = &mut self.cache {
            // Target pixel (X, Y) shows the design point the texture's pixel
            // (X, Y) − canvas_px would: the same samples as a render into the texture.
            let origin = [
                req.origin[0] - canvas_px[0] / req.scale,
                req.origin[1] - canvas_px[1] / req.scale,
            ];
            cache.set_frame(queue, op, origin, req.scale, req.antialias);
        }
    }
}

/// Submits `encoder`'s commands as one tile, counted in flight until the queue says the
/// GPU has finished them (the canvas is redrawn then).
fn submit_counted(
    queue: &wgpu::Queue,
    encoder: wgpu::CommandEncoder,
    in_flight: &Arc<AtomicUsize>,
    ctx: &egui::Context,
) {
    queue.submit([encoder.finish()]);
    in_flight.fetch_add(1, Ordering::SeqCst);
    let (in_flight, ctx) = (in_flight.clone(), ctx.clone());
    queue.on_submitted_work_done(move || {
        in_flight.fetch_sub(1, Ordering::SeqCst);
        ctx.request_repaint();
    });
}

/// Has the queue store `value` into `cell` once the GPU has finished the work submitted
/// so far, and redraw then.
fn when_done(queue: &wgpu::Queue, cell: &Arc<AtomicU64>, value: u64, ctx: &egui::Context) {
    let (cell, ctx) = (cell.clone(), ctx.clone());
    queue.on_submitted_work_done(move || {
        cell.store(value, Ordering::SeqCst);
        ctx.request_repaint();
    });
}

/// The texture pixels of `req` whose centres show a point of `design`'s sheet (the
/// others are never shown, so never drawn).
fn sheet_region(design: &Design, req: &FrameRequest) -> PixelRect {
    // Pixel i samples design point origin + (i + 0.5) / scale.
    let span = |origin: f64, extent: u32, size: u32| {
        let first = (-origin * req.scale - 0.5).ceil().max(0.0);
        let end = ((f64::from(extent) - origin) * req.scale - 0.5)
            .ceil()
            .clamp(0.0, f64::from(size));
        let first = first.min(end);
        (first as u32, (end - first) as u32)
    };
    let (x, w) = span(req.origin[0], design.width, req.size[0]);
    let (y, h) = span(req.origin[1], design.height, req.size[1]);
    [x, y, w, h]
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

/// The per-frame paint callback: moves the exact frame and the preview cache on by a
/// tile when they are not complete, and shows the best frame there is.
pub struct CanvasCallback {
    /// The committed design shown (without the pending op).
    pub shown: Shown,
    /// What to draw.
    pub request: FrameRequest,
    /// Where it goes in egui's target.
    pub placement: CanvasPlacement,
    /// Where the outcome is reported.
    pub status: Arc<Mutex<CanvasStatus>>,
    /// Woken when GPU work the UI waits for has finished.
    pub ctx: egui::Context,
    /// True while the user acts (pointer moving or pressed, keys): frames then aim at
    /// [`ACTIVE_FRAME_MS`] with one tile each, otherwise at [`IDLE_FRAME_MS`] with
    /// [`TILES_WHILE_IDLE`] (one submission each, so none holds the GPU for long).
    pub active: bool,
}

/// Tiles (submissions) a frame's budget is split into while the user does nothing.
pub const TILES_WHILE_IDLE: usize = 3;

impl CanvasCallback {
    /// This frame's GPU work and what to show.
    fn advance(
        &self,
        gpu: &mut CanvasGpu,
        status: &mut CanvasStatus,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
    ) {
        let req = &self.request;
        let shown = &self.shown;
        let exact = req.exact_frame();
        let dragging = req.pending.is_some();
        // While dragging, the exact frame of the design under the drag stays as it is
        // (the preview's antialiasing may differ from the exact frame's).
        if !dragging && gpu.refining.as_ref().map(|(r, _)| r) != Some(&exact) {
            status.drawn = None;
            status.error = None;
            if let Err(e) = gpu.start_exact(device, queue, shown, &exact) {
                // Not tried again for this frame: the error is the outcome.
                gpu.refining = Some((exact.clone(), Refinement::new([0; 4])));
                status.error = Some(e);
                status.drawn = Some(exact.clone());
                status.work.exact += 1;
                when_done(queue, &status.exact_done, status.work.exact, &self.ctx);
            }
        }
        let (tiles, target_ms) = if self.active {
            (1, ACTIVE_FRAME_MS)
        } else {
            (TILES_WHILE_IDLE, IDLE_FRAME_MS)
        };
        gpu.begin_frame(crate::platform::now_ms(), target_ms);
        let mut drew = false;
        for _ in 0..tiles {
            if !gpu.may_submit() {
                break;
            }
            let exact_done = gpu.refining.as_ref().is_some_and(|(_, r)| r.is_done());
            if !dragging && !exact_done {
                if gpu.exact_tile(device, queue, &self.ctx, shown.op_count(), tiles) {
                    status.work.exact += 1;
                    status.drawn = Some(exact.clone());
                    when_done(queue, &status.exact_done, status.work.exact, &self.ctx);
                }
            } else if gpu.cache_wanted(req) {
                // While dragging the live preview needs the cache before the exact frame.
                match gpu.cache_tile(device, queue, &self.ctx, shown, req, tiles) {
                    Ok(true) => {
                        status.cache_ready = Some(req.design_key);
                        when_done(queue, &status.cache_done, req.design_key, &self.ctx);
                    }
                    Ok(false) => {}
                    Err(e) => {
                        gpu.cache_failed = Some(req.design_key);
                        status.error = Some(e);
                    }
                }
            } else {
                break;
            }
            status.work.tiles += 1;
            drew = true;
        }
        if drew {
            gpu.last_tile_frame_ms = Some(crate::platform::now_ms());
        }
        status.work.frame_units = gpu.budget.units();
        status.work.caches = gpu.caches_built;
        status.work.ops_written = gpu.ops_written;
        let refinement = gpu.refining.as_ref().map(|(_, r)| r);
        let exact_done = refinement.is_some_and(Refinement::is_done);
        status.progress = refinement
            .filter(|r| !r.is_done())
            .map(Refinement::progress);
        if (!exact_done && !dragging) || gpu.cache_wanted(req) {
            self.ctx.request_repaint();
        }
        // What to show.
        let cached = |key: u64| gpu.cache.as_ref().is_some_and(|(k, _)| *k == key);
        let canvas_px = self.placement.canvas_px;
        gpu.show = if dragging {
            if cached(req.design_key) {
                gpu.aim_preview(queue, req, req.pending.as_ref(), canvas_px);
                status.work.preview += 1;
                Show::Preview
            } else {
                Show::Exact
            }
        } else if exact_done {
            Show::Exact
        } else if cached(req.design_key) {
            gpu.aim_preview(queue, req, None, canvas_px);
            Show::Refining
        } else if let Some(s) = req.stand_in.clone().filter(|s| cached(s.key)) {
            gpu.aim_preview(queue, req, s.op.as_ref(), canvas_px);
            Show::Refining
        } else {
            // Nothing better: the texture as it is (the previous frame, or the paper)
            // with the new tiles over it.
            Show::Exact
        };
    }
}

impl egui_wgpu::CallbackTrait for CanvasCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Ok(mut status) = self.status.lock() else {
            return Vec::new();
        };
        let Some(gpu) = resources.get_mut::<CanvasGpu>() else {
            return Vec::new();
        };
        self.advance(gpu, &mut status, device, queue);
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
        let scissor = |pass: &mut wgpu::RenderPass<'static>, r: Rect| {
            pass.set_scissor_rect(
                r.min.x as u32,
                r.min.y as u32,
                r.width() as u32,
                r.height() as u32,
            );
        };
        scissor(pass, sheet);
        let cache = gpu.cache.as_ref().map(|(_, c)| c);
        match (gpu.show, cache) {
            (Show::Preview, Some(cache)) => gpu.preview.draw(pass, cache),
            (Show::Refining, Some(cache)) => {
                gpu.preview.draw(pass, cache);
                let done = gpu.refining.as_ref().map(|(_, r)| r.done_rects());
                let [cx, cy] = self.placement.canvas_px.map(|v| v as f32);
                for [x, y, w, h] in done.unwrap_or_default() {
                    let r = Rect::from_min_size(
                        Pos2::new(cx + x as f32, cy + y as f32),
                        egui::vec2(w as f32, h as f32),
                    )
                    .intersect(sheet);
                    if r.is_positive() {
                        scissor(pass, r);
                        gpu.presenter.draw(pass, source);
                    }
                }
            }
            _ => gpu.presenter.draw(pass, source),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::compare::compare;
    use marbling_core::synth::{Mix, random_design};
    use marbling_core::{RenderOptions, RgbaImage, render};
    use marbling_gpu::{GpuContext, copy_to_buffer, read_buffer};

    /// The texture's pixels `[x, y, w, h]`.
    fn read(g: &GpuContext, target: &RenderTarget, [x, y, w, h]: PixelRect) -> RgbaImage {
        let mut encoder = g
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        let (buffer, padded) = copy_to_buffer(&g.device, &mut encoder, target);
        g.queue.submit([encoder.finish()]);
        let mut image = RgbaImage::filled(w, h, [0, 0, 0, 255]);
        let row = (w * 4) as usize;
        read_buffer(
            g,
            &buffer,
            padded,
            target.width,
            target.height,
            |yy, bytes| {
                if (y..y + h).contains(&yy) {
                    let start = ((yy - y) as usize) * row;
                    image.pixels[start..start + row]
                        .copy_from_slice(&bytes[(x * 4) as usize..((x + w) * 4) as usize]);
                }
            },
        )
        .expect("readback");
        image
    }

    /// Frame after frame as the app draws them (one tile each, the GPU polled between
    /// frames as a browser's event loop would): the exact frame arrives in several tiles
    /// with rising progress, is reported drawn only after the last, and equals the CPU
    /// render; the preview cache follows in tiles; an edit then shows the stand-in.
    #[test]
    fn the_exact_frame_is_drawn_in_tiles_then_the_cache() {
        let Some(g) = crate::test_window::gpu_or_skip() else {
            return;
        };
        let design = Arc::new(random_design(9, 100, 80, 200, Mix::Mixed));
        let mut gpu = CanvasGpu::new(&g.device, CANVAS_FORMAT);
        let request = FrameRequest {
            design_key: 1,
            size: [120, 90],
            scale: 1.0,
            // Texture pixel i samples design x = i − 10 + 0.5: the sheet is pixels 10..110.
            origin: [-10.0, -5.0],
            antialias: Antialias::Rgss,
            pending: None,
            stand_in: None,
            transient: false,
        };
        assert_eq!(sheet_region(&design, &request), [10, 5, 100, 80]);
        let mut callback = CanvasCallback {
            shown: Shown::all(design.clone()),
            request,
            placement: CanvasPlacement {
                canvas_px: [0.0, 0.0],
                sheet_px: [10.0, 5.0, 110.0, 85.0],
            },
            status: Arc::default(),
            ctx: egui::Context::default(),
            active: true,
        };
        let frame = |gpu: &mut CanvasGpu, callback: &CanvasCallback| {
            let mut status = callback.status.lock().expect("status");
            callback.advance(gpu, &mut status, &g.device, &g.queue);
            drop(status);
            g.device
                .poll(wgpu::PollType::wait_indefinitely())
                .expect("poll");
        };
        let mut progress = Vec::new();
        for _ in 0..1000 {
            frame(&mut gpu, &callback);
            let st = callback.status.lock().expect("status");
            if st.drawn.is_some() {
                break;
            }
            progress.extend(st.progress);
        }
        let st = callback.status.lock().expect("status");
        assert!(st.error.is_none(), "{:?}", st.error);
        assert!(st.drawn.is_some(), "the exact frame was never done");
        assert!(st.work.tiles >= 2, "one tile: {:?}", st.work);
        assert_eq!(st.work.tiles as usize, progress.len() + 1);
        assert!(progress.windows(2).all(|w| w[0] < w[1]) && progress.iter().all(|p| *p < 1.0));
        assert_eq!(st.work.exact, 1);
        assert_eq!(
            st.exact_done.load(Ordering::SeqCst),
            1,
            "the GPU's finish not heard"
        );
        assert_eq!(st.progress, None);
        assert_eq!(
            st.cache_ready, None,
            "the cache is drawn after the exact frame"
        );
        let tiles = st.work.tiles;
        drop(st);
        assert_eq!(gpu.show, Show::Exact);
        let (target, _) = gpu.target.as_ref().expect("texture");
        let shown = read(&g, target, [10, 5, 100, 80]);
        let cpu = render(
            &design,
            &RenderOptions {
                scale: 1.0,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
        let diff = compare(&cpu, &shown, 24).expect("size");
        assert!(diff.fraction() < 0.01, "tiled frame vs CPU: {diff:?}");

        // Then the preview cache, in tiles of its own.
        for _ in 0..1000 {
            frame(&mut gpu, &callback);
            if callback
                .status
                .lock()
                .expect("status")
                .cache_ready
                .is_some()
            {
                break;
            }
        }
        let st = callback.status.lock().expect("status");
        assert_eq!(st.cache_ready, Some(1));
        assert_eq!(st.cache_done.load(Ordering::SeqCst), 1);
        assert_eq!(st.work.caches, 1);
        assert!(st.work.tiles > tiles);
        let tiles = st.work.tiles;
        drop(st);
        // Idle: nothing more is drawn.
        frame(&mut gpu, &callback);
        assert_eq!(callback.status.lock().expect("status").work.tiles, tiles);

        // An edit: the design before it stands in at once, with the new op over it.
        let op = design.ops[0].clone();
        let mut edited = (*design).clone();
        edited.ops.push(op.clone());
        callback.shown = Shown::all(Arc::new(edited));
        callback.request.design_key = 2;
        callback.request.stand_in = Some(StandIn {
            key: 1,
            op: Some(op),
        });
        // (A frame that may draw no tile, as when earlier tiles are still in flight.)
        gpu.in_flight.store(MAX_IN_FLIGHT, Ordering::SeqCst);
        frame(&mut gpu, &callback);
        assert_eq!(gpu.show, Show::Refining);
        let (_, prepared) = gpu.prepared.as_ref().expect("uploaded");
        assert_eq!(
            (prepared.op_count(), prepared.ops_written()),
            (201, 201),
            "the edit wrote its one op, not the design again"
        );
        assert!(callback.status.lock().expect("status").drawn.is_none());
    }

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
