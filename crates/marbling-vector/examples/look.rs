//! Writes the CPU reference render, the vector preview, their diff strip and the SVG of
//! one synthetic design, for looking at: `cargo run --example look -- SEED OPS MIX [T] [OUT_DIR]`
//! (MIX: mixed, drop, comb). Environment: `NO_SIMPLIFY=1` keeps every refined vertex,
//! `REF_AA=grid4` compares against the 16-sample CPU render instead of RGSS.

use marbling_core::compare::{compare, diff_strip};
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};
use marbling_vector::{Blend, TraceOptions, rasterize, to_svg, trace};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |i: usize, d: &str| args.get(i).cloned().unwrap_or_else(|| d.to_string());
    let seed: u64 = arg(0, "1004").parse()?;
    let ops: usize = arg(1, "300").parse()?;
    let mix = match arg(2, "drop").as_str() {
        "mixed" => Mix::Mixed,
        "comb" => Mix::CombHeavy,
        _ => Mix::DropHeavy,
    };
    let tolerance: f64 = arg(3, "1").parse()?;
    let dir = std::path::PathBuf::from(arg(4, "/tmp/look"));
    std::fs::create_dir_all(&dir)?;
    let design = random_design(seed, 200, 150, ops, mix);
    let opts = TraceOptions {
        tolerance,
        simplify: std::env::var_os("NO_SIMPLIFY").is_none(),
        ..TraceOptions::default()
    };
    let t0 = std::time::Instant::now();
    let vector = trace(&design, &opts)?;
    println!("trace {:.3} s", t0.elapsed().as_secs_f64());
    let actual = rasterize(&vector, 1.0, Blend::default())?;
    let aa = match std::env::var("REF_AA").as_deref() {
        Ok("grid4") => Antialias::Grid4,
        _ => Antialias::Rgss,
    };
    let expected = render(
        &design,
        &RenderOptions {
            scale: 1.0,
            antialias: aa,
        },
    )?;
    let diff = compare(&expected, &actual, 48)?;
    println!(
        "{:?}\nmismatch {:.3} %",
        vector.stats,
        100.0 * diff.fraction()
    );
    std::fs::write(
        dir.join("strip.png"),
        diff_strip(&expected, &actual, 48).to_png()?,
    )?;
    std::fs::write(dir.join("design.json"), design.to_json_pretty())?;
    std::fs::write(dir.join("out.svg"), to_svg(&vector))?;
    Ok(())
}
