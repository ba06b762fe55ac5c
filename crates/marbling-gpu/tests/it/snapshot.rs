//! A golden image of the GPU renderer (tests/snapshots/gpu/), itself checked against
//! the CPU reference so the golden cannot silently drift from the truth.
//! Regenerate with `UPDATE_SNAPSHOTS=1 cargo test -p marbling-gpu --test it snapshot`.

use marbling_core::compare::{check_snapshot, compare};
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};

#[test]
fn golden_mixed_design() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let design = random_design(2026, 128, 96, 250, Mix::Mixed);
    let opts = RenderOptions {
        scale: 2.0,
        antialias: Antialias::Rgss,
    };
    let image = gpu.render(&design, &opts).expect("GPU render");
    assert_eq!((image.width, image.height), (256, 192));
    let cpu = render(&design, &opts).expect("CPU render");
    let d = compare(&cpu, &image, 8).expect("size");
    assert!(d.fraction() <= 0.01, "GPU vs CPU: {d:?}");
    let path = marbling_testkit::goldens("gpu").join("mixed_250_rgss.png");
    check_snapshot(&path, &image, 8, 0.005).unwrap_or_else(|e| panic!("{e}"));
}
