//! The CPU reference renderer against an independent naive walk, the drop law, output
//! scale, antialiasing in linear light, and size limits.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, SplitMix64, random_design};
use marbling_core::{
    Antialias, Back, Design, Drop, Op, Point, RenderError, RenderOptions, Rgb8, RgbaImage, Traced,
    Walker, output_size, render,
};

const WHITE: Rgb8 = Rgb8::new(255, 255, 255);
const RED: Rgb8 = Rgb8::new(200, 30, 40);
const BLUE: Rgb8 = Rgb8::new(20, 40, 200);

fn opts(scale: f64, antialias: Antialias) -> RenderOptions {
    RenderOptions { scale, antialias }
}

/// A deliberately simple, separate implementation: per pixel, walk `Op::inverse`.
fn naive_render(design: &Design, scale: f64) -> RgbaImage {
    let (w, h) = output_size(design, scale).expect("size");
    let mut img = RgbaImage::filled(w, h, [0, 0, 0, 255]);
    for j in 0..h {
        for i in 0..w {
            let mut p = Point::new((f64::from(i) + 0.5) / scale, (f64::from(j) + 0.5) / scale);
            let mut color = design.background;
            for op in design.ops.iter().rev() {
                match op.inverse(p) {
                    Back::Moved(q) => p = q,
                    Back::Ink(c) => {
                        color = c;
                        break;
                    }
                }
            }
            img.set_pixel(i, j, [color.r, color.g, color.b, 255]);
        }
    }
    img
}

fn count_color(img: &RgbaImage, c: Rgb8) -> usize {
    img.pixels
        .chunks_exact(4)
        .filter(|p| p[..3] == [c.r, c.g, c.b])
        .count()
}

#[test]
fn walker_agrees_with_the_op_inverses() {
    let mut rng = SplitMix64(99);
    for seed in 0..20 {
        let d = random_design(seed, 300, 200, 300, Mix::Mixed);
        let walker = Walker::new(&d.ops);
        for _ in 0..500 {
            let mut p = Point::new(rng.range(-50.0, 350.0), rng.range(-50.0, 250.0));
            let start = p;
            let mut expected = None;
            for (k, op) in d.ops.iter().enumerate().rev() {
                match op.inverse(p) {
                    Back::Moved(q) => p = q,
                    Back::Ink(_) => {
                        expected = Some(k);
                        break;
                    }
                }
            }
            match (walker.trace(start), expected) {
                (Traced::Ink(a), Some(b)) => assert_eq!(a, b, "seed {seed} at {start:?}"),
                (Traced::Background(q), None) => assert!((q - p).hypot() < 1e-6, "{q:?} vs {p:?}"),
                (got, want) => panic!("seed {seed} at {start:?}: walker {got:?}, naive {want:?}"),
            }
        }
    }
}

#[test]
fn batch_walk_equals_point_walk() {
    let d = random_design(5, 200, 200, 500, Mix::Mixed);
    let walker = Walker::new(&d.ops);
    let mut batch = marbling_core::Batch::default();
    let pts: Vec<Point> = (0..400)
        .map(|i| {
            Point::new(
                f64::from(i % 20) * 10.0 + 0.3,
                f64::from(i / 20) * 10.0 + 0.7,
            )
        })
        .collect();
    for (i, p) in pts.iter().enumerate() {
        batch.push(p.x, p.y, i as u32);
    }
    let mut out = vec![Traced::Ink(usize::MAX); pts.len()];
    walker.trace_batch(&mut batch, &mut out);
    for (p, got) in pts.iter().zip(&out) {
        assert_eq!(*got, walker.trace(*p), "at {p:?}");
    }
}

#[test]
fn renderer_matches_an_independent_naive_walk() {
    for seed in 0..6 {
        let d = random_design(seed, 160, 120, 400, Mix::Mixed);
        let exact = render(&d, &opts(1.0, Antialias::None)).expect("render");
        let diff = compare(&exact, &naive_render(&d, 1.0), 0).expect("same size");
        // Only the rake distance's fast fmod may flip a pixel exactly on an ink edge.
        assert!(diff.fraction() <= 0.001, "seed {seed}: {diff:?}");
    }
}

#[test]
fn a_drop_inside_an_older_drop_leaves_an_annulus_of_the_same_area() {
    let mut d = Design::new(400, 400, WHITE);
    d.ops.push(Op::Drop(Drop {
        center: Point::new(200.0, 200.0),
        radius: 80.0,
        color: RED,
    }));
    d.ops.push(Op::Drop(Drop {
        center: Point::new(215.0, 190.0),
        radius: 50.0,
        color: BLUE,
    }));
    let img = render(&d, &opts(1.0, Antialias::None)).expect("render");
    let red = count_color(&img, RED) as f64;
    let blue = count_color(&img, BLUE) as f64;
    let (area_red, area_blue) = (
        std::f64::consts::PI * 80.0 * 80.0,
        std::f64::consts::PI * 50.0 * 50.0,
    );
    assert!(
        (red / area_red - 1.0).abs() < 0.01,
        "red {red} vs {area_red}"
    );
    assert!(
        (blue / area_blue - 1.0).abs() < 0.01,
        "blue {blue} vs {area_blue}"
    );
    // The older ink really is an annulus: the new drop's centre shows blue, and red
    // surrounds it on every side.
    assert_eq!(img.pixel(215, 190)[..3], [BLUE.r, BLUE.g, BLUE.b]);
    for (x, y) in [
        (215 + 60, 190),
        (215 - 60, 190),
        (215, 190 + 60),
        (215, 190 - 60),
    ] {
        assert_eq!(img.pixel(x, y)[..3], [RED.r, RED.g, RED.b], "at {x},{y}");
    }
}

#[test]
fn high_scale_renders_are_crisp_not_enlarged() {
    let mut d = Design::new(300, 200, WHITE);
    d.ops.push(Op::Drop(Drop {
        center: Point::new(150.3, 100.2),
        radius: 37.0,
        color: RED,
    }));
    let img = render(&d, &opts(8.0, Antialias::None)).expect("render");
    assert_eq!((img.width, img.height), (2400, 1600));
    // Only the two exact colours, and the area of the drop at 8× resolution.
    assert_eq!(
        count_color(&img, RED) + count_color(&img, WHITE),
        2400 * 1600
    );
    let expected = std::f64::consts::PI * (37.0 * 8.0f64).powi(2);
    assert!((count_color(&img, RED) as f64 / expected - 1.0).abs() < 0.001);
    // With antialiasing, blended pixels appear only in a one-pixel band along the edge.
    let aa = render(&d, &opts(8.0, Antialias::Rgss)).expect("render");
    for y in 0..aa.height {
        for x in 0..aa.width {
            let p = aa.pixel(x, y);
            if p[..3] != [RED.r, RED.g, RED.b] && p[..3] != [255, 255, 255] {
                let c = Point::new((f64::from(x) + 0.5) / 8.0, (f64::from(y) + 0.5) / 8.0);
                let dist = ((c - Point::new(150.3, 100.2)).hypot() - 37.0).abs() * 8.0;
                assert!(
                    dist < 1.0,
                    "blended pixel {x},{y} is {dist} px from the edge"
                );
            }
        }
    }
}

#[test]
fn samples_are_averaged_in_linear_light() {
    // A straight black edge through the middle of pixel column 0 (a huge drop).
    let mut d = Design::new(4, 4, WHITE);
    let r = 1.0e6;
    d.ops.push(Op::Drop(Drop {
        center: Point::new(0.5 - r, 2.0),
        radius: r,
        color: Rgb8::new(0, 0, 0),
    }));
    let img = render(&d, &opts(1.0, Antialias::Grid4)).expect("render");
    // Half the light: linear 0.5 is sRGB 188, not 128.
    assert_eq!(img.pixel(0, 1)[..3], [188, 188, 188]);
    assert_eq!(img.pixel(2, 1)[..3], [255, 255, 255]);
}

#[test]
fn adaptive_is_grid4_where_rgss_disagrees_and_flat_elsewhere() {
    let d = random_design(11, 160, 120, 300, Mix::DropHeavy);
    let grid = render(&d, &opts(1.0, Antialias::Grid4)).expect("render");
    let rgss = render(&d, &opts(1.0, Antialias::Rgss)).expect("render");
    let adaptive = render(&d, &opts(1.0, Antialias::Adaptive)).expect("render");
    let mut palette: Vec<[u8; 3]> = d
        .ops
        .iter()
        .filter_map(|o| o.ink())
        .map(|c| [c.r, c.g, c.b])
        .collect();
    palette.push([d.background.r, d.background.g, d.background.b]);
    let mut refined = 0;
    for y in 0..grid.height {
        for x in 0..grid.width {
            let (a, g, r) = (adaptive.pixel(x, y), grid.pixel(x, y), rgss.pixel(x, y));
            if a == g && !palette.contains(&[r[0], r[1], r[2]]) {
                refined += 1;
                continue;
            }
            // Not refined: the four RGSS samples agreed, so it is their exact colour.
            assert!(
                a == r && palette.contains(&[a[0], a[1], a[2]]),
                "{x},{y}: {a:?} {g:?} {r:?}"
            );
        }
    }
    assert!(refined > 500, "only {refined} refined pixels");
    let mut flat = Design::new(16, 16, BLUE);
    flat.ops.clear();
    let img = render(&flat, &opts(1.0, Antialias::Adaptive)).expect("render");
    assert_eq!(count_color(&img, BLUE), 256);
}

#[test]
fn scale_sets_the_output_size() {
    let d = Design::new(300, 200, WHITE);
    assert_eq!(output_size(&d, 1.0), Ok((300, 200)));
    assert_eq!(output_size(&d, 0.5), Ok((150, 100)));
    assert_eq!(output_size(&d, 4096.0 / 300.0), Ok((4096, 2731)));
    assert_eq!(output_size(&d, 1e-9), Ok((1, 1)));
    let img = render(&d, &opts(0.1, Antialias::Rgss)).expect("render");
    assert_eq!((img.width, img.height), (30, 20));
}

#[test]
fn bad_scales_and_huge_outputs_are_refused() {
    let d = Design::new(300, 200, WHITE);
    for s in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(
            matches!(output_size(&d, s), Err(RenderError::BadScale(_))),
            "{s}"
        );
    }
    let err = output_size(&d, 1000.0).expect_err("too large");
    assert_eq!(
        err.to_string(),
        "output of 300000×200000 pixels is too large (at most 65536 per side and 268435456 pixels)"
    );
}
