//! The tiny-skia preview of traced outlines agrees with the exact CPU reference render.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};
use marbling_vector::{Blend, TraceOptions, preview, trace};
use std::time::Instant;

/// Pixels differing by more than this (of 255) count as mismatches.
const THRESHOLD: u8 = 48;
/// Largest allowed fraction of mismatching pixels.
const BUDGET: f64 = 0.01;

#[test]
fn vector_preview_agrees_with_cpu_reference() {
    let mixes = [Mix::Mixed, Mix::DropHeavy, Mix::CombHeavy];
    let sizes = [10, 40, 80, 150, 300];
    let t: f64 = std::env::var("AGREE_T")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1.0);
    let scale: f64 = std::env::var("AGREE_S")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1.0);
    let mut failures = Vec::new();
    let mut n = 0;
    println!("design                  ops  regions  vertices  refined  capped  mismatch  trace s");
    for (i, &ops) in sizes.iter().cycle().take(21).enumerate() {
        let mix = mixes[i % mixes.len()];
        let ops = if mix == Mix::CombHeavy {
            ops.min(100)
        } else {
            ops
        };
        let seed = 1000 + i as u64;
        let design = random_design(seed, 200, 150, ops, mix);
        let opts = TraceOptions {
            tolerance: t,
            scale,
            ..TraceOptions::default()
        };
        let start = Instant::now();
        let vector = trace(&design, &opts).expect("traceable");
        let secs = start.elapsed().as_secs_f64();
        let actual = preview(&vector, opts.scale, Blend::default()).expect("preview");
        let expected = render(
            &design,
            &RenderOptions {
                scale: opts.scale,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
        let diff = compare(&expected, &actual, THRESHOLD).expect("same size");
        let s = vector.stats;
        println!(
            "seed {seed} {mix:<10?} {ops:>5} {:>8} {:>9} {:>8} {:>7} {:>8.3}% {:>8.3}",
            s.regions - s.culled,
            s.vertices,
            s.refined_vertices,
            s.capped,
            100.0 * diff.fraction(),
            secs
        );
        if diff.fraction() > BUDGET {
            failures.push(format!("seed {seed}: {:.3} %", 100.0 * diff.fraction()));
        }
        n += 1;
    }
    assert!(n >= 20);
    assert!(failures.is_empty(), "over budget: {failures:?}");
}
