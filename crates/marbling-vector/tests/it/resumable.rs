//! The resumable tracer behind the app's Export SVG: stepped one unit per call (a clock
//! that jumps past every budget), it gives the same SVG as tracing whole, reports
//! progress that only grows, and refuses to finish early.

use crate::exact::forward_only;
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{TraceOptions, Tracer, to_svg, trace};
use std::cell::Cell;

/// The SVG of `design` traced by `advance` calls that each do one step, and the calls.
fn stepped(design: &marbling_core::Design, opts: &TraceOptions) -> (String, usize) {
    let mut tracer = Tracer::new(design.clone(), opts).expect("traceable");
    let clock = Cell::new(0.0);
    let now = || {
        clock.set(clock.get() + 100.0);
        clock.get()
    };
    let mut calls = 0;
    let mut last = (0, 0);
    loop {
        calls += 1;
        let done = tracer.advance(25.0, now).expect("traces");
        let (d, t) = tracer.progress();
        assert!(d >= last.0 && d <= t, "progress {d}/{t} after {last:?}");
        last = (d, t);
        if done {
            break;
        }
    }
    assert_eq!(last.0, last.1, "complete but progress says {last:?}");
    (to_svg(&tracer.finish().expect("complete")), calls)
}

#[test]
fn a_stepped_trace_is_the_whole_trace() {
    let design = random_design(41, 160, 120, 300, Mix::Mixed);
    // Forward tracing that hands regions to the contour method, and contours only.
    let mixed = TraceOptions {
        max_live: 2_000,
        ..forward_only()
    };
    for opts in [mixed, TraceOptions::default()] {
        let whole = to_svg(&trace(&design, &opts).expect("traceable"));
        let (svg, calls) = stepped(&design, &opts);
        assert_eq!(svg, whole, "the stepped trace differs ({opts:?})");
        // Every op traced forward is a step, and the label raster takes several.
        let least = if opts.contour_all > 0.0 {
            4
        } else {
            design.ops.len() + 4
        };
        assert!(
            calls >= least,
            "{calls} steps: the trace was not spread out"
        );
    }
}

#[test]
fn an_unfinished_trace_cannot_be_taken() {
    let design = random_design(42, 80, 60, 20, Mix::Mixed);
    let mut tracer = Tracer::new(design, &TraceOptions::default()).expect("traceable");
    assert!(!tracer.step().expect("steps"));
    let Err(err) = tracer.finish() else {
        panic!("an unfinished trace was taken")
    };
    assert!(err.to_string().contains("not complete"), "{err}");
}
