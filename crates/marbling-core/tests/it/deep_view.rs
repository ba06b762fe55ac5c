//! Deep views of the f64 walk: at 10³, 10⁵ and 10⁶ zoom, each sample's walk back is
//! checked by pushing where it ended forward again through the same ops (the inverse
//! maps checked by their forward maps). The gap |F(W⁻¹(p)) − p| is the walk's backward
//! error: the render equals an exact render whose samples were moved by at most that
//! much. The bound asserted: 10⁻² of a pixel at every depth.

use marbling_core::synth::{Mix, random_design};
use marbling_core::{Batch, Design, Point, Traced, Walker, Window};

/// Largest backward error allowed, in output pixels.
const BOUND_PIXELS: f64 = 1e-2;

/// The drops, combs, styli and vortices the test looks into.
fn designs() -> Vec<(&'static str, Design)> {
    let vortex = Design::from_json(
        r##"{"version":1,"width":400,"height":300,"background":"#f3ead7","ops":[
        {"type":"drop","center":[200,150],"radius":80,"color":"#1d3557"},
        {"type":"drop","center":[200,150],"radius":55,"color":"#e63946"},
        {"type":"drop","center":[200,150],"radius":30,"color":"#f1faee"},
        {"type":"vortex","center":[190,140],"alpha":90,"lambda":20},
        {"type":"circular","center":[210,160],"radius":60,"alpha":50,"lambda":12},
        {"type":"vortex","center":[230,150],"alpha":-60,"lambda":15}]}"##,
    );
    vec![
        ("drops", random_design(11, 400, 300, 200, Mix::DropHeavy)),
        ("combs", random_design(12, 400, 300, 200, Mix::CombHeavy)),
        ("tines", random_design(13, 400, 300, 120, Mix::AllTypes)),
        ("stylus", random_design(14, 400, 300, 40, Mix::Stylus)),
        (
            "vortex",
            vortex.unwrap_or_else(|e| panic!("vortex design: {e}")),
        ),
    ]
}

/// A point on an edge between two colours (bisected on a row of the sheet), where a deep
/// view has something to show.
fn edge_point(walker: &Walker, design: &Design) -> Point {
    let ink = |p: Point| match walker.trace(p) {
        Traced::Ink(k) => k as i64,
        Traced::Background(_) => -1,
    };
    let y = f64::from(design.height) * 0.45;
    let w = f64::from(design.width);
    for i in 0..200 {
        let (mut a, mut b) = (w * f64::from(i) / 200.0, w * f64::from(i + 1) / 200.0);
        let ka = ink(Point::new(a, y));
        if ink(Point::new(b, y)) == ka {
            continue;
        }
        for _ in 0..60 {
            let m = 0.5 * (a + b);
            if ink(Point::new(m, y)) == ka {
                a = m;
            } else {
                b = m;
            }
        }
        return Point::new(a, y);
    }
    Point::new(w / 2.0, y)
}

/// The largest backward error (design pixels) over a `side × side` window's pixel
/// centres at `scale` around `centre`, and whether the window shows more than one colour;
/// `start` rounds each sample's point before its walk (the identity for the f64 walk).
fn backward_error(
    walker: &Walker,
    centre: Point,
    scale: f64,
    side: u32,
    start: impl Fn(Point) -> Point,
) -> (f64, bool) {
    let window = Window::centred(centre, scale, side, side);
    let mut batch = Batch::default();
    let mut samples = Vec::new();
    for j in 0..side {
        for i in 0..side {
            let p = Point::new(
                window.x0 + (f64::from(i) + 0.5) / scale,
                window.y0 + (f64::from(j) + 0.5) / scale,
            );
            let q = start(p);
            batch.push(q.x, q.y, samples.len() as u32);
            samples.push(p);
        }
    }
    let mut traced = vec![Traced::Ink(0); samples.len()];
    let mut ends = vec![Point::ZERO; samples.len()];
    walker.trace_batch_with_ends(&mut batch, &mut traced, &mut ends);
    let steps = walker.steps();
    let mut worst = 0.0_f64;
    for ((p, t), end) in samples.iter().zip(&traced).zip(&ends) {
        let first = match t {
            Traced::Ink(k) => k + 1,
            Traced::Background(_) => 0,
        };
        let pushed = steps[first..].iter().fold(*end, |q, s| s.forward(q));
        worst = worst.max((pushed - *p).hypot());
    }
    let mixed = traced.iter().any(|t| *t != traced[0]);
    (worst, mixed)
}

#[test]
fn the_f64_walk_is_exact_to_a_hundredth_of_a_pixel_at_a_million_times_zoom() {
    let mut report = Vec::new();
    for (name, design) in designs() {
        let walker = Walker::new(&design.ops);
        let centre = edge_point(&walker, &design);
        for scale in [1e3, 1e5, 1e6] {
            let (error, _) = backward_error(&walker, centre, scale, 12, |p| p);
            let pixels = error * scale;
            report.push(format!("{name} at {scale:e}: {pixels:.2e} px"));
            assert!(
                pixels <= BOUND_PIXELS,
                "{name} at {scale:e}×: backward error {pixels:e} px (bound {BOUND_PIXELS})\n{}",
                report.join("\n")
            );
        }
    }
    println!("{}", report.join("\n"));
}

#[test]
fn the_bound_catches_a_walk_started_in_f32_at_a_million_times() {
    let (_, design) = &designs()[1];
    let walker = Walker::new(&design.ops);
    let centre = edge_point(&walker, design);
    let f32_start = |p: Point| Point::new(f64::from(p.x as f32), f64::from(p.y as f32));
    let (error, _) = backward_error(&walker, centre, 1e6, 12, f32_start);
    assert!(
        error * 1e6 > 100.0 * BOUND_PIXELS,
        "an f32 start should move samples by much more than the bound, got {:e} px",
        error * 1e6
    );
}

#[test]
fn a_deep_window_on_an_edge_shows_both_sides_of_it() {
    for (name, design) in designs() {
        let walker = Walker::new(&design.ops);
        let centre = edge_point(&walker, &design);
        let (_, mixed) = backward_error(&walker, centre, 1e6, 12, |p| p);
        assert!(
            mixed,
            "{name}: the 10⁶× window at {centre:?} shows one colour"
        );
    }
}
