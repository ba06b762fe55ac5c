//! The exported SVG, rendered by resvg, agrees with the exact CPU render (4×4
//! supersampling) on random designs of up to 1,000 ops, chaotic ones among them
//! (comb-heavy at full strength), at the default tolerance T = 1 output pixel: at most
//! 2 % of pixels differ by more than 48/255. Small canvases keep the test quick; the
//! benchmarks (`make bench-svg`) measure the same at 1024².

use crate::exact::svg_against_exact;
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{TraceOptions, to_svg, trace};
use std::time::Instant;

/// Largest allowed fraction of mismatching pixels.
const BUDGET: f64 = 0.02;

/// Exports each design at T = 1, checks the budget and returns the worst mismatch.
fn check(cases: &[(u64, Mix, usize)], (w, h): (u32, u32)) -> f64 {
    let opts = TraceOptions::default();
    println!(
        "seed mix           ops  by contour / regions  dense px  vertices     bytes mismatch  s"
    );
    let mut failures = Vec::new();
    let mut worst: f64 = 0.0;
    for &(seed, mix, ops) in cases {
        let design = random_design(seed, w, h, ops, mix);
        let start = Instant::now();
        let vector = trace(&design, &opts).expect("traceable");
        let svg = to_svg(&vector);
        let secs = start.elapsed().as_secs_f64();
        let diff = svg_against_exact(&design, &svg, 1.0);
        let s = vector.stats;
        println!(
            "{seed} {mix:<12?} {ops:>5} {:>10} / {:<7} {:>9} {:>9} {:>9} {:>6.3} % {secs:.2}",
            s.contour_regions,
            s.regions,
            s.dense_pixels,
            s.vertices,
            svg.len(),
            100.0 * diff.fraction(),
        );
        worst = worst.max(diff.fraction());
        if diff.fraction() > BUDGET {
            failures.push(format!("seed {seed}: {:.3} %", 100.0 * diff.fraction()));
        }
    }
    assert!(failures.is_empty(), "over budget: {failures:?}");
    worst
}

#[test]
fn svg_agrees_with_the_exact_raster_on_random_designs_up_to_1000_ops() {
    let mut cases = Vec::new();
    for (i, mix) in [Mix::Mixed, Mix::DropHeavy, Mix::CombHeavy]
        .into_iter()
        .enumerate()
    {
        for (j, ops) in [40, 150, 400, 1000].into_iter().enumerate() {
            cases.push((1000 + 10 * i as u64 + j as u64, mix, ops));
        }
    }
    let worst = check(&cases, (160, 120));
    println!("worst mismatch {:.3} %", 100.0 * worst);
}

/// Designs of all fourteen op types (schema v3: shift, turn, comb, drop patterns,
/// jiggle, stylus among them) and stylus-heavy ones are traced like the others.
#[test]
fn svg_agrees_on_designs_with_every_op_type() {
    let cases = [
        (2001, Mix::AllTypes, 40),
        (2002, Mix::AllTypes, 200),
        (2003, Mix::Stylus, 60),
    ];
    for &(seed, mix, ops) in &cases {
        assert_eq!(random_design(seed, 160, 120, ops, mix).version(), 3);
    }
    check(&cases, (160, 120));
}

/// At 1024² a chaotic design (comb-heavy at full strength, 300 ops: most of it
/// filaments, a tenth of the pixels in the dense patch) stays within 4 MB and 600 000
/// vertices at T = 1.
#[test]
fn a_chaotic_1024_design_stays_within_the_size_budget() {
    let design = random_design(7, 1024, 1024, 300, Mix::CombHeavy);
    let vector = trace(&design, &TraceOptions::default()).expect("traceable");
    let svg = to_svg(&vector);
    let s = vector.stats;
    println!(
        "{} vertices, {} dense px, {} bytes, {} of {} regions by contour",
        s.vertices,
        s.dense_pixels,
        svg.len(),
        s.contour_regions,
        s.regions
    );
    assert!(s.contour_regions > 0 && s.dense_pixels > 0);
    assert!(s.vertices <= 600_000, "{} vertices", s.vertices);
    assert!(svg.len() <= 4_000_000, "{} bytes", svg.len());
}
