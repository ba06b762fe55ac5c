//! naga checks of WGSL, shared by the crates whose shaders the tests validate: a module
//! parses and validates, and a host struct mirrors a WGSL struct member for member.

/// Parses and validates `source` (the module `name`, for messages) with naga, with no
/// optional capabilities (what WebGL2 and every WebGPU adapter accept); panics with
/// naga's report, pointing into the source.
pub fn validate(name: &str, source: &str) -> naga::Module {
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

/// The members (name, byte offset) of WGSL struct `name` in `module`, and its size.
pub fn struct_layout(module: &naga::Module, name: &str) -> (Vec<(String, u32)>, u32) {
    for (_, ty) in module.types.iter() {
        if ty.name.as_deref() == Some(name)
            && let naga::TypeInner::Struct { members, span } = &ty.inner
        {
            let members = members
                .iter()
                .map(|m| (m.name.clone().unwrap_or_default(), m.offset))
                .collect();
            return (members, *span);
        }
    }
    panic!("no struct {name} in the module");
}

/// Asserts that the host struct described by `host` ((field, `offset_of!`) for every
/// field) and `host_size` (`size_of`) lays out as WGSL struct `name`: the same size and
/// every named member at the same offset, in order. Padding (names starting with `_`)
/// is left out on both sides, so it may be split differently; a member added on one
/// side only fails.
pub fn check_struct(module: &naga::Module, name: &str, host: &[(&str, usize)], host_size: usize) {
    let (members, size) = struct_layout(module, name);
    let wgsl: Vec<(String, u32)> = members
        .into_iter()
        .filter(|(n, _)| !n.starts_with('_'))
        .collect();
    let host: Vec<(String, u32)> = host
        .iter()
        .filter(|(n, _)| !n.starts_with('_'))
        .map(|&(n, o)| (n.to_owned(), o as u32))
        .collect();
    assert_eq!(wgsl, host, "{name}: members differ between WGSL and Rust");
    assert_eq!(size as usize, host_size, "{name}: sizes differ");
}

/// [`check_struct`] for a uniform block's struct, whose size must also be a multiple
/// of 16 bytes.
pub fn check_uniform(module: &naga::Module, name: &str, host: &[(&str, usize)], host_size: usize) {
    check_struct(module, name, host, host_size);
    assert_eq!(
        host_size % 16,
        0,
        "{name}: uniform size must be a multiple of 16"
    );
}

/// The GLSL ES 3.00 that WebGL2 compiles for entry point `entry` (of `stage`) of the
/// WGSL `source`, written by naga's WebGL2 writer as wgpu's GL backend uses it; an error
/// names the step that failed.
pub fn webgl2_glsl(source: &str, stage: naga::ShaderStage, entry: &str) -> Result<String, String> {
    use naga::back::glsl;
    let module = naga::front::wgsl::parse_str(source).map_err(|e| e.emit_to_string(source))?;
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .map_err(|e| e.emit_to_string(source))?;
    let options = glsl::Options {
        version: glsl::Version::Embedded {
            version: 300,
            is_webgl: true,
        },
        ..Default::default()
    };
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
    .map_err(|e| format!("{entry} → GLSL ES 3.00: {e}"))?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "struct P { a: f32, b: u32, _pad: vec2<u32>, c: vec4<f32> }
        @group(0) @binding(0) var<uniform> p: P;
        @compute @workgroup_size(1) fn main() { _ = p.a; }";

    #[test]
    fn a_matching_struct_passes() {
        let m = validate("test", SOURCE);
        check_uniform(&m, "P", &[("a", 0), ("b", 4), ("_pad0", 8), ("c", 16)], 32);
    }

    #[test]
    fn a_member_missing_on_the_host_side_fails() {
        let m = validate("test", SOURCE);
        let r = std::panic::catch_unwind(|| check_struct(&m, "P", &[("a", 0), ("b", 4)], 32));
        assert!(r.is_err(), "a WGSL member the host does not list passed");
        let r = std::panic::catch_unwind(|| {
            check_struct(&m, "P", &[("a", 0), ("b", 8), ("c", 16)], 32)
        });
        assert!(r.is_err(), "a wrong offset passed");
    }

    #[test]
    #[should_panic(expected = "does not validate")]
    fn an_invalid_module_is_refused() {
        validate("broken", "fn f() -> f32 { return 1u; }");
    }
}
