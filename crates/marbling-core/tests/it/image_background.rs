//! Image backgrounds: against a straightforward bilinear reference, the three fits,
//! the marbling of the picture by an op (exact drop formula), JSON round trips, and the
//! refusals of oversize, corrupt and misnamed images.

use marbling_core::image_background::{ImagePixels, MAX_IMAGE_BYTES, data_uri};
use marbling_core::synth::test_photo;
use marbling_core::{
    Antialias, Design, Drop, ImageBackground, ImageFit, Op, RenderOptions, Rgb8, RgbaImage, render,
};

fn photo_png(w: u32, h: u32) -> Vec<u8> {
    test_photo(5, w, h).to_png().expect("encode PNG")
}

fn design_with(w: u32, h: u32, png: &[u8], fit: ImageFit) -> Design {
    let mut d = Design::new(w, h, Rgb8::new(10, 200, 30));
    d.set_background_image(Some(
        ImageBackground::from_file_bytes(png, fit).expect("decodes"),
    ));
    d
}

fn one_sample(d: &Design) -> RgbaImage {
    render(
        d,
        &RenderOptions {
            scale: 1.0,
            antialias: Antialias::None,
        },
    )
    .expect("render")
}

fn to_linear(b: u8) -> f64 {
    let c = f64::from(b) / 255.0;
    if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn to_srgb_byte(l: f64) -> u8 {
    let c = if l <= 0.003_130_8 {
        12.92 * l
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// The textbook bilinear lookup (texel centres at whole + ½, clamped, linear light).
fn reference(img: &RgbaImage, u: f64, v: f64) -> [u8; 3] {
    let (fx, fy) = (u - 0.5, v - 0.5);
    let (x0, y0) = (fx.floor(), fy.floor());
    let (tx, ty) = (fx - x0, fy - y0);
    let at = |x: f64, y: f64, k: usize| {
        let x = x.clamp(0.0, f64::from(img.width - 1)) as u32;
        let y = y.clamp(0.0, f64::from(img.height - 1)) as u32;
        to_linear(img.pixel(x, y)[k])
    };
    std::array::from_fn(|k| {
        let top = at(x0, y0, k) * (1.0 - tx) + at(x0 + 1.0, y0, k) * tx;
        let bottom = at(x0, y0 + 1.0, k) * (1.0 - tx) + at(x0 + 1.0, y0 + 1.0, k) * tx;
        to_srgb_byte(top * (1.0 - ty) + bottom * ty)
    })
}

/// Largest channel difference between the render and `expected(x, y)`.
fn max_diff(out: &RgbaImage, mut expected: impl FnMut(u32, u32) -> [u8; 3]) -> u8 {
    let mut worst = 0;
    for y in 0..out.height {
        for x in 0..out.width {
            let (o, e) = (out.pixel(x, y), expected(x, y));
            for k in 0..3 {
                worst = worst.max(o[k].abs_diff(e[k]));
            }
        }
    }
    worst
}

#[test]
fn stretch_matches_the_bilinear_reference() {
    // A 37×23 picture stretched onto 120×80: every output pixel is an interpolation.
    let photo = test_photo(5, 37, 23);
    let d = design_with(120, 80, &photo.to_png().expect("png"), ImageFit::Stretch);
    let out = one_sample(&d);
    let worst = max_diff(&out, |x, y| {
        let u = (f64::from(x) + 0.5) * 37.0 / 120.0;
        let v = (f64::from(y) + 0.5) * 23.0 / 80.0;
        reference(&photo, u, v)
    });
    assert!(worst <= 1, "max channel difference {worst}");
    // The comparator sees a half-texel shift.
    let shifted = max_diff(&out, |x, y| {
        let u = (f64::from(x) + 1.0) * 37.0 / 120.0;
        let v = (f64::from(y) + 0.5) * 23.0 / 80.0;
        reference(&photo, u, v)
    });
    assert!(shifted > 8, "a shifted lookup should differ, got {shifted}");
}

#[test]
fn a_picture_of_the_sheet_size_renders_as_itself() {
    let photo = test_photo(9, 64, 48);
    for fit in [ImageFit::Stretch, ImageFit::Cover, ImageFit::Contain] {
        let d = design_with(64, 48, &photo.to_png().expect("png"), fit);
        let out = one_sample(&d);
        let worst = max_diff(&out, |x, y| {
            let p = photo.pixel(x, y);
            [p[0], p[1], p[2]]
        });
        assert!(worst <= 1, "{fit:?}: max channel difference {worst}");
    }
}

#[test]
fn contain_letterboxes_with_the_paper_and_cover_crops() {
    // A 100×50 picture on a 100×100 sheet: contain leaves 25-pixel bands of paper above
    // and below; cover scales it ×2 and crops the sides.
    let photo = test_photo(3, 100, 50);
    let png = photo.to_png().expect("png");
    let paper = [10, 200, 30];
    let out = one_sample(&design_with(100, 100, &png, ImageFit::Contain));
    for x in 0..100 {
        for y in (0..25).chain(75..100) {
            assert_eq!(out.pixel(x, y)[..3], paper, "({x}, {y}) should be paper");
        }
        let p = photo.pixel(x, 10);
        assert!(
            out.pixel(x, 35)[..3]
                .iter()
                .zip(&p[..3])
                .all(|(a, b)| a.abs_diff(*b) <= 1),
            "({x}, 35) should be picture row 10"
        );
    }
    let cover = one_sample(&design_with(100, 100, &png, ImageFit::Cover));
    let worst = max_diff(&cover, |x, y| {
        // Scale 2, centred: u = (x − (100 − 200)/2)/2.
        let u = (f64::from(x) + 0.5 + 50.0) / 2.0;
        let v = (f64::from(y) + 0.5) / 2.0;
        reference(&photo, u, v)
    });
    assert!(worst <= 1, "cover: max channel difference {worst}");
    assert!(
        (0..100).all(|y| cover.pixel(0, y)[..3] != paper),
        "cover leaves no paper"
    );
}

#[test]
fn a_drop_marbles_the_picture_exactly() {
    // Outside a drop of radius r at c, the picture seen at p is the one at the
    // back-traced point c + (p − c)·√(1 − r²/|p − c|²) (paper's equation 1, inverted).
    let photo = test_photo(11, 80, 80);
    let mut d = design_with(80, 80, &photo.to_png().expect("png"), ImageFit::Stretch);
    let (c, r) = ((40.0, 40.0), 15.0);
    d.ops.push(Op::Drop(Drop {
        center: marbling_core::Point::new(c.0, c.1),
        radius: r,
        color: Rgb8::new(0, 0, 0),
    }));
    let out = one_sample(&d);
    let mut checked = 0;
    let worst = max_diff(&out, |x, y| {
        let p = (f64::from(x) + 0.5, f64::from(y) + 0.5);
        let (dx, dy) = (p.0 - c.0, p.1 - c.1);
        let d2 = dx * dx + dy * dy;
        if d2 <= r * r {
            return [0, 0, 0];
        }
        checked += 1;
        let k = (1.0 - r * r / d2).sqrt();
        reference(&photo, c.0 + dx * k, c.1 + dy * k)
    });
    assert!(worst <= 1, "max channel difference {worst}");
    assert!(checked > 5000, "only {checked} pixels outside the drop");
    // A drop really moved the picture: the plain picture differs near the drop.
    let plain = one_sample(&design_with(
        80,
        80,
        &photo.to_png().expect("png"),
        ImageFit::Stretch,
    ));
    let moved = (0..80)
        .filter(|&x| out.pixel(x, 20) != plain.pixel(x, 20))
        .count();
    assert!(moved > 20, "only {moved} pixels of row 20 moved");
}

#[test]
fn image_designs_round_trip_through_json() {
    let d = design_with(40, 30, &photo_png(16, 12), ImageFit::Contain);
    let text = d.to_json_pretty();
    assert!(text.contains("\"version\": 2"), "{}", &text[..200]);
    assert!(text.contains("data:image/png;base64,"));
    assert!(text.contains("\"paper\":\"#0ac81e\""));
    let back = Design::from_json(&text).expect("reads back");
    assert_eq!(back, d);
    assert_eq!(back.background_image.expect("image").pixels().width, 16);
}

fn read_error(background: &str) -> String {
    let text =
        format!(r#"{{"version":2,"width":10,"height":10,"background":{background},"ops":[]}}"#);
    Design::from_json(&text)
        .expect_err("must be refused")
        .to_string()
}

#[test]
fn bad_images_are_refused_with_the_place_named() {
    let oversize = RgbaImage::filled(4097, 2, [1, 2, 3, 255])
        .to_png()
        .expect("png");
    let e = read_error(&format!(
        r#"{{"image":"{}"}}"#,
        data_uri("image/png", &oversize)
    ));
    assert!(
        e.contains("background.image") && e.contains("4097×2") && e.contains("too large"),
        "{e}"
    );
    let e = read_error(&format!(
        r#"{{"image":"{}"}}"#,
        data_uri("image/png", b"this is not a picture at all")
    ));
    assert!(
        e.contains("background.image") && e.contains("cannot decode"),
        "{e}"
    );
    let mut truncated = photo_png(20, 20);
    truncated.truncate(truncated.len() / 2);
    let e = read_error(&format!(
        r#"{{"image":"{}"}}"#,
        data_uri("image/png", &truncated)
    ));
    assert!(e.contains("cannot decode"), "{e}");
    let e = read_error(r#"{"image":"photo.jpg"}"#);
    assert!(
        e.contains("background.image") && e.contains("data: URI"),
        "{e}"
    );
    let e = read_error(&format!(
        r#"{{"image":"{}","fit":"fill"}}"#,
        data_uri("image/png", &photo_png(4, 4))
    ));
    assert!(e.contains("background.fit") && e.contains("contain"), "{e}");
    let e = ImagePixels::decode(&vec![0u8; MAX_IMAGE_BYTES + 1]).expect_err("too big");
    assert!(e.to_string().contains("8 MB"), "{e}");
    let v1 = r#"{"version":1,"width":10,"height":10,"background":{"image":"x"},"ops":[]}"#;
    let e = Design::from_json(v1).expect_err("v1").to_string();
    assert!(e.contains("version\": 2"), "{e}");
}

#[test]
fn jpeg_and_downscaled_pictures_decode() {
    let d = design_with(40, 30, &photo_png(300, 200), ImageFit::Cover);
    let img = d.background_image.expect("image");
    let small = img.downscaled(64, 80);
    assert!(small.source().starts_with("data:image/jpeg;base64,"));
    assert_eq!(
        (small.pixels().width, small.pixels().height),
        (64, 43),
        "longest side 64, aspect kept"
    );
    assert!(small.source().len() < img.source().len());
}
