//! Schema v3's ops: an independent implementation of the formulas of the issue that
//! introduced them agrees with the reference renderer pixel for pixel (`--aa none`), a
//! drop pattern renders exactly like its drops one by one, the documents round-trip,
//! and every broken rule is named with its JSON path.

use crate::common::errors;
use marbling_core::{
    Antialias, Design, DropSet, Op, Point, Radii, RenderOptions, Rgb8, Stylus, Vec2, render,
};
use std::f64::consts::TAU;
use std::path::PathBuf;
use std::sync::Arc;

fn example(name: &str) -> Design {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/designs")
        .join(format!("{name}.json"));
    Design::from_json(&std::fs::read_to_string(path).expect("example")).expect("valid")
}

/// The stream function's velocity per unit of travel of one tip at the origin moving
/// along +x, by central differences of ψ(x, y) = y·e^{−ρ/L}·c(ρ/8L) (no analytic
/// derivative, unlike the crate).
fn tip_velocity(x: f64, y: f64, wake: f64) -> (f64, f64) {
    let psi = |x: f64, y: f64| {
        let rho = x.hypot(y);
        let t = rho / (8.0 * wake);
        if t >= 1.0 {
            return 0.0;
        }
        y * (-rho / wake).exp() * (1.0 - t * t).powi(3)
    };
    let h = 1e-6 * wake;
    let dx = (psi(x + h, y) - psi(x - h, y)) / (2.0 * h);
    let dy = (psi(x, y + h) - psi(x, y - h)) / (2.0 * h);
    (dy, -dx)
}

/// The stylus walked back independently: segments newest first, N = max(1, ⌈2ℓ/L⌉)
/// sub-steps each, newest first, each solving P = P′ − δ·u((P + P′)/2) by plain
/// fixed-point iteration (the crate uses Newton's method).
fn stylus_back(s: &Stylus, p: Point) -> Point {
    let tips: Vec<f64> = s.tips.as_deref().map_or(vec![0.0], <[f64]>::to_vec);
    let mut q = p;
    for w in s.path.windows(2).rev() {
        let d = w[1] - w[0];
        let len = d.hypot();
        if len == 0.0 {
            continue;
        }
        let n = d / len;
        let nt = Vec2::new(-n.y, n.x);
        let steps = (2.0 * len / s.wake).ceil().max(1.0) as usize;
        let delta = len / steps as f64;
        for j in (0..steps).rev() {
            let mid = w[0] + n * ((j as f64 + 0.5) * delta);
            let u = |m: Point| {
                let r = m - mid;
                let (x, y) = (r.dot(n), r.dot(nt));
                tips.iter().fold(Vec2::ZERO, |acc, o| {
                    let (ux, uy) = tip_velocity(x, y - o, s.wake);
                    acc + n * ux + nt * uy
                })
            };
            let mut prev = q;
            for _ in 0..200 {
                let next = q - u(prev.midpoint(q)) * delta;
                let done = (next - prev).hypot() < 1e-11;
                prev = next;
                if done {
                    break;
                }
            }
            q = prev;
        }
    }
    q
}

/// φ + c·sin φ = t by bisection.
fn kepler(t: f64, c: f64) -> f64 {
    let (mut lo, mut hi) = (t - c.abs() - 1e-9, t + c.abs() + 1e-9);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid + c * mid.sin() < t {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Walks `p` back through `ops` with the formulas as written in the issue: Some(ink)
/// when a drop covers it, else None with `p` moved.
fn walk_back(ops: &[Op], p: &mut Point) -> Option<Rgb8> {
    let comb_shift = |origin: Point, dir: Vec2, offs: &[f64], alpha: f64, lambda: f64, q: Point| {
        let m = dir / dir.hypot();
        let nn = Vec2::new(-m.y, m.x);
        let s = (q - origin).dot(nn);
        let d = offs.iter().map(|o| (s - o).abs()).fold(f64::MAX, f64::min);
        m * (alpha * lambda / (d + lambda))
    };
    let rot =
        |v: Vec2, a: f64| Vec2::new(a.cos() * v.x - a.sin() * v.y, a.sin() * v.x + a.cos() * v.y);
    for op in ops.iter().rev() {
        match op {
            Op::Drops(set) | Op::Sprays(set) => {
                for i in (0..set.centers.len()).rev() {
                    let (c, r) = (set.centers[i], set.radius(i));
                    let d2 = (*p - c).hypot2();
                    if d2 < r * r {
                        return Some(set.colors[i % set.colors.len()]);
                    }
                    if matches!(op, Op::Drops(_)) {
                        *p = c + (*p - c) * (1.0 - r * r / d2).sqrt();
                    }
                }
            }
            Op::Shift(s) => *p -= s.offset,
            Op::Turn(t) => *p = t.center + rot(*p - t.center, -t.angle),
            Op::Comb(c) => *p -= comb_shift(c.origin, c.direction, &c.tines, c.alpha, c.lambda, *p),
            Op::Tine(t) => *p -= comb_shift(t.origin, t.direction, &[0.0], t.alpha, t.lambda, *p),
            Op::Jiggle(j) => {
                let u = Vec2::new(j.angle.cos(), j.angle.sin());
                let v = Vec2::new(-u.y, u.x);
                let k = TAU / j.wavelength;
                let phi = kepler(k * p.to_vec2().dot(u) + j.phase, k * j.along);
                *p = *p - u * (j.along * phi.sin()) - v * (j.across * phi.cos());
            }
            Op::Stylus(s) => *p = stylus_back(s, *p),
            Op::Circular(c) => {
                let rho = (*p - c.center).hypot();
                let a = c.alpha * c.lambda / ((rho - c.radius).abs() + c.lambda) / rho;
                *p = c.center + rot(*p - c.center, -a);
            }
            Op::Vortex(v) => {
                let rho = (*p - v.center).hypot();
                let a = v.alpha * v.lambda / (rho + v.lambda) / rho;
                *p = v.center + rot(*p - v.center, -a);
            }
            other => panic!("the independent walk has no {}", other.type_name()),
        }
    }
    None
}

#[test]
fn an_independent_implementation_agrees_with_the_renderer() {
    for name in [
        "v3-shift",
        "v3-turn",
        "v3-comb",
        "v3-drops",
        "v3-sprays",
        "v3-jiggle",
        "v3-stylus",
    ] {
        let d = example(name);
        let scale = 0.25;
        let img = render(
            &d,
            &RenderOptions {
                scale,
                antialias: Antialias::None,
            },
        )
        .expect("render");
        let mut differ = 0;
        for y in 0..img.height {
            for x in 0..img.width {
                let mut p = Point::new((f64::from(x) + 0.5) / scale, (f64::from(y) + 0.5) / scale);
                let c = walk_back(&d.ops, &mut p).unwrap_or(d.background);
                let i = ((y * img.width + x) * 4) as usize;
                if img.pixels[i..i + 3] != [c.r, c.g, c.b] {
                    differ += 1;
                }
            }
        }
        let total = img.width * img.height;
        // Only pixels whose sample lies within rounding of an ink edge may differ.
        assert!(
            differ * 1000 <= total,
            "{name}: {differ} of {total} pixels differ"
        );
        eprintln!("{name}: {differ} of {total} pixels differ");
    }
}

#[test]
fn the_independent_walk_sees_a_wrong_formula() {
    // The same check on a stylus whose wake is a little larger: many pixels differ.
    let d = example("v3-stylus");
    let mut wrong = d.ops.clone();
    for op in &mut wrong {
        if let Op::Stylus(s) = op {
            s.wake *= 1.05;
        }
    }
    let img = render(
        &d,
        &RenderOptions {
            scale: 0.25,
            antialias: Antialias::None,
        },
    )
    .expect("render");
    let mut differ = 0;
    for y in 0..img.height {
        for x in 0..img.width {
            let mut p = Point::new((f64::from(x) + 0.5) * 4.0, (f64::from(y) + 0.5) * 4.0);
            let c = walk_back(&wrong, &mut p).unwrap_or(d.background);
            let i = ((y * img.width + x) * 4) as usize;
            differ += usize::from(img.pixels[i..i + 3] != [c.r, c.g, c.b]);
        }
    }
    assert!(
        differ * 1000 > (img.width * img.height) as usize,
        "{differ}"
    );
}

#[test]
fn a_drop_pattern_renders_exactly_like_its_drops() {
    for name in ["v3-drops", "v3-sprays", "v3-comb"] {
        let d = example(name);
        let mut expanded = d.clone();
        expanded.ops = d
            .ops
            .iter()
            .flat_map(|op| match op {
                Op::Drops(s) => s.expand(false).collect::<Vec<_>>(),
                Op::Sprays(s) => s.expand(true).collect(),
                other => vec![other.clone()],
            })
            .collect();
        assert!(expanded.ops.len() > d.ops.len());
        assert_eq!(d.counted_ops(), expanded.ops.len());
        let opts = RenderOptions {
            scale: 0.5,
            antialias: Antialias::Rgss,
        };
        let (a, b) = (
            render(&d, &opts).expect("render"),
            render(&expanded, &opts).expect("render"),
        );
        assert!(
            a.pixels == b.pixels,
            "{name}: the pattern and its drops differ"
        );
    }
}

#[test]
fn v3_documents_round_trip_and_older_ones_keep_their_version() {
    for name in ["v3-shift", "v3-stylus", "v3-drops", "v3-jiggle"] {
        let d = example(name);
        assert_eq!(d.version(), 3);
        let back = Design::from_json(&d.to_json_pretty()).expect("round trip");
        assert_eq!(back, d, "{name}");
        let compact = Design::from_json(&d.to_json_compact()).expect("round trip");
        assert_eq!(compact, d, "{name}");
    }
    // A design without v3 ops is still written as version 1.
    let mut d = example("v3-drops");
    d.ops.retain(|o| !o.is_v3());
    assert_eq!(d.version(), 1);
    assert!(d.to_json_compact().starts_with("{\"version\":1"));
}

fn doc(version: u32, op: &str) -> String {
    format!(
        r##"{{"version":{version},"width":100,"height":80,"background":"#ffffff","ops":[{op}]}}"##
    )
}

#[test]
fn broken_v3_ops_are_named_with_their_paths() {
    let cases = [
        (
            doc(2, r#"{"type":"shift","offset":[1,2]}"#),
            r#"ops[0].type: op type "shift" needs "version": 3 (this document is version 2)"#,
        ),
        (
            doc(
                3,
                r##"{"type":"drops","centers":[[1,2]],"radius":3,"radii":[3],"colors":["#000000"]}"##,
            ),
            r#"ops[0].radius: give either "radius" (one for all) or "radii" (one per centre), not both"#,
        ),
        (
            doc(
                3,
                r##"{"type":"sprays","centers":[[1,2],[3,4]],"radii":[3],"colors":["#000000"]}"##,
            ),
            "ops[0].radii: must hold one radius per centre (2), got 1",
        ),
        (
            doc(
                3,
                r##"{"type":"drops","centers":[[1,"x"]],"radius":3,"colors":["#000000"]}"##,
            ),
            r#"ops[0].centers[0][1]: must be a number, got a string"#,
        ),
        (
            doc(
                3,
                r##"{"type":"drops","centers":[[1,2]],"radius":3,"colors":[]}"##,
            ),
            "ops[0].colors: must hold at least one colour, got none",
        ),
        (
            doc(
                3,
                r#"{"type":"comb","origin":[0,0],"direction":[1,0],"tines":[],"alpha":5,"lambda":2}"#,
            ),
            "ops[0].tines: must hold 1..=256 tine offsets, got 0",
        ),
        (
            doc(
                3,
                r#"{"type":"jiggle","angle":0,"wavelength":10,"along":2,"across":0,"phase":0}"#,
            ),
            "ops[0].along: must satisfy |2π·along/wavelength| < 1 (the jiggle must not fold the tank), got 1.2566 for along 2 and wavelength 10; use a smaller along or a longer wavelength",
        ),
        (
            doc(3, r#"{"type":"stylus","path":[[0,0]],"wake":2}"#),
            "ops[0].path: must hold 2..=2048 points, got 1",
        ),
        (
            doc(3, r#"{"type":"stylus","path":[[0,0],[5000,0]],"wake":1}"#),
            "ops[0].path: needs 10000 sub-steps × 1 tip(s) = 10000, more than 4096; use a larger wake or a shorter path",
        ),
        (
            doc(
                3,
                r#"{"type":"stylus","path":[[0,0],[10,0]],"wake":0,"tips":[1,"a"]}"#,
            ),
            "ops[0].tips[1]: must be a number, got a string",
        ),
    ];
    for (text, expected) in cases {
        let errs = errors(&text);
        assert!(
            errs.iter().any(|e| e == expected),
            "wanted {expected:?} in {errs:#?}"
        );
    }
}

#[test]
fn every_drop_of_a_pattern_counts_toward_the_op_cap() {
    let centers: Arc<[Point]> = (0..10_000)
        .map(|i| Point::new(f64::from(i % 100), 1.0))
        .collect();
    let set = DropSet {
        centers,
        radii: Radii::One(1.0),
        colors: Arc::from([Rgb8::new(0, 0, 0)]),
    };
    let mut d = Design::new(100, 100, Rgb8::new(255, 255, 255));
    d.ops = vec![Op::Sprays(set); 10];
    assert!(d.validate().is_ok());
    d.ops.push(Op::Shift(marbling_core::Shift {
        offset: Vec2::new(1.0, 0.0),
    }));
    let e = d.validate().expect_err("100,001 counted ops");
    assert_eq!(
        e.to_string(),
        "ops: at most 100000 ops are allowed (each drop of a pattern counts), got 100001"
    );
}

/// Drop and spray patterns compile to plain discs, so the GPU draws a design of them
/// with the v1 walk (its extra cases cost a v1 walk 3.5× on lavapipe); every other v3
/// type needs the v3 walk.
#[test]
fn only_v3_kinds_need_the_v3_walk() {
    use marbling_core::synth::{Mix, random_design};
    let d = random_design(9, 200, 150, 300, Mix::AllTypes);
    for op in &d.ops {
        let v3_kind = marbling_core::CompiledOp::of(op)
            .iter()
            .any(|c| c.kind().code() >= marbling_core::OpKind::Rigid.code());
        assert_eq!(op.walks_v3(), v3_kind, "{}", op.type_name());
    }
    assert!(d.ops.iter().any(|o| matches!(o, Op::Drops(_))) && d.ops.iter().any(Op::walks_v3));
}
