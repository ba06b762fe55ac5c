//! Every WGSL module parses and validates with naga: no GPU needed.

use marbling_gpu::shaders::all;

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
    for (name, source) in all() {
        let module = validate(name, &source);
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
    let source = &all()[0].1;
    assert!(source.contains("return Hit(b, false, p);"));
    let broken = source.replace("return Hit(b, false, p);", "return Hit(b.xyz, false, p);");
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

/// Each entry point translates to GLSL ES 3.00 for WebGL2 (what wgpu's GL backend does
/// in the browser), so nothing in the WGSL needs a feature WebGL2 lacks.
#[test]
fn every_entry_point_translates_to_webgl2_glsl() {
    use naga::back::glsl;
    for (name, source) in all() {
        let module = naga::front::wgsl::parse_str(&source).expect("parses");
        let info = naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::empty(),
        )
        .validate(&module)
        .expect("validates");
        let options = glsl::Options {
            version: glsl::Version::Embedded {
                version: 300,
                is_webgl: true,
            },
            ..Default::default()
        };
        for (stage, entry) in [
            (naga::ShaderStage::Vertex, "vs_main"),
            (naga::ShaderStage::Fragment, "fs_main"),
        ] {
            let pipeline = glsl::PipelineOptions {
                shader_stage: stage,
                entry_point: entry.to_owned(),
                multiview: None,
            };
            let mut out = String::new();
            glsl::Writer::new(
                &mut out,
                &module,
                &info,
                &options,
                &pipeline,
                naga::proc::BoundsCheckPolicies::default(),
            )
            .and_then(|mut w| w.write())
            .unwrap_or_else(|e| panic!("{name}.wgsl {entry} → GLSL ES 300: {e}"));
            assert!(out.starts_with("#version 300 es"), "{name} {entry}");
        }
    }
}
