//! A render split into small tiles equals the untiled render, and reports progress.

use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions};
use std::cell::RefCell;

#[test]
fn tiled_render_equals_untiled() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let design = random_design(42, 230, 170, 400, Mix::Mixed);
    let opts = RenderOptions {
        scale: 1.1,
        antialias: Antialias::Adaptive,
    };
    let whole = gpu.render(&design, &opts).expect("untiled");
    assert_eq!((whole.width, whole.height), (253, 187));
    let tiled = gpu.with_tile_side(64);
    let calls = RefCell::new(Vec::new());
    let parts = tiled
        .render_with_progress(&design, &opts, &|d, t| calls.borrow_mut().push((d, t)))
        .expect("tiled");
    assert_eq!(
        calls.into_inner(),
        (1..=12).map(|d| (d, 12)).collect::<Vec<_>>()
    );
    assert!(whole == parts, "tiles differ from the whole render");
}
