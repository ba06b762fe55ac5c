//! The SVG export parses with usvg and, rendered by resvg, matches the tiny-skia preview
//! painted the way SVG renderers paint (sRGB blending).

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{Blend, TraceOptions, rasterize, to_svg, trace};
use resvg::usvg;

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

/// Forward outlines are written to T/50 (budget 0.2 % of pixels off by more than
/// 16/255); contour outlines to T/10, which moves sub-pixel filaments a little more
/// (budget 2 %).
#[test]
fn resvg_render_of_svg_matches_preview() {
    println!("seed mix         ops scale vertices   bytes mismatch");
    for (seed, mix, ops, scale, contour) in [
        (1, Mix::Mixed, 60, 1.0, false),
        (2, Mix::DropHeavy, 150, 1.0, false),
        (3, Mix::CombHeavy, 60, 2.0, false),
        (2, Mix::DropHeavy, 150, 1.0, true),
        (4, Mix::CombHeavy, 400, 1.0, true),
    ] {
        let design = random_design(seed, 200, 150, ops, mix);
        let opts = TraceOptions {
            scale,
            ..if contour {
                TraceOptions::default()
            } else {
                crate::exact::forward_only()
            }
        };
        let vector = trace(&design, &opts).expect("traceable");
        let svg = to_svg(&vector);
        let tree = usvg::Tree::from_str(&svg, &usvg::Options::default()).expect("valid SVG");
        // Background rectangle plus one path per outline.
        assert_eq!(count_paths(tree.root()), 1 + vector.outlines.len());
        let actual = crate::exact::rasterise_svg(&svg);
        let expected = rasterize(&vector, scale, Blend::Srgb).expect("preview");
        let diff = compare(&expected, &actual, 16).expect("same size");
        println!(
            "{seed} {mix:<12?} {ops:>3} {scale:>5} {:>8} {:>7} {:.3} %",
            vector.stats.vertices,
            svg.len(),
            100.0 * diff.fraction()
        );
        let budget = if contour { 0.02 } else { 0.002 };
        assert!(
            diff.fraction() <= budget,
            "{:.3} %",
            100.0 * diff.fraction()
        );
    }
}

/// A schema v2 design: noise background, paper grain and pigment grain.
const V2_DESIGN: &str = r##"{"version":2,"width":160,"height":120,
  "background":{"noise":{"type":"perlin","frequency":0.03,"octaves":4,"seed":4},"palette":"marble"},
  "overlays":[
    {"type":"pigment-grain","noise":{"type":"worley","frequency":0.1,"seed":1},"strength":0.8},
    {"type":"paper-grain","noise":{"type":"perlin","frequency":0.2,"seed":2},"strength":0.5}],
  "ops":[
    {"type":"drop","center":[80,60],"radius":30,"color":"#1d3557"},
    {"type":"drop","center":[60,50],"radius":12,"color":"#e63946"},
    {"type":"tine","origin":[0,60],"direction":[1,0],"alpha":20,"lambda":6},
    {"type":"wavy","angle":0.5,"amplitude":6,"wavelength":70,"phase":0}]}"##;

/// The noise background under the ink and the grain multiplied over it: the SVG,
/// rendered by resvg, looks like the exact CPU render.
#[test]
fn v2_design_renders_like_the_cpu_render() {
    let design = marbling_core::Design::from_json(V2_DESIGN).expect("valid v2 design");
    let vector = trace(&design, &TraceOptions::default()).expect("traceable");
    let svg = to_svg(&vector);
    assert_eq!(svg.matches("<image ").count(), 2, "underlay and grain");
    assert_eq!(svg.matches("mix-blend-mode:multiply").count(), 1);
    let diff = crate::exact::svg_against_exact(&design, &svg, 1.0);
    // Without the grain layer the picture is visibly lighter: the comparison can fail.
    let mut bare = vector.clone();
    bare.grain = None;
    let without = crate::exact::svg_against_exact(&design, &to_svg(&bare), 1.0);
    println!(
        "v2: {:.3} % differ, {:.3} % without the grain layer, {} bytes",
        100.0 * diff.fraction(),
        100.0 * without.fraction(),
        svg.len()
    );
    assert!(diff.fraction() <= 0.02, "{:.3} %", 100.0 * diff.fraction());
    assert!(
        without.fraction() > 0.02,
        "{:.3} %",
        100.0 * without.fraction()
    );
}

/// An image background is embedded as the raster underlay of the outlines, marbled
/// like the ink: the SVG, rendered by resvg, looks like the exact CPU render.
#[test]
fn image_background_is_embedded_under_the_outlines() {
    let mut design = marbling_core::Design::from_json(V2_DESIGN).expect("valid v2 design");
    design.overlays.clear();
    let photo = marbling_core::synth::test_photo(4, 80, 60)
        .to_png()
        .expect("png");
    design.set_background_image(Some(
        marbling_core::ImageBackground::from_file_bytes(&photo, marbling_core::ImageFit::Cover)
            .expect("photo"),
    ));
    let vector = trace(&design, &TraceOptions::default()).expect("traceable");
    let svg = to_svg(&vector);
    assert_eq!(svg.matches("<image ").count(), 1, "the underlay");
    let diff = crate::exact::svg_against_exact(&design, &svg, 1.0);
    let mut bare = vector.clone();
    bare.underlay = None;
    let without = crate::exact::svg_against_exact(&design, &to_svg(&bare), 1.0);
    println!(
        "image background: {:.3} % differ, {:.3} % without the underlay",
        100.0 * diff.fraction(),
        100.0 * without.fraction()
    );
    assert!(diff.fraction() <= 0.02, "{:.3} %", 100.0 * diff.fraction());
    assert!(
        without.fraction() > 0.2,
        "{:.3} %",
        100.0 * without.fraction()
    );
}
