//! The contour method: regions past the vertex budget are read off the exact label
//! raster, the SVG says which method drew each region, the dense pixels come as one
//! raster patch, and the result still agrees with the exact render.

use crate::exact::{forward_only, svg_against_exact};
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{Method, TraceOptions, to_svg, trace};

#[test]
fn a_cheap_raster_contours_every_region_and_exact_traces_none() {
    let design = random_design(40, 160, 120, 60, Mix::Mixed);
    let all = trace(&design, &TraceOptions::default()).expect("traceable");
    assert_eq!(all.stats.contour_regions, all.stats.regions);
    assert!(all.outlines.iter().all(|o| o.method == Method::Contour));
    let forward = trace(&design, &forward_only()).expect("traceable");
    assert_eq!(forward.stats.contour_regions, 0);
    assert!(forward.outlines.iter().all(|o| o.method == Method::Forward));
    // The contour method grows older ink under newer: where drops abut, no seam of
    // background shows, so it agrees at least as well as forward tracing.
    let (a, f) = (
        svg_against_exact(&design, &to_svg(&all), 1.0),
        svg_against_exact(&design, &to_svg(&forward), 1.0),
    );
    println!(
        "contour {:.3} %, forward {:.3} %",
        100.0 * a.fraction(),
        100.0 * f.fraction()
    );
    assert!(a.fraction() <= f.fraction() + 0.001);
}

#[test]
fn regions_past_the_budget_are_contoured_and_marked() {
    let design = random_design(41, 160, 120, 300, Mix::Mixed);
    let forward = trace(&design, &forward_only()).expect("traceable");
    let tight = trace(
        &design,
        &TraceOptions {
            max_live: 2_000,
            ..forward_only()
        },
    )
    .expect("traceable");
    let (f, t) = (forward.stats, tight.stats);
    println!("default {f:?}\ntight {t:?}");
    assert!(t.contour_regions > f.contour_regions);
    assert!(t.contour_samples > 0 && t.contour_step == 0.25);
    let svg = to_svg(&tight);
    let by = |m: Method| tight.outlines.iter().filter(|o| o.method == m).count();
    let marked = |name: &str| {
        svg.matches(&format!("<path data-method=\"{name}\""))
            .count()
    };
    assert!(by(Method::Contour) > 0 && by(Method::Forward) > 0);
    assert_eq!(marked("contour"), by(Method::Contour));
    assert_eq!(marked("forward"), by(Method::Forward));
    assert_eq!(
        svg.matches("data-method=\"raster\"").count(),
        usize::from(tight.dense.is_some())
    );
    // Painter's order is op order, whichever method drew a region.
    assert!(
        tight
            .outlines
            .windows(2)
            .all(|w| w[0].op_index < w[1].op_index)
    );
    let diff = svg_against_exact(&design, &svg, 1.0);
    println!("tight budget: {:.3} % differ", 100.0 * diff.fraction());
    assert!(diff.fraction() <= 0.02, "{:.3} %", 100.0 * diff.fraction());
}

/// The dense patch carries the pixels where three or more inks meet: without it the
/// SVG of a chaotic design is far from the exact render (so the agreement test can
/// fail), with it within budget.
#[test]
fn the_dense_patch_is_what_keeps_chaotic_designs_faithful() {
    let design = random_design(42, 160, 120, 1000, Mix::CombHeavy);
    let vector = trace(&design, &TraceOptions::default()).expect("traceable");
    assert!(vector.stats.dense_pixels > 0);
    let with = svg_against_exact(&design, &to_svg(&vector), 1.0);
    let mut bare = vector.clone();
    bare.dense = None;
    let without = svg_against_exact(&design, &to_svg(&bare), 1.0);
    let mut shifted = vector.clone();
    for p in shifted
        .outlines
        .iter_mut()
        .flat_map(|o| o.rings.iter_mut().flatten())
    {
        p.x += 3.0;
    }
    let moved = svg_against_exact(&design, &to_svg(&shifted), 1.0);
    println!(
        "{} dense px: {:.3} % differ, {:.3} % without the patch, {:.3} % with outlines moved 3 px",
        vector.stats.dense_pixels,
        100.0 * with.fraction(),
        100.0 * without.fraction(),
        100.0 * moved.fraction()
    );
    assert!(with.fraction() <= 0.02);
    assert!(without.fraction() > 0.05);
    assert!(moved.fraction() > 0.02);
}
