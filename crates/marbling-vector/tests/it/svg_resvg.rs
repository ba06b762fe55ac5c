//! The SVG export parses with usvg and, rendered by resvg, matches the tiny-skia preview
//! painted the way SVG renderers paint (sRGB blending).

use marbling_core::RgbaImage;
use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{Blend, TraceOptions, rasterize, to_svg, trace};
use resvg::{tiny_skia, usvg};

fn rasterise(svg: &str) -> RgbaImage {
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

/// Paths in a usvg group, recursively (a viewBox scale adds a group).
fn count_paths(group: &usvg::Group) -> usize {
    group
        .children()
        .iter()
        .map(|node| match node {
            usvg::Node::Group(g) => count_paths(g),
            usvg::Node::Path(_) => 1,
            _ => 0,
        })
        .sum()
}

#[test]
fn resvg_render_of_svg_matches_preview() {
    println!("seed mix         ops scale vertices   bytes mismatch");
    for (seed, mix, ops, scale) in [
        (1, Mix::Mixed, 60, 1.0),
        (2, Mix::DropHeavy, 150, 1.0),
        (3, Mix::CombHeavy, 60, 2.0),
    ] {
        let design = random_design(seed, 200, 150, ops, mix);
        let opts = TraceOptions {
            scale,
            ..TraceOptions::default()
        };
        let vector = trace(&design, &opts).expect("traceable");
        let svg = to_svg(&vector);
        let tree = usvg::Tree::from_str(&svg, &usvg::Options::default()).expect("valid SVG");
        // Background rectangle plus one path per outline.
        assert_eq!(count_paths(tree.root()), 1 + vector.outlines.len());
        let actual = rasterise(&svg);
        let expected = rasterize(&vector, scale, Blend::Srgb).expect("preview");
        let diff = compare(&expected, &actual, 16).expect("same size");
        println!(
            "{seed} {mix:<12?} {ops:>3} {scale:>5} {:>8} {:>7} {:.3} %",
            vector.stats.vertices,
            svg.len(),
            100.0 * diff.fraction()
        );
        assert!(diff.fraction() <= 0.002, "{:.3} %", 100.0 * diff.fraction());
    }
}
