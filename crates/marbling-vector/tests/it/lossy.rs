//! The optional thin step bounds vertex counts and says what it dropped; the vertex
//! budget hands regions to the contour method; options out of range are refused.

use marbling_core::synth::{Mix, random_design};
use marbling_vector::{TraceOptions, VectorError, trace};

#[test]
fn thin_step_bounds_growth_and_reports_what_it_dropped() {
    let design = random_design(31, 200, 150, 150, Mix::CombHeavy);
    let lossy = trace(
        &design,
        &TraceOptions {
            thin: 1.0 / 16.0,
            ..crate::exact::forward_only()
        },
    )
    .expect("traceable");
    let exact = trace(
        &design,
        &TraceOptions {
            thin: 0.0,
            ..crate::exact::forward_only()
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
fn vertex_budget_hands_costly_regions_to_the_contour_method() {
    let design = random_design(32, 400, 300, 300, Mix::DropHeavy);
    let free = trace(
        &design,
        &TraceOptions {
            max_live: usize::MAX,
            ..crate::exact::forward_only()
        },
    )
    .expect("traceable");
    let tight = trace(
        &design,
        &TraceOptions {
            max_live: 5_000,
            ..crate::exact::forward_only()
        },
    )
    .expect("traceable");
    println!("free {:?}\ntight {:?}", free.stats, tight.stats);
    assert_eq!(free.stats.contour_regions, 0);
    assert!(tight.stats.contour_regions >= 1);
    assert!(tight.stats.contour_samples > 0);
    assert!(tight.stats.vertices < free.stats.vertices);
}

#[test]
fn out_of_range_fractions_are_refused() {
    let design = random_design(33, 100, 80, 5, Mix::Mixed);
    for opts in [
        TraceOptions {
            thin: -0.5,
            ..crate::exact::forward_only()
        },
        TraceOptions {
            deviation: 0.0,
            ..crate::exact::forward_only()
        },
        TraceOptions {
            epsilon: f64::NAN,
            ..crate::exact::forward_only()
        },
        TraceOptions {
            chord: 0.5,
            ..crate::exact::forward_only()
        },
    ] {
        let err = trace(&design, &opts).expect_err("refused");
        assert!(matches!(err, VectorError::BadFraction(..)), "{err}");
    }
}
