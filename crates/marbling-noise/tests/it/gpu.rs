//! CPU ≡ WGSL: every noise evaluated by `sample_noise` on the GPU (lavapipe here, with
//! WGPU_BACKEND=vulkan) matches the CPU reference at 256²: at most 1 % of pixels differ by
//! more than 4/255 after the 0.5 + n/6 grey map. Fails when no adapter exists unless
//! MARBLING_SKIP_GPU=1.

use crate::common::gpu::GpuNoise;
use marbling_noise::noise_gpu::NoiseGpu;
use marbling_noise::{NoiseSpec, noise_to_grey, sample_grid};

const SIZE: u32 = 256;

const SPECS: &[&str] = &[
    r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#,
    r#"{"type":"gabor","kind":"isotropic","frequency":0.08,"bandwidth":0.04,"impulses":32,"seed":3}"#,
    r#"{"type":"gabor","kind":"random-phase","frequency":0.1,"orientation":1.0,"bandwidth":0.05,"seed":5,"tile":true}"#,
    r#"{"type":"gabor","kind":"anisotropic","frequency":0.08,"bandwidth":0.05,"seed":2,
        "orientation_field":{"noise":{"type":"perlin","frequency":0.01,"octaves":2,"seed":9},"amount":1.2},
        "frequency_field":{"noise":{"type":"value","frequency":0.01,"seed":4},"amount":0.5}}"#,
    r#"{"type":"phasor","profile":"sine","frequency":0.05,"orientation":0.4,"bandwidth":0.02,"impulses":32,"seed":7}"#,
    r#"{"type":"phasor","kind":"isotropic","profile":"triangle","frequency":0.06,"bandwidth":0.03,"impulses":16,"seed":3,"tile":true}"#,
    r#"{"type":"phasor","profile":"square","frequency":0.04,"orientation":1.2,"bandwidth":0.02,"impulses":24,"seed":5}"#,
    r#"{"type":"perlin","frequency":0.02,"octaves":5,"seed":4}"#,
    r#"{"type":"perlin","frequency":0.03,"octaves":4,"seed":4,"tile":true}"#,
    r#"{"type":"value","frequency":0.05,"octaves":3,"seed":4}"#,
    r#"{"type":"worley","frequency":0.05,"feature":"f1","metric":"euclidean","seed":1}"#,
    r#"{"type":"worley","frequency":0.05,"feature":"f2","metric":"manhattan","seed":1,"tile":true}"#,
    r#"{"type":"worley","frequency":0.05,"feature":"f2-f1","metric":"chebyshev","seed":1}"#,
    r#"{"type":"white","seed":5}"#,
    r#"{"type":"curl","frequency":0.02,"octaves":3,"seed":6,"component":"magnitude"}"#,
    r#"{"type":"curl","frequency":0.02,"octaves":2,"seed":6,"component":"x","tile":true}"#,
    r#"{"type":"paper","length":14,"width":1.5,"density":0.25,"seed":8,"impurities":{"density":0.002,"radius":1.5,"strength":2}}"#,
    r#"{"type":"canvas","length":10,"width":2.5,"density":0.25,"weights":[1,1.5],"seed":8,"tile":true}"#,
];

fn grey(n: f32) -> i32 {
    (noise_to_grey(n) * 255.0).round() as i32
}

#[test]
fn cpu_matches_wgsl() {
    let Some(gpu) = marbling_testkit::gpu_or_skip(GpuNoise::new()) else {
        return;
    };
    println!("adapter: {}", gpu.adapter);
    let mut report = String::new();
    let mut ok = true;
    for text in SPECS {
        let spec = NoiseSpec::from_json(text).expect("valid spec");
        let cpu = sample_grid(&spec, SIZE).expect("noise");
        let u = NoiseGpu::from_spec(&spec, SIZE).expect("GPU form");
        let (wgsl, _) = gpu.run(&u, SIZE);
        let mut differing = 0;
        let mut max = 0;
        for (a, b) in cpu.iter().zip(&wgsl) {
            let d = (grey(*a) - grey(*b)).abs();
            max = max.max(d);
            if d > 4 {
                differing += 1;
            }
        }
        let fraction = f64::from(differing) / f64::from(SIZE * SIZE);
        report.push_str(&format!(
            "{:.3} % differ > 4/255 (max {max}): {}\n",
            100.0 * fraction,
            text.split_whitespace().collect::<String>()
        ));
        ok &= fraction <= 0.01;
    }
    println!("{report}");
    assert!(ok, "{report}");

    // The comparison must be able to fail: a different seed on the GPU side differs.
    let spec = NoiseSpec::from_json(SPECS[0]).expect("valid spec");
    let cpu = sample_grid(&spec, SIZE).expect("noise");
    let mut u = NoiseGpu::from_spec(&spec, SIZE).expect("GPU form");
    u.gabor.seed += 1;
    let (other, _) = gpu.run(&u, SIZE);
    let differing = cpu
        .iter()
        .zip(&other)
        .filter(|(a, b)| (grey(**a) - grey(**b)).abs() > 4)
        .count();
    assert!(
        differing as f64 > 0.01 * f64::from(SIZE * SIZE),
        "a perturbed GPU image passed the comparison"
    );
}

/// Layered specs, every combine mode, with thresholds and a tiling stack.
const STACKS: &[&str] = &[
    r#"{"type":"perlin","frequency":0.02,"octaves":3,"seed":4,
        "layers":[{"type":"worley","frequency":0.05,"seed":1,"combine":"add"},
                  {"type":"value","frequency":0.04,"seed":2,"combine":"multiply","weight":0.7}]}"#,
    r#"{"type":"worley","frequency":0.04,"feature":"f2-f1","seed":3,
        "transfer":{"type":"threshold","threshold":0.0,"width":0.5,"invert":false},
        "layers":[{"type":"perlin","frequency":0.03,"seed":5,"combine":"max"},
                  {"type":"white","seed":6,"combine":"min","weight":0.3}]}"#,
    r#"{"type":"perlin","frequency":0.02,"seed":7,"tile":true,
        "layers":[{"type":"gabor","frequency":0.08,"orientation":0.5,"bandwidth":0.05,"impulses":16,"seed":8,
                   "combine":"mask","mask":{"type":"perlin","frequency":0.01,"seed":9,
                   "transfer":{"type":"threshold","threshold":0.0,"width":0.2,"invert":true}}}]}"#,
];

#[test]
fn layer_stacks_cpu_match_wgsl() {
    use marbling_noise::Renderer;
    use marbling_noise::stack_gpu::NoiseStackGpu;
    let Some(gpu) = marbling_testkit::gpu_or_skip(GpuNoise::new()) else {
        return;
    };
    const N: u32 = 128;
    let level = |v: f32| (v * 255.0).round() as i32;
    let compare = |spec: &NoiseSpec, u: &NoiseStackGpu| {
        let cpu = Renderer::new(spec, N).expect("size");
        let (wgsl, _) = gpu.run_stack(u, N);
        let mut differing = 0;
        for (k, g) in wgsl.iter().enumerate() {
            let (i, j) = (k as u32 % N, k as u32 / N);
            let c = cpu.intensity(i as f32 + 0.5, j as f32 + 0.5);
            if (level(c) - level(*g)).abs() > 4 {
                differing += 1;
            }
        }
        f64::from(differing) / f64::from(N * N)
    };
    let mut report = String::new();
    for text in STACKS {
        let spec = NoiseSpec::from_json(text).expect("valid spec");
        let u = NoiseStackGpu::from_spec(&spec, N).expect("GPU form");
        let f = compare(&spec, &u);
        report.push_str(&format!("{:.3} % differ > 4/255\n", 100.0 * f));
        assert!(f <= 0.01, "{report}{text}");
    }
    println!("{report}");
    // The comparison can fail: another combine mode on the GPU side differs.
    let spec = NoiseSpec::from_json(STACKS[0]).expect("valid spec");
    let mut u = NoiseStackGpu::from_spec(&spec, N).expect("GPU form");
    u.layers[1].combine = marbling_noise::Combine::Max.index();
    assert!(
        compare(&spec, &u) > 0.05,
        "a changed stack passed the comparison"
    );
}
