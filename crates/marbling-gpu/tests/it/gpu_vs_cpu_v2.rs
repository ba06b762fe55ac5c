//! Schema v2 on the GPU against the f64 CPU reference: noise backgrounds (Perlin fBm,
//! Worley, Gabor) marbled by random ops, with paper and pigment grain, within the same
//! pixel budgets as v1 designs (tests/it/gpu_vs_cpu.rs); and the comparison shown to see
//! the grain (a wrong strength fails it).

use marbling_core::compare::{ImageDiff, compare};
use marbling_core::synth::{Mix, random_design};
use marbling_core::{
    Antialias, Design, NoiseBackground, NoiseLayer, Op, Overlay, Palette, RenderOptions, render,
};
use marbling_gpu::GpuRenderer;

/// A channel difference above this counts as a differing pixel (out of 255).
const THRESHOLD: u8 = 8;
const WIDTH: u32 = 160;
const HEIGHT: u32 = 120;

fn layer(json: &str) -> NoiseLayer {
    NoiseLayer::from_json(json).expect("valid test noise")
}

/// (name, background noise, palette) of each case.
const BACKGROUNDS: [(&str, &str, &str); 4] = [
    (
        "perlin fbm",
        r#"{"type":"perlin","frequency":0.03,"octaves":5,"seed":4}"#,
        "marble",
    ),
    (
        "worley f2-f1",
        r#"{"type":"worley","frequency":0.05,"feature":"f2-f1","seed":1}"#,
        "ocean",
    ),
    (
        "gabor",
        // Both drives: the shader evaluates them through one fBm call site.
        r#"{"type":"gabor","kind":"anisotropic","frequency":0.06,"orientation":0.7,"bandwidth":0.05,"impulses":32,"seed":7,"orientation_field":{"noise":{"type":"perlin","frequency":0.008,"octaves":2,"seed":9},"amount":1.5},"frequency_field":{"noise":{"type":"value","frequency":0.005,"seed":4},"amount":0.6}}"#,
        "sepia",
    ),
    (
        "phasor",
        r#"{"type":"phasor","profile":"sine","frequency":0.05,"orientation":0.4,"bandwidth":0.03,"impulses":8,"seed":5}"#,
        "ocean",
    ),
];

/// Paper grain of the budgeted cases: a fine value-noise fBm (paper fibers cost ~100×
/// more per sample; they have their own smaller case, [`paper_fibers_as_grain`]).
const PAPER: &str = r#"{"type":"value","frequency":0.2,"octaves":3,"seed":8}"#;
/// Real paper fibers, with specks.
const FIBERS: &str = r#"{"type":"paper","length":10,"width":1.5,"density":0.2,"seed":8,"impurities":{"density":0.001}}"#;
const PIGMENT: &str = r#"{"type":"perlin","frequency":0.12,"octaves":2,"seed":3}"#;

/// A random design (combs at 0.3 strength as in tests/it/gpu_vs_cpu.rs) on a noise
/// background with both grains.
fn design(i: usize, ops: usize) -> (String, Design) {
    let (name, noise, palette) = BACKGROUNDS[i % BACKGROUNDS.len()];
    let mix = [Mix::Mixed, Mix::DropHeavy, Mix::CombHeavy][i % 3];
    let mut d = random_design(300 + i as u64, WIDTH, HEIGHT, ops, mix);
    for op in &mut d.ops {
        match op {
            Op::Tine(t) => t.alpha *= 0.3,
            Op::Rake(r) => r.alpha *= 0.3,
            Op::Wavy(w) => w.amplitude *= 0.3,
            Op::Circular(c) => c.alpha *= 0.3,
            Op::Vortex(v) => v.alpha *= 0.3,
            _ => {}
        }
    }
    d.set_background_noise(Some(NoiseBackground::new(
        layer(noise),
        Palette::named(palette).expect("palette"),
    )));
    d.overlays = vec![
        Overlay::paper_grain(layer(PAPER), 0.25),
        Overlay::pigment_grain(layer(PIGMENT), 0.3),
    ];
    (format!("{name} {mix:?} {ops} ops"), d)
}

fn diff(gpu: &GpuRenderer, design: &Design, opts: &RenderOptions) -> ImageDiff {
    let g = gpu.render(design, opts).expect("GPU render");
    let c = render(design, opts).expect("CPU render");
    compare(&c, &g, THRESHOLD).expect("same size")
}

/// Renders cases `0..n` with `aa`, prints one line per case, then checks the budget.
fn check(gpu: &GpuRenderer, aa: Antialias, budget: f64, n: usize) {
    let mut over = Vec::new();
    for i in 0..n {
        let (name, d) = design(i, [0, 20, 80, 150, 300, 40][i]);
        let opts = RenderOptions {
            scale: [1.0, 0.8, 1.25][i % 3],
            antialias: aa,
        };
        let r = diff(gpu, &d, &opts);
        println!(
            "{name:<32} aa {:<6} {:>5}/{} px differ ({:.3} %), max channel diff {}",
            aa.name(),
            r.differing,
            r.total,
            100.0 * r.fraction(),
            r.max_channel_diff
        );
        if r.fraction() > budget {
            over.push(format!("{name}: {:.3} %", 100.0 * r.fraction()));
        }
    }
    assert!(
        over.is_empty(),
        "over the budget of {:.2} %: {over:?}",
        100.0 * budget
    );
}

#[test]
fn noise_backgrounds_and_grain_without_antialiasing() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    check(&gpu, Antialias::None, 0.005, 6);
}

#[test]
fn noise_backgrounds_and_grain_with_rgss_and_adaptive() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    // Lavapipe is slow on the noise shaders: every case with RGSS, three adaptive.
    check(&gpu, Antialias::Rgss, 0.01, 6);
    check(&gpu, Antialias::Adaptive, 0.01, 3);
}

#[test]
fn paper_fibers_as_grain() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let (name, mut d) = design(1, 40);
    d.overlays[0] = Overlay::paper_grain(layer(FIBERS), 0.4);
    let opts = RenderOptions {
        scale: 0.5,
        antialias: Antialias::None,
    };
    let r = diff(&gpu, &d, &opts);
    println!("{name} with paper fibers: {r:?}");
    assert!(r.fraction() <= 0.005, "{r:?}");
}

#[test]
fn a_wrong_grain_strength_fails_the_comparison() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let (_, d) = design(0, 30);
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::None,
    };
    let cpu = render(&d, &opts).expect("CPU render");
    assert!(
        compare(&cpu, &gpu.render(&d, &opts).expect("GPU"), THRESHOLD)
            .expect("size")
            .fraction()
            <= 0.005
    );
    for k in 0..2 {
        let mut wrong = d.clone();
        wrong.overlays[k].strength += 0.2;
        let g = gpu.render(&wrong, &opts).expect("GPU render");
        let r = compare(&cpu, &g, THRESHOLD).expect("size");
        println!("overlay {k} strength + 0.2: {r:?}");
        assert!(r.fraction() > 0.05, "overlay {k}: {r:?}");
    }
    // Pigment grain sampled at the output point instead (as paper grain) must fail too.
    let mut fixed = d.clone();
    fixed.overlays[1].kind = marbling_core::GrainKind::Paper;
    fixed.overlays.swap(0, 1);
    fixed.overlays.remove(1);
    let mut cpu_fixed = d.clone();
    cpu_fixed.overlays.remove(0);
    let g = gpu.render(&fixed, &opts).expect("GPU render");
    let c = render(&cpu_fixed, &opts).expect("CPU render");
    let r = compare(&c, &g, THRESHOLD).expect("size");
    println!("pigment grain drawn as paper grain: {r:?}");
    assert!(r.fraction() > 0.05, "{r:?}");
}
