//! The shapes drawn over the canvas (the tool overlay and the sheet's outline) drawn by
//! the flat-mesh pipeline instead of egui's shader.
//!
//! They are untextured lines and circles, redrawn every frame while a tool is hovered
//! or dragged. egui's fragment shader carries paths for textures, filtering modes and
//! dithering; a software GPU (SwiftShader) runs all of them for every pixel, so these
//! few thousand pixels cost it milliseconds a frame (docs/BENCHMARKS.md).
//! [`substitute`] tessellates the shapes as egui would and hands the triangles to
//! [`FlatMeshRenderer`] in a paint callback: the same triangles, colours
//! and blending, without the texture lookup and without egui's dithering.

use super::flat_mesh::{FlatMeshRenderer, FlatVertex};
use super::layer_shapes;
use eframe::egui_wgpu;
use egui::epaint::{Primitive, Shape, WHITE_UV};
use egui::{LayerId, Rect};
use std::ops::Range;

/// The triangles of the replaced shapes, drawn by one callback.
struct FlatShapes {
    target_format: wgpu::TextureFormat,
    vertices: Vec<FlatVertex>,
    indices: Vec<u32>,
    /// Each mesh's clip rectangle (points) and its range of `indices`.
    draws: Vec<(Rect, Range<u32>)>,
}

/// The flat-mesh renderer kept in egui's callback resources (one per target format).
struct FlatMeshes {
    format: wgpu::TextureFormat,
    renderer: FlatMeshRenderer,
}

/// Replaces the shapes `range` of `layer` (painted this frame) by one paint callback
/// drawing their triangles with the flat-mesh pipeline into a `target_format` window.
/// Returns false and leaves them to egui when any of them is textured (text, images) or
/// is a callback, or when there is no wgpu renderer (`target_format` None). Only one
/// such callback may be painted per frame: they share one set of buffers.
pub fn substitute(
    ctx: &egui::Context,
    target_format: Option<wgpu::TextureFormat>,
    layer: LayerId,
    range: Range<usize>,
) -> bool {
    let Some(target_format) = target_format else {
        return false;
    };
    let shapes = layer_shapes::get(ctx, layer, range.clone());
    if shapes.is_empty() || shapes.iter().any(|s| matches!(s.shape, Shape::Callback(_))) {
        return false;
    }
    let area = shapes
        .iter()
        .map(|s| s.clip_rect)
        .fold(Rect::NOTHING, |a, b| a.union(b));
    let mut flat = FlatShapes {
        target_format,
        vertices: Vec::new(),
        indices: Vec::new(),
        draws: Vec::new(),
    };
    for primitive in ctx.tessellate(shapes, ctx.pixels_per_point()) {
        let Primitive::Mesh(mesh) = &primitive.primitive else {
            return false;
        };
        let untextured = mesh.texture_id == egui::TextureId::default()
            && mesh.vertices.iter().all(|v| v.uv == WHITE_UV);
        if !untextured {
            return false;
        }
        let base = flat.vertices.len() as u32;
        let start = flat.indices.len() as u32;
        flat.vertices
            .extend(mesh.vertices.iter().map(|v| FlatVertex {
                position: [v.pos.x, v.pos.y],
                uv: [v.uv.x, v.uv.y],
                color: v.color.to_array(),
            }));
        flat.indices.extend(mesh.indices.iter().map(|i| base + i));
        flat.draws
            .push((primitive.clip_rect, start..flat.indices.len() as u32));
    }
    let callback = egui_wgpu::Callback::new_paint_callback(area, flat);
    layer_shapes::replace(ctx, layer, range, area, callback.into());
    true
}

/// `clip` (points) in whole pixels of a `size`-pixel target, rounded and clamped as
/// egui's renderer does: x, y, width, height.
fn scissor(clip: Rect, pixels_per_point: f32, size: [u32; 2]) -> [u32; 4] {
    let px = |v: f32, max: u32| ((v * pixels_per_point).round().max(0.0) as u32).min(max);
    let (x0, y0) = (px(clip.min.x, size[0]), px(clip.min.y, size[1]));
    let (x1, y1) = (
        px(clip.max.x, size[0]).max(x0),
        px(clip.max.y, size[1]).max(y0),
    );
    [x0, y0, x1 - x0, y1 - y0]
}

impl egui_wgpu::CallbackTrait for FlatShapes {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        if resources
            .get::<FlatMeshes>()
            .is_none_or(|m| m.format != self.target_format)
        {
            resources.insert(FlatMeshes {
                format: self.target_format,
                renderer: FlatMeshRenderer::new(device, self.target_format),
            });
        }
        if let Some(meshes) = resources.get_mut::<FlatMeshes>() {
            let [w, h] = screen.size_in_pixels;
            let points = [w as f32, h as f32].map(|v| v / screen.pixels_per_point);
            meshes
                .renderer
                .upload(device, queue, points, &self.vertices, &self.indices);
        }
        Vec::new()
    }

    fn paint(
        &self,
        info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(meshes) = resources.get::<FlatMeshes>() else {
            return;
        };
        let [w, h] = info.screen_size_px;
        pass.set_viewport(0.0, 0.0, w as f32, h as f32, 0.0, 1.0);
        for (clip, indices) in &self.draws {
            let [x, y, sw, sh] = scissor(*clip, info.pixels_per_point, [w, h]);
            if sw == 0 || sh == 0 {
                continue;
            }
            pass.set_scissor_rect(x, y, sw, sh);
            meshes.renderer.draw(pass, indices.clone());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::layer_shapes::count as shape_count;
    use super::*;
    use crate::gpu::test_window::{FORMAT, Window, differing};
    use egui::{Color32, Pos2, Stroke};

    /// One frame with a canvas and, over it, what the tool overlay paints: thick and
    /// thin lines, circles and a polyline, partly outside the canvas's clip rectangle;
    /// drawn by egui (`flat` false) or by the flat-mesh callback.
    fn frame(window: &mut Window, flat: bool, offset: f32) -> (Vec<u8>, bool) {
        let mut substituted = false;
        let pixels = window.frame(|ui, _| {
            egui::Panel::left("panel").show(ui, |ui| ui.label("tools"));
            egui::CentralPanel::default().show(ui, |ui| {
                let rect = ui.max_rect();
                let painter = ui.painter_at(rect);
                let layer = painter.layer_id();
                let start = shape_count(ui.ctx(), layer);
                let dark = Color32::from_black_alpha(160);
                let light = Color32::from_white_alpha(220);
                let a = Pos2::new(rect.left() - 20.0, rect.top() + 30.0 + offset);
                let b = Pos2::new(rect.right() + 20.0, rect.bottom() - 40.0);
                painter.line_segment([a, b], Stroke::new(3.0, dark));
                painter.line_segment([a, b], Stroke::new(1.2, light));
                painter.circle_stroke(rect.center(), 40.0, Stroke::new(3.0, dark));
                painter.circle_stroke(rect.center(), 40.0, Stroke::new(1.2, light));
                let wave: Vec<Pos2> = (0..40)
                    .map(|i| {
                        let x = rect.left() + i as f32 * 6.0;
                        Pos2::new(x, rect.center().y + 20.0 * (i as f32 * 0.5).sin())
                    })
                    .collect();
                painter.add(Shape::line(wave, Stroke::new(1.2, light)));
                painter.rect_stroke(
                    rect.shrink(10.0),
                    0.0,
                    Stroke::new(1.0, Color32::from_gray(20)),
                    egui::StrokeKind::Outside,
                );
                if flat {
                    let end = shape_count(ui.ctx(), layer);
                    substituted = substitute(ui.ctx(), Some(FORMAT), layer, start..end);
                }
            });
        });
        (pixels, substituted)
    }

    #[test]
    fn overlay_shapes_look_exactly_as_egui_draws_them() {
        let Some(mut window) = Window::new([320, 240]) else {
            return;
        };
        // egui lays out the panels in the first frame.
        frame(&mut window, false, 0.0);
        let (by_egui, _) = frame(&mut window, false, 0.0);
        let (flat, substituted) = frame(&mut window, true, 0.0);
        assert!(substituted);
        assert_eq!(differing(&by_egui, &flat), 0);
        // The comparison sees a line moved by one point.
        let (moved, _) = frame(&mut window, true, 1.0);
        assert!(differing(&by_egui, &moved) > 100);
    }

    #[test]
    fn text_is_left_to_egui() {
        let Some(mut window) = Window::new([160, 120]) else {
            return;
        };
        let mut substituted = true;
        window.frame(|ui, _| {
            let layer = ui.layer_id();
            let start = shape_count(ui.ctx(), layer);
            ui.label("text samples the font texture");
            let end = shape_count(ui.ctx(), layer);
            substituted = substitute(ui.ctx(), Some(FORMAT), layer, start..end);
        });
        assert!(!substituted);
    }

    #[test]
    fn scissors_round_and_clamp_as_egui_does() {
        let clip = Rect::from_min_max(Pos2::new(-3.0, 10.2), Pos2::new(50.6, 500.0));
        assert_eq!(scissor(clip, 1.0, [40, 300]), [0, 10, 40, 290]);
        assert_eq!(scissor(clip, 2.0, [400, 300]), [0, 20, 101, 280]);
        let outside = Rect::from_min_max(Pos2::new(500.0, 0.0), Pos2::new(600.0, 10.0));
        assert_eq!(scissor(outside, 1.0, [400, 300]), [400, 0, 0, 10]);
    }
}
