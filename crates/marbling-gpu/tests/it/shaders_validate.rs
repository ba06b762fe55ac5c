//! Every WGSL module parses and validates with naga: no GPU needed.

use marbling_gpu::shaders::{all, compute_modules};

use marbling_testkit::wgsl::validate;

/// The names of `module`'s entry points, in order.
fn entry_points(module: &naga::Module) -> Vec<&str> {
    module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect()
}

#[test]
fn every_shader_parses_and_validates() {
    for (name, source) in all() {
        let module = validate(&name, &source);
        let expected: &[&str] = if name.starts_with("preview") {
            &["vs_main", "fs_main", "fs_one_sample"]
        } else if name == "present" {
            &["vs_main", "fs_copy", "fs_decode"]
        } else if name.starts_with("view3d") {
            &["vs_main", "fs_main", "fs_view3d"]
        } else {
            &["vs_main", "fs_main"]
        };
        assert_eq!(entry_points(&module), expected, "{name}");
    }
    for (name, source) in compute_modules() {
        let module = validate(&name, &source);
        assert_eq!(
            entry_points(&module),
            ["vs_main", "fs_main", "cs_main"],
            "{name}"
        );
    }
}

#[test]
fn a_broken_shader_is_caught() {
    let source = &all()[0].1;
    assert!(source.contains("return Hit(e.ink, false, e.p);"));
    let broken = source.replace(
        "return Hit(e.ink, false, e.p);",
        "return Hit(e.ink.xyz, false, e.p);",
    );
    let caught = std::panic::catch_unwind(|| validate("broken", &broken)).is_err();
    assert!(caught, "a type error went unnoticed");
}

/// Each entry point translates to GLSL ES 3.00 for WebGL2 (what wgpu's GL backend does
/// in the browser), so nothing in the WGSL needs a feature WebGL2 lacks.
#[test]
fn every_entry_point_translates_to_webgl2_glsl() {
    for (name, source) in all() {
        let module = naga::front::wgsl::parse_str(&source).expect("parses");
        for entry in &module.entry_points {
            let (stage, entry) = (entry.stage, entry.name.as_str());
            let out = marbling_testkit::wgsl::webgl2_glsl(&source, stage, entry)
                .unwrap_or_else(|e| panic!("{name}.wgsl {entry}: {e}"));
            assert!(out.starts_with("#version 300 es"), "{name} {entry}");
            let missing = missing_from_glsl_es_300(&out);
            assert!(
                missing.is_empty(),
                "{name} {entry}: naga wrote {missing:?}, which GLSL ES 3.00 (WebGL2) lacks"
            );
        }
    }
}

/// Built-in functions naga may write that GLSL ES 3.00 does not have (they came in ES
/// 3.10): WebGL2 refuses the shader ("'findLSB' : no matching overloaded function").
fn missing_from_glsl_es_300(glsl: &str) -> Vec<&'static str> {
    [
        "findLSB(",
        "findMSB(",
        "bitCount(",
        "bitfieldExtract(",
        "bitfieldInsert(",
        "bitfieldReverse(",
    ]
    .into_iter()
    .filter(|f| glsl.contains(f))
    .collect()
}

#[test]
fn functions_webgl2_lacks_are_seen() {
    assert_eq!(
        missing_from_glsl_es_300("uint k = uint(findLSB(x)); int n = bitCount(y);"),
        ["findLSB(", "bitCount("]
    );
    assert!(missing_from_glsl_es_300("uint k = x >> 3u;").is_empty());
}

/// Decimal float literals in the code of `source` (digits with a `.` and/or an exponent;
/// `//` comments skipped), as written.
fn float_literals(source: &str) -> Vec<String> {
    let code: String = source
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let source = code.as_str();
    let mut out = Vec::new();
    let bytes = source.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if !starts {
            i += 1;
            continue;
        }
        let start = i;
        while i < bytes.len()
            && (bytes[i].is_ascii_alphanumeric()
                || bytes[i] == b'.'
                || ((bytes[i] == b'-' || bytes[i] == b'+') && matches!(bytes[i - 1], b'e' | b'E')))
        {
            i += 1;
        }
        let token = &source[start..i];
        let is_float = !token.starts_with("0x")
            && (token.contains('.') || token.contains('e') || token.contains('E'));
        if is_float {
            out.push(token.trim_end_matches(['f', 'h']).to_owned());
        }
    }
    out
}

/// Chrome's WGSL compiler (Tint) rejects a literal above f32::MAX ("cannot be represented
/// as 'f32'") even where naga rounds it to f32::MAX, so no shader may contain one.
#[test]
fn float_literals_are_representable_as_f32() {
    for (name, source) in all() {
        for literal in float_literals(&source) {
            let value: f64 = literal
                .parse()
                .unwrap_or_else(|e| panic!("{name}: literal {literal}: {e}"));
            assert!(
                value.abs() <= f64::from(f32::MAX),
                "{name}: literal {literal} is beyond f32::MAX; Tint refuses it"
            );
        }
    }
}

#[test]
fn float_literal_scan_finds_what_tint_would_refuse() {
    let found = float_literals(
        "var a = 3.4028235e38; // 9.9e99 in a comment\nlet b = 1.5e-3 + x2.0; let c = 0x1p4; 2u",
    );
    assert_eq!(found, ["3.4028235e38", "1.5e-3"]);
    assert!("3.4028235e38".parse::<f64>().expect("a float") > f64::from(f32::MAX));
}

/// The shaders' `KIND_…` constants are the codes of [`marbling_core::OpKind`] (the one
/// list the GPU records are made from), and there is no other.
#[test]
fn the_shaders_op_kinds_are_the_op_kind_codes() {
    let source = marbling_gpu::shaders::COMMON;
    let module = naga::front::wgsl::parse_str(source).expect("common.wgsl parses");
    let mut found = Vec::new();
    for (_, c) in module.constants.iter() {
        let Some(name) = c.name.as_deref().filter(|n| n.starts_with("KIND_")) else {
            continue;
        };
        let naga::Expression::Literal(naga::Literal::U32(value)) =
            module.global_expressions[c.init]
        else {
            panic!("{name} is not a u32 literal");
        };
        found.push((name.to_owned(), value));
    }
    let expected: Vec<(String, u32)> = marbling_core::OpKind::ALL
        .iter()
        .map(|k| (k.wgsl_name().to_owned(), k.code()))
        .collect();
    assert_eq!(found, expected);
}

/// The per-op test's compute entry point (tests/op_back.wgsl, appended to common.wgsl)
/// validates too, so a broken test shader is caught without a GPU.
#[test]
fn the_op_back_test_shader_validates() {
    let source = [
        marbling_gpu::shaders::walk_wgsl().as_str(),
        include_str!("op_back.wgsl"),
    ]
    .join("\n");
    let module = validate("op_back", &source);
    assert_eq!(entry_points(&module), ["cs_op_back"]);
}
