//! What the agreement tests compare: the exported SVG rendered by resvg, and the exact
//! CPU render with 4×4 supersampling.

use marbling_core::compare::{ImageDiff, compare};
use marbling_core::{Antialias, Design, RenderOptions, RgbaImage, render};
use resvg::{tiny_skia, usvg};

/// The default options with every region traced forward (no contour method): for the
/// tests of forward tracing itself.
pub fn forward_only() -> marbling_vector::TraceOptions {
    marbling_vector::TraceOptions {
        contour_all: 0.0,
        ..marbling_vector::TraceOptions::default()
    }
}

/// Pixels differing by more than this (of 255) count as mismatches.
pub const THRESHOLD: u8 = 48;

/// `svg` rendered by resvg at its width and height attributes.
pub fn rasterise_svg(svg: &str) -> RgbaImage {
    let tree = usvg::Tree::from_str(svg, &usvg::Options::default()).expect("valid SVG");
    let size = tree.size().to_int_size();
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height()).expect("pixmap");
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    RgbaImage {
        width: size.width(),
        height: size.height(),
        pixels: pixmap.take(),
    }
}

/// The exact render of `design` at `scale` with the regular 4×4 grid of samples.
pub fn exact_raster(design: &Design, scale: f64) -> RgbaImage {
    render(
        design,
        &RenderOptions {
            scale,
            antialias: Antialias::Grid4,
        },
    )
    .expect("render")
}

/// How `svg`, rendered by resvg, differs from the exact render of `design`.
pub fn svg_against_exact(design: &Design, svg: &str, scale: f64) -> ImageDiff {
    compare(&exact_raster(design, scale), &rasterise_svg(svg), THRESHOLD).expect("same size")
}
