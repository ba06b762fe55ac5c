//! Every WGSL module parses and validates with naga: no GPU needed.

use marbling_gpu::shaders::ALL;

fn validate(name: &str, source: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{name}.wgsl does not parse:\n{}", e.emit_to_string(source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| {
        panic!(
            "{name}.wgsl does not validate:\n{}",
            e.emit_to_string(source)
        )
    });
    module
}

#[test]
fn every_shader_parses_and_validates() {
    for (name, source) in ALL {
        let module = validate(name, source);
        let entries: Vec<&str> = module
            .entry_points
            .iter()
            .map(|e| e.name.as_str())
            .collect();
        assert_eq!(entries, ["vs_main", "fs_main"], "{name}");
    }
}

#[test]
fn a_broken_shader_is_caught() {
    let broken = ALL[0].1.replace("return b;", "return b.xyz;");
    let parsed = naga::front::wgsl::parse_str(&broken);
    let valid = parsed.as_ref().ok().map(|m| {
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(m)
        .is_ok()
    });
    assert_ne!(valid, Some(true), "a type error went unnoticed");
}
