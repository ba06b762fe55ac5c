//! How the 3D view's styles meet the render's colour (ink, multiply, overlay: the field
//! bytes both renderers read) and their links to the scene: frequency by shading
//! (darker, denser) and strokes along the marbled ink's own stretch.

use marbling_core::view3d::style::{StyleFrame, blend_pixel, byte_grey, grey_byte, style_frame};
use marbling_core::view3d::{Camera, Shape, View3d, render_3d};
use marbling_core::{Antialias, Design, Drop, Op, Point, Rgb8, Tine, Vec2};
use marbling_noise::{Follow, StyleBlend, StyleKind, StyleSpec};

fn view(shape: Shape, width: u32, height: u32) -> View3d {
    View3d {
        shape,
        camera: Camera {
            yaw: Some(0.0),
            pitch: Some(0.0),
            ..Camera::default()
        },
        width,
        height,
        antialias: Antialias::None,
        texture: None,
        displace: Default::default(),
    }
}

fn drop_design() -> Design {
    let mut d = Design::new(100, 100, Rgb8::new(250, 245, 230));
    d.ops.push(Op::Drop(Drop {
        center: Point::new(50.0, 50.0),
        radius: 30.0,
        color: Rgb8::new(20, 30, 120),
    }));
    d
}

fn frame(design: &Design, view: &View3d, spec: &StyleSpec) -> StyleFrame {
    match style_frame(design, view, spec) {
        Ok(f) => f,
        Err(e) => panic!("style frame: {e}"),
    }
}

#[test]
fn the_blends_follow_their_formulas_and_half_grey_changes_nothing() {
    let base = [0.2, 0.5, 0.9];
    let ink = [0.1, 0.4, 0.8];
    let close = |a: [f32; 3], b: [f32; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-6);
    assert!(close(
        blend_pixel(base, 0.0, 0.5, ink, StyleBlend::Ink),
        base
    ));
    assert!(close(
        blend_pixel(base, 1.0, 0.5, ink, StyleBlend::Ink),
        ink
    ));
    assert!(close(
        blend_pixel(base, 0.0, 0.5, ink, StyleBlend::Multiply),
        base
    ));
    assert!(close(
        blend_pixel(base, 1.0, 0.5, ink, StyleBlend::Multiply),
        [0.02, 0.2, 0.72]
    ));
    assert!(close(
        blend_pixel(base, 0.0, 0.5, ink, StyleBlend::Overlay),
        base
    ));
    // overlay(0.2, 0.75) = 2·0.2·0.75; overlay(0.9, 0.75) = 1 − 2·0.1·0.25.
    let o = blend_pixel(base, 0.0, 0.75, ink, StyleBlend::Overlay);
    assert!(close(o, [0.3, 0.75, 0.95]), "{o:?}");
    // The grey's byte holds ½ exactly, and every byte decodes back to itself.
    assert_eq!(grey_byte(0.5), 128);
    assert_eq!(byte_grey(128), 0.5);
    for b in 1..=255u8 {
        assert_eq!(grey_byte(byte_grey(b)), b);
    }
}

#[test]
fn watercolor_and_painterly_overlay_a_grey_on_the_object_only_and_felt_multiplies() {
    let d = drop_design();
    let v = view(Shape::Sphere, 160, 120);
    let plain = match render_3d(&d, &v) {
        Ok(i) => i,
        Err(e) => panic!("render: {e}"),
    };
    for kind in [StyleKind::Watercolor, StyleKind::Painterly, StyleKind::Felt] {
        let spec = StyleSpec::preset(kind);
        let f = frame(&d, &v, &spec);
        assert_eq!(f.blend, kind.blend());
        let field = f.field();
        let on_object: Vec<usize> = (0..f.noise.len())
            .filter(|&i| f.noise[i].is_finite())
            .collect();
        assert!(
            on_object.len() > 5000,
            "{kind:?}: {} object pixels",
            on_object.len()
        );
        let off = (0..f.noise.len()).filter(|i| !f.noise[*i].is_finite());
        if kind == StyleKind::Felt {
            assert!(f.grey.is_empty());
            let inked = on_object.iter().filter(|&&i| field[4 * i] > 20).count();
            assert!(inked > on_object.len() / 20, "felt inked {inked} pixels");
        } else {
            // Off the object the grey is ½ (no change); on it, both lighter and darker.
            assert!(
                off.into_iter()
                    .all(|i| field[4 * i + 1] == 128 && field[4 * i] == 0)
            );
            let lighter = on_object
                .iter()
                .filter(|&&i| field[4 * i + 1] > 140)
                .count();
            let darker = on_object
                .iter()
                .filter(|&&i| field[4 * i + 1] < 116)
                .count();
            let n = on_object.len() / 20;
            assert!(
                lighter > n && darker > n,
                "{kind:?}: {lighter} lighter, {darker} darker"
            );
        }
        let mut styled = plain.clone();
        f.composite(&mut styled);
        assert_ne!(styled.pixels, plain.pixels, "{kind:?} changed nothing");
        // At opacity 0 the colour comes back byte for byte.
        let mut none = plain.clone();
        frame(
            &d,
            &v,
            &StyleSpec {
                opacity: 0.0,
                ..spec
            },
        )
        .composite(&mut none);
        assert_eq!(none.pixels, plain.pixels, "{kind:?} at opacity 0");
    }
}

/// Sign changes per pixel along rows of the noise over the pixels `keep` selects.
fn crossings(f: &StyleFrame, keep: impl Fn(f64) -> bool) -> f64 {
    let (w, h) = (f.width as usize, f.height as usize);
    let (cx, cy, r) = (w as f64 / 2.0, h as f64 / 2.0, sphere_radius(f));
    let (mut changes, mut pairs) = (0u32, 0u32);
    for y in 0..h {
        for x in 0..w - 1 {
            let rho = ((x as f64 + 1.0 - cx).hypot(y as f64 + 0.5 - cy)) / r;
            let (a, b) = (f.noise[y * w + x], f.noise[y * w + x + 1]);
            if keep(rho) && a.is_finite() && b.is_finite() {
                pairs += 1;
                changes += u32::from((a > 0.0) != (b > 0.0));
            }
        }
    }
    assert!(pairs > 1000, "too few samples: {pairs}");
    f64::from(changes) / f64::from(pairs)
}

/// The sphere's screen radius: half the object's extent along the middle row.
fn sphere_radius(f: &StyleFrame) -> f64 {
    let (w, y) = (f.width as usize, f.height as usize / 2);
    let row = &f.noise[y * w..(y + 1) * w];
    0.5 * row.iter().filter(|n| n.is_finite()).count() as f64
}

#[test]
fn frequency_by_shading_packs_the_marks_where_the_sphere_is_dark() {
    let d = drop_design();
    let v = view(Shape::Sphere, 240, 240);
    let ratio = |k: f32| {
        let mut s = StyleSpec::preset(StyleKind::Hatching);
        s.marks.follow = Follow::Screen;
        s.marks.orientation = 90.0;
        s.marks.frequency_shading = k;
        let f = frame(&d, &v, &s);
        // The headlight: the centre faces the camera (light), the rim turns away (dark).
        crossings(&f, |rho| (0.8..0.95).contains(&rho)) / crossings(&f, |rho| rho < 0.4)
    };
    let (fixed, shaded) = (ratio(0.0), ratio(1.5));
    println!("rim/centre crossing rate: {fixed:.2} fixed, {shaded:.2} shaded");
    assert!((0.7..1.4).contains(&fixed), "without shading: {fixed}");
    assert!(shaded > 1.8 * fixed, "shaded {shaded} vs fixed {fixed}");
}

/// Σ over the pixels with |x − cx| < band of the noise's squared differences along x
/// and along y.
fn gradient_energy(f: &StyleFrame, band: f64) -> (f64, f64) {
    let (w, h) = (f.width as usize, f.height as usize);
    let cx = w as f64 / 2.0;
    let (mut ex, mut ey) = (0.0, 0.0);
    for y in 0..h - 1 {
        for x in 0..w - 1 {
            if (x as f64 + 0.5 - cx).abs() >= band {
                continue;
            }
            let (n, nx, ny) = (
                f.noise[y * w + x],
                f.noise[y * w + x + 1],
                f.noise[(y + 1) * w + x],
            );
            if n.is_finite() && nx.is_finite() && ny.is_finite() {
                ex += f64::from(nx - n).powi(2);
                ey += f64::from(ny - n).powi(2);
            }
        }
    }
    (ex, ey)
}

#[test]
fn strokes_follow_the_stretch_of_the_marbled_ink() {
    // A vertical tine through the middle of a 400×300 sheet shears the ink into
    // streaks along y within some 60 design pixels of its line (stretch ratio ≥ 1.9).
    let mut d = Design::new(400, 300, Rgb8::new(250, 245, 230));
    d.ops.push(Op::Tine(Tine {
        origin: Point::new(200.0, 0.0),
        direction: Vec2::new(0.0, 1.0),
        alpha: 600.0,
        lambda: 60.0,
    }));
    let v = view(Shape::Plane, 320, 240);
    let energy = |follow| {
        let mut s = StyleSpec::preset(StyleKind::Hatching);
        s.marks.follow = follow;
        s.marks.orientation = 0.0;
        let f = frame(&d, &v, &s);
        // The plane's screen width holds 400 design pixels: the band of ±40 of them.
        let (w, y) = (f.width as usize, f.height as usize / 2);
        let across = f.noise[y * w..(y + 1) * w]
            .iter()
            .filter(|n| n.is_finite())
            .count();
        gradient_energy(&f, 40.0 * across as f64 / 400.0)
    };
    // Strokes along y vary across x; the plane's rows (curvature) run along x.
    let (sx, sy) = energy(Follow::Stretch);
    let (cx, cy) = energy(Follow::Curvature);
    println!("stretch: x {sx:.0}, y {sy:.0}; curvature: x {cx:.0}, y {cy:.0}");
    assert!(sx > 3.0 * sy, "stretch: x {sx}, y {sy}");
    assert!(cy > 3.0 * cx, "curvature: x {cx}, y {cy}");
}
