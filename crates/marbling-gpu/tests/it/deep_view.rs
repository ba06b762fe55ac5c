//! Deep zoom on the GPU: the perturbed walk (`shaders/deep.wgsl`) against the CPU's f64
//! render of the same window at 10⁴, 10⁵ and 10⁶ zoom, and the plain f32 walk shown to
//! fail there (so the comparison can tell the two apart).

use crate::common::{renderer, rounded_to_f32, scaled};
use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, Design, Point, RgbaImage, Traced, Walker, Window, render_window};
use marbling_gpu::GpuRenderer;

/// A channel difference above this counts as a differing pixel (out of 255).
const THRESHOLD: u8 = 8;
/// Window side, pixels.
const SIDE: u32 = 96;
/// Largest share of differing pixels on well-conditioned designs.
const BUDGET: f64 = 0.005;

/// A point on an edge between two colours (bisected along one of a few rows), where a
/// deep window has something to show.
fn edge_point(design: &Design) -> Point {
    let walker = Walker::new(&design.ops);
    let colour = |p: Point| match walker.trace(p) {
        Traced::Ink(k) => walker.steps()[k].ink(),
        Traced::Background(_) => None,
    };
    let w = f64::from(design.width);
    for row in [0.5, 0.3, 0.7, 0.4, 0.6] {
        let y = f64::from(design.height) * row;
        for i in 0..100 {
            let (mut a, mut b) = (w * f64::from(i) / 100.0, w * f64::from(i + 1) / 100.0);
            let ka = colour(Point::new(a, y));
            if colour(Point::new(b, y)) == ka {
                continue;
            }
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if colour(Point::new(m, y)) == ka {
                    a = m;
                } else {
                    b = m;
                }
            }
            return Point::new(a, y);
        }
    }
    panic!("no edge between two colours found");
}

/// Well-conditioned designs: drops then combs, swirls and styli at 0.3 strength.
fn designs() -> Vec<(&'static str, Design)> {
    vec![
        (
            "combs",
            scaled(random_design(21, 400, 300, 300, Mix::CombHeavy), 0.3),
        ),
        (
            "mixed",
            scaled(random_design(22, 400, 300, 200, Mix::Mixed), 0.3),
        ),
        (
            "v3",
            scaled(random_design(23, 400, 300, 120, Mix::AllTypes), 0.3),
        ),
        ("stylus", random_design(24, 400, 300, 30, Mix::Stylus)),
    ]
}

#[test]
fn the_deep_walk_matches_the_f64_render_at_a_million_times_and_the_plain_walk_does_not() {
    let Some(gpu) = renderer() else { return };
    let mut report = Vec::new();
    for (name, design) in designs() {
        let centre = edge_point(&design);
        for scale in [1e4, 1e5, 1e6] {
            let window = Window::centred(centre, scale, SIDE, SIDE);
            let cpu = render_window(&design, &window, Antialias::Rgss)
                .unwrap_or_else(|e| panic!("{name}: cpu {e}"));
            let deep = gpu
                .render_window(&design, &window, Antialias::Rgss)
                .unwrap_or_else(|e| panic!("{name}: gpu {e}"));
            let diff = compare(&cpu, &deep, THRESHOLD).map(|d| d.fraction());
            report.push(format!("{name} at {scale:e}: deep {diff:?}"));
            assert!(
                diff.as_ref().is_ok_and(|f| *f <= BUDGET),
                "{name} at {scale:e}×: {diff:?} of pixels differ (budget {BUDGET})\n{}",
                report.join("\n")
            );
            let colours: std::collections::HashSet<&[u8]> = cpu.pixels.chunks(4).collect();
            assert!(
                colours.len() > 1,
                "{name} at {scale:e}×: the window at {centre:?} shows one colour\n{}",
                report.join("\n")
            );
            if scale == 1e5 {
                let plain = plain_window(&gpu, &design, &window);
                let f = compare(&cpu, &plain, THRESHOLD).map(|d| d.fraction());
                report.push(format!("{name} at {scale:e}: plain f32 {f:?}"));
                assert!(
                    f.as_ref().is_ok_and(|f| *f > BUDGET),
                    "{name}: the plain f32 walk at 10⁵ should miss the budget, got {f:?}"
                );
            }
        }
    }
    println!("{}", report.join("\n"));
}

/// `window` drawn by the plain f32 walk.
fn plain_window(gpu: &GpuRenderer, design: &Design, window: &Window) -> RgbaImage {
    gpu.render_window_f32(design, window, Antialias::Rgss)
        .unwrap_or_else(|e| panic!("plain: {e}"))
}

#[test]
fn on_a_chaotic_design_the_deep_walk_stays_within_the_f32_chaos_baseline() {
    let Some(gpu) = renderer() else { return };
    // Full-strength combs stretch ink exponentially: rounding the design's own numbers to
    // f32 (what any f32 renderer receives) already moves edges; that is the baseline.
    let design = random_design(31, 400, 300, 300, Mix::CombHeavy);
    let window = Window::centred(edge_point(&design), 1e5, SIDE, SIDE);
    let render = |d: &Design| {
        render_window(d, &window, Antialias::Rgss).unwrap_or_else(|e| panic!("cpu: {e}"))
    };
    let cpu = render(&design);
    let fraction = |img: &RgbaImage| compare(&cpu, img, THRESHOLD).map_or(1.0, |d| d.fraction());
    let baseline = fraction(&render(&rounded_to_f32(design.clone())));
    let deep = fraction(
        &gpu.render_window(&design, &window, Antialias::Rgss)
            .unwrap_or_else(|e| panic!("gpu: {e}")),
    );
    println!("chaotic comb-heavy at 1e5: deep {deep}, f32-rounded design {baseline}");
    assert!(
        deep <= baseline + BUDGET,
        "deep walk {deep} of pixels differ, beyond the f32 baseline {baseline} + {BUDGET}"
    );
}
