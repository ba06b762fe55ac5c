//! The 3D view: texture coordinates land where the conventions say, and a close-up of
//! an ink edge stays sharp when every sample is walked, unlike a baked texture.

use marbling_core::view3d::{Camera, Shape, View3d, render_3d};
use marbling_core::{Antialias, Design, Drop, Op, Point, Rgb8, RgbaImage};

const INK: Rgb8 = Rgb8::new(20, 30, 120);
const PAPER: Rgb8 = Rgb8::new(250, 245, 230);

fn one_drop(w: u32, h: u32, center: (f64, f64), radius: f64) -> Design {
    let mut d = Design::new(w, h, PAPER);
    d.ops.push(Op::Drop(Drop {
        center: Point::new(center.0, center.1),
        radius,
        color: INK,
    }));
    d
}

fn view(shape: Shape, camera: Camera, size: (u32, u32)) -> View3d {
    View3d {
        shape,
        camera,
        width: size.0,
        height: size.1,
        antialias: Antialias::Rgss,
        texture: None,
        displace: marbling_core::view3d::Displace::default(),
    }
}

/// How many pixels of row `y` are neither ink nor paper (a channel ≥ 12 from both).
fn edge_width(img: &RgbaImage, y: u32) -> usize {
    let near = |p: [u8; 4], c: Rgb8| {
        p[0].abs_diff(c.r) < 12 && p[1].abs_diff(c.g) < 12 && p[2].abs_diff(c.b) < 12
    };
    (0..img.width)
        .filter(|&x| {
            let p = img.pixel(x, y);
            !near(p, INK) && !near(p, PAPER)
        })
        .count()
}

#[test]
fn the_sphere_shows_the_design_where_the_mapping_says() {
    // u = ½ + atan2(x, z)/2π: the front (yaw 0) shows u = ½, the right side (yaw 90°)
    // u = ¾; v = ½ on the equator.
    let mut d = one_drop(200, 100, (100.0, 50.0), 6.0);
    d.ops.push(Op::Drop(Drop {
        center: Point::new(150.0, 50.0),
        radius: 6.0,
        color: Rgb8::new(200, 20, 20),
    }));
    for (yaw, expected) in [(0.0, INK), (90.0, Rgb8::new(200, 20, 20))] {
        let camera = Camera {
            yaw: Some(yaw),
            pitch: Some(0.0),
            ..Camera::default()
        };
        let img = render_3d(&d, &view(Shape::Sphere, camera, (64, 64))).expect("render");
        let c = img.pixel(32, 32);
        // Lit head-on: the colour itself (the headlight's factor is 1 there).
        assert!(
            [c[0], c[1], c[2]]
                .iter()
                .zip([expected.r, expected.g, expected.b])
                .all(|(a, b)| a.abs_diff(b) <= 3),
            "yaw {yaw}: centre pixel {c:?}, expected {expected}"
        );
        // The corners miss the sphere: backdrop, not ink.
        assert_ne!(img.pixel(0, 0)[..3], [expected.r, expected.g, expected.b]);
    }
}

#[test]
fn a_close_up_edge_stays_sharp_and_a_baked_texture_blurs() {
    // A drop edge at design point (356, 256), seen at zoom 200 on the plane and on the
    // vase (a hundredth of a design pixel off, so it crosses a pixel): the exact view keeps it ≤ 2 px wide;
    // a 2048² texture of the same design spreads it over about one texel, 2048/200
    // texels being ~10 across the frame's 120-pixel height.
    let d = one_drop(512, 512, (256.0, 256.0), 100.0);
    for shape in [Shape::Plane, Shape::Vase] {
        let camera = Camera {
            zoom: 200.0,
            look_at: Some(Point::new(356.01, 256.0)),
            ..Camera::default()
        };
        let exact = render_3d(&d, &view(shape, camera, (240, 120))).expect("exact");
        let mut textured = view(shape, camera, (240, 120));
        textured.texture = Some(2048);
        let baked = render_3d(&d, &textured).expect("texture");
        let (e, t) = (edge_width(&exact, 60), edge_width(&baked, 60));
        println!(
            "{}: edge {e} px exact, {t} px from a 2048² texture",
            shape.name()
        );
        assert!(e <= 2, "{}: exact edge {e} px wide", shape.name());
        assert!(t >= 8, "{}: texture edge only {t} px wide", shape.name());
        // The edge is in the frame: ink on the left, paper on the right.
        let (left, right) = (exact.pixel(5, 60), exact.pixel(234, 60));
        assert_eq!(left[..3], [INK.r, INK.g, INK.b], "{}", shape.name());
        assert_eq!(right[..3], [PAPER.r, PAPER.g, PAPER.b], "{}", shape.name());
    }
}

#[test]
fn bad_views_are_refused() {
    let d = one_drop(100, 100, (50.0, 50.0), 10.0);
    let mut v = view(Shape::Book, Camera::default(), (32, 32));
    v.camera.zoom = 0.0;
    let e = render_3d(&d, &v).expect_err("zoom 0").to_string();
    assert!(e.contains("zoom"), "{e}");
    v.camera.zoom = 1.0;
    v.camera.look_at = Some(Point::new(150.0, 5.0));
    let e = render_3d(&d, &v).expect_err("outside").to_string();
    assert!(e.contains("outside the 100×100 design"), "{e}");
    v.camera.look_at = None;
    v.camera.pitch = Some(90.0);
    assert!(render_3d(&d, &v).is_err());
    v.camera.pitch = None;
    v.texture = Some(100_000);
    let e = render_3d(&d, &v).expect_err("texture").to_string();
    assert!(e.contains("texture side"), "{e}");
    v.texture = None;
    v.width = 0;
    assert!(render_3d(&d, &v).is_err());
}

#[test]
fn every_shape_draws_the_design_and_its_own_faces() {
    let d = one_drop(160, 120, (80.0, 60.0), 40.0);
    for shape in Shape::ALL {
        let camera = Camera {
            yaw: Some(30.0),
            pitch: Some(20.0),
            ..Camera::default()
        };
        let img = render_3d(&d, &view(shape, camera, (48, 48))).expect("render");
        let inky = (0..48 * 48)
            .filter(|i| {
                let p = img.pixel(i % 48, i / 48);
                i32::from(p[2]) > i32::from(p[0]) + 20
            })
            .count();
        assert!(inky > 20, "{}: only {inky} ink pixels", shape.name());
    }
}

/// Width in pixels of a red sphere on row `y` (red even where the headlight grazes it,
/// unlike the grey backdrop).
fn red_width(img: &RgbaImage, y: u32) -> usize {
    (0..img.width)
        .filter(|&x| {
            let p = img.pixel(x, y);
            p[0] > 80 && p[1] < 50 && p[2] < 50
        })
        .count()
}

#[test]
fn a_dolly_moves_the_camera_along_its_line_and_a_turn_adds_to_the_yaw() {
    // An all-red sphere: its silhouette's half-angle θ at camera distance c from the
    // centre has tan θ = r/√(c² − r²), r = 1, and the frame's tan(fov/2) stays as zoom 1
    // sets it, so the width on screen scales with tan θ.
    let mut d = Design::new(200, 100, Rgb8::new(200, 20, 20));
    d.ops.clear();
    let size = (240, 240);
    let width = |dolly: f64| {
        let camera = Camera {
            yaw: Some(0.0),
            pitch: Some(0.0),
            // Zoomed out, so the sphere fits the frame at the nearest dolly too.
            zoom: 0.5,
            dolly,
            ..Camera::default()
        };
        let img = render_3d(&d, &view(Shape::Sphere, camera, size)).expect("render");
        red_width(&img, 120) as f64
    };
    let base = View3d::distance(&view(Shape::Sphere, Camera::default(), size).object(&d));
    let tan = |c: f64| 1.0 / (c * c - 1.0).sqrt();
    let (w1, w2, w07) = (width(1.0), width(2.0), width(0.7));
    for (dolly, w) in [(2.0, w2), (0.7, w07)] {
        let expected = w1 * tan(base * dolly) / tan(base);
        println!("dolly {dolly}: {w} px wide, expected {expected:.1} (dolly 1: {w1})");
        assert!(
            (w - expected).abs() <= 2.0,
            "dolly {dolly}: {w} vs {expected}"
        );
    }
    // Out of range: a message naming the dolly.
    let mut v = view(Shape::Sphere, Camera::default(), size);
    v.camera.dolly = 0.5;
    let e = render_3d(&d, &v).expect_err("too close").to_string();
    assert!(e.contains("dolly must be a number from 0.7 to 5"), "{e}");

    // A turn resolves the camera facing its look-at point first, then adds degrees.
    d = one_drop(200, 100, (100.0, 50.0), 6.0);
    d.ops.push(Op::Drop(Drop {
        center: Point::new(150.0, 50.0),
        radius: 6.0,
        color: Rgb8::new(200, 20, 20),
    }));
    let facing = view(
        Shape::Sphere,
        Camera {
            look_at: Some(Point::new(100.0, 50.0)),
            ..Camera::default()
        },
        (64, 64),
    );
    let unturned = render_3d(&d, &facing).expect("facing");
    let same = render_3d(&d, &facing.turned(&d, 0.0)).expect("turned 0");
    assert_eq!(
        unturned.pixels, same.pixels,
        "a turn of 0° is the view itself"
    );
    let yaw = facing.turned(&d, 90.0).camera.yaw.expect("resolved");
    assert!((yaw - 90.0).abs() < 1e-9, "yaw {yaw}");
    // About the centre (no look-at point), a quarter turn shows u = ¾.
    let mut centred = facing;
    centred.camera.look_at = None;
    let quarter = centred.turned(&d, 90.0);
    let c = render_3d(&d, &quarter).expect("turned 90").pixel(32, 32);
    assert!(
        c[0] > 150 && c[2] < 60,
        "a quarter turn faces the red drop: {c:?}"
    );
}
