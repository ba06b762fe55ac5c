//! Noise specs read from JSON: every problem reported with its path.

use marbling_noise::GaborSpec;
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
        Source::Gabor(GaborSpec {
            kind: GaborKind::Anisotropic,
            seed: 7,
            ..
        })
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
        "type: unknown noise type 'blob'; expected one of gabor, phasor, perlin, value, worley, white, curl, paper, canvas, product"
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

#[test]
fn layers_tiles_curves_and_data_name_their_problems() {
    let p = r#"{"type":"perlin","frequency":0.1,"#;
    assert_eq!(
        errors(&format!(r#"{p}"layers":[{{"type":"white"}}]}}"#)),
        ["layers[0].combine: missing; expected one of add, multiply, max, min, mask"]
    );
    assert_eq!(
        errors(&format!(
            r#"{p}"layers":[{{"type":"white","combine":"mask"}}]}}"#
        )),
        [r#"layers[0].mask: missing: combine "mask" needs a mask noise"#]
    );
    assert_eq!(
        errors(&format!(
            r#"{p}"layers":[{{"type":"white","combine":"max","weight":2}}]}}"#
        )),
        ["layers[0].weight: must be ≤ 1, got 2"]
    );
    assert!(
        errors(&format!(r#"{p}"layers":[]}}"#))[0]
            .starts_with("layers: must be an array of 1 to 4 layers")
    );
    assert_eq!(
        errors(&format!(r#"{p}"tile":0}}"#)),
        ["tile: must be true, false or a period in pixels (1 to 16384), got 0"]
    );
    assert_eq!(
        errors(&format!(
            r#"{p}"transfer":{{"type":"curve","points":[[0,0],[0.5,0.2],[0.4,1]]}}}}"#
        )),
        ["transfer.points[2]: x must be greater than the previous point's"]
    );
    assert_eq!(
        errors(
            r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"weather","channel":4,"amount":1}}"#
        ),
        ["frequency_field.channel: must be ≤ 3, got 4"]
    );
    let s = NoiseSpec::from_json(&format!(r#"{p}"tile":64}}"#)).expect("valid");
    assert_eq!(s.tile, marbling_noise::Tile::Period(64));
}
