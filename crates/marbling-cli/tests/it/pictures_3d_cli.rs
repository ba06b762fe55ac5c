//! `marbling render-3d` and picture backgrounds from the outside: the plane facing the
//! camera is the 2D render, a picture named relative to the design file is embedded, a
//! picture too large for a link is refused or downscaled, and bad arguments or
//! pictures fail with a message and a non-zero exit.

use crate::common::marbling;
use marbling_core::RgbaImage;
use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design, test_photo};
use std::path::{Path, PathBuf};

fn workdir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-3d-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn path(dir: &Path, name: &str) -> String {
    dir.join(name).to_string_lossy().into_owned()
}

fn read_png(p: &str) -> RgbaImage {
    RgbaImage::from_png(&std::fs::read(p).expect("written")).expect("png")
}

fn ok(args: &[&str]) -> String {
    let o = marbling(args, None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into_owned()
}

#[test]
fn render_3d_plane_facing_the_camera_equals_render() {
    let dir = workdir("plane");
    // A picture background too, named relative to the design file.
    std::fs::create_dir_all(dir.join("pictures")).expect("dir");
    std::fs::write(
        dir.join("pictures/photo.png"),
        test_photo(2, 64, 40).to_png().expect("png"),
    )
    .expect("photo");
    let d = random_design(17, 160, 120, 60, Mix::Mixed);
    let mut v = d.to_value();
    v["version"] = 2.into();
    v["background"] = serde_json::json!({"image": "pictures/photo.png", "fit": "cover"});
    let design = path(&dir, "design.json");
    std::fs::write(&design, v.to_string()).expect("design");
    let (flat, plane) = (path(&dir, "flat.png"), path(&dir, "plane.png"));
    ok(&["render", &design, "-o", &flat]);
    let summary = ok(&[
        "render-3d",
        &design,
        "-o",
        &plane,
        "--surface",
        "plane",
        "--size",
        "160x120",
    ]);
    assert!(summary.contains("exact design on a plane"), "{summary}");
    let r = compare(&read_png(&flat), &read_png(&plane), 8).expect("same size");
    println!("render-3d plane vs render: {r:?}");
    assert!(r.fraction() <= 0.01, "{r:?}");
    // The comparator sees a camera turned by 3°.
    let turned = path(&dir, "turned.png");
    ok(&[
        "render-3d",
        &design,
        "-o",
        &turned,
        "--surface",
        "plane",
        "--size",
        "160x120",
        "--yaw",
        "3",
    ]);
    let r = compare(&read_png(&flat), &read_png(&turned), 8).expect("same size");
    assert!(r.fraction() > 0.05, "a turned plane should differ: {r:?}");
}

#[test]
fn render_3d_and_image_errors_name_the_problem() {
    let dir = workdir("errors");
    let design = path(&dir, "design.json");
    std::fs::write(
        &design,
        r##"{"version":2,"width":50,"height":40,"background":{"image":"missing.jpg"},"ops":[]}"##,
    )
    .expect("design");
    let out = path(&dir, "out.png");
    let o = marbling(&["render", &design, "-o", &out], None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        err.contains("background.image") && err.contains("missing.jpg"),
        "{err}"
    );
    std::fs::write(dir.join("missing.jpg"), b"\xff\xd8\xff not really a jpeg").expect("bad");
    let o = marbling(&["render", &design, "-o", &out], None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(err.contains("cannot decode"), "{err}");
    std::fs::write(
        &design,
        r##"{"version":1,"width":50,"height":40,"background":"#ffffff","ops":[]}"##,
    )
    .expect("design");
    for (args, expected) in [
        (vec!["--surface", "teapot"], "unknown surface"),
        (vec!["--zoom", "0"], "zoom"),
        (vec!["--look-at", "60,10"], "outside the 50×40 design"),
        (vec!["--look-at", "ten,10"], "design point like"),
        (vec!["--size", "0x5"], "expected a size"),
    ] {
        render_3d_fails(&design, &out, &args, expected);
    }
}

/// `marbling render-3d DESIGN -o OUT ARGS` fails with a message containing `expected`.
fn render_3d_fails(design: &str, out: &str, args: &[&str], expected: &str) {
    let mut all = vec!["render-3d", design, "-o", out];
    all.extend(args.iter().copied());
    let o = marbling(&all, None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "{args:?}");
    assert!(err.contains(expected), "{args:?}: {err}");
}

#[test]
fn a_picture_too_large_for_a_link_is_refused_or_downscaled() {
    let dir = workdir("link");
    // A noisy picture: it does not compress, so its link is far over 64 KB.
    let mut photo = RgbaImage::filled(300, 200, [0, 0, 0, 255]);
    let mut rng = marbling_core::synth::SplitMix64(9);
    for px in photo.pixels.chunks_exact_mut(4) {
        px[..3].copy_from_slice(&rng.next_u64().to_le_bytes()[..3]);
    }
    std::fs::write(dir.join("noise.png"), photo.to_png().expect("png")).expect("photo");
    let design = path(&dir, "design.json");
    std::fs::write(
        &design,
        r##"{"version":2,"width":300,"height":200,"background":{"image":"noise.png"},"ops":[]}"##,
    )
    .expect("design");
    let o = marbling(&["link", &design], None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success());
    assert!(
        err.contains("links hold about 64 KB") && err.contains("--downscale"),
        "{err}"
    );
    let link = ok(&["link", &design, "--downscale"]);
    let link = link.trim();
    assert!(link.len() <= 64 * 1024 + 40, "{} characters", link.len());
    let back = marbling_core::decode_share(link).expect("the link opens");
    let p = back.background_image.expect("the picture is in the link");
    assert!(p.pixels().width < 300 && p.source().starts_with("data:image/jpeg"));
}

#[test]
fn render_3d_turn_writes_a_loop_of_the_turned_views() {
    let dir = workdir("turn");
    let d = random_design(29, 160, 120, 40, Mix::Mixed);
    let design = path(&dir, "design.json");
    std::fs::write(&design, d.to_value().to_string()).expect("design");
    let common = ["--surface", "sphere", "--size", "48x36", "--dolly", "1.5"];
    let apng = path(&dir, "turn.png");
    let mut args = vec!["render-3d", &design, "-o", &apng, "--yaw", "10"];
    args.extend(common);
    args.extend(["--turn", "360", "--frames", "4"]);
    let summary = ok(&args);
    assert!(
        summary.contains("4 frames of a sphere turning 360°"),
        "{summary}"
    );
    let (declared, frames) =
        crate::making_cli::apng_frames(&std::fs::read(&apng).expect("written"));
    assert_eq!((declared, frames.len()), (4, 4));
    // Frame k is the still render at yaw 10 + 90k, byte for byte.
    for (k, frame) in frames.iter().enumerate() {
        let still = path(&dir, &format!("still-{k}.png"));
        let yaw = (10 + 90 * k).to_string();
        let mut args = vec!["render-3d", &design, "-o", &still, "--yaw", &yaw];
        args.extend(common);
        ok(&args);
        assert_eq!(read_png(&still).pixels, frame.pixels, "frame {k}");
    }
    assert_ne!(frames[0].pixels, frames[1].pixels, "the frames turn");
    // A GIF of the same loop.
    let gif_path = path(&dir, "turn.gif");
    let mut args = vec!["render-3d", &design, "-o", &gif_path];
    args.extend(common);
    args.extend(["--turn", "-90", "--frames", "3", "--fps", "10"]);
    ok(&args);
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::fs::File::open(&gif_path).expect("gif"))
        .expect("a gif");
    let mut n = 0;
    while let Some(f) = decoder.read_next_frame().expect("frame") {
        assert_eq!((f.width, f.height, f.delay), (48, 36, 10));
        n += 1;
    }
    assert_eq!(n, 3);
    for (args, expected) in [
        (
            vec!["--turn", "360", "--frames", "1"],
            "--frames must be 2 to",
        ),
        (vec!["--turn", "inf"], "--turn must be a number of degrees"),
        (
            vec!["--dolly", "0.2"],
            "dolly must be a number from 0.7 to 5",
        ),
        (vec!["--frames", "3"], "--turn"),
    ] {
        render_3d_fails(&design, &path(&dir, "bad.png"), &args, expected);
    }
    let mp4 = path(&dir, "turn.mp4");
    render_3d_fails(&design, &mp4, &["--turn", "90"], "-o must name a .png");
}

#[test]
fn render_3d_displace_moves_the_surface_and_refuses_bad_numbers() {
    let dir = workdir("displace");
    let d = random_design(31, 160, 120, 30, Mix::DropHeavy);
    let design = path(&dir, "design.json");
    std::fs::write(&design, d.to_value().to_string()).expect("design");
    let common = ["--surface", "sphere", "--size", "48x36"];
    let render = |name: &str, extra: &[&str]| {
        let out = path(&dir, name);
        let mut args = vec!["render-3d", &design, "-o", &out];
        args.extend(common);
        args.extend(extra.iter().copied());
        ok(&args);
        read_png(&out)
    };
    let flat = render("flat.png", &[]);
    // Frequency 0: the noise is 0 everywhere (Perlin is 0 on its lattice).
    assert_eq!(
        render("f0.png", &["--displace", "0.3,0"]).pixels,
        flat.pixels
    );
    let bumpy = render("bumpy.png", &["--displace", "0.2,3"]);
    let fbm = render("fbm.png", &["--displace", "0.2,3,4,2,0.6"]);
    assert_ne!(bumpy.pixels, flat.pixels, "the surface moved");
    assert_ne!(fbm.pixels, bumpy.pixels, "octaves add detail");
    for (value, expected) in [
        (
            "0.9,1",
            "displace amount must be a number from 0 to 0.5, got 0.9",
        ),
        (
            "0.1,x",
            "expected --displace S,F or S,F,OCTAVES,LACUNARITY,PERSISTENCE",
        ),
        ("0.1", "expected --displace S,F"),
        ("0.1,2,9,2,0.5", "displace octaves must be 1 to 6, got 9"),
    ] {
        render_3d_fails(
            &design,
            &path(&dir, "bad.png"),
            &["--displace", value],
            expected,
        );
    }
}

#[test]
fn render_3d_styles_lay_marks_or_fibres_over_the_render_and_refuse_bad_specs() {
    let dir = workdir("style");
    let d = random_design(37, 160, 120, 30, Mix::DropHeavy);
    let design = path(&dir, "design.json");
    std::fs::write(&design, d.to_value().to_string()).expect("design");
    let render = |name: &str, extra: &[&str]| {
        let out = path(&dir, name);
        let mut args = vec!["render-3d", &design, "-o", &out, "--surface", "sphere"];
        args.extend(["--size", "64x48", "--aa", "none"]);
        args.extend(extra.iter().copied());
        let report = ok(&args);
        (read_png(&out), report)
    };
    let (plain, _) = render("plain.png", &[]);
    assert_eq!(
        render("none.png", &["--style", "none"]).0.pixels,
        plain.pixels
    );
    let (hatched, report) = render("hatching.png", &["--style", "hatching"]);
    assert!(report.contains("style hatching ("), "{report}");
    let changed = compare(&plain, &hatched, 24).expect("same size").fraction();
    assert!(changed > 0.05, "hatching changed {changed} of the pixels");
    let (paper, report) = render("paper.png", &["--style", "paper"]);
    assert!(
        report.contains("style paper (") && report.contains(" fibres, "),
        "{report}"
    );
    assert_ne!(paper.pixels, plain.pixels);
    // A spec: red stipples.
    let spec = path(&dir, "red.json");
    std::fs::write(
        &spec,
        r##"{"style":"stipple","ink":"#ff0000","opacity":1}"##,
    )
    .expect("spec");
    let (red, _) = render("red.png", &["--style-spec", &spec]);
    let reddish = red
        .pixels
        .chunks_exact(4)
        .filter(|p| p[0] > 200 && p[1] < 60 && p[2] < 60)
        .count();
    assert!(reddish > 20, "{reddish} red pixels");
    // The media that work the colour, one with strokes along the ink and denser in the
    // shade: each changes the picture, the colour stays where it was (no ink laid).
    let along = path(&dir, "along.json");
    std::fs::write(
        &along,
        r#"{"style":"painterly","follow":"stretch","frequency_shading":1.2}"#,
    )
    .expect("spec");
    for extra in [
        &["--style", "watercolor"][..],
        &["--style", "felt"],
        &["--style-spec", &along],
    ] {
        let (styled, report) = render("media.png", extra);
        assert!(report.contains(" kernels, "), "{report}");
        let changed = compare(&plain, &styled, 8).expect("same size").fraction();
        assert!(changed > 0.05, "{extra:?} changed {changed} of the pixels");
    }
    // Bénard et al.'s figure 1: surface, screen and texture anchorings side by side, the
    // first third the plain --style frame, the other two other marks.
    let (three, report) = render("three.png", &["--style", "hatching", "--anchorings"]);
    assert!(
        report.contains("anchored surface, screen, texture side by side"),
        "{report}"
    );
    assert_eq!((three.width, three.height), (3 * 64, 48));
    let third = |k: usize| -> Vec<u8> {
        (0..48)
            .flat_map(|y| {
                three.pixels[(y * 192 + k * 64) * 4..(y * 192 + k * 64 + 64) * 4].to_vec()
            })
            .collect()
    };
    assert_eq!(
        third(0),
        hatched.pixels,
        "the surface third is the --style frame"
    );
    assert_ne!(third(1), third(0));
    assert_ne!(third(2), third(0));
    // A turning loop carries the style on every frame.
    let gif = path(&dir, "turn.gif");
    let report = ok(&[
        "render-3d",
        &design,
        "-o",
        &gif,
        "--surface",
        "sphere",
        "--size",
        "64x48",
        "--style",
        "canvas",
        "--turn",
        "30",
        "--frames",
        "3",
    ]);
    assert!(report.contains("3 frames"), "{report}");
    let bad = path(&dir, "bad.json");
    std::fs::write(&bad, r#"{"style":"stipple","tone":9}"#).expect("spec");
    let fast = path(&dir, "fast.json");
    std::fs::write(&fast, r#"{"style":"felt","frequency_shading":3}"#).expect("spec");
    for (args, expected) in [
        (
            vec!["--style", "oil"],
            "--style must be one of hatching, stipple",
        ),
        (
            vec!["--style-spec", bad.as_str()],
            "tone: must be a number from -4 to 4, got 9",
        ),
        (
            vec!["--style", "paper", "--style-spec", spec.as_str()],
            "--style paper disagrees with",
        ),
        (
            vec!["--style", "paper", "--anchorings"],
            "--anchorings compares where marks live",
        ),
        (
            vec!["--style-spec", fast.as_str()],
            "frequency_shading: must be a number from 0 to 1.8, got 3",
        ),
        (
            vec!["--style-spec", "missing.json"],
            "cannot read 'missing.json'",
        ),
    ] {
        render_3d_fails(&design, &path(&dir, "bad.png"), &args, expected);
    }
}
