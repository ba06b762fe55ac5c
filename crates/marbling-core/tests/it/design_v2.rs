//! Schema v2: noise backgrounds and grain overlays. v1 documents load and write back
//! unchanged, v2 documents round-trip exactly, errors name their path, and the CPU
//! renderer marbles the noise background, moves pigment grain with the ink and keeps
//! paper grain fixed.

use crate::common::{assert_error, errors};
use marbling_core::{
    Antialias, Design, GrainKind, NoiseBackground, NoiseLayer, Overlay, Palette, RenderOptions,
    Rgb8, Traced, Walker, render,
};

const V2: &str = r##"{"version":2,"width":96,"height":64,
  "background":{"noise":{"type":"perlin","frequency":0.04,"octaves":4,"seed":4},"palette":"marble"},
  "overlays":[
    {"type":"paper-grain","noise":{"type":"paper","length":12,"width":1.5,"density":0.3,"seed":2},"strength":0.2},
    {"type":"pigment-grain","noise":{"type":"worley","frequency":0.08,"seed":1},"strength":0.35}],
  "ops":[
    {"type":"drop","center":[48,32],"radius":14,"color":"#1d3557"},
    {"type":"tine","origin":[0,32],"direction":[1,0],"alpha":20,"lambda":6}]}"##;

#[test]
fn v1_documents_load_and_write_back_as_v1() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/designs");
    let mut seen = 0;
    for entry in std::fs::read_dir(dir).expect("examples/designs") {
        let path = entry.expect("entry").path();
        let text = std::fs::read_to_string(&path).expect("read");
        let d = Design::from_json(&text).expect("valid example");
        if text.contains("\"version\": 1") || text.contains("\"version\":1") {
            seen += 1;
            assert_eq!(d.version(), 1, "{path:?}");
            assert!(!d.uses_v2() && d.background_noise.is_none() && d.overlays.is_empty());
            let written = d.to_json_pretty();
            assert!(written.contains("\"version\": 1"), "{written}");
            assert!(!written.contains("overlays"));
            assert_eq!(Design::from_json(&written).expect("reparse"), d);
        }
    }
    assert!(seen >= 5, "only {seen} v1 examples");
    // A v1 document is written back byte for byte in compact form (share links).
    let v1 = r##"{"version":1,"width":10,"height":8,"background":"#102030","ops":[{"type":"drop","center":[5,4],"radius":2.5,"color":"#ffffff"}]}"##;
    let d = Design::from_json(v1).expect("v1");
    assert_eq!(d.to_json_compact(), v1);
}

#[test]
fn v2_round_trips_exactly() {
    let d = Design::from_json(V2).expect("valid v2");
    assert_eq!(d.version(), 2);
    let bg = d.background_noise.as_ref().expect("noise background");
    assert_eq!(bg.noise.type_name(), "perlin");
    assert_eq!(bg.palette.name.as_deref(), Some("marble"));
    assert_eq!(d.background, bg.mid_color());
    assert_eq!(
        d.overlays.iter().map(|o| o.kind).collect::<Vec<_>>(),
        [GrainKind::Paper, GrainKind::Pigment]
    );
    for text in [d.to_json_pretty(), d.to_json_compact()] {
        let again = Design::from_json(&text).expect("reparse");
        assert_eq!(again, d);
        assert_eq!(again.to_json_pretty(), d.to_json_pretty());
    }
    // Palette arrays and a plain colour background with overlays stay v2.
    let text = V2.replace(
        r#""palette":"marble""#,
        r##""palette":["#000000","#808080","#ffffff"]"##,
    );
    let d = Design::from_json(&text).expect("stops");
    let p = &d.background_noise.as_ref().expect("noise").palette;
    assert_eq!(p.name, None);
    assert_eq!(p.stops[1], Rgb8::new(128, 128, 128));
    assert_eq!(Design::from_json(&d.to_json_compact()).expect("reparse"), d);
    let mut plain = Design::from_json(V2).expect("v2");
    plain.set_background_noise(None);
    assert_eq!(plain.version(), 2, "overlays alone need v2");
    plain.overlays.clear();
    assert_eq!(plain.version(), 1);
    assert!(plain.to_json_compact().starts_with(r#"{"version":1,"#));
}

#[test]
fn built_in_code_like_the_app_will() {
    let noise = NoiseLayer::from_json(r#"{"type":"gabor","frequency":0.06,"bandwidth":0.05}"#)
        .expect("gabor");
    let mut d = Design::new(64, 48, Rgb8::new(255, 255, 255));
    d.set_background_noise(Some(NoiseBackground::new(
        noise.clone(),
        Palette::named("ocean").expect("ocean"),
    )));
    d.overlays.push(Overlay::pigment_grain(noise, 0.5));
    assert!(d.validate().is_ok());
    let back = Design::from_json(&d.to_json_pretty()).expect("reparse");
    assert_eq!(back, d);
    d.overlays[0].strength = 1.5;
    let e = d.validate().expect_err("strength");
    assert_eq!(
        e.to_string(),
        "overlays[0].strength: must be in [0, 1], got 1.5"
    );
    assert!(Palette::named("rainbow").is_err());
    assert!(Palette::from_stops(vec![Rgb8::new(0, 0, 0)]).is_err());
}

#[test]
fn errors_name_their_path() {
    assert_error(
        &V2.replace(r#""frequency":0.04"#, r#""frequency":-1"#),
        "background.noise.frequency: must be > 0, got -1",
    );
    assert_error(
        &V2.replace(r#""strength":0.35"#, r#""strength":2"#),
        "overlays[1].strength: must be in [0, 1], got 2",
    );
    assert_error(
        &V2.replace("pigment-grain", "glitter"),
        "overlays[1].type: unknown overlay type \"glitter\"; expected one of paper-grain, pigment-grain",
    );
    assert_error(
        &V2.replace(r#""palette":"marble""#, r#""palette":"rainbow""#),
        "background.palette: unknown palette \"rainbow\"; expected one of grey, ink, sepia, ocean, ember, marble, viridis or an array of \"#rrggbb\"",
    );
    assert_error(
        &V2.replace(r#""palette":"marble""#, r##""palette":["#000000","red"]"##),
        "background.palette[1]: must be a colour \"#rrggbb\", got \"red\"",
    );
    assert_error(
        &V2.replace(r#""seed":4}"#, r#""seed":4,"tile":true}"#),
        "background.noise.tile: not allowed in a design (a design does not repeat)",
    );
    assert_error(
        &V2.replace(r#""seed":4}"#, r#""seed":4,"palette":"ocean"}"#),
        "background.noise.palette: not allowed inside the noise; put the palette beside \"noise\"",
    );
    assert_error(
        &V2.replace(r#""seed":2}"#, r#""seed":2,"density":-3}"#),
        "overlays[0].noise.density: must be > 0, got -3",
    );
    assert_error(
        &V2.replace(r#""version":2"#, r#""version":1"#),
        "background: a noise or image background needs \"version\": 2; version 1 takes a colour \"#rrggbb\"",
    );
    let v1_overlays =
        r##"{"version":1,"width":4,"height":4,"background":"#ffffff","overlays":[],"ops":[]}"##;
    assert!(
        errors(v1_overlays)[0].starts_with("overlays: unknown field"),
        "{:?}",
        errors(v1_overlays)
    );
    assert_error(
        &V2.replace(
            r#"{"type":"perlin","frequency":0.04,"octaves":4,"seed":4}"#,
            r#"{"type":"product","inputs":[{"type":"perlin","frequency":0.1},{"type":"white"}]}"#,
        ),
        "background.noise.type: a product is not allowed in a design",
    );
    let twice = V2.replace(
        r#"{"type":"pigment-grain""#,
        r#"{"type":"paper-grain","noise":{"type":"white"},"strength":0.1},{"type":"pigment-grain""#,
    );
    assert_error(
        &twice,
        "overlays[1].type: at most one paper-grain overlay is allowed",
    );
    // Several problems at once, each with its own path.
    let e = errors(
        &V2.replace(r#""frequency":0.04"#, r#""frequency":0"#)
            .replace(r#""strength":0.2"#, r#""strength":-1"#),
    );
    assert_eq!(e.len(), 2, "{e:?}");
}

fn opts() -> RenderOptions {
    RenderOptions {
        scale: 1.0,
        antialias: Antialias::None,
    }
}

fn pixel_rgb(img: &marbling_core::RgbaImage, x: u32, y: u32) -> [u8; 3] {
    let p = img.pixel(x, y);
    [p[0], p[1], p[2]]
}

/// A white design of 96×64 with one strong tine and the given overlays/background.
fn combed(overlays: &str, background: &str, tine: bool) -> Design {
    let ops = if tine {
        r#"{"type":"tine","origin":[0,32],"direction":[1,0],"alpha":30,"lambda":10}"#
    } else {
        ""
    };
    Design::from_json(&format!(
        r#"{{"version":2,"width":96,"height":64,"background":{background},"overlays":[{overlays}],"ops":[{ops}]}}"#
    ))
    .expect("test design")
}

const GRAIN: &str = r#"{"type":"perlin","frequency":0.08,"octaves":2,"seed":9}"#;

#[test]
fn pigment_grain_flows_with_the_ink_and_paper_grain_stays() {
    let white = r##""#ffffff""##;
    let pigment = format!(r#"{{"type":"pigment-grain","noise":{GRAIN},"strength":1}}"#);
    let paper = format!(r#"{{"type":"paper-grain","noise":{GRAIN},"strength":1}}"#);
    let flat_pigment = render(&combed(&pigment, white, false), &opts()).expect("render");
    let moved_pigment = render(&combed(&pigment, white, true), &opts()).expect("render");
    let flat_paper = render(&combed(&paper, white, false), &opts()).expect("render");
    let moved_paper = render(&combed(&paper, white, true), &opts()).expect("render");
    // Paper grain does not move with the tine.
    assert_eq!(flat_paper, moved_paper);
    // With no ops the two grains are the same picture.
    assert_eq!(flat_paper, flat_pigment);
    // Pigment grain does move…
    let moved = marbling_core::compare::compare(&flat_pigment, &moved_pigment, 8).expect("size");
    assert!(
        moved.fraction() > 0.2,
        "pigment grain barely moved: {moved:?}"
    );
    // …exactly to where the ink went: pixel p shows the grain at its back-traced point.
    let d = combed(&pigment, white, true);
    let walker = Walker::new(&d.ops);
    let grain = &d.overlays[0].noise;
    for (x, y) in [(10, 30), (48, 33), (80, 20), (5, 60), (70, 40)] {
        let p = marbling_core::Point::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
        let Traced::Background(q) = walker.trace(p) else {
            panic!("no ink here")
        };
        assert!(
            (q - p).hypot() > 0.5,
            "the tine moved ({x}, {y}) too little"
        );
        let expected = marbling_core::color::linear_to_srgb(1.0 - grain.intensity(q.x, q.y));
        let got = pixel_rgb(&moved_pigment, x, y);
        assert!(
            got.iter().all(|&c| c.abs_diff(expected) <= 1),
            "({x}, {y}): {got:?} vs {expected}"
        );
        // And the un-deformed grain at the back-traced point is the same value.
        let flat = marbling_core::color::linear_to_srgb(1.0 - grain.intensity(p.x, p.y));
        assert_eq!(pixel_rgb(&flat_pigment, x, y), [flat; 3]);
    }
}

#[test]
fn noise_background_is_marbled_like_ink() {
    let bg = r##"{"noise":{"type":"worley","frequency":0.06,"seed":3},"palette":["#000000","#ffffff"]}"##;
    let d = combed("", bg, true);
    let img = render(&d, &opts()).expect("render");
    let layer = &d.background_noise.as_ref().expect("noise").noise;
    let walker = Walker::new(&d.ops);
    let mut checked = 0;
    for y in (0..64).step_by(7) {
        for x in (0..96).step_by(5) {
            let p = marbling_core::Point::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let Traced::Background(q) = walker.trace(p) else {
                continue;
            };
            let t = layer.intensity(q.x, q.y);
            let lin = marbling_core::surface::srgb_unit_to_linear(t);
            let expected = marbling_core::color::linear_to_srgb(lin);
            let got = pixel_rgb(&img, x, y);
            assert!(
                got.iter().all(|&c| c.abs_diff(expected) <= 1),
                "({x}, {y}): {got:?} vs {expected}"
            );
            checked += 1;
        }
    }
    assert!(checked > 100);
    // Not a flat image.
    let first = pixel_rgb(&img, 0, 0);
    assert!((0..64).any(|y| pixel_rgb(&img, 50, y) != first));
}

#[test]
fn ink_keeps_its_colour_under_a_noise_background() {
    let d = Design::from_json(V2).expect("v2");
    let mut no_overlays = d.clone();
    no_overlays.overlays.clear();
    let img = render(&no_overlays, &opts()).expect("render");
    // The drop's centre, pushed 20 px right by the tine, shows the ink exactly.
    assert_eq!(pixel_rgb(&img, 68, 32), [0x1d, 0x35, 0x57]);
    // The background around it varies.
    let row: Vec<[u8; 3]> = (0..96).map(|x| pixel_rgb(&img, x, 5)).collect();
    assert!(row.iter().any(|&c| c != row[0]), "flat background row");
    // Every antialiasing mode renders (adaptive refines only at source edges).
    for aa in Antialias::ALL {
        let img = render(
            &d,
            &RenderOptions {
                scale: 0.75,
                antialias: aa,
            },
        )
        .expect("render");
        assert_eq!((img.width, img.height), (72, 48));
    }
}

/// Every noise type an editor starts from makes a layer a design can hold, written as its
/// spec's document; a tiling spec is refused at `tile`.
#[test]
fn every_starting_noise_makes_a_design_layer() {
    use marbling_noise::{NOISE_TYPES, NoiseSpec, Source, Tile};
    for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
        let spec = NoiseSpec::plain(Source::starting(t, 3).expect("a starting source"));
        let layer = NoiseLayer::from_spec(&spec).expect(t);
        assert_eq!(layer.json(), &spec.to_value(), "{t}");
        assert_eq!(layer.spec(), &spec, "{t}");
        let tiled = NoiseSpec {
            tile: Tile::Output,
            ..spec
        };
        let refused = NoiseLayer::from_spec(&tiled).expect_err("tiling is refused");
        assert_eq!(refused[0].path, "tile", "{t}");
    }
}
