//! Every WGSL module parses and validates with naga (no GPU needed), and the host
//! uniform structs match the WGSL struct layouts.

use marbling_noise::wgsl::{self, FbmGpu, FiberGridGpu, FibersGpu, GaborGpu, NoiseGpu};
use std::mem::{offset_of, size_of};

fn parse(name: &str) -> (naga::Module, String) {
    let src = wgsl::module(name).expect("known module");
    let module = match naga::front::wgsl::parse_str(&src) {
        Ok(m) => m,
        Err(e) => panic!("{name}.wgsl does not parse:\n{}", e.emit_to_string(&src)),
    };
    (module, src)
}

#[test]
fn every_module_parses_and_validates() {
    for (name, _) in wgsl::FILES {
        let (module, src) = parse(name);
        let mut v = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::default(),
        );
        if let Err(e) = v.validate(&module) {
            panic!("{name}.wgsl does not validate:\n{}", e.emit_to_string(&src));
        }
    }
}

/// (member name, offset) of the WGSL struct `name`, and its size.
fn wgsl_layout(module: &naga::Module, name: &str) -> (Vec<(String, u32)>, u32) {
    for (_, ty) in module.types.iter() {
        if ty.name.as_deref() == Some(name)
            && let naga::TypeInner::Struct { members, span } = &ty.inner
        {
            return (
                members
                    .iter()
                    .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                    .collect(),
                *span,
            );
        }
    }
    panic!("no struct {name}");
}

#[test]
fn host_structs_match_wgsl_layout() {
    let (module, _) = parse("noise");
    let check = |name: &str, size: usize, offsets: &[(&str, usize)]| {
        let (members, span) = wgsl_layout(&module, name);
        assert_eq!(span as usize, size, "{name} size");
        for (field, off) in offsets {
            let found = members
                .iter()
                .find(|(n, _)| n == field)
                .unwrap_or_else(|| panic!("{name}.{field} missing in WGSL"));
            assert_eq!(found.1 as usize, *off, "{name}.{field} offset");
        }
    };
    check(
        "FbmParams",
        size_of::<FbmGpu>(),
        &[
            ("frequency", offset_of!(FbmGpu, frequency)),
            ("octaves", offset_of!(FbmGpu, octaves)),
            ("period", offset_of!(FbmGpu, period)),
        ],
    );
    check(
        "GaborParams",
        size_of::<GaborGpu>(),
        &[
            ("drives", offset_of!(GaborGpu, drives)),
            ("inv_std", offset_of!(GaborGpu, inv_std)),
            ("poisson_parts", offset_of!(GaborGpu, poisson_parts)),
            ("frequency_amount", offset_of!(GaborGpu, frequency_amount)),
            ("reach_cells", offset_of!(GaborGpu, reach_cells)),
        ],
    );
    check(
        "FiberGrid",
        size_of::<FiberGridGpu>(),
        &[
            ("exp_neg_part", offset_of!(FiberGridGpu, exp_neg_part)),
            ("poisson_parts", offset_of!(FiberGridGpu, poisson_parts)),
        ],
    );
    check(
        "FiberParams",
        size_of::<FibersGpu>(),
        &[
            ("mean", offset_of!(FibersGpu, mean)),
            ("speck_strength", offset_of!(FibersGpu, speck_strength)),
        ],
    );
    check(
        "NoiseUniform",
        size_of::<NoiseGpu>(),
        &[
            ("period", offset_of!(NoiseGpu, period)),
            ("frequency", offset_of!(NoiseGpu, frequency)),
            ("fbm", offset_of!(NoiseGpu, fbm)),
            ("gabor", offset_of!(NoiseGpu, gabor)),
            (
                "gabor_orientation_drive",
                offset_of!(NoiseGpu, gabor_orientation_drive),
            ),
            (
                "gabor_frequency_drive",
                offset_of!(NoiseGpu, gabor_frequency_drive),
            ),
            ("fibers", offset_of!(NoiseGpu, fibers)),
            ("fiber_grid", offset_of!(NoiseGpu, fiber_grid)),
            ("speck_grid", offset_of!(NoiseGpu, speck_grid)),
        ],
    );
}
