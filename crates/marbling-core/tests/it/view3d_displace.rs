//! Perlin displacement of the 3D view (Kung 2019, ch. 3): off, it leaves today's
//! picture; barely on, the march finds the analytic surfaces; on, every surface point
//! moves along its normal by at most s·max|noise|, and bad numbers are refused by name.

use marbling_core::view3d::{Camera, Displace, Object, Shape, Vec3, View3d, render_3d};
use marbling_core::{Antialias, Design, Drop, Op, Point, Rgb8, RgbaImage};
use marbling_noise::{PERLIN3_BOUND, fbm3};

fn design() -> Design {
    let mut d = Design::new(120, 80, Rgb8::new(250, 245, 230));
    for (i, x) in [20.0, 60.0, 100.0].into_iter().enumerate() {
        d.ops.push(Op::Drop(Drop {
            center: Point::new(x, 40.0),
            radius: 14.0,
            color: [
                Rgb8::new(20, 30, 120),
                Rgb8::new(200, 40, 30),
                Rgb8::new(30, 140, 60),
            ][i],
        }));
    }
    d
}

fn view(shape: Shape, displace: Displace) -> View3d {
    View3d {
        shape,
        camera: Camera {
            yaw: Some(30.0),
            pitch: Some(20.0),
            ..Camera::default()
        },
        width: 96,
        height: 64,
        antialias: Antialias::Rgss,
        texture: None,
        displace,
    }
}

fn render(shape: Shape, displace: Displace) -> RgbaImage {
    render_3d(&design(), &view(shape, displace)).expect("renders")
}

/// Share of pixels whose channels differ by more than `tolerance`.
fn differing(a: &RgbaImage, b: &RgbaImage, tolerance: u8) -> f64 {
    let n = a
        .pixels
        .chunks(4)
        .zip(b.pixels.chunks(4))
        .filter(|(p, q)| {
            p.iter()
                .zip(q.iter())
                .any(|(x, y)| x.abs_diff(*y) > tolerance)
        })
        .count();
    n as f64 / (a.pixels.len() / 4) as f64
}

fn displace(amount: f64, frequency: f64) -> Displace {
    Displace {
        amount,
        frequency,
        ..Displace::default()
    }
}

#[test]
fn no_displacement_is_todays_picture_and_a_tiny_one_marches_onto_the_same_surfaces() {
    for shape in Shape::ALL {
        let plain = render(shape, Displace::default());
        // s = 0 or f = 0: the same bytes.
        assert_eq!(
            render(shape, displace(0.0, 5.0)).pixels,
            plain.pixels,
            "{shape:?} s = 0"
        );
        assert_eq!(
            render(shape, displace(0.4, 0.0)).pixels,
            plain.pixels,
            "{shape:?} f = 0"
        );
        // s = 1e-7: the march and its finite-difference normals, on every shape, land on
        // the analytic surface (edge pixels of the silhouette may flip: 1.5 %).
        let marched = render(shape, displace(1e-7, 3.0));
        let off = differing(&plain, &marched, 6);
        assert!(
            off < 0.015,
            "{shape:?}: {:.2} % of pixels differ",
            100.0 * off
        );
    }
}

#[test]
fn a_displaced_point_moves_along_its_normal_by_at_most_s_times_the_noise_bound() {
    let d = displace(0.3, 3.0);
    let sphere = Object {
        shape: Shape::Sphere,
        aspect: 1.5,
        displace: d,
    };
    let (mut hits, mut largest) = (0, 0.0_f64);
    let origin = Vec3::new(0.0, 0.4, 5.0);
    for i in 0..40 {
        for j in 0..40 {
            let dir = Vec3::new(
                (f64::from(i) - 19.5) / 60.0,
                (f64::from(j) - 19.5) / 60.0 - 0.08,
                -1.0,
            )
            .normalized();
            let Some(hit) = sphere.hit(origin, dir) else {
                continue;
            };
            hits += 1;
            let x = origin + dir * hit.t;
            let r = x.length();
            let foot = x * (1.0 / r);
            // On the sphere the displaced surface is r = 1 + s·fbm(f·x̂) exactly.
            let expected = 0.3
                * f64::from(fbm3(
                    [
                        (foot.x * 3.0) as f32,
                        (foot.y * 3.0) as f32,
                        (foot.z * 3.0) as f32,
                    ],
                    1,
                    2.0,
                    0.5,
                    marbling_core::view3d::displace::SEED,
                ));
            assert!(
                (r - 1.0 - expected).abs() < 1e-4,
                "r − 1 = {} vs h = {expected}",
                r - 1.0
            );
            assert!((r - 1.0).abs() <= 0.3 * f64::from(PERLIN3_BOUND));
            largest = largest.max((r - 1.0).abs());
            assert!(hit.normal.dot(dir) < 0.0, "the normal faces the ray");
        }
    }
    assert!(hits > 400, "{hits} rays hit the sphere");
    // The surface did move (a broken height would leave the unit sphere).
    assert!(largest > 0.1, "largest displacement {largest}");
}

#[test]
fn a_displaced_picture_differs_and_bad_numbers_are_refused_by_name() {
    let plain = render(Shape::Sphere, Displace::default());
    let bumpy = render(Shape::Sphere, displace(0.25, 4.0));
    assert!(differing(&plain, &bumpy, 24) > 0.2);
    for (d, message) in [
        (
            displace(0.9, 1.0),
            "displace amount must be a number from 0 to 0.5, got 0.9",
        ),
        (
            displace(0.1, f64::NAN),
            "displace frequency must be a number from 0 to 12, got NaN",
        ),
        (
            Displace {
                octaves: 9,
                ..displace(0.1, 1.0)
            },
            "displace octaves must be 1 to 6, got 9",
        ),
    ] {
        let e = view(Shape::Vase, d).check(&design()).expect_err("refused");
        assert_eq!(e.to_string(), message);
    }
}
