//! The agreement comparison can fail: a perturbed vector render is caught.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};
use marbling_vector::{Blend, rasterize, trace};

#[test]
fn perturbed_vector_render_fails_the_budget() {
    let design = random_design(7, 200, 150, 60, Mix::DropHeavy);
    let opts = crate::exact::forward_only();
    let mut vector = trace(&design, &opts).expect("traceable");
    let reference = render(&design, &RenderOptions::default()).expect("render");
    let good = rasterize(&vector, 1.0, Blend::Linear(Antialias::Rgss)).expect("preview");
    let ok = compare(&reference, &good, 48).expect("same size");
    assert!(
        ok.fraction() <= 0.01,
        "unperturbed: {:.3} %",
        100.0 * ok.fraction()
    );
    // Shift every outline by 3 design pixels: the comparison must notice.
    for o in &mut vector.outlines {
        for p in o.rings.iter_mut().flatten() {
            p.x += 3.0;
        }
    }
    let bad = rasterize(&vector, 1.0, Blend::Linear(Antialias::Rgss)).expect("preview");
    let d = compare(&reference, &bad, 48).expect("same size");
    println!(
        "unperturbed {:.3} %, shifted {:.3} %",
        100.0 * ok.fraction(),
        100.0 * d.fraction()
    );
    assert!(
        d.fraction() > 0.01,
        "shifted render passed: {:.3} %",
        100.0 * d.fraction()
    );
    // And the reference against itself is exact (the comparison is not vacuous).
    assert_eq!(
        compare(&reference, &reference, 0)
            .expect("same size")
            .differing,
        0
    );
}
