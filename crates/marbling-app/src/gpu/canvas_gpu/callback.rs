//! The canvas's per-frame paint callback: it moves the exact frame and the preview cache
//! on by a tile within the frame's budget and draws the best frame there is.

use super::*;

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
    /// [`Pace::Active`]'s interval with one tile each, otherwise at [`Pace::Idle`]'s with
    /// [`TILES_WHILE_IDLE`] (one submission each, so none holds the GPU for long).
    pub active: bool,
}

/// Tiles (submissions) a frame's budget is split into while the user does nothing.
pub const TILES_WHILE_IDLE: usize = 3;

impl CanvasCallback {
    /// This frame's GPU work and what to show.
    pub(super) fn advance(
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
            let paper = req.stand_in.as_ref().is_some_and(|s| s.paper);
            if let Err(e) = gpu.start_exact(device, queue, shown, &exact, paper) {
                // Not tried again for this frame: the error is the outcome.
                gpu.refining = Some((exact.clone(), Refinement::new([0; 4])));
                status.error = Some(e);
                status.drawn = Some(exact.clone());
                status.work.exact += 1;
                when_done(queue, &status.exact_done, status.work.exact, &self.ctx);
            }
        }
        let (tiles, pace) = if self.active {
            (1, Pace::Active)
        } else {
            (TILES_WHILE_IDLE, Pace::Idle)
        };
        gpu.begin_frame(crate::platform::now_ms(), pace);
        let mut drew = false;
        for _ in 0..tiles {
            if !gpu.may_submit() {
                break;
            }
            let exact_done = gpu.refining.as_ref().is_some_and(|(_, r)| r.is_done());
            if !dragging && !exact_done {
                if gpu.exact_tile(device, queue, &self.ctx, shown.walk_cost(), tiles) {
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
            gpu.last_tile_frame = Some((crate::platform::now_ms(), pace));
        }
        status.work.frame_units = gpu.budget.of(pace).units();
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
        let canvas_px = self.placement.canvas_px;
        gpu.show = if dragging {
            if gpu.hold_cache(req.design_key) {
                gpu.aim_preview(queue, req, req.pending.as_ref(), canvas_px);
                status.work.preview += 1;
                Show::Preview
            } else {
                Show::Exact
            }
        } else if exact_done || req.live.is_some() {
            // A live video's next frame is drawn over the last one: the preview cache
            // holds no video, so the texture as it is shows best.
            Show::Exact
        } else if gpu.hold_cache(req.design_key) {
            gpu.aim_preview(queue, req, None, canvas_px);
            Show::Refining
        } else if let Some(s) = req
            .stand_in
            .as_ref()
            .filter(|s| s.key.is_some_and(|k| gpu.hold_cache(k)))
        {
            gpu.aim_preview(queue, req, s.op.as_ref(), canvas_px);
            Show::Refining
        } else {
            // Nothing better: the texture as it is (the previous frame of this state, or
            // bare paper) with the new tiles over it.
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
