//! The tolerance contract, measured: refined segments against densely sampled forward
//! points, the simplification bound, the initial n-gon, and a golden preview.

use marbling_core::compare::check_snapshot;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{CompiledOp, Design, Op};
use marbling_vector::reference::{Refiner, distance_to_segment};
use marbling_vector::simplify::rdp_closed;
use marbling_vector::{Blend, initial_sides, rasterize, trace};

/// Refiners for every ink op of `design` at tolerance `t` (scale 1, no off-canvas
/// relaxation, so the bounds apply everywhere).
fn refiners<'a>(design: &Design, steps: &'a [CompiledOp], t: f64) -> Vec<Refiner<'a>> {
    design
        .ops
        .iter()
        .enumerate()
        .filter_map(|(k, op)| {
            let (center, radius) = match op {
                Op::Drop(d) => (d.center, d.radius),
                Op::Spray(s) => (s.center, s.radius),
                _ => return None,
            };
            Some(Refiner {
                ops: &steps[k + 1..],
                center,
                radius,
                spacing: t,
                deviation: t / 4.0,
                canvas: None,
                max_depth: 30,
                max_vertices: 10_000_000,
            })
        })
        .collect()
}

#[test]
fn refined_segments_stay_within_tolerance_of_dense_forward_points() {
    println!(
        "seed mix          ops   T  segments  worst chord  worst deviation (dense, 32/segment)"
    );
    for (seed, mix, ops) in [
        (11, Mix::Mixed, 80),
        (12, Mix::DropHeavy, 120),
        (13, Mix::CombHeavy, 60),
    ] {
        let design = random_design(seed, 200, 150, ops, mix);
        let steps = CompiledOp::compile(&design.ops);
        for t in [1.0, 0.25] {
            let (mut worst_dev, mut worst_chord, mut segments) = (0.0f64, 0.0f64, 0);
            for r in refiners(&design, &steps, t) {
                let sides = initial_sides(r.radius, t);
                let out = r.refine(sides).expect("refines");
                assert_eq!(out.capped, 0);
                let n = out.points.len();
                for i in 0..n {
                    let (a, b) = (out.points[i], out.points[(i + 1) % n]);
                    let ta = out.angles[i];
                    let tb = if i + 1 == n {
                        std::f64::consts::TAU
                    } else {
                        out.angles[i + 1]
                    };
                    worst_chord = worst_chord.max((b - a).hypot());
                    for k in 1..32 {
                        let p = r.map(ta + (tb - ta) * f64::from(k) / 32.0);
                        worst_dev = worst_dev.max(distance_to_segment(p, a, b));
                    }
                    segments += 1;
                }
            }
            println!(
                "{seed} {mix:<12?} {ops:>4} {t:>4} {segments:>9} {worst_chord:>12.4} {worst_dev:>16.4}"
            );
            assert!(worst_chord <= t, "chord {worst_chord} > T {t}");
            // The refinement checks T/4 at the quarter, half and three-quarter points of
            // each segment; between them the crate docs state the measured worst case
            // (about 0.66·T, at outline parts that pass close to a later drop's centre,
            // where the forward map is extremely non-uniform) and this asserts T.
            assert!(worst_dev <= t, "deviation {worst_dev} > T at T {t}");
        }
    }
}

#[test]
fn simplification_moves_outlines_by_at_most_a_quarter_tolerance() {
    let design = random_design(21, 200, 150, 100, Mix::Mixed);
    let t = 1.0;
    let eps = t / 4.0;
    let steps = CompiledOp::compile(&design.ops);
    let (mut before, mut after, mut worst) = (0, 0, 0.0f64);
    for r in refiners(&design, &steps, t) {
        let dense = r
            .refine(initial_sides(r.radius, t))
            .expect("refines")
            .points;
        let simple = rdp_closed(&dense, eps);
        before += dense.len();
        after += simple.len();
        if simple.len() < 2 {
            continue;
        }
        for &p in &dense {
            let d = (0..simple.len())
                .map(|i| distance_to_segment(p, simple[i], simple[(i + 1) % simple.len()]))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d);
        }
    }
    println!("vertices {before} → {after}, worst distance {worst:.4} (bound {eps})");
    assert!(worst <= eps + 1e-9);
    assert!(after * 3 < before, "simplification removed too little");
}

#[test]
fn initial_polygon_sides_follow_radius_and_tolerance() {
    // Sagitta r(1 − cos(π/n)) ≤ T/4 with n minimal, at least 8.
    assert_eq!(initial_sides(0.5, 1.0), 8);
    assert_eq!(initial_sides(40.0, 1.0), 29);
    assert_eq!(initial_sides(40.0, 0.25), 57);
    assert_eq!(initial_sides(160.0, 1.0), 57);
    assert!(initial_sides(1e9, 1e-9) <= 1 << 16);
}

#[test]
fn traced_outlines_keep_vertex_counts_bounded_on_a_single_drop() {
    // One drop, nothing after it: the exported circle needs about π·√(R/(2ε)) vertices
    // (one per √(8Rε) of arc, ε = epsilon·T) whatever refinement did.
    let mut design = Design::new(200, 200, marbling_core::Rgb8::new(255, 255, 255));
    design.ops.push(Op::Drop(marbling_core::Drop {
        center: marbling_core::Point::new(100.0, 100.0),
        radius: 80.0,
        color: marbling_core::Rgb8::new(0, 0, 0),
    }));
    let opts = crate::exact::forward_only();
    let v = trace(&design, &opts).expect("traceable");
    let eps = opts.epsilon * opts.tolerance;
    let expected = std::f64::consts::PI * (80.0 / (2.0 * eps)).sqrt();
    println!("{:?}, expected about {expected:.0}", v.stats);
    // Refinement: probes within deviation·T of their chords, so at least as many
    // vertices as that sagitta allows on a circle.
    let min_refined = std::f64::consts::PI * (80.0 / (2.0 * opts.deviation)).sqrt();
    assert!(v.stats.refined_vertices as f64 >= min_refined);
    // RDP picks farthest points rather than even spacing: within 2× of the optimum.
    assert!((v.stats.vertices as f64) < 2.0 * expected);
}

#[test]
fn golden_vector_preview() {
    let design = random_design(5, 160, 120, 80, Mix::Mixed);
    let vector = trace(&design, &crate::exact::forward_only()).expect("traceable");
    let image = rasterize(&vector, 1.0, Blend::default()).expect("preview");
    // The golden image itself agrees with the CPU reference (so updating it cannot
    // bless a wrong render).
    let reference =
        marbling_core::render(&design, &marbling_core::RenderOptions::default()).expect("render");
    let diff = marbling_core::compare::compare(&reference, &image, 48).expect("same size");
    assert!(diff.fraction() <= 0.01, "{:.3} %", 100.0 * diff.fraction());
    let path = marbling_testkit::goldens("vector").join("mixed_80ops_160x120.png");
    check_snapshot(&path, &image, 16, 0.002).unwrap_or_else(|e| panic!("{e}"));
}
