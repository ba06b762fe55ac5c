//! The compute path of headless renders draws the same bytes as the fragment pipeline
//! (the app's path): v1 designs with every antialiasing mode, tiled, and a schema v2
//! design with a noise background and both grains; and the comparison sees a change.

mod common;

use marbling_core::synth::{Mix, random_design};
use marbling_core::{
    Antialias, Design, NoiseBackground, NoiseLayer, Overlay, Palette, RenderOptions, RgbaImage,
};
use marbling_gpu::{GpuContext, GpuRenderer};

/// (compute, fragment) renderers on one device of the best adapter.
fn renderers() -> Option<(GpuRenderer, GpuRenderer)> {
    let ctx = common::or_skip(GpuContext::new_headless())?;
    let compute = GpuRenderer::new(ctx.clone());
    let fragment = GpuRenderer::new(ctx).with_fragment_path();
    eprintln!("adapter: {}", compute.context().describe());
    assert_eq!(
        compute.path(),
        "compute",
        "the adapter has no compute path, so nothing would be compared"
    );
    assert_eq!(fragment.path(), "fragment");
    Some((compute, fragment))
}

/// Pixels whose bytes differ.
fn differing(a: &RgbaImage, b: &RgbaImage) -> usize {
    assert_eq!((a.width, a.height), (b.width, b.height));
    a.pixels
        .chunks_exact(4)
        .zip(b.pixels.chunks_exact(4))
        .filter(|(x, y)| x != y)
        .count()
}

fn v2_design() -> Design {
    let mut d = random_design(11, 160, 120, 60, Mix::Mixed);
    let layer = |json: &str| NoiseLayer::from_json(json).expect("valid test noise");
    d.background_noise = Some(NoiseBackground {
        noise: layer(r#"{"type":"perlin","frequency":0.03,"octaves":4,"seed":4}"#),
        palette: Palette::named("marble").expect("built-in palette"),
    });
    d.overlays = vec![
        Overlay::paper_grain(
            layer(r#"{"type":"value","frequency":0.2,"octaves":3,"seed":8}"#),
            0.3,
        ),
        Overlay::pigment_grain(
            layer(r#"{"type":"perlin","frequency":0.12,"octaves":2,"seed":3}"#),
            0.4,
        ),
    ];
    d
}

#[test]
fn compute_path_draws_the_fragment_path_bytes() {
    let Some((compute, fragment)) = renderers() else {
        return;
    };
    let compute = compute.with_tile_side(96);
    let fragment = fragment.with_tile_side(96);
    let v1 = random_design(5, 200, 150, 150, Mix::Mixed);
    for aa in [
        Antialias::None,
        Antialias::Rgss,
        Antialias::Adaptive,
        Antialias::Rooks8,
    ] {
        let opts = RenderOptions {
            scale: 1.3,
            antialias: aa,
        };
        let a = compute.render(&v1, &opts).expect("compute render");
        let b = fragment.render(&v1, &opts).expect("fragment render");
        assert_eq!(differing(&a, &b), 0, "v1, {aa:?}");
    }
    let v2 = v2_design();
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::Rgss,
    };
    let a = compute.render(&v2, &opts).expect("compute render");
    let b = fragment.render(&v2, &opts).expect("fragment render");
    assert_eq!(differing(&a, &b), 0, "v2 surface");
    // The comparison sees a one-op change.
    let mut changed = v1.clone();
    changed.ops.pop();
    let c = compute.render(&changed, &opts).expect("compute render");
    let d = fragment.render(&v1, &opts).expect("fragment render");
    assert!(differing(&c, &d) > 0, "dropping an op changed nothing");
}
