//! For unit tests: an egui context drawn by egui's wgpu renderer into a texture the way
//! eframe draws a window (lavapipe or any adapter; `MARBLING_SKIP_GPU=1` skips).

use crate::fast_paint::panel_cache::PanelGpu;
use eframe::egui_wgpu;
use egui::Rect;
use egui::mutex::RwLock;
use marbling_gpu::{GpuContext, RenderTarget, copy_to_buffer, read_buffer};

pub const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;
pub const CLEAR: [f32; 4] = [0.2, 0.2, 0.2, 1.0];

/// A headless device (lavapipe or any adapter), or `None` where `MARBLING_SKIP_GPU=1`
/// lets a missing adapter skip; otherwise a missing adapter fails the test
/// (`marbling_testkit`).
pub fn gpu_or_skip() -> Option<GpuContext> {
    marbling_testkit::gpu_or_skip(GpuContext::new_headless())
}

/// The window: context, device and egui's renderer (without dithering, so that pixels
/// compare exactly).
pub struct Window {
    pub ctx: egui::Context,
    gpu: GpuContext,
    renderer: RwLock<egui_wgpu::Renderer>,
    /// The window's size, pixels (one pixel per point).
    pub size: [u32; 2],
}

impl Window {
    /// A `size`-pixel window, or None (with a note) when `MARBLING_SKIP_GPU=1` and there
    /// is no adapter.
    pub fn new(size: [u32; 2]) -> Option<Self> {
        let gpu = gpu_or_skip()?;
        let options = egui_wgpu::RendererOptions {
            dithering: false,
            ..Default::default()
        };
        let renderer = egui_wgpu::Renderer::new(&gpu.device, FORMAT, options);
        Some(Self {
            ctx: egui::Context::default(),
            gpu,
            renderer: RwLock::new(renderer),
            size,
        })
    }

    /// One frame of `ui`, which also gets what rendering outside egui takes; returns the
    /// window's pixels (RGBA).
    pub fn frame(&mut self, mut ui: impl FnMut(&mut egui::Ui, PanelGpu<'_>)) -> Vec<u8> {
        let input = egui::RawInput {
            screen_rect: Some(Rect::from_min_size(
                egui::Pos2::ZERO,
                egui::vec2(self.size[0] as f32, self.size[1] as f32),
            )),
            ..Default::default()
        };
        let Self {
            ctx, gpu, renderer, ..
        } = self;
        let output = ctx.run_ui(input, |egui_ui| {
            let panel_gpu = PanelGpu {
                device: &gpu.device,
                queue: &gpu.queue,
                target_format: FORMAT,
                renderer,
            };
            ui(egui_ui, panel_gpu);
        });
        let primitives = ctx.tessellate(output.shapes, output.pixels_per_point);
        let mut textures = output.textures_delta;
        let pixels = self.draw(&mut textures, &primitives, output.pixels_per_point);
        textures.clear();
        pixels
    }

    /// Draws as eframe does: textures, buffers, one pass cleared to [`CLEAR`].
    fn draw(
        &self,
        textures: &mut egui::TexturesDelta,
        primitives: &[egui::ClippedPrimitive],
        pixels_per_point: f32,
    ) -> Vec<u8> {
        let (device, queue) = (&self.gpu.device, &self.gpu.queue);
        let mut renderer = self.renderer.write();
        for (id, deltas) in textures.set.drain() {
            for delta in &deltas {
                renderer.update_texture(device, queue, id, delta);
            }
        }
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: self.size,
            pixels_per_point,
        };
        let mut encoder = device.create_command_encoder(&Default::default());
        let [w, h] = self.size;
        let target = RenderTarget::new(device, w, h, FORMAT);
        let prepared = crate::fast_paint::panel_cache::record_egui(
            (device, queue),
            &mut renderer,
            &mut encoder,
            &target.view,
            CLEAR,
            primitives,
            &screen,
        );
        let (buffer, padded) = copy_to_buffer(device, &mut encoder, &target);
        queue.submit(prepared.into_iter().chain([encoder.finish()]));
        let row = w as usize * 4;
        let mut pixels = vec![0; row * h as usize];
        read_buffer(&self.gpu, &buffer, padded, w, h, |y, b| {
            pixels[y as usize * row..(y as usize + 1) * row].copy_from_slice(b);
        })
        .expect("readback");
        pixels
    }
}

/// Pixels that differ between two windows' pixels.
pub fn differing(a: &[u8], b: &[u8]) -> usize {
    a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| p != q).count()
}
