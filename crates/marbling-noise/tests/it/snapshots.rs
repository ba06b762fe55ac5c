//! Small golden images of every noise type (tests/snapshots/noise/, regenerate with
//! UPDATE_SNAPSHOTS=1) and a check that the comparator catches a perturbed image.

use marbling_core::RgbaImage;
use marbling_core::compare::check_snapshot;
use marbling_noise::{NoiseSpec, Renderer};
use std::path::PathBuf;

/// Side of the golden images.
const SIZE: u32 = 96;

const CASES: &[(&str, &str)] = &[
    (
        "gabor_anisotropic",
        r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#,
    ),
    (
        "gabor_isotropic",
        r#"{"type":"gabor","kind":"isotropic","frequency":0.08,"bandwidth":0.05,"impulses":32,"seed":3}"#,
    ),
    (
        "gabor_random_phase_driven",
        r#"{"type":"gabor","kind":"random-phase","frequency":0.08,"orientation":0,"bandwidth":0.05,"seed":2,
            "orientation_field":{"noise":{"type":"perlin","frequency":0.01,"seed":9},"amount":1.2}}"#,
    ),
    (
        "phasor_square",
        r#"{"type":"phasor","profile":"square","frequency":0.06,"orientation":0.5,"bandwidth":0.02,"impulses":32,"seed":5}"#,
    ),
    (
        "perlin_fbm",
        r#"{"type":"perlin","frequency":0.03,"octaves":5,"seed":4}"#,
    ),
    (
        "value",
        r#"{"type":"value","frequency":0.06,"octaves":3,"seed":4}"#,
    ),
    (
        "worley_f1",
        r#"{"type":"worley","frequency":0.05,"seed":1}"#,
    ),
    (
        "worley_f2_f1_chebyshev",
        r#"{"type":"worley","frequency":0.05,"feature":"f2-f1","metric":"chebyshev","seed":1}"#,
    ),
    ("white", r#"{"type":"white","seed":5}"#),
    (
        "curl_magnitude",
        r#"{"type":"curl","frequency":0.02,"octaves":3,"seed":6}"#,
    ),
    (
        "paper",
        r#"{"type":"paper","length":14,"width":1.5,"density":0.25,"seed":8,"impurities":{"density":0.002,"radius":1.5,"strength":2}}"#,
    ),
    (
        "canvas",
        r#"{"type":"canvas","length":10,"width":2.5,"density":0.25,"weights":[1,1.5],"seed":8}"#,
    ),
    (
        "cross_hatch",
        r#"{"type":"product","palette":"ink","inputs":[
            {"type":"gabor","frequency":0.1,"orientation":0.785,"bandwidth":0.04,"seed":1,"transfer":{"type":"threshold","threshold":0.6,"width":0.6,"invert":true}},
            {"type":"gabor","frequency":0.1,"orientation":-0.785,"bandwidth":0.04,"seed":2,"transfer":{"type":"threshold","threshold":0.6,"width":0.6,"invert":true}}]}"#,
    ),
    (
        "spline_decay_blend",
        r#"{"type":"gabor","kind":"random-phase","frequency":0.1,"orientation":0.3,"bandwidth":0.05,"seed":3,
            "transfer":{"type":"spline-decay","value":"x"},"blend":{"beta":0.6,"palette":"ember"}}"#,
    ),
];

fn golden_dir() -> PathBuf {
    marbling_testkit::goldens("noise")
}

fn render(text: &str, size: u32) -> RgbaImage {
    let spec = NoiseSpec::from_json(text).expect("valid spec");
    let img = Renderer::new(&spec, size).expect("size").render();
    let mut out = RgbaImage::filled(size, size, [0, 0, 0, 255]);
    for (k, p) in img.pixels.iter().enumerate() {
        let (x, y) = (k as u32 % size, k as u32 / size);
        out.set_pixel(x, y, [p[0], p[1], p[2], 255]);
    }
    out
}

#[test]
fn golden_images() {
    let mut failures = Vec::new();
    for (name, text) in CASES {
        let path = golden_dir().join(format!("{name}.png"));
        if let Err(e) = check_snapshot(&path, &render(text, SIZE), 2, 0.01) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
