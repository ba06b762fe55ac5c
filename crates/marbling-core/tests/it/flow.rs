//! Schema v4's flow: an independent walk (ψ by central differences of the f32 noise, each
//! sub-step by fixed-point iteration) agrees with the crate's, the op and its reverse
//! render as the design without them, each ink keeps its area, the documents round-trip
//! as version 4, and every broken rule is named with its JSON path.

use crate::common::errors;
use marbling_core::{
    Antialias, Design, FLOW_STEP_PX, Flow, Op, Point, RenderOptions, Rgb8, RgbaImage, render,
};
use marbling_noise::Fbm;
use std::collections::HashMap;
use std::f64::consts::TAU;
use std::path::PathBuf;

fn example() -> Design {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/designs/v4-flow.json");
    Design::from_json(&std::fs::read_to_string(path).expect("example")).expect("valid")
}

fn flow_of(d: &Design) -> Flow {
    match d.ops.last() {
        Some(Op::Flow(f)) => f.clone(),
        other => panic!("the example ends with a flow, got {other:?}"),
    }
}

/// The velocity u = (∂ψ/∂y, −∂ψ/∂x) with ψ = U·n/(2πf), by central differences of the
/// f32 fBm's value (the crate uses the f64 noise's analytic derivatives).
fn velocity(fbm: &Fbm, f: &Flow, p: Point) -> (f64, f64) {
    let psi = |x: f64, y: f64| {
        f.strength * f64::from(fbm.eval(x as f32, y as f32)) / (TAU * f64::from(f.noise.frequency))
    };
    let h = 0.05;
    let dx = (psi(p.x + h, p.y) - psi(p.x - h, p.y)) / (2.0 * h);
    let dy = (psi(p.x, p.y + h) - psi(p.x, p.y - h)) / (2.0 * h);
    (dy, -dx)
}

/// The flow walked back independently: N sub-steps of −T/N, each solving
/// P = P′ − Δt·u((P + P′)/2) by fixed-point iteration.
fn flow_back(f: &Flow, p: Point) -> Point {
    let fbm = f.fbm();
    let n = f.sub_steps();
    let dt = f.time / n as f64;
    let mut q = p;
    for _ in 0..n {
        let mut prev = q;
        for _ in 0..20 {
            let mid = Point::new(0.5 * (q.x + prev.x), 0.5 * (q.y + prev.y));
            let (ux, uy) = velocity(&fbm, f, mid);
            prev = Point::new(q.x - dt * ux, q.y - dt * uy);
        }
        q = prev;
    }
    q
}

#[test]
fn an_independent_walk_agrees_with_the_crate() {
    let f = flow_of(&example());
    let op = Op::Flow(f.clone());
    let mut far = 0.0_f64;
    let mut moved = 0.0_f64;
    for k in 0..25 {
        let p = Point::new(20.0 + 15.0 * f64::from(k), 30.0 + 9.0 * f64::from(k));
        let marbling_core::Back::Moved(q) = op.inverse(p) else {
            panic!("a flow lays no ink");
        };
        let r = flow_back(&f, p);
        far = far.max((q - r).hypot());
        moved = moved.max((q - p).hypot());
    }
    // The f32 noise and its differences of 0.05 px carry about 1e-5 px per sub-step.
    assert!(far < 0.02, "the walks differ by {far} px");
    assert!(moved > 10.0, "the flow moved points only {moved} px");
}

/// The check above fails for a flow whose velocity has the wrong sign or scale.
#[test]
fn the_independent_walk_sees_a_wrong_formula() {
    let f = flow_of(&example());
    let p = Point::new(200.0, 150.0);
    let marbling_core::Back::Moved(q) = Op::Flow(f.clone()).inverse(p) else {
        panic!("a flow lays no ink");
    };
    for wrong in [
        Flow {
            strength: -f.strength,
            ..f.clone()
        },
        Flow {
            strength: f.strength * 1.1,
            ..f.clone()
        },
    ] {
        let r = flow_back(&wrong, p);
        assert!(
            (q - r).hypot() > 0.5,
            "{wrong:?} looks right: {q:?} vs {r:?}"
        );
    }
}

/// Four drops with smaller drops inside in the middle of a 160-px sheet, then a flow
/// along a 50-px Perlin noise of two octaves that moves ink about 15 px and keeps it on
/// the sheet (82 sub-steps).
fn small() -> Design {
    let mut d = Design::new(160, 160, Rgb8::new(250, 248, 240));
    let inks = [
        Rgb8::new(29, 53, 87),
        Rgb8::new(230, 57, 70),
        Rgb8::new(241, 196, 83),
        Rgb8::new(42, 157, 143),
        Rgb8::new(120, 40, 120),
    ];
    let centers = [(60.0, 60.0), (100.0, 60.0), (60.0, 100.0), (100.0, 100.0)];
    for (k, &(x, y)) in centers.iter().enumerate() {
        for (r, ink) in [(22.0, inks[k]), (9.0, inks[(k + 1) % 5])] {
            d.ops.push(Op::Drop(marbling_core::Drop {
                center: Point::new(x, y),
                radius: r,
                color: ink,
            }));
        }
    }
    d.ops.push(Op::Flow(Flow {
        noise: marbling_noise::FbmParams {
            frequency: 1.0 / 50.0,
            octaves: 2,
            seed: 3,
            ..marbling_noise::FbmParams::default()
        },
        strength: 15.0,
        time: 1.0,
    }));
    d
}

fn render_none(d: &Design) -> RgbaImage {
    render(
        d,
        &RenderOptions {
            scale: 1.0,
            antialias: Antialias::None,
        },
    )
    .expect("renders")
}

#[test]
fn a_flow_and_its_reverse_render_as_the_design_without_them() {
    let d = small();
    let f = flow_of(&d);
    let mut there_and_back = d.clone();
    there_and_back.ops.push(Op::Flow(Flow {
        time: -f.time,
        ..f.clone()
    }));
    let mut without = d.clone();
    without.ops.pop();
    let (a, b) = (render_none(&there_and_back), render_none(&without));
    let differ = a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .filter(|(p, q)| p != q)
        .count();
    let total = (a.width * a.height) as usize;
    assert!(differ * 1000 <= total, "{differ} of {total} pixels differ");
    // And the flow alone does change the picture.
    let flowed = render_none(&d);
    let changed = flowed
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .filter(|(p, q)| p != q)
        .count();
    assert!(
        changed * 10 > total,
        "the flow changed only {changed} pixels"
    );
}

fn ink_counts(img: &RgbaImage) -> HashMap<[u8; 3], usize> {
    let mut m = HashMap::new();
    for p in img.pixels.chunks(4) {
        *m.entry([p[0], p[1], p[2]]).or_insert(0) += 1;
    }
    m
}

/// Area preserving: every ink covers the same number of pixels (within 1 %) before and
/// after the flow (the inks stay on the sheet).
#[test]
fn each_ink_keeps_its_area_through_a_flow() {
    let d = small();
    let mut without = d.clone();
    without.ops.pop();
    let (before, after) = (
        ink_counts(&render_none(&without)),
        ink_counts(&render_none(&d)),
    );
    let paper: [u8; 3] = {
        let c: Rgb8 = d.background;
        [c.r, c.g, c.b]
    };
    let mut compared = 0;
    for (colour, &n) in &before {
        if *colour == paper {
            continue;
        }
        let m = after.get(colour).copied().unwrap_or(0);
        let rel = (m as f64 - n as f64).abs() / n as f64;
        assert!(rel <= 0.01, "{colour:?}: {n} → {m} pixels ({rel:.4})");
        compared += 1;
    }
    assert!(compared >= 4, "only {compared} inks compared");
}

#[test]
fn flow_documents_round_trip_as_version_4() {
    let d = example();
    assert_eq!(d.version(), 4);
    for text in [d.to_json_pretty(), d.to_json_compact()] {
        assert!(text.contains("\"version\":4") || text.contains("\"version\": 4"));
        assert_eq!(Design::from_json(&text).expect("round trip"), d);
    }
    let f = flow_of(&d);
    // U = 30, f = 0.008, 3 octaves, T = 1.2: a bound of 119 px per unit time, so
    // ⌈1.2·119/½⌉ sub-steps.
    assert_eq!(
        f.sub_steps(),
        (1.2 * f.speed_bound() / FLOW_STEP_PX).ceil() as usize
    );
    assert!((280..=290).contains(&f.sub_steps()), "{}", f.sub_steps());
}

fn doc(version: u32, op: &str) -> String {
    format!(
        r##"{{"version":{version},"width":100,"height":80,"background":"#ffffff","ops":[{op}]}}"##
    )
}

#[test]
fn broken_flows_are_named_with_their_paths() {
    let noise = r#"{"type":"perlin","frequency":0.01,"octaves":2}"#;
    let cases = [
        (
            doc(3, &format!(r#"{{"type":"flow","noise":{noise},"strength":5,"time":1}}"#)),
            r#"ops[0].type: op type "flow" needs "version": 4 (this document is version 3)"#
                .to_owned(),
        ),
        (
            doc(4, &format!(r#"{{"type":"flow","noise":{noise},"strength":5}}"#)),
            "ops[0].time: missing".to_owned(),
        ),
        (
            doc(
                4,
                r#"{"type":"flow","noise":{"type":"worley","frequency":0.01},"strength":5,"time":1}"#,
            ),
            r#"ops[0].noise: must be a "perlin" or "value" noise (a flow follows the curl of an fBm)"#
                .to_owned(),
        ),
        (
            doc(
                4,
                r#"{"type":"flow","noise":{"type":"perlin","frequency":0.01,"tile":true},"strength":5,"time":1}"#,
            ),
            "ops[0].noise: a flow's noise is the fBm alone: no tile, transfer, layers, palette or blend"
                .to_owned(),
        ),
        (
            doc(
                4,
                &format!(r#"{{"type":"flow","noise":{noise},"strength":5000,"time":100}}"#),
            ),
            "ops[0].time: needs".to_owned(),
        ),
        (
            doc(4, r#"{"type":"flow","noise":{"type":"perlin","frequency":0.01,"octaves":40},"strength":5,"time":1}"#),
            "ops[0].noise.octaves:".to_owned(),
        ),
    ];
    for (text, expected) in cases {
        let errs = errors(&text);
        assert!(
            errs.iter().any(|e| e.starts_with(&expected)),
            "wanted {expected:?} in {errs:#?}"
        );
    }
}
