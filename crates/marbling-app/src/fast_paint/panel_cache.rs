//! The side panel and status bar shown from a texture while they do not change.
//!
//! egui draws every shape again each frame. On a software GPU (SwiftShader, what headless
//! Chromium uses where there is no GPU) egui's draws are dear whatever they cover: its
//! fragment shader runs all of its branches for every pixel, and every triangle costs
//! SwiftShader's pixel routine a call per band of the target, so a status bar's hundred
//! glyph triangles cost milliseconds (docs/BENCHMARKS.md). While the panels' shapes are the
//! same as in the previous frame (dragging or hovering a tool over the canvas),
//! [`PanelCache`] renders them once into a texture with egui's own renderer and puts, in
//! place of each panel's shapes, one callback that copies that texture's pixels 1:1 within
//! the panel (the present pipeline: one triangle). As soon as they change (the pointer over
//! a widget, a new history entry), egui draws them itself again.
//!
//! The texture is rendered as eframe renders the window: the same shapes, tessellation,
//! screen size, clear colour, renderer and target format, so its pixels are the ones egui
//! would draw. It assumes eframe's default render options, which `main.rs` uses: no MSAA
//! and no depth buffer.

use super::layer_shapes;
use eframe::egui_wgpu;
use egui::epaint::{ClippedShape, Shape};
use egui::{LayerId, Rect};
use marbling_gpu::{Placement, PresentSource, Presenter};
use std::ops::Range;
use std::sync::{Arc, Mutex};

/// Everything the panels' pixels depend on.
#[derive(Clone, Debug, PartialEq)]
struct Snapshot {
    /// Each panel's shapes, in paint order.
    panels: Vec<Vec<ClippedShape>>,
    /// The window's (canvas's) size, physical pixels.
    size_in_pixels: [u32; 2],
    pixels_per_point: f32,
    /// Text's texture coordinates are divided by the font atlas's size when tessellating.
    font_atlas: [usize; 2],
    clear_color: [f32; 4],
}

/// What rendering the panel takes from eframe's wgpu set-up.
pub struct PanelGpu<'a> {
    /// The device egui draws with.
    pub device: &'a wgpu::Device,
    /// Its queue.
    pub queue: &'a wgpu::Queue,
    /// The window surface's format, which egui's renderer draws in.
    pub target_format: wgpu::TextureFormat,
    /// egui's renderer, with the font and image textures it has uploaded.
    pub renderer: &'a egui::mutex::RwLock<egui_wgpu::Renderer>,
}

impl<'a> From<&'a egui_wgpu::RenderState> for PanelGpu<'a> {
    fn from(rs: &'a egui_wgpu::RenderState) -> Self {
        Self {
            device: &rs.device,
            queue: &rs.queue,
            target_format: rs.target_format,
            renderer: &rs.renderer,
        }
    }
}

/// Keeps the panel's last rendering and decides, frame by frame, whether to use it.
#[derive(Default)]
pub struct PanelCache {
    /// The panel as last painted, and the frame (`cumulative_frame_nr`) it was painted in.
    last: Option<(Snapshot, u64)>,
    /// The texture, holding `last` when `holds_last`.
    texture: Option<Arc<PanelTexture>>,
    holds_last: bool,
    /// The window size the last copy was painted into (from its callback), pixels, with
    /// egui's estimate of it at the time (see [`PanelCache::window_size`]).
    painted_size: Arc<Mutex<Option<PaintedSize>>>,
    /// Frames drawn from the texture (for tests and `data-gpu-work`).
    pub copies: u64,
    /// Renders into the texture.
    pub renders: u64,
}

/// The panel's pixels and their binding for the copy.
struct PanelTexture {
    presenter: Presenter,
    source: PresentSource,
    view: wgpu::TextureView,
    size: [u32; 2],
}

/// A window size in pixels as egui estimated it and as the painter had it.
#[derive(Clone, Copy)]
struct PaintedSize {
    estimated: [u32; 2],
    actual: [u32; 2],
}

/// The paint callback standing in for the panel's shapes.
struct PanelCopy {
    texture: Arc<PanelTexture>,
    /// egui's estimate of the window size when the callback was made.
    estimated_size: [u32; 2],
    painted_size: Arc<Mutex<Option<PaintedSize>>>,
}

impl PanelCache {
    /// Replaces the shapes of each panel in `panels` (ranges of `layer`'s shapes, just
    /// painted this frame, in paint order and not overlapping) by one copy of their
    /// rendering when they are all the same as in the previous frame, rendering them into
    /// the texture first if it holds something else. Does nothing without a wgpu renderer,
    /// or when a panel is empty or holds paint callbacks of its own.
    pub fn substitute(
        &mut self,
        ctx: &egui::Context,
        gpu: Option<PanelGpu<'_>>,
        layer: LayerId,
        panels: &[Range<usize>],
        clear_color: [f32; 4],
    ) {
        let Some(gpu) = gpu else {
            return;
        };
        let shapes: Vec<Vec<ClippedShape>> = panels
            .iter()
            .map(|range| layer_shapes::get(ctx, layer, range.clone()))
            .collect();
        let cacheable = |p: &Vec<ClippedShape>| {
            !p.is_empty() && !p.iter().any(|s| matches!(s.shape, Shape::Callback(_)))
        };
        if shapes.is_empty() || !shapes.iter().all(cacheable) {
            self.last = None;
            return;
        }
        let pixels_per_point = ctx.pixels_per_point();
        let size_in_pixels = self.window_size(ctx, pixels_per_point);
        let snapshot = Snapshot {
            panels: shapes,
            size_in_pixels,
            pixels_per_point,
            font_atlas: ctx.fonts(|f| f.font_image_size()),
            clear_color,
        };
        let frame = ctx.cumulative_frame_nr();
        match &self.last {
            // The same as in an earlier frame, whose new glyphs and images egui's renderer
            // has uploaded since (not as in an earlier pass of this frame).
            Some((last, painted)) if *last == snapshot && *painted < frame => {}
            Some((last, _)) if *last == snapshot => return,
            _ => {
                self.last = Some((snapshot, frame));
                self.holds_last = false;
                return;
            }
        }
        if !self.holds_last {
            self.render(ctx, &gpu, &snapshot);
            self.holds_last = true;
        }
        let Some(texture) = self.texture.clone() else {
            return;
        };
        let screen = Rect::from_min_size(
            egui::Pos2::ZERO,
            egui::vec2(size_in_pixels[0] as f32, size_in_pixels[1] as f32) / pixels_per_point,
        );
        let estimated_size = estimated_size(ctx, pixels_per_point);
        for (range, shapes) in panels.iter().zip(&snapshot.panels) {
            let area = shapes
                .iter()
                .map(|s| s.clip_rect)
                .fold(Rect::NOTHING, |a, b| a.union(b))
                .intersect(screen);
            let copy = egui_wgpu::Callback::new_paint_callback(
                area,
                PanelCopy {
                    texture: texture.clone(),
                    estimated_size,
                    painted_size: self.painted_size.clone(),
                },
            );
            layer_shapes::replace(ctx, layer, range.clone(), area, copy.into());
        }
        self.copies += 1;
    }

    /// The window's size in physical pixels: egui's screen in points times the pixels
    /// per point, or what the last copy was really painted into when egui estimated the
    /// same then (the two may differ by rounding; a resize changes the estimate, so a
    /// stale painted size is never used).
    fn window_size(&self, ctx: &egui::Context, pixels_per_point: f32) -> [u32; 2] {
        let estimated = estimated_size(ctx, pixels_per_point);
        match self.painted_size.lock().ok().and_then(|s| *s) {
            Some(painted) if painted.estimated == estimated => painted.actual,
            _ => estimated,
        }
    }

    /// Renders `snapshot`'s shapes into the texture (made or remade at the window's size).
    fn render(&mut self, ctx: &egui::Context, gpu: &PanelGpu<'_>, snapshot: &Snapshot) {
        let size = snapshot.size_in_pixels;
        if size[0] == 0 || size[1] == 0 {
            self.texture = None;
            return;
        }
        if self.texture.as_ref().is_none_or(|t| t.size != size) {
            self.texture = Some(Arc::new(PanelTexture::new(gpu, size)));
        }
        let Some(texture) = &self.texture else {
            return;
        };
        let shapes = snapshot.panels.iter().flatten().cloned().collect();
        let primitives = ctx.tessellate(shapes, snapshot.pixels_per_point);
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: size,
            pixels_per_point: snapshot.pixels_per_point,
        };
        let mut encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("marbling panel cache"),
            });
        let prepared = record_egui(
            (gpu.device, gpu.queue),
            &mut gpu.renderer.write(),
            &mut encoder,
            &texture.view,
            snapshot.clear_color,
            &primitives,
            &screen,
        );
        // Submitted now, before eframe writes this frame's own vertices into the
        // renderer's buffers.
        gpu.queue
            .submit(prepared.into_iter().chain([encoder.finish()]));
        self.renders += 1;
    }
}

/// egui's screen in points times `pixels_per_point`, rounded: the window in pixels.
fn estimated_size(ctx: &egui::Context, pixels_per_point: f32) -> [u32; 2] {
    let points = ctx.viewport_rect().size();
    [
        (points.x * pixels_per_point).round() as u32,
        (points.y * pixels_per_point).round() as u32,
    ]
}

/// Records egui's `primitives` into `encoder` the way eframe draws its window: the
/// renderer's buffers uploaded, then one pass into `view` cleared to `clear_color`.
/// Returns the command buffers of paint callbacks' preparation, to be submitted before
/// `encoder`'s.
pub(crate) fn record_egui(
    (device, queue): (&wgpu::Device, &wgpu::Queue),
    renderer: &mut egui_wgpu::Renderer,
    encoder: &mut wgpu::CommandEncoder,
    view: &wgpu::TextureView,
    clear_color: [f32; 4],
    primitives: &[egui::ClippedPrimitive],
    screen: &egui_wgpu::ScreenDescriptor,
) -> Vec<wgpu::CommandBuffer> {
    let prepared = renderer.update_buffers(device, queue, encoder, primitives, screen);
    let [r, g, b, a] = clear_color.map(f64::from);
    let mut pass = encoder
        .begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("marbling panel cache"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view,
                resolve_target: None,
                depth_slice: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        })
        .forget_lifetime();
    renderer.render(&mut pass, primitives, screen);
    prepared
}

impl PanelTexture {
    fn new(gpu: &PanelGpu<'_>, size: [u32; 2]) -> Self {
        let texture = marbling_gpu::bindings::texture(
            gpu.device,
            "marbling panel cache",
            size,
            gpu.target_format,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
        );
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        let presenter = Presenter::new(gpu.device, gpu.target_format);
        let mut source = presenter.source_in_target_format(gpu.device, &view);
        source.place(gpu.queue, &Placement { origin: [0.0, 0.0] });
        Self {
            presenter,
            source,
            view,
            size,
        }
    }
}

impl egui_wgpu::CallbackTrait for PanelCopy {
    fn paint(
        &self,
        info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        _resources: &egui_wgpu::CallbackResources,
    ) {
        // A window resized since the texture was made shows it this once (the panel
        // keeps its place at the left edge); the next frames render it at the new size.
        if let Ok(mut painted) = self.painted_size.lock() {
            *painted = Some(PaintedSize {
                estimated: self.estimated_size,
                actual: info.screen_size_px,
            });
        }
        self.texture.presenter.draw(pass, &self.texture.source);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::test_window::{CLEAR, Window, differing};

    const SIZE: [u32; 2] = [320, 240];

    /// A window whose side panel and status bar are offered to a panel cache.
    struct Panels {
        window: Window,
        cache: PanelCache,
    }

    impl Panels {
        fn new() -> Option<Self> {
            Some(Self {
                window: Window::new(SIZE)?,
                cache: PanelCache::default(),
            })
        }

        /// One frame with a side panel headed `heading` and a status bar saying `status`
        /// (their shapes offered to the cache) and a canvas label; returns the window's
        /// pixels (RGBA).
        fn frame(&mut self, heading: &str, status: &str) -> Vec<u8> {
            let cache = &mut self.cache;
            self.window.frame(|ui, gpu| {
                let layer = ui.layer_id();
                let start = layer_shapes::count(ui.ctx(), layer);
                egui::Panel::left("panel").show(ui, |ui| {
                    ui.heading(heading);
                    let _ = ui.button("A button");
                    ui.add(egui::Slider::new(&mut 0.25_f32, 0.0..=1.0));
                    ui.label("Ink, palette and history");
                });
                let end = layer_shapes::count(ui.ctx(), layer);
                egui::Panel::bottom("status").show(ui, |ui| ui.label(status));
                let panels = [start..end, end..layer_shapes::count(ui.ctx(), layer)];
                cache.substitute(ui.ctx(), Some(gpu), layer, &panels, CLEAR);
                egui::CentralPanel::default().show(ui, |ui| ui.label("the canvas"));
            })
        }
    }

    #[test]
    fn unchanged_panels_are_copied_and_look_exactly_as_egui_draws_them() {
        let Some(mut window) = Panels::new() else {
            return;
        };
        // egui sizes the panel in the first frame; the second is egui's own drawing of
        // the settled panel, different from the first.
        window.frame("Tools", "3 ops");
        let drawn = window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (0, 0));
        // The second frame shows the same panel from the texture.
        let copied = window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        assert_eq!(differing(&drawn, &copied), 0);
        // Later frames copy it without rendering it again.
        let again = window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (2, 1));
        assert_eq!(differing(&drawn, &again), 0);
    }

    #[test]
    fn a_changed_panel_is_drawn_by_egui_and_then_cached_anew() {
        let Some(mut window) = Panels::new() else {
            return;
        };
        window.frame("Tools", "3 ops");
        let tools = window.frame("Tools", "3 ops");
        window.frame("Tools", "3 ops");
        // The heading changes: egui draws this frame itself, and it shows the change.
        let ink = window.frame("Ink", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        assert!(
            differing(&tools, &ink) > 50,
            "the comparison sees a new heading"
        );
        // From the next frame on, the new panel is copied from a new rendering.
        let copied = window.frame("Ink", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (2, 2));
        assert_eq!(differing(&ink, &copied), 0);
    }

    #[test]
    fn a_changed_status_bar_alone_is_noticed_too() {
        let Some(mut window) = Panels::new() else {
            return;
        };
        window.frame("Tools", "3 ops");
        let three = window.frame("Tools", "3 ops");
        window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        // Only the status bar changes: egui draws both panels itself this frame.
        let four = window.frame("Tools", "4 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        assert!(
            differing(&three, &four) > 5,
            "the comparison sees a new digit"
        );
        let copied = window.frame("Tools", "4 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (2, 2));
        assert_eq!(differing(&four, &copied), 0);
    }

    #[test]
    fn a_resized_window_is_drawn_by_egui_then_cached_at_its_new_size() {
        let Some(mut window) = Panels::new() else {
            return;
        };
        window.frame("Tools", "3 ops");
        window.frame("Tools", "3 ops");
        window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        // Taller and wider: the first frame at the new size is egui's own drawing.
        window.window.size = [400, 300];
        let resized = window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (1, 1));
        // Then the panels come from a texture made at the new size: a texture left at
        // the old size would end 60 pixels above the status bar.
        let copied = window.frame("Tools", "3 ops");
        assert_eq!((window.cache.copies, window.cache.renders), (2, 2));
        assert_eq!(differing(&resized, &copied), 0);
    }
}
