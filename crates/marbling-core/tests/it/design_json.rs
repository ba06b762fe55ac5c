//! Design documents: the exact v1 shape, round trips, and one test per validation rule,
//! each checking the message names the JSON path.

use crate::common::{assert_error, errors};
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Design, DesignError, Drop, Op, Point, Rgb8, Tine, Vec2};

const DESIGN_MD_EXAMPLE: &str = r##"{ "version": 1, "width": 800, "height": 600, "background": "#f3ead7",
  "ops": [
    {"type":"drop",     "center":[400,300], "radius":60, "color":"#1d3557"},
    {"type":"spray",    "center":[120,80],  "radius":3,  "color":"#e63946"},
    {"type":"tine",     "origin":[0,300], "direction":[1,0], "alpha":80, "lambda":8},
    {"type":"rake",     "origin":[0,0],   "direction":[0,1], "spacing":40, "alpha":60, "lambda":6},
    {"type":"wavy",     "angle":0.0, "amplitude":12, "wavelength":120, "phase":0.0},
    {"type":"circular", "center":[400,300], "radius":150, "alpha":60, "lambda":12},
    {"type":"vortex",   "center":[400,300], "alpha":90, "lambda":20}
  ] }"##;

/// Replaces `from` (which must occur) in the example above: the README's schema v1
/// example, one op of each of the seven v1 types.
fn variant(from: &str, to: &str) -> String {
    assert!(DESIGN_MD_EXAMPLE.contains(from), "{from} not in example");
    DESIGN_MD_EXAMPLE.replacen(from, to, 1)
}

#[test]
fn design_md_example_parses_with_every_op_type() {
    let d = Design::from_json(DESIGN_MD_EXAMPLE).expect("valid");
    assert_eq!(
        (d.width, d.height, d.background),
        (800, 600, Rgb8::new(0xf3, 0xea, 0xd7))
    );
    let types: Vec<_> = d.ops.iter().map(Op::type_name).collect();
    assert_eq!(types, marbling_core::OP_TYPES[..7]);
    assert_eq!(
        d.ops[0],
        Op::Drop(Drop {
            center: Point::new(400.0, 300.0),
            radius: 60.0,
            color: Rgb8::new(0x1d, 0x35, 0x57)
        })
    );
    assert_eq!(
        d.ops[2],
        Op::Tine(Tine {
            origin: Point::new(0.0, 300.0),
            direction: Vec2::new(1.0, 0.0),
            alpha: 80.0,
            lambda: 8.0
        })
    );
}

#[test]
fn written_documents_have_the_v1_shape() {
    let d = Design::from_json(DESIGN_MD_EXAMPLE).expect("valid");
    let v: serde_json::Value = serde_json::from_str(&d.to_json_pretty()).expect("json");
    let original: serde_json::Value = serde_json::from_str(DESIGN_MD_EXAMPLE).expect("json");
    // Numerically equal field by field (the writer prints integral numbers as integers).
    assert_eq!(v["version"], 1);
    assert_eq!(v["background"], "#f3ead7");
    for (a, b) in v["ops"]
        .as_array()
        .expect("ops")
        .iter()
        .zip(original["ops"].as_array().expect("ops"))
    {
        let (a, b) = (a.as_object().expect("op"), b.as_object().expect("op"));
        assert_eq!(a.keys().collect::<Vec<_>>().len(), b.len());
        for (k, bv) in b {
            let av = &a[k];
            match (av.as_f64(), bv.as_f64()) {
                (Some(x), Some(y)) => assert_eq!(x, y, "{k}"),
                _ => assert_eq!(av.to_string(), bv.to_string(), "{k}"),
            }
        }
    }
    assert_eq!(d.to_json_compact(), d.to_value().to_string());
}

#[test]
fn parse_write_parse_round_trips_random_designs() {
    for seed in 0..50 {
        let d = random_design(seed, 640, 480, 200, Mix::Mixed);
        for text in [d.to_json_pretty(), d.to_json_compact()] {
            let back = Design::from_json(&text).expect("own output parses");
            let first = back.ops.iter().zip(&d.ops).position(|(a, b)| a != b);
            assert_eq!(
                first,
                None,
                "seed {seed}: {:?}",
                first.map(|i| (back.ops[i].clone(), d.ops[i].clone()))
            );
            assert_eq!(back, d, "seed {seed}");
        }
    }
}

#[test]
fn empty_design_round_trips() {
    let d = Design::new(1, 16384, Rgb8::new(0, 0, 0));
    assert_eq!(Design::from_json(&d.to_json_pretty()).expect("valid"), d);
}

#[test]
fn syntax_errors_give_line_and_column() {
    let err =
        Design::from_json("{\n  \"version\": 1,\n  \"width\": 80 80\n}").expect_err("bad json");
    match err {
        DesignError::Syntax {
            line,
            column,
            ref message,
        } => {
            assert_eq!((line, column), (3, 15), "{message}");
            assert!(err.to_string().starts_with("line 3, column 15: "), "{err}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn huge_numbers_are_refused_by_the_parser() {
    let err =
        Design::from_json(&variant("\"radius\":60", "\"radius\":1e999")).expect_err("overflow");
    assert!(matches!(err, DesignError::Syntax { .. }), "{err:?}");
}

#[test]
fn radius_must_be_positive() {
    assert_error(
        &variant("\"radius\":60", "\"radius\":-3"),
        "ops[0].radius: must be > 0, got -3",
    );
    assert_error(
        &variant("\"radius\":3,", "\"radius\":0,"),
        "ops[1].radius: must be > 0, got 0",
    );
    assert_error(
        &variant("\"radius\":150", "\"radius\":-1.5"),
        "ops[5].radius: must be > 0, got -1.5",
    );
}

#[test]
fn lambda_must_be_positive() {
    assert_error(
        &variant("\"lambda\":8", "\"lambda\":0"),
        "ops[2].lambda: must be > 0, got 0",
    );
    assert_error(
        &variant("\"lambda\":20", "\"lambda\":-20"),
        "ops[6].lambda: must be > 0, got -20",
    );
}

#[test]
fn spacing_must_be_positive() {
    assert_error(
        &variant("\"spacing\":40", "\"spacing\":0"),
        "ops[3].spacing: must be > 0, got 0",
    );
}

#[test]
fn wavelength_must_be_positive() {
    assert_error(
        &variant("\"wavelength\":120", "\"wavelength\":-120"),
        "ops[4].wavelength: must be > 0, got -120",
    );
}

#[test]
fn direction_must_be_non_zero() {
    assert_error(
        &variant("\"direction\":[1,0]", "\"direction\":[0,0]"),
        "ops[2].direction: must be non-zero, got [0, 0]",
    );
}

#[test]
fn numbers_must_be_finite() {
    // JSON cannot spell NaN or infinity; designs built in code can, and validate() says where.
    let mut d = Design::from_json(DESIGN_MD_EXAMPLE).expect("valid");
    if let Op::Drop(drop) = &mut d.ops[0] {
        drop.center.y = f64::NAN;
        drop.radius = f64::INFINITY;
    }
    let errs: Vec<String> = d
        .validate()
        .expect_err("invalid")
        .0
        .iter()
        .map(ToString::to_string)
        .collect();
    assert_eq!(
        errs,
        [
            "ops[0].center[1]: must be a finite number, got NaN",
            "ops[0].radius: must be a finite number, got inf"
        ]
    );
}

#[test]
fn width_and_height_are_bounded_integers() {
    assert_error(
        &variant("\"width\": 800", "\"width\": 0"),
        "width: must be in 1..=16384, got 0",
    );
    assert_error(
        &variant("\"height\": 600", "\"height\": 16385"),
        "height: must be in 1..=16384, got 16385",
    );
    assert_error(
        &variant("\"width\": 800", "\"width\": 800.5"),
        "width: must be an integer in 1..=16384, got 800.5",
    );
    assert_error(
        &variant("\"width\": 800", "\"width\": -2"),
        "width: must be an integer in 1..=16384, got -2",
    );
}

#[test]
fn op_count_is_bounded() {
    let op = r##"{"type":"spray","center":[1,1],"radius":1,"color":"#000000"}"##;
    let ops = vec![op; 100_001].join(",");
    let text =
        format!(r##"{{"version":1,"width":10,"height":10,"background":"#ffffff","ops":[{ops}]}}"##);
    assert_eq!(
        errors(&text),
        ["ops: at most 100000 ops are allowed (each drop of a pattern counts), got 100001"]
    );
}

#[test]
fn colours_must_be_hex() {
    assert_error(
        &variant("\"color\":\"#1d3557\"", "\"color\":\"navy\""),
        "ops[0].color: must be a colour \"#rrggbb\", got \"navy\"",
    );
    assert_error(
        &variant("\"background\": \"#f3ead7\"", "\"background\": \"#f3ead\""),
        "background: must be a colour \"#rrggbb\", got \"#f3ead\"",
    );
    assert_error(
        &variant("\"color\":\"#e63946\"", "\"color\":16777215"),
        "ops[1].color: must be a colour \"#rrggbb\", got 16777215",
    );
}

#[test]
fn unknown_fields_are_rejected() {
    assert_error(
        &variant("\"radius\":60,", "\"radius\":60, \"colour\":\"#000000\","),
        "ops[0].colour: unknown field; expected one of type, center, radius, color",
    );
    assert_error(
        &variant("\"version\": 1,", "\"version\": 1, \"title\": \"x\","),
        "title: unknown field; expected one of version, width, height, background, ops, gestures, recipe",
    );
}

#[test]
fn unknown_op_types_are_rejected() {
    assert_error(
        &variant("\"type\":\"vortex\"", "\"type\":\"whirl\""),
        "ops[6].type: unknown op type \"whirl\"; expected one of drop, spray, tine, rake, wavy, circular, vortex, shift, turn, comb, drops, sprays, jiggle, stylus, flow",
    );
}

#[test]
fn unsupported_versions_name_the_supported_ones() {
    assert_eq!(
        errors(&variant("\"version\": 1", "\"version\": 7")),
        ["version: unsupported version 7; this build reads version 1, 2, 3, 4"]
    );
}

#[test]
fn missing_fields_and_wrong_types_are_named() {
    assert_error(&variant("\"radius\":60, ", ""), "ops[0].radius: missing");
    assert_error(
        &variant("\"alpha\":80", "\"alpha\":\"80\""),
        "ops[2].alpha: must be a number, got a string",
    );
    assert_error(
        &variant("\"center\":[400,300]", "\"center\":[400]"),
        "ops[0].center: must be an array [x, y] of two numbers, got [400]",
    );
    assert_error(
        &variant("\"origin\":[0,300]", "\"origin\":[0,null]"),
        "ops[2].origin[1]: must be a number, got null",
    );
    // A problem with the document itself has no path to name.
    assert_eq!(
        errors("[1, 2]"),
        ["must be an object, got an array".to_owned()]
    );
}

#[test]
fn every_error_is_reported_at_once() {
    let text =
        variant("\"radius\":60", "\"radius\":-3").replacen("\"lambda\":8", "\"lambda\":0", 1);
    let errs = errors(&text.replacen("\"spacing\":40", "\"spacing\":-1", 1));
    assert_eq!(
        errs,
        [
            "ops[0].radius: must be > 0, got -3",
            "ops[2].lambda: must be > 0, got 0",
            "ops[3].spacing: must be > 0, got -1"
        ]
    );
}

/// `gestures` ([[first, count], …]): each rule has its message and JSON path.
#[test]
fn gesture_spans_are_read_written_and_checked() {
    let with =
        |g: &str| DESIGN_MD_EXAMPLE.replacen("\n  ] }", &format!("\n  ], \"gestures\": {g} }}"), 1);
    assert!(DESIGN_MD_EXAMPLE.contains("\n  ] }"));
    let d = Design::from_json(&with("[[0, 2], [3, 4]]")).expect("valid");
    assert_eq!(d.gesture_sizes(), vec![2, 1, 4]);
    let back = Design::from_json(&d.to_json_pretty()).expect("valid");
    assert_eq!(back, d);
    assert!(
        d.to_json_compact()
            .ends_with(r#""gestures":[[0,2],[3,4]]}"#)
    );
    // Without gestures nothing is written: documents made op by op are unchanged.
    let plain = Design::from_json(DESIGN_MD_EXAMPLE).expect("valid");
    assert!(!plain.to_json_pretty().contains("gestures"));
    assert_error(
        &with("[[0, 1]]"),
        "gestures[0]: a gesture has at least 2 ops, got 1 (a lone op needs no entry)",
    );
    assert_error(
        &with("[[6, 2]]"),
        "gestures[0]: ops 6..8 lie past the last op (7 ops)",
    );
    assert_error(
        &with("[[0, 3], [2, 2]]"),
        "gestures[1]: starts at op 2 inside gestures[0], which ends at op 3; gestures are sorted and disjoint",
    );
    assert_error(
        &with("[[0, -2]]"),
        "gestures[0]: must be [first, count], two whole numbers, got [0,-2]",
    );
    assert_error(
        &with("{}"),
        "gestures: must be an array of [first, count] pairs, got an object",
    );
    // Designs built in code are checked the same way.
    let mut bad = plain.clone();
    bad.gestures = vec![marbling_core::GestureSpan { first: 5, count: 9 }];
    assert!(
        bad.validate()
            .expect_err("an error")
            .to_string()
            .contains("gestures[0]: ops 5..14")
    );
}

/// Rounding ops as the app does at commit (`Op::rounded`) keeps the picture and makes
/// links much shorter: the stone example's link shrinks to less than half.
#[test]
fn rounded_ops_make_short_links() {
    let stone = Design::from_json(include_str!("../../../../examples/designs/stone.json"))
        .expect("valid example");
    let mut rounded = stone.clone();
    rounded.ops = stone.ops.iter().map(Op::rounded).collect();
    let (full, short) = (
        marbling_core::share_fragment(&stone).len(),
        marbling_core::share_fragment(&rounded).len(),
    );
    println!(
        "stone, {} ops: link {full} → {short} characters rounded ({:.1} per op)",
        stone.ops.len(),
        short as f64 / stone.ops.len() as f64
    );
    assert!(short * 2 < full, "{full} → {short}");
    // The link holds exactly the rounded design.
    assert_eq!(
        marbling_core::decode_share(&marbling_core::share_fragment(&rounded)).expect("a value"),
        rounded
    );
}

#[test]
fn a_recipe_round_trips_and_its_errors_name_the_field() {
    let text = r##"{"version": 1, "width": 100, "height": 80, "background": "#ffffff",
        "ops": [
          {"type":"drop","center":[50,40],"radius":10,"color":"#112233"},
          {"type":"drop","center":[20,40],"radius":10,"color":"#112233"},
          {"type":"tine","origin":[0,40],"direction":[1,0],"alpha":20,"lambda":4}],
        "gestures": [[0, 2]],
        "recipe": {"name": "Test", "history": "Made here.", "captions": ["two drops"]}}"##;
    let d = Design::from_json(text).expect("valid");
    let r = d.recipe.clone().expect("recipe");
    assert_eq!((r.name.as_str(), r.captions.len()), ("Test", 1));
    assert_eq!(d.version(), 1, "a recipe needs no new schema version");
    assert_eq!(Design::from_json(&d.to_json_pretty()).expect("pretty"), d);
    assert_eq!(Design::from_json(&d.to_json_compact()).expect("compact"), d);
    // The second step has no caption of its own: it is described from its numbers.
    assert_eq!(
        d.step_captions(),
        vec![
            "two drops".to_string(),
            "a tine drawn left to right through (0, 40): shift 20 px, decay 4 px".into()
        ]
    );
    // Undo past the captioned step: the writer keeps only captions of existing steps.
    let mut short = d.clone();
    short.truncate_ops(0);
    let back = Design::from_json(&short.to_json_pretty()).expect("still valid");
    assert_eq!(back.recipe.expect("kept").captions, Vec::<String>::new());

    for (bad, message) in [
        (
            text.replace(
                r#""captions": ["two drops"]"#,
                r#""captions": ["a", "b", "c"]"#,
            ),
            "recipe.captions: at most one caption per step: 3 captions for 2 steps",
        ),
        (
            text.replace(r#""name": "Test""#, r#""name": """#),
            "recipe.name: must be 1 to 80 characters long, got 0",
        ),
        (
            text.replace(r#""captions": ["two drops"]"#, r#""captions": [7]"#),
            "recipe.captions[0]: must be a string, got a number",
        ),
        (
            text.replace(r#""history""#, r#""story""#),
            "recipe.story: unknown field; expected one of name, history, captions",
        ),
    ] {
        let err = Design::from_json(&bad).expect_err("refused").to_string();
        assert!(err.contains(message), "{err}\nexpected: {message}");
    }
}
