//! Writes the example designs of `examples/designs/` as real marbling recipes: a stone
//! base of drops, then combs, rakes and swirls, as a marbler would make them.
//!
//! Run from the workspace root: `cargo run -p marbling-core --example make_designs`.

use marbling_core::synth::SplitMix64;
use marbling_core::{
    Circular, Design, Drop, NoiseBackground, NoiseLayer, Op, Overlay, Palette, Point, Rake, Rgb8,
    Tine, Vec2, Vortex, Wavy,
};
use std::f64::consts::FRAC_PI_2;

const W: u32 = 640;
const H: u32 = 400;

fn hex(s: &str) -> Rgb8 {
    s.parse().expect("palette colours are valid")
}

/// A stone pattern: rounds of drops, each colour scattered over the whole sheet, the
/// later (smaller) drops pushing the earlier ones into polygonal stones.
fn stone(seed: u64, colors: &[&str], drops: usize, r: (f64, f64)) -> Vec<Op> {
    let mut rng = SplitMix64(seed);
    (0..drops)
        .map(|i| {
            let t = i as f64 / drops as f64;
            Op::Drop(Drop {
                center: Point::new(
                    rng.range(-20.0, f64::from(W) + 20.0),
                    rng.range(-20.0, f64::from(H) + 20.0),
                ),
                radius: rng.range(r.0, r.1) * (1.0 - 0.5 * t),
                color: hex(colors[i % colors.len()]),
            })
        })
        .collect()
}

/// Horizontal bands: rows of overlapping drops, one colour per row, laid top to bottom.
fn stripes(colors: &[&str], rows: usize) -> Vec<Op> {
    let mut ops = Vec::new();
    let dy = f64::from(H) / rows as f64;
    for row in 0..rows {
        let y = (row as f64 + 0.5) * dy;
        for k in 0..12 {
            ops.push(Op::Drop(Drop {
                center: Point::new((k as f64 + 0.5) * f64::from(W) / 12.0, y),
                radius: dy * 0.8,
                color: hex(colors[row % colors.len()]),
            }));
        }
    }
    ops
}

fn rake(
    origin_x: f64,
    origin_y: f64,
    dir: (f64, f64),
    spacing: f64,
    alpha: f64,
    lambda: f64,
) -> Op {
    Op::Rake(Rake {
        origin: Point::new(origin_x, origin_y),
        direction: Vec2::new(dir.0, dir.1),
        spacing,
        alpha,
        lambda,
    })
}

/// Gel-git: stone, a rake drawn down the sheet, then back up between the first strokes.
fn gel_git_combs(spacing: f64, alpha: f64) -> Vec<Op> {
    vec![
        rake(0.0, 0.0, (0.0, 1.0), spacing, alpha, 8.0),
        rake(spacing / 2.0, 0.0, (0.0, -1.0), spacing, alpha, 8.0),
    ]
}

fn design(background: &str, ops: Vec<Op>) -> Design {
    let mut d = Design::new(W, H, hex(background));
    d.ops = ops;
    d
}

fn noise(json: &str) -> NoiseLayer {
    NoiseLayer::from_json(json).expect("example noise specs are valid")
}

/// Schema v2 "start from noise": a Perlin fBm stone texture as the background, marbled
/// by a wavy comb, a rake back and forth and two vortices (no ink at all).
fn fbm_marbled() -> Design {
    let mut d = design("#f4ecd8", Vec::new());
    d.set_background_noise(Some(NoiseBackground::new(
        noise(r#"{"type":"perlin","frequency":0.01,"octaves":6,"persistence":0.55,"seed":11}"#),
        Palette::named("marble").expect("built-in palette"),
    )));
    d.ops = vec![
        Op::Wavy(Wavy {
            angle: 0.0,
            amplitude: 18.0,
            wavelength: 140.0,
            phase: 0.0,
        }),
        rake(0.0, 0.0, (1.0, 0.0), 50.0, 40.0, 10.0),
        rake(0.0, 25.0, (-1.0, 0.0), 50.0, 40.0, 10.0),
        Op::Vortex(Vortex {
            center: Point::new(200.0, 200.0),
            alpha: 120.0,
            lambda: 40.0,
        }),
        Op::Vortex(Vortex {
            center: Point::new(450.0, 210.0),
            alpha: -120.0,
            lambda: 40.0,
        }),
    ];
    d
}

/// Worley cells as the background, drops of ink, a gel-git comb, and pigment grain that
/// flows with everything (compare the grain's stretch along the comb strokes).
fn worley_pigment() -> Design {
    let mut d = design(
        "#f4ecd8",
        stone(7, &["#14213d", "#fca311", "#e5e5e5"], 40, (20.0, 40.0)),
    );
    d.set_background_noise(Some(NoiseBackground::new(
        noise(r#"{"type":"worley","frequency":0.03,"feature":"f2-f1","seed":5}"#),
        Palette::from_stops(vec![hex("#0b4f6c"), hex("#a8dadc"), hex("#f1faee")])
            .expect("three stops"),
    )));
    d.ops.extend(gel_git_combs(48.0, 60.0));
    d.ops.push(Op::Tine(Tine {
        origin: Point::new(0.0, 200.0),
        direction: Vec2::new(1.0, 0.0),
        alpha: 120.0,
        lambda: 20.0,
    }));
    d.overlays.push(Overlay::pigment_grain(
        noise(r#"{"type":"perlin","frequency":0.12,"octaves":2,"seed":3}"#),
        0.35,
    ));
    d
}

/// A plain stone design printed on paper: paper grain fixed to the sheet while the ink
/// is combed over it.
fn on_paper() -> Design {
    let earth = ["#1d3557", "#c0392b", "#e9c46a", "#2a9d8f"];
    let mut d = design("#f6efe0", stone(8, &earth, 90, (24.0, 48.0)));
    d.ops.push(rake(0.0, 0.0, (0.0, 1.0), 60.0, 50.0, 10.0));
    d.ops.push(Op::Wavy(Wavy {
        angle: FRAC_PI_2,
        amplitude: 12.0,
        wavelength: 100.0,
        phase: 0.5,
    }));
    d.overlays.push(Overlay::paper_grain(
        noise(
            r#"{"type":"paper","length":16,"width":1.5,"density":0.25,"seed":8,"impurities":{"density":0.0008,"radius":1.5,"strength":1.5}}"#,
        ),
        0.3,
    ));
    d
}

fn main() -> std::io::Result<()> {
    let earth = ["#1d3557", "#c0392b", "#e9c46a", "#2a9d8f", "#f4f1de"];
    let indigo = ["#14213d", "#fca311", "#e5e5e5", "#3d5a80", "#98c1d9"];
    let rose = ["#6d597a", "#b56576", "#e56b6f", "#eaac8b", "#355070"];

    let stone_ops = stone(1, &earth, 260, (22.0, 46.0));

    let mut gel_git = stone(2, &indigo, 160, (22.0, 50.0));
    gel_git.extend(gel_git_combs(36.0, 48.0));

    let mut chevron = stripes(&rose, 10);
    chevron.extend(gel_git_combs(80.0, 70.0));
    chevron.push(rake(0.0, 0.0, (1.0, 0.0), 100.0, 60.0, 25.0));

    let mut nonpareil = stone(3, &earth, 320, (18.0, 40.0));
    nonpareil.extend(gel_git_combs(30.0, 45.0));
    nonpareil.push(rake(0.0, 0.0, (1.0, 0.0), 9.0, 14.0, 3.0));

    // Stripes: a dense stone pulled out sideways by strong rakes back and forth.
    let mut serpentine = stone(6, &indigo, 300, (18.0, 40.0));
    serpentine.push(rake(0.0, 0.0, (1.0, 0.0), 24.0, 160.0, 30.0));
    serpentine.push(rake(0.0, 12.0, (-1.0, 0.0), 24.0, 160.0, 30.0));
    serpentine.push(Op::Wavy(Wavy {
        angle: FRAC_PI_2,
        amplitude: 26.0,
        wavelength: 160.0,
        phase: 0.0,
    }));
    serpentine.push(Op::Wavy(Wavy {
        angle: 0.0,
        amplitude: 10.0,
        wavelength: 90.0,
        phase: 1.0,
    }));

    let mut bouquet = stone(4, &rose, 160, (22.0, 50.0));
    bouquet.extend(gel_git_combs(32.0, 45.0));
    bouquet.push(rake(0.0, 0.0, (1.0, 0.0), 10.0, 12.0, 3.0));
    bouquet.push(Op::Wavy(Wavy {
        angle: 0.0,
        amplitude: 14.0,
        wavelength: 64.0,
        phase: 0.0,
    }));

    let mut vortex = stone(5, &indigo, 120, (24.0, 55.0));
    for (cx, cy, a) in [(170.0, 200.0, 160.0), (470.0, 200.0, -160.0)] {
        vortex.push(Op::Vortex(Vortex {
            center: Point::new(cx, cy),
            alpha: a,
            lambda: 40.0,
        }));
    }
    vortex.push(Op::Circular(Circular {
        center: Point::new(320.0, 200.0),
        radius: 120.0,
        alpha: 90.0,
        lambda: 18.0,
    }));

    let designs = [
        ("stone", design("#f4ecd8", stone_ops)),
        ("gel-git", design("#f7f3e8", gel_git)),
        ("chevron", design("#f7efe2", chevron)),
        ("nonpareil", design("#f4ecd8", nonpareil)),
        ("serpentine", design("#f7f3e8", serpentine)),
        ("bouquet", design("#f7efe2", bouquet)),
        ("vortex", design("#f7f3e8", vortex)),
        ("fbm-marbled", fbm_marbled()),
        ("worley-pigment", worley_pigment()),
        ("on-paper", on_paper()),
    ];
    std::fs::create_dir_all("examples/designs")?;
    for (name, d) in designs {
        assert!(d.validate().is_ok(), "{name} is invalid");
        std::fs::write(format!("examples/designs/{name}.json"), d.to_json_pretty())?;
        println!("examples/designs/{name}.json: {} ops", d.ops.len());
    }
    Ok(())
}
