//! Raster preview of traced outlines with tiny-skia (antialiased, any scale).

use crate::{TraceOptions, VectorDesign, VectorError, trace};
use marbling_core::{Design, RgbaImage, Rgb8, output_size};
use tiny_skia::{Color, FillRule, Paint, PathBuilder, Pixmap, Transform};

/// Rasterises `vector` at `scale` output pixels per design pixel, with the same output
/// size and pixel convention as the CPU reference renderer (pixel (i, j) covers design
/// square [i/s, (i+1)/s) × [j/s, (j+1)/s)). Regions are filled in painter's order with
/// tiny-skia's antialiasing (coverage blended in sRGB, as browsers and resvg do).
pub fn preview(vector: &VectorDesign, scale: f64) -> Result<RgbaImage, VectorError> {
    let probe = Design::new(vector.width, vector.height, vector.background);
    let (w, h) = output_size(&probe, scale)?;
    let mut pixmap = Pixmap::new(w, h).ok_or(VectorError::BadScale(scale))?;
    pixmap.fill(color(vector.background));
    let transform = Transform::from_scale(scale as f32, scale as f32);
    let mut paint = Paint {
        anti_alias: true,
        ..Paint::default()
    };
    for outline in &vector.outlines {
        let mut pb = PathBuilder::with_capacity(outline.points.len() + 1, outline.points.len());
        let mut it = outline.points.iter();
        let Some(first) = it.next() else { continue };
        pb.move_to(first.x as f32, first.y as f32);
        for p in it {
            pb.line_to(p.x as f32, p.y as f32);
        }
        pb.close();
        let Some(path) = pb.finish() else { continue };
        paint.set_color(color(outline.color));
        pixmap.fill_path(&path, &paint, FillRule::Winding, transform, None);
    }
    Ok(RgbaImage {
        width: w,
        height: h,
        pixels: pixmap.take(),
    })
}

/// Traces `design` at `opts` and rasterises it at `opts.scale`: the `--backend vector`
/// render.
pub fn render_vector(design: &Design, opts: &TraceOptions) -> Result<RgbaImage, VectorError> {
    preview(&trace(design, opts)?, opts.scale)
}

fn color(c: Rgb8) -> Color {
    Color::from_rgba8(c.r, c.g, c.b, 255)
}
