//! Every WGSL module parses and validates with naga (no GPU needed), and the host
//! uniform structs match the WGSL struct layouts.

use marbling_noise::noise_gpu::{FbmGpu, FiberGridGpu, FibersGpu, GaborGpu, NoiseGpu};
use marbling_noise::stack_gpu::{NoiseStackGpu, StackLayerGpu, StackTransferGpu};
use marbling_noise::wgsl;
use std::mem::{offset_of, size_of};

/// The noise module `name`, parsed and validated (`marbling_testkit::wgsl`).
fn module(name: &str) -> naga::Module {
    let src = wgsl::module(name).expect("known module");
    marbling_testkit::wgsl::validate(name, &src)
}

#[test]
fn every_module_parses_and_validates() {
    for (name, _) in wgsl::FILES {
        module(name);
    }
}

/// (field, offset) of every field of a host struct, in order.
macro_rules! fields {
    ($t:ty: $($f:ident),* $(,)?) => {
        &[$((stringify!($f), offset_of!($t, $f))),*]
    };
}

#[test]
fn host_structs_match_wgsl_layout() {
    use marbling_testkit::wgsl::{check_struct, check_uniform};
    let m = module("noise");
    check_struct(
        &m,
        "FbmParams",
        fields!(FbmGpu: frequency, lacunarity, persistence, octaves, seed, basis, period),
        size_of::<FbmGpu>(),
    );
    check_struct(
        &m,
        "GaborParams",
        fields!(GaborGpu: kind, seed, period_cells, drives, frequency, orientation, cell,
            radius2, pi_a2, exp_neg_part, inv_std, orientation_amount, frequency_amount,
            poisson_parts, reach_cells, profile),
        size_of::<GaborGpu>(),
    );
    check_struct(
        &m,
        "FiberGrid",
        fields!(FiberGridGpu: cell, reach_cells, period_cells, exp_neg_part, poisson_parts),
        size_of::<FiberGridGpu>(),
    );
    check_struct(
        &m,
        "FiberParams",
        fields!(FibersGpu: fiber_layout, seed, has_impurities, length, width,
            horizontal_probability, mean, inv_std, speck_radius, speck_strength),
        size_of::<FibersGpu>(),
    );
    check_uniform(
        &m,
        "NoiseUniform",
        fields!(NoiseGpu: noise_type, seed, feature, metric, period, frequency, fbm, gabor,
            gabor_orientation_drive, gabor_frequency_drive, fibers, fiber_grid, speck_grid),
        size_of::<NoiseGpu>(),
    );
    let m = module("layers");
    check_struct(
        &m,
        "StackTransfer",
        fields!(StackTransferGpu: threshold, width, transfer),
        size_of::<StackTransferGpu>(),
    );
    check_struct(
        &m,
        "StackLayer",
        fields!(StackLayerGpu: combine, weight),
        size_of::<StackLayerGpu>(),
    );
    check_uniform(
        &m,
        "NoiseStack",
        fields!(NoiseStackGpu: layer_count, noises, transfers, layers),
        size_of::<NoiseStackGpu>(),
    );
}

#[test]
fn a_module_for_some_noise_types_draws_only_those() {
    use marbling_noise::wgsl::{NoiseKind, NoiseKinds, UniformAt, module_for};

    let kinds = NoiseKinds::NONE
        .with(NoiseKind::Gabor)
        .with(NoiseKind::Curl);
    assert_eq!(kinds.name(), "gabor+curl");
    let m = module_for("noise", kinds, UniformAt::Argument).expect("noise module");
    marbling_testkit::wgsl::validate("noise (gabor+curl)", &m);
    let switch = &m[m.find("fn sample_noise").expect("sample_noise")..];
    assert!(switch.contains("case 0u") && switch.contains("case 4u"));
    for other in ["case 1u", "case 2u", "case 3u", "case 5u", "case 6u"] {
        assert!(!switch.contains(other), "{other} in {switch}");
    }
    // Every type has its case in the full module, in `noise_type` order.
    let all = wgsl::module("noise").expect("noise module");
    let all = &all[all.find("fn sample_noise").expect("sample_noise")..];
    let at: Vec<usize> = NoiseKind::ALL
        .iter()
        .map(|k| all.find(&format!("case {}u", *k as u32)).expect("case"))
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]));
    assert_eq!(NoiseKinds::ALL.iter().count(), NoiseKind::ALL.len());
    assert_eq!(NoiseKind::of(5), Some(NoiseKind::Fibers));
    assert_eq!(NoiseKind::of(6), Some(NoiseKind::DrivenGabor));
    assert_eq!(NoiseKind::of(7), None);
}

/// The drives' fBm is compiled only into modules with a driven Gabor noise, and a
/// `sample_noise` reading an array element copies no uniform.
#[test]
fn only_a_driven_gabor_compiles_the_drives() {
    use marbling_noise::wgsl::{NoiseKind, NoiseKinds, UniformAt, module_for};

    let gabor = NoiseKinds::NONE.with(NoiseKind::Gabor);
    let driven = gabor.with(NoiseKind::DrivenGabor);
    let at = UniformAt::Element("surface.noises");
    let undriven = module_for("noise", gabor, at).expect("noise module");
    let with_drives = module_for("noise", driven, at).expect("noise module");
    let drive = "drive[d] = fbm(ip, fp);";
    assert!(!undriven.contains(drive) && with_drives.contains(drive));
    for m in [&undriven, &with_drives] {
        assert_eq!(m.matches("fn gabor_drive(").count(), 1);
    }
    // Validates once given the array it reads.
    let uniform = "struct Surface { noises: array<NoiseUniform, 3> }\n@group(0) @binding(0) var<uniform> surface: Surface;\n";
    for (name, m) in [("undriven", &undriven), ("driven", &with_drives)] {
        marbling_testkit::wgsl::validate(name, &format!("{m}{uniform}"));
    }
    let switch = &undriven[undriven.find("fn sample_noise").expect("sample_noise")..];
    assert!(switch.starts_with("fn sample_noise(p: vec2<f32>, i: u32) -> f32"));
    assert!(switch.contains("gabor(p, surface.noises[i].gabor,"));
    // A driven spec's uniform names its own type.
    let spec = |s: &str| marbling_noise::NoiseSpec::from_json(s).expect("spec");
    let drives = r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"orientation_field":{"noise":{"type":"perlin","frequency":0.008,"seed":9},"amount":1}}"#;
    let plain = r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05}"#;
    let noise_type = |s: &str| {
        marbling_noise::noise_gpu::NoiseGpu::from_spec(&spec(s), 256)
            .expect("wgsl form")
            .noise_type
    };
    assert_eq!(noise_type(drives), NoiseKind::DrivenGabor as u32);
    assert_eq!(noise_type(plain), NoiseKind::Gabor as u32);
}
