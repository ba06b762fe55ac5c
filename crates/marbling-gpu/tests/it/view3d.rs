//! The 3D view on the GPU against marbling-core's f64 twin: every shape, exact and
//! texture-mapped, within a stated pixel budget; a wrong camera fails the comparison.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::view3d::{Camera, Shape, View3d, render_3d};
use marbling_core::{Antialias, Point};

/// A channel difference above this counts as a differing pixel (out of 255).
const THRESHOLD: u8 = 8;
/// Share of pixels that may differ: f32 rays graze silhouettes and the vase's marched
/// profile a little differently.
const BUDGET: f64 = 0.01;

fn view(shape: Shape, yaw: f64, texture: Option<u32>) -> View3d {
    View3d {
        shape,
        camera: Camera {
            yaw: Some(yaw),
            pitch: Some(15.0),
            zoom: 1.0,
            look_at: None,
            dolly: 1.0,
        },
        width: 96,
        height: 64,
        antialias: Antialias::Rgss,
        texture,
        displace: marbling_core::view3d::Displace::default(),
    }
}

#[test]
fn every_shape_matches_the_cpu() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let d = random_design(23, 160, 120, 40, Mix::DropHeavy);
    for (i, shape) in Shape::ALL.into_iter().enumerate() {
        let texture = (i == 1).then_some(256);
        let mut v = view(shape, 20.0 + 30.0 * i as f64, texture);
        // Every other shape with the camera dollied in or out.
        v.camera.dolly = [1.0, 0.7, 1.0, 2.5, 1.0][i % 5];
        let c = render_3d(&d, &v).expect("CPU");
        let g = gpu.render_3d(&d, &v).expect("GPU");
        let r = compare(&c, &g, THRESHOLD).expect("same size");
        println!(
            "{} (texture {texture:?}, dolly {}): {r:?}",
            shape.name(),
            v.camera.dolly
        );
        assert!(r.fraction() <= BUDGET, "{}: {r:?}", shape.name());
    }
    // A close-up with adaptive antialiasing.
    let mut close = view(Shape::Sphere, 0.0, None);
    close.camera = Camera {
        zoom: 20.0,
        look_at: Some(Point::new(80.0, 60.0)),
        ..Camera::default()
    };
    close.antialias = Antialias::Adaptive;
    let r = compare(
        &render_3d(&d, &close).expect("CPU"),
        &gpu.render_3d(&d, &close).expect("GPU"),
        THRESHOLD,
    )
    .expect("same size");
    println!("sphere close-up, adaptive: {r:?}");
    assert!(r.fraction() <= BUDGET, "{r:?}");
    // The comparator sees a camera turned by 90° (the other side of the design).
    let turned = view(Shape::Vase, 110.0, None);
    let r = compare(
        &render_3d(&d, &view(Shape::Vase, 20.0, None)).expect("CPU"),
        &gpu.render_3d(&d, &turned).expect("GPU"),
        THRESHOLD,
    )
    .expect("same size");
    assert!(
        r.fraction() > 3.0 * BUDGET,
        "a turned vase should differ: {r:?}"
    );
}

/// Share of pixels a displaced view may differ by: the march's steps and bisection run
/// in f32 on the GPU and f64 on the CPU, so grazing rays can cross a bump one step
/// apart.
const DISPLACED_BUDGET: f64 = 0.02;

#[test]
fn displaced_shapes_match_the_cpu() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let d = random_design(29, 160, 120, 30, Mix::DropHeavy);
    let displace = marbling_core::view3d::Displace {
        amount: 0.12,
        frequency: 3.0,
        octaves: 2,
        offset: [0.3, -0.2, 0.1],
        ..Default::default()
    };
    for (i, shape) in Shape::ALL.into_iter().enumerate() {
        let mut v = view(shape, 25.0 + 40.0 * i as f64, None);
        v.displace = displace;
        let c = render_3d(&d, &v).expect("CPU");
        let g = gpu.render_3d(&d, &v).expect("GPU");
        let r = compare(&c, &g, THRESHOLD).expect("same size");
        println!("displaced {}: {r:?}", shape.name());
        assert!(r.fraction() <= DISPLACED_BUDGET, "{}: {r:?}", shape.name());
        // The comparator sees the displacement: the undisplaced GPU view differs.
        let mut flat = v;
        flat.displace = Default::default();
        let r = compare(&c, &gpu.render_3d(&d, &flat).expect("GPU"), THRESHOLD).expect("same size");
        assert!(
            r.fraction() > 0.05,
            "{}: displaced ≈ flat: {r:?}",
            shape.name()
        );
    }
}

/// Every style blended by the GPU's shader equals the CPU's composite over its own
/// render within [`BUDGET`] (the same field bytes and blend formula; the renders under
/// them differ as the plain views do), and the style is there: every styled view
/// differs from the plain one.
#[test]
fn styled_views_match_the_cpu() {
    use marbling_core::view3d::style::style_frame;
    use marbling_noise::{STYLE_KINDS, StyleSpec};
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let d = random_design(41, 160, 120, 30, Mix::DropHeavy);
    for (i, (name, kind)) in STYLE_KINDS.into_iter().enumerate() {
        let shape = Shape::ALL[i % Shape::ALL.len()];
        // Yaws within ±60° of the front: the plane and book show their design faces. At
        // twice the plain test's size: patches of the small vase hold under one kernel.
        let v = View3d {
            width: 192,
            height: 128,
            ..view(shape, (15.0 + 50.0 * i as f64) % 120.0 - 60.0, None)
        };
        let spec = StyleSpec::preset(kind);
        let frame = style_frame(&d, &v, &spec).expect("style");
        let mut c = render_3d(&d, &v).expect("CPU");
        let plain = c.clone();
        frame.composite(&mut c);
        let g = gpu.render_3d_styled(&d, &v, Some(&frame)).expect("GPU");
        let r = compare(&c, &g, THRESHOLD).expect("same size");
        println!("{name} on the {}: {r:?}", shape.name());
        assert!(r.fraction() <= BUDGET, "{name}: {r:?}");
        let changed = compare(&plain, &c, THRESHOLD).expect("same size");
        // Stipples are sparse dots: a few pixels of a 192×128 frame.
        assert!(changed.differing > 5, "{name} drew nothing: {changed:?}");
    }
}
