//! Noise specs read from JSON: every problem reported with its path.

use marbling_noise::{GaborKind, NoiseSpec, Source, SpecError};

fn errors(text: &str) -> Vec<String> {
    match NoiseSpec::from_json(text) {
        Err(SpecError::Invalid(e)) => e.iter().map(ToString::to_string).collect(),
        other => panic!("expected errors, got {other:?}"),
    }
}

#[test]
fn parses_the_issue_gabor_spec() {
    let s = NoiseSpec::from_json(
        r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#,
    )
    .expect("valid");
    assert!(matches!(
        s.source,
        Source::Gabor {
            kind: GaborKind::Anisotropic,
            seed: 7,
            ..
        }
    ));
    assert!(!s.is_colored());
}

#[test]
fn path_named_errors() {
    assert_eq!(
        errors(r#"{"type":"gabor","frequency":-3,"bandwidth":0.05}"#),
        ["frequency: must be > 0, got -3"]
    );
    assert_eq!(
        errors(r#"{"type":"blob"}"#)[0],
        "type: unknown noise type 'blob'; expected one of gabor, perlin, value, worley, white, curl, paper, canvas, product"
    );
    let e = errors(r#"{"type":"perlin","frequency":0.1,"colour":"red"}"#);
    assert!(e[0].starts_with("colour: unknown field"), "{e:?}");
    let e = errors(
        r#"{"type":"product","inputs":[{"type":"gabor","frequency":0.1,"bandwidth":0.05},{"type":"gabor","frequency":0.1,"bandwidth":0,"kind":"diagonal"}]}"#,
    );
    assert_eq!(
        e,
        [
            "inputs[1].kind: must be one of anisotropic, isotropic, random-phase, got \"diagonal\"",
            "inputs[1].bandwidth: must be ≥ 0.002, got 0"
        ]
    );
    let e = errors(
        r#"{"type":"gabor","frequency":0.1,"bandwidth":0.05,"orientation_field":{"noise":{"type":"perlin"},"amount":1}}"#,
    );
    assert_eq!(e, ["orientation_field.noise.frequency: missing"]);
    let e = errors(r#"{"type":"white","palette":"rainbow","seed":-1}"#);
    assert_eq!(e.len(), 2, "{e:?}");
    assert!(matches!(
        NoiseSpec::from_json("{\"type\":"),
        Err(SpecError::Syntax { line: 1, .. })
    ));
}
