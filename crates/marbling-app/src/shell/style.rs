//! The app's egui look: egui's default visuals with widget corners of
//! [`WIDGET_CORNER_RADIUS`] points instead of 4–6.
//!
//! Why: egui tessellates a rounded corner of radius ≤ 2 with 3 points and one of 6 with
//! 9, and every outline point costs triangles (fill, outline and anti-aliasing feather):
//! a button-sized filled and outlined rectangle takes 178 triangles instead of 322. The
//! side panel shows about forty buttons, fields and swatches; with small corners its
//! triangles per frame fell from ~4,300 to ~2,900, which on a software GPU (SwiftShader,
//! what headless Chromium uses where there is no GPU) is ~3 ms a frame
//! (docs/BENCHMARKS.md).

use egui::CornerRadius;

/// Corner radius of buttons, fields, sliders and swatches, points.
pub const WIDGET_CORNER_RADIUS: u8 = 2;

/// Applies the look to both themes of `ctx`, and the app's fonts (src/shell/fonts.rs).
pub fn apply(ctx: &egui::Context) {
    ctx.set_fonts(crate::shell::fonts::definitions());
    ctx.all_styles_mut(small_corners);
}

fn small_corners(style: &mut egui::Style) {
    let w = &mut style.visuals.widgets;
    for state in [
        &mut w.noninteractive,
        &mut w.inactive,
        &mut w.hovered,
        &mut w.active,
        &mut w.open,
    ] {
        state.corner_radius = CornerRadius::same(WIDGET_CORNER_RADIUS);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::epaint::{Shape, StrokeKind, TessellationOptions, Tessellator, TextureAtlas};
    use egui::{Color32, Rect, Stroke, pos2, vec2};

    /// Triangles egui makes for one filled, outlined widget-sized rounded rectangle.
    fn triangles(radius: CornerRadius) -> usize {
        let atlas = TextureAtlas::new([1024, 1024], Default::default());
        let mut tessellator = Tessellator::new(
            1.0,
            TessellationOptions::default(),
            atlas.size(),
            atlas.prepared_discs(),
        );
        let rect = Rect::from_min_size(pos2(10.0, 10.0), vec2(80.0, 20.0));
        let shape = Shape::rect_filled(rect, radius, Color32::GRAY);
        let stroke = Shape::rect_stroke(
            rect,
            radius,
            Stroke::new(1.0, Color32::BLACK),
            StrokeKind::Inside,
        );
        let mut mesh = egui::epaint::Mesh::default();
        tessellator.tessellate_shape(shape, &mut mesh);
        tessellator.tessellate_shape(stroke, &mut mesh);
        mesh.indices.len() / 3
    }

    #[test]
    fn every_widget_state_gets_the_small_radius() {
        let ctx = egui::Context::default();
        apply(&ctx);
        ctx.all_styles_mut(|style| {
            let w = &style.visuals.widgets;
            for state in [
                &w.noninteractive,
                &w.inactive,
                &w.hovered,
                &w.active,
                &w.open,
            ] {
                assert_eq!(
                    state.corner_radius,
                    CornerRadius::same(WIDGET_CORNER_RADIUS)
                );
            }
        });
    }

    #[test]
    fn small_corners_take_far_fewer_triangles() {
        let ours = triangles(CornerRadius::same(WIDGET_CORNER_RADIUS));
        let egui_default = triangles(
            egui::Style::default()
                .visuals
                .widgets
                .inactive
                .corner_radius,
        );
        // 178 vs 322 with egui 0.37's tessellator.
        assert!(
            10 * ours <= 6 * egui_default,
            "{ours} triangles with radius {WIDGET_CORNER_RADIUS} vs {egui_default} with egui's"
        );
    }
}
