//! The gallery's thumbnails, drawn exactly by the GPU renderer into one atlas texture
//! that egui shows (registered once at start-up): a thumbnail a frame while the
//! gallery is on screen, so opening it never stalls a frame.

use crate::gpu::canvas_gpu::CANVAS_FORMAT;
use eframe::egui_wgpu;
use marbling_core::{Antialias, Design};
use marbling_gpu::{ExactRenderer, RenderTarget, View};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// One thumbnail's cell in the atlas, texture pixels (16:10, the patterns' shape).
pub const CELL: [u32; 2] = [240, 150];
/// Cells per atlas row.
pub const COLUMNS: u32 = 6;
/// Atlas rows (room for `COLUMNS × ROWS` thumbnails).
pub const ROWS: u32 = 5;

/// The atlas and what has been drawn into it (egui-wgpu callback resource).
pub struct GalleryGpu {
    target: RenderTarget,
    /// Built on first use: only a user who opens the gallery pays for its pipeline.
    renderer: Option<ExactRenderer>,
    drawn: usize,
}

impl GalleryGpu {
    /// An atlas cleared to `surround` (sRGB bytes).
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, surround: [u8; 3]) -> Self {
        let target = RenderTarget::new(device, CELL[0] * COLUMNS, CELL[1] * ROWS, CANVAS_FORMAT);
        let [r, g, b] = surround.map(|v| f64::from(v) / 255.0);
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        drop(target.begin_pass_clearing(&mut encoder, wgpu::Color { r, g, b, a: 1.0 }));
        queue.submit([encoder.finish()]);
        Self {
            target,
            renderer: None,
            drawn: 0,
        }
    }

    /// The atlas texture view (to register with egui).
    pub fn view(&self) -> &wgpu::TextureView {
        &self.target.view
    }

    /// Records the next thumbnail of `designs` into the atlas; the number drawn so far.
    fn draw_next(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        designs: &[Design],
    ) -> (usize, Option<wgpu::CommandBuffer>) {
        let n = self.drawn;
        let Some(design) = designs.get(n).filter(|_| n < (COLUMNS * ROWS) as usize) else {
            return (n, None);
        };
        self.drawn += 1;
        let renderer = self
            .renderer
            .get_or_insert_with(|| ExactRenderer::new(device, CANVAS_FORMAT));
        // A design that cannot be uploaded keeps its cell blank (its card still opens
        // it, and opening says what is wrong).
        let Ok(mut prepared) = renderer.prepare(device, queue, design) else {
            return (self.drawn, None);
        };
        let [x, y, w, h] = cell_pixels(n, (design.width, design.height));
        let scale = f64::from(w) / f64::from(design.width);
        prepared.set_view(
            queue,
            &View {
                scale,
                offset: [-f64::from(x), -f64::from(y)],
                antialias: Antialias::Rgss,
            },
        );
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = self.target.begin_pass_keeping(&mut encoder);
            renderer.draw_rect(&mut pass, &prepared, [x, y, w, h]);
        }
        (self.drawn, Some(encoder.finish()))
    }
}

/// Where thumbnail `n` of a design of `size` (design pixels) lies in the atlas, pixels
/// `[x, y, w, h]`: its cell, letterboxed to the design's shape.
pub fn cell_pixels(n: usize, size: (u32, u32)) -> [u32; 4] {
    let (col, row) = (n as u32 % COLUMNS, n as u32 / COLUMNS);
    let (width, height) = (f64::from(size.0), f64::from(size.1));
    let s = (f64::from(CELL[0]) / width).min(f64::from(CELL[1]) / height);
    let w = ((width * s).round() as u32).clamp(1, CELL[0]);
    let h = ((height * s).round() as u32).clamp(1, CELL[1]);
    [
        col * CELL[0] + (CELL[0] - w) / 2,
        row * CELL[1] + (CELL[1] - h) / 2,
        w,
        h,
    ]
}

/// Thumbnail `n`'s rectangle in texture coordinates (0..=1), for a design of `size`.
pub fn cell_uv(n: usize, size: (u32, u32)) -> egui::Rect {
    let [x, y, w, h] = cell_pixels(n, size).map(|v| v as f32);
    let (tw, th) = ((CELL[0] * COLUMNS) as f32, (CELL[1] * ROWS) as f32);
    egui::Rect::from_min_size(egui::pos2(x / tw, y / th), egui::vec2(w / tw, h / th))
}

/// Draws the next thumbnail in egui's prepare step (draws nothing itself).
pub struct ThumbnailCallback {
    /// The gallery's designs, in order.
    pub designs: Arc<Vec<Design>>,
    /// Thumbnails drawn so far (read by the app for repaints and the hook).
    pub drawn: Arc<AtomicUsize>,
}

impl egui_wgpu::CallbackTrait for ThumbnailCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(gallery) = resources.get_mut::<GalleryGpu>() else {
            return Vec::new();
        };
        let (drawn, commands) = gallery.draw_next(device, queue, &self.designs);
        self.drawn.store(drawn, Ordering::SeqCst);
        commands.into_iter().collect()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        _pass: &mut wgpu::RenderPass<'static>,
        _resources: &egui_wgpu::CallbackResources,
    ) {
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{RenderOptions, render};
    use marbling_gpu::{copy_to_buffer, read_buffer};

    #[test]
    fn cells_tile_the_atlas_and_letterbox_other_shapes() {
        assert_eq!(cell_pixels(0, (640, 400)), [0, 0, 240, 150]);
        assert_eq!(cell_pixels(7, (640, 400)), [240, 150, 240, 150]);
        assert_eq!(cell_pixels(1, (500, 500)), [240 + 45, 0, 150, 150]);
        let uv = cell_uv(COLUMNS as usize, (640, 400));
        assert!((uv.min.y - 1.0 / ROWS as f32).abs() < 1e-6 && uv.min.x == 0.0);
    }

    /// The thumbnails the atlas holds are the exact renders of the gallery's designs.
    #[test]
    fn thumbnails_are_exact_renders_in_their_cells() {
        let Some(g) = crate::gpu::test_window::gpu_or_skip() else {
            return;
        };
        let designs: Vec<Design> = crate::shell::gallery::entries()[..2]
            .iter()
            .map(|e| e.design().expect("valid"))
            .collect();
        let mut gallery = GalleryGpu::new(&g.device, &g.queue, [40, 40, 40]);
        for _ in 0..3 {
            let (_, commands) = gallery.draw_next(&g.device, &g.queue, &designs);
            g.queue.submit(commands);
        }
        assert_eq!(gallery.drawn, 2, "stops after the last design");
        let t = &gallery.target;
        let mut encoder = g
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        let (buffer, padded) = copy_to_buffer(&g.device, &mut encoder, t);
        g.queue.submit([encoder.finish()]);
        let mut atlas = vec![0u8; (t.width * t.height * 4) as usize];
        let row = (t.width * 4) as usize;
        read_buffer(&g, &buffer, padded, t.width, t.height, |y, bytes| {
            atlas[y as usize * row..][..row].copy_from_slice(&bytes[..row]);
        })
        .expect("readback");
        for (n, d) in designs.iter().enumerate() {
            let [x, y, w, h] = cell_pixels(n, (d.width, d.height));
            let cpu = render(
                d,
                &RenderOptions {
                    scale: f64::from(w) / f64::from(d.width),
                    antialias: Antialias::Rgss,
                },
            )
            .expect("render");
            let mut cell = marbling_core::RgbaImage::filled(w, h, [0, 0, 0, 255]);
            for yy in 0..h as usize {
                let src = &atlas[(y as usize + yy) * row + x as usize * 4..][..w as usize * 4];
                cell.pixels[yy * w as usize * 4..][..w as usize * 4].copy_from_slice(src);
            }
            let diff = marbling_core::compare::compare(&cpu, &cell, 24).expect("same size");
            assert!(diff.fraction() < 0.01, "thumbnail {n}: {}", diff.fraction());
        }
        // Outside the cells the atlas keeps its clear colour.
        let last = (t.height as usize - 1) * row;
        assert_eq!(&atlas[last..last + 3], &[40, 40, 40]);
    }
}
