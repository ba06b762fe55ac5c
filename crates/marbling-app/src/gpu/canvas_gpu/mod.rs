//! The canvas's GPU side. The exact render of the design is drawn into an offscreen
//! texture whenever the design or the view changes, in tiles over successive frames
//! (`refine.rs`: as much a frame as keeps frame intervals at their aim, measured from
//! the frames before), so no frame waits for a whole render and input stays live. Until the last
//! tile is drawn, the preview stands in under the tiles already drawn: the preview
//! cache of this design, or of the design just before an edit with the edit's op
//! walked on top (what the last drag frame showed), or of an earlier state that looks
//! the same (an Undo's: the cache before the newest is kept). With none of these the
//! tiles are drawn over the last frame of the same state, or over bare paper. Every frame then copies the
//! texture 1:1 into egui's pass over the sheet in one cheap draw (the grey around it is
//! the window's clear colour), so hovering never re-walks the ops. Once the exact frame
//! is done, the live-preview cache of the design is brought up to date the same way, in
//! tiles. While a tool is dragged, the live preview is drawn straight into egui's pass
//! over the sheet instead.

use crate::gpu::refine::{MAX_IN_FLIGHT, Pace, PacedBudget, PixelRect, Refinement, per_pixel};
use crate::marbling::shown::Shown;
use eframe::egui_wgpu;
use egui::{Pos2, Rect};
use marbling_core::{Antialias, Design, Op};
use marbling_gpu::{
    ExactRenderer, Placement, PreparedDesign, PresentSource, Presenter, PreviewCache,
    PreviewRenderer, RenderTarget, View,
};
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

mod callback;
pub use callback::{CanvasCallback, TILES_WHILE_IDLE};

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
    /// A live video frame shown as the design's picture (each new frame is a new exact
    /// frame), or `None` for the design's own background.
    pub live: Option<crate::media::video::LiveFrame>,
    /// A frame of the design streaming along a curl noise: the shown design ends with
    /// the frame's flow, walked for each layer's time (src/marbling/stream.rs).
    pub stream: Option<crate::marbling::stream::StreamFrame>,
}

/// What shows while the requested design's exact frame is drawn in tiles, when that
/// design has no preview cache yet.
#[derive(Clone, Debug, PartialEq)]
pub struct StandIn {
    /// A design whose preview cache may stand in for it, if the GPU still holds one: the
    /// design before an edit, or an earlier state that looks the same as the requested
    /// one (the state an Undo or Redo returns to).
    pub key: Option<u64>,
    /// The op to walk over that cache (the op just committed), if any.
    pub op: Option<Op>,
    /// The canvas texture's last frame shows another state (an Undo, a loaded design):
    /// with no cache to stand in, the tiles are drawn over bare paper, never over that
    /// frame (half one state, half the other).
    pub paper: bool,
}

impl StandIn {
    /// Another state of the document: the cache of `key` if held, else bare paper.
    pub fn other_state(key: Option<u64>) -> Self {
        Self {
            key,
            op: None,
            paper: true,
        }
    }
}

impl FrameRequest {
    /// What identifies the exact frame this request asks for (the rest says how to get
    /// there or what to show meanwhile).
    pub(crate) fn exact_frame(&self) -> FrameRequest {
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
    /// The complete preview cache of the design shown before `cache`'s (an Undo returns
    /// to it: it stands in at once).
    previous: Option<(u64, PreviewCache)>,
    /// A preview cache being drawn in tiles.
    building: Option<(u64, PreviewCache, Refinement)>,
    caches_built: u64,
    /// Ops written into the exact op texture so far (all uploads).
    ops_written: u64,
    /// The design whose preview cache could not be made (not tried again).
    cache_failed: Option<u64>,
    /// The tiles' work per frame, one budget per pace.
    budget: PacedBudget,
    /// When the last frame that drew tiles began, ms, and its pace (its interval steers
    /// that pace's budget).
    last_tile_frame: Option<(f64, Pace)>,
    /// This frame's pace.
    pace: Pace,
    /// Tiles submitted and not heard of yet.
    in_flight: Arc<AtomicUsize>,
    show: Show,
}

impl CanvasGpu {
    /// Builds the pipelines for `device`; egui draws into targets of `surface_format`.
    pub fn new(device: &wgpu::Device, surface_format: wgpu::TextureFormat) -> Self {
        let exact = ExactRenderer::new(device, CANVAS_FORMAT);
        Self {
            preview: PreviewRenderer::sharing(device, surface_format, &exact),
            exact,
            presenter: Presenter::new(device, surface_format),
            target: None,
            prepared: None,
            refining: None,
            cache: None,
            previous: None,
            building: None,
            caches_built: 0,
            ops_written: 0,
            cache_failed: None,
            budget: PacedBudget::default(),
            last_tile_frame: None,
            pace: Pace::Idle,
            in_flight: Arc::default(),
            show: Show::Exact,
        }
    }

    /// Starts drawing the exact frame of `req`: (re)creates the texture at its size
    /// (cleared to the design's paper), brings the uploaded design up to `shown` if it
    /// changed, sets the view. The texture keeps what it showed until tiles replace it,
    /// unless `paper` asks for bare paper under the tiles of a new design.
    fn start_exact(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        shown: &Shown,
        req: &FrameRequest,
        paper: bool,
    ) -> Result<(), String> {
        let design = &*shown.design;
        let new_design = self.refining.as_ref().map(|(r, _)| r.design_key) != Some(req.design_key);
        self.refining = None;
        let fits = self
            .target
            .as_ref()
            .is_some_and(|(t, _)| [t.width, t.height] == req.size);
        if !fits {
            let target = RenderTarget::new(device, req.size[0], req.size[1], CANVAS_FORMAT);
            let source = self.presenter.source(device, &target.view);
            self.target = Some((target, source));
        }
        if let Some((target, _)) = self
            .target
            .as_ref()
            .filter(|_| !fits || (paper && new_design))
        {
            let c = design.background;
            let [r, g, b] = [c.r, c.g, c.b].map(|v| f64::from(v) / 255.0);
            let mut encoder =
                device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            drop(target.begin_pass_clearing(&mut encoder, wgpu::Color { r, g, b, a: 1.0 }));
            queue.submit([encoder.finish()]);
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
            let live = req.live.as_ref().map(|l| (l.pixels.clone(), l.fit));
            self.exact
                .set_live_image(device, queue, prepared, shown.prefix(), live)
                .map_err(|e| e.to_string())?;
            prepared.set_turbulence(queue, req.stream.as_ref().map(|s| s.layers));
            let extent = f64::from(design.width.max(design.height));
            if marbling_gpu::deep::needs_deep(extent, req.scale) {
                let view = marbling_gpu::deep::DeepView {
                    origin: marbling_core::Point::new(req.origin[0], req.origin[1]),
                    scale: req.scale,
                    size: req.size,
                    antialias: req.antialias,
                };
                self.exact
                    .set_deep_view(device, queue, prepared, &view)
                    .map_err(|e| e.to_string())?;
            } else {
                prepared.set_view(
                    queue,
                    &View {
                        scale: req.scale,
                        offset: [req.origin[0] * req.scale, req.origin[1] * req.scale],
                        antialias: req.antialias,
                    },
                );
            }
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

    /// True when a complete preview cache of `key` is held; it is then the one drawn
    /// (`cache`: the previous one changes places with it).
    fn hold_cache(&mut self, key: u64) -> bool {
        if self.cache.as_ref().is_some_and(|(k, _)| *k == key) {
            return true;
        }
        if self.previous.as_ref().is_some_and(|(k, _)| *k == key) {
            std::mem::swap(&mut self.cache, &mut self.previous);
            return true;
        }
        false
    }

    /// True when another tile may be submitted.
    fn may_submit(&self) -> bool {
        self.in_flight.load(Ordering::SeqCst) < MAX_IN_FLIGHT
    }

    /// Starts a frame at `now_ms` at `pace`: a frame that follows one that drew tiles
    /// steers the budget of that frame's pace.
    fn begin_frame(&mut self, now_ms: f64, pace: Pace) {
        if let Some((last, drawn_at)) = self.last_tile_frame.take() {
            self.budget.record_frame(now_ms - last, drawn_at);
        }
        self.pace = pace;
    }

    /// The largest tile of a render of ops costing `cost` ([`Op::walk_cost`]) with
    /// `samples` samples per pixel that fits a `tiles`-th of this frame's budget, pixels.
    fn tile_pixels(&self, cost: u64, samples: usize, tiles: usize) -> u64 {
        (self.budget.of(self.pace).units() / tiles.max(1) as u64 / per_pixel(cost, samples)).max(1)
    }

    /// Draws the next tile of the exact frame, a `tiles`-th of the frame's budget; true
    /// when it was the last.
    fn exact_tile(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        ctx: &egui::Context,
        cost: u64,
        tiles: usize,
    ) -> bool {
        let Some(samples) = self
            .refining
            .as_ref()
            .map(|(req, _)| req.antialias.samples().len())
        else {
            return false;
        };
        let pixels = self.tile_pixels(cost, samples, tiles);
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
        let pixels = self.tile_pixels(shown.walk_cost(), 1, tiles);
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
            let built = self.building.take().map(|(k, c, _)| (k, c));
            let before = std::mem::replace(&mut self.cache, built);
            // A cache of another design is kept for an Undo (one of this design at another
            // scale is not).
            if before.as_ref().is_some_and(|(k, _)| *k != key) {
                self.previous = before;
            }
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
    /// Where a canvas at `rect` (points) with the sheet's corners at `sheet` (min x,
    /// min y, max x, max y, page points in f64: 10⁸ points off at 10⁶× zoom) is drawn at
    /// `ppp` physical pixels per point: the canvas corner rounded as egui rounds its
    /// viewport, the sheet relative to it.
    pub fn new(rect: Rect, sheet: [f64; 4], ppp: f64) -> Self {
        let [rx, ry] = [f64::from(rect.min.x) * ppp, f64::from(rect.min.y) * ppp];
        let canvas_px = [rx.round(), ry.round()];
        let (dx, dy) = (canvas_px[0] - rx, canvas_px[1] - ry);
        let [x0, y0, x1, y1] = sheet.map(|v| v * ppp);
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

#[cfg(test)]
mod tests;
