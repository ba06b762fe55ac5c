//! Styles of the 3D view (Bénard et al. 2010; Kaplan & Cohen 2005): the marks keep their
//! screen size as the object recedes (texture mapping does not), move with the surface
//! as the camera turns (a screen-fixed noise does not), change continuously with the
//! kernel density, and the fibres hold their density per screen pixel from zoom 1 to 16.

use marbling_core::view3d::style::{StyleFrame, style_frame};
use marbling_core::view3d::{Camera, Shape, Vec3, View3d};
use marbling_core::{Antialias, Design, Drop, Op, Point, Rgb8};
use marbling_noise::{Anchoring, Follow, STYLE_KINDS, StyleKind, StyleSpec};

fn design() -> Design {
    let mut d = Design::new(100, 100, Rgb8::new(250, 245, 230));
    d.ops.push(Op::Drop(Drop {
        center: Point::new(50.0, 50.0),
        radius: 30.0,
        color: Rgb8::new(20, 30, 120),
    }));
    d
}

fn view(shape: Shape, side: u32, zoom: f64, yaw: f64, pitch: f64) -> View3d {
    View3d {
        shape,
        camera: Camera {
            yaw: Some(yaw),
            pitch: Some(pitch),
            zoom,
            ..Camera::default()
        },
        width: side,
        height: side,
        antialias: Antialias::None,
        texture: None,
        displace: Default::default(),
    }
}

fn frame(view: &View3d, spec: &StyleSpec) -> StyleFrame {
    match style_frame(&design(), view, spec) {
        Ok(f) => f,
        Err(e) => panic!("style frame: {e}"),
    }
}

/// Vertical strokes (frequency along x) fixed to the screen's axes.
fn vertical_hatching(anchoring: Anchoring) -> StyleSpec {
    let mut s = StyleSpec::preset(StyleKind::Hatching);
    s.marks.follow = Follow::Screen;
    s.marks.orientation = 90.0;
    s.anchoring = anchoring;
    s
}

/// Sign changes per pixel along rows of the noise in a square of half-side `half`
/// about the frame's centre: about twice the frequency across the strokes.
fn crossing_rate(f: &StyleFrame, half: u32) -> f64 {
    let (w, c) = (f.width as usize, (f.width / 2) as usize);
    let (mut changes, mut pairs) = (0u32, 0u32);
    for y in c - half as usize..c + half as usize {
        for x in c - half as usize..c + half as usize - 1 {
            let (a, b) = (f.noise[y * w + x], f.noise[y * w + x + 1]);
            if a.is_finite() && b.is_finite() {
                pairs += 1;
                changes += u32::from((a > 0.0) != (b > 0.0));
            }
        }
    }
    assert!(pairs > 1000, "too few samples: {pairs}");
    f64::from(changes) / f64::from(pairs)
}

#[test]
fn marks_keep_their_screen_size_as_the_object_recedes_and_texture_mapping_does_not() {
    let rate = |anchoring, zoom: f64| {
        let v = view(Shape::Sphere, 240, zoom, 0.0, 0.0);
        // Half the sphere's screen radius (about 107 px at zoom 1).
        crossing_rate(
            &frame(&v, &vertical_hatching(anchoring)),
            (50.0 * zoom) as u32,
        )
    };
    let (near, far) = (rate(Anchoring::Surface, 1.0), rate(Anchoring::Surface, 0.5));
    let expected = 2.0 * f64::from(StyleSpec::preset(StyleKind::Hatching).marks.frequency);
    assert!(
        (near / expected - 1.0).abs() < 0.2,
        "crossings {near}/px, expected about {expected}"
    );
    assert!(
        (far / near - 1.0).abs() < 0.15,
        "surface anchoring: {near} at zoom 1, {far} at zoom 0.5"
    );
    let (near, far) = (rate(Anchoring::Texture, 1.0), rate(Anchoring::Texture, 0.5));
    assert!(
        far / near > 1.6,
        "texture mapping should shrink the marks: {near} at zoom 1, {far} at zoom 0.5"
    );
}

/// The surface point seen at the centre of `a`, projected in `b`: its screen x.
fn centre_moves_to(a: &View3d, b: &View3d) -> f64 {
    let d = design();
    let (ra, rb) = (a.rig(&d), b.rig(&d));
    let (w, h) = (f64::from(a.width), f64::from(a.height));
    let dir = ra.ray(0.5 * w, 0.5 * h, w, h);
    let Some(hit) = a.object(&d).hit(ra.origin, dir) else {
        panic!("the centre ray misses the sphere");
    };
    let p: Vec3 = ra.origin + dir * hit.t;
    let v = p - rb.origin;
    let z = v.dot(rb.forward);
    0.5 * w + v.dot(rb.right) * 0.5 * h / (z * rb.tan_half)
}

/// The shift dx in [−25, 25] that best lines `b` up with `a` about the centre.
fn best_shift(a: &StyleFrame, b: &StyleFrame) -> i32 {
    let (w, c) = (a.width as i32, (a.width / 2) as i32);
    let at = |f: &StyleFrame, x: i32, y: i32| f.noise[(y * w + x) as usize];
    (-25..=25)
        .map(|dx| {
            let mut sum = 0.0f64;
            for y in c - 20..c + 20 {
                for x in c - 20..c + 20 {
                    let (p, q) = (at(a, x, y), at(b, x + dx, y));
                    if p.is_finite() && q.is_finite() {
                        sum += f64::from(p * q);
                    }
                }
            }
            (dx, sum)
        })
        .max_by(|l, r| l.1.total_cmp(&r.1))
        .map_or(0, |(dx, _)| dx)
}

#[test]
fn stipples_move_with_the_surface_as_the_camera_turns_and_a_screen_noise_stays() {
    let (a, b) = (
        view(Shape::Sphere, 240, 1.0, 0.0, 0.0),
        view(Shape::Sphere, 240, 1.0, 4.0, 0.0),
    );
    let expected = centre_moves_to(&a, &b) - 120.0;
    assert!(
        expected.abs() > 8.0,
        "the turn should move the surface: {expected}"
    );
    let mut spec = StyleSpec::preset(StyleKind::Stipple);
    let shift = best_shift(&frame(&a, &spec), &frame(&b, &spec));
    assert!(
        (f64::from(shift) - expected).abs() <= 2.0,
        "stipples moved {shift} px, the surface {expected:.1} px"
    );
    spec.anchoring = Anchoring::Screen;
    let shift = best_shift(&frame(&a, &spec), &frame(&b, &spec));
    assert!(shift.abs() <= 1, "a screen noise stays put, moved {shift}");
}

#[test]
fn the_same_pose_gives_the_same_bytes_and_the_density_changes_the_noise_continuously() {
    let v = view(Shape::Vase, 120, 1.3, 25.0, 15.0);
    for (name, kind) in STYLE_KINDS {
        let spec = StyleSpec::preset(kind);
        let (a, b) = (frame(&v, &spec), frame(&v, &spec));
        assert_eq!(a.field(), b.field(), "{name}");
        // Ink reaches 0.3 coverage, or an overlay grey moves 0.1 from ½.
        let drawn =
            a.coverage.iter().any(|&c| c > 0.3) || a.grey.iter().any(|&g| (g - 0.5).abs() > 0.1);
        assert!(drawn, "{name} draws nothing");
    }
    let noise = |impulses: f32| {
        let mut s = StyleSpec::preset(StyleKind::Hatching);
        s.marks.impulses = impulses;
        frame(&v, &s).noise
    };
    let mean_change = |a: &[f32], b: &[f32]| {
        let d: Vec<f64> = a
            .iter()
            .zip(b)
            .filter(|(p, q)| p.is_finite() && q.is_finite())
            .map(|(p, q)| f64::from((p - q).abs()))
            .collect();
        d.iter().sum::<f64>() / d.len() as f64
    };
    let base = noise(32.0);
    let tiny = mean_change(&base, &noise(32.0 * 1.001));
    let large = mean_change(&base, &noise(48.0));
    assert!(
        tiny < 0.02,
        "0.1 % more kernels changed the noise by {tiny}"
    );
    assert!(large > 0.2, "50 % more kernels should change it: {large}");
}

#[test]
fn fibres_hold_their_density_per_screen_pixel_from_zoom_1_to_16() {
    let spec = StyleSpec::preset(StyleKind::Paper);
    let d = design();
    for zoom in [1.0, 2.0, 4.0, 16.0] {
        let v = view(Shape::Sphere, 200, zoom, 10.0, 10.0);
        let f = frame(&v, &spec);
        let drawn: f64 = f
            .fibres
            .iter()
            .filter(|f| f.on_object)
            .map(|f| f.weight)
            .sum();
        let rig = v.rig(&d);
        let object = v.object(&d);
        let shown = (0..200 * 200)
            .filter(|i| {
                let (x, y) = (f64::from(i % 200) + 0.5, f64::from(i / 200) + 0.5);
                object
                    .hit(rig.origin, rig.ray(x, y, 200.0, 200.0))
                    .is_some()
            })
            .count() as f64;
        let per_pixel = drawn / shown;
        let want = f64::from(spec.fibres.per_pixel);
        assert!(
            (per_pixel / want - 1.0).abs() < 0.05,
            "zoom {zoom}: {per_pixel:.4} fibres per visible pixel, want {want}"
        );
    }
}

#[test]
fn fibres_keep_their_screen_length_at_every_depth_and_canvas_threads_run_at_0_and_90_degrees() {
    // A plane tilted away: its top is farther than its bottom.
    let v = view(Shape::Plane, 200, 1.0, 0.0, 60.0);
    let f = frame(&v, &StyleSpec::preset(StyleKind::Paper));
    let mean = |upper: bool| {
        let l: Vec<f64> = f
            .fibres
            .iter()
            .filter(|f| f.on_object && (f.start[1] < 100.0) == upper)
            .map(|f| f.length)
            .collect();
        assert!(l.len() > 50, "too few fibres: {}", l.len());
        l.iter().sum::<f64>() / l.len() as f64
    };
    let (far, near) = (mean(true), mean(false));
    assert!(
        (far / near - 1.0).abs() < 0.05,
        "far {far:.1} px, near {near:.1} px"
    );
    assert!((25.0..35.0).contains(&near), "mean length {near}");
    let canvas = frame(&v, &StyleSpec::preset(StyleKind::Canvas));
    assert!(!canvas.fibres.is_empty());
    for fibre in &canvas.fibres {
        let [dx, dy] = fibre.dir;
        assert!(dx.abs() < 1e-12 || dy.abs() < 1e-12, "thread at {dx}, {dy}");
    }
}
