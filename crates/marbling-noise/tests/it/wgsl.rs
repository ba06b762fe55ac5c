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
    use marbling_noise::wgsl::{NoiseKind, NoiseKinds, module_for};

    let kinds = NoiseKinds::NONE
        .with(NoiseKind::Gabor)
        .with(NoiseKind::Curl);
    assert_eq!(kinds.name(), "gabor+curl");
    let m = module_for("noise", kinds).expect("noise module");
    marbling_testkit::wgsl::validate("noise (gabor+curl)", &m);
    let switch = &m[m.find("fn sample_noise").expect("sample_noise")..];
    assert!(switch.contains("case 0u") && switch.contains("case 4u"));
    for other in ["case 1u", "case 2u", "case 3u", "case 5u"] {
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
    assert_eq!(NoiseKind::of(6), None);
}
