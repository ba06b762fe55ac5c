//! The lossy steps bound vertex counts, say what they dropped, and can be turned off.

use marbling_core::synth::{Mix, random_design};
use marbling_vector::{TraceOptions, VectorError, trace};

#[test]
fn thin_step_bounds_growth_and_reports_what_it_dropped() {
    let design = random_design(31, 200, 150, 150, Mix::CombHeavy);
    let lossy = trace(&design, &TraceOptions::default()).expect("traceable");
    let exact = trace(
        &design,
        &TraceOptions {
            thin: 0.0,
            ..TraceOptions::default()
        },
    )
    .expect("traceable");
    let (l, e) = (lossy.stats, exact.stats);
    println!("lossy {l:?}\nexact {e:?}");
    assert_eq!(e.dropped_pieces, 0);
    assert_eq!(e.dropped_area, 0.0);
    assert!(l.dropped_pieces > 0 && l.dropped_area > 0.0);
    // Dropped pieces are thinner than T/16 on average: little area for what they cost.
    assert!(l.dropped_area < 0.05 * 200.0 * 150.0, "{}", l.dropped_area);
    assert!(l.peak_vertices < e.peak_vertices);
    assert!(l.vertices < e.vertices);
}

#[test]
fn vertex_budget_coarsens_and_keeps_counts_down() {
    let design = random_design(32, 400, 300, 300, Mix::DropHeavy);
    let free = trace(
        &design,
        &TraceOptions {
            max_live: usize::MAX,
            ..TraceOptions::default()
        },
    )
    .expect("traceable");
    let tight = trace(
        &design,
        &TraceOptions {
            max_live: 5_000,
            ..TraceOptions::default()
        },
    )
    .expect("traceable");
    println!("free {:?}\ntight {:?}", free.stats, tight.stats);
    assert_eq!(free.stats.level, 0);
    assert!(tight.stats.level >= 1);
    assert!(tight.stats.peak_vertices < free.stats.peak_vertices);
    assert!(tight.stats.vertices < free.stats.vertices);
}

#[test]
fn out_of_range_fractions_are_refused() {
    let design = random_design(33, 100, 80, 5, Mix::Mixed);
    for opts in [
        TraceOptions {
            thin: -0.5,
            ..TraceOptions::default()
        },
        TraceOptions {
            deviation: 0.0,
            ..TraceOptions::default()
        },
        TraceOptions {
            epsilon: f64::NAN,
            ..TraceOptions::default()
        },
        TraceOptions {
            chord: 0.5,
            ..TraceOptions::default()
        },
    ] {
        let err = trace(&design, &opts).expect_err("refused");
        assert!(matches!(err, VectorError::BadFraction(..)), "{err}");
    }
}
