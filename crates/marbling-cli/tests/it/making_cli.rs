//! `marbling pattern`, `marbling animate` and `marbling render --steps` end to end.

use marbling_core::compare::compare;
use marbling_core::{Design, RgbaImage};
use std::path::PathBuf;

use crate::common::marbling;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-making-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    dir
}

/// Runs `marbling ARGS`, asserting success; its standard output.
pub(crate) fn ok(args: &[&str]) -> String {
    let o = marbling(args, None);
    assert!(
        o.status.success(),
        "{:?}: {}",
        args,
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// Runs `marbling ARGS`, asserting it fails with `needle` in its errors, without a panic.
pub(crate) fn fails_with(args: &[&str], needle: &str) {
    let o = marbling(args, None);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains(needle),
        "{args:?}: {err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn pattern_lists_writes_and_varies_the_recipes() {
    let list = ok(&["pattern", "--list"]);
    assert_eq!(list.lines().count(), 24, "{list}");
    assert!(list.contains("nightingale-nest") && list.contains("Old Dutch"));
    let json = ok(&[
        "pattern",
        "chevron",
        "--size",
        "320x200",
        "--colors",
        "#aa0000,#0000aa",
        "--seed",
        "7",
        "-o",
        "-",
    ]);
    let d = Design::from_json(&json).expect("a valid design");
    assert_eq!((d.width, d.height), (320, 200));
    assert_eq!(d.recipe.as_ref().map(|r| r.name.as_str()), Some("Chevron"));
    assert!(json.contains("#aa0000") && !json.contains("#6d597a"));
    fails_with(
        &["pattern", "marbled", "-o", "-"],
        "unknown pattern \"marbled\"",
    );
    fails_with(
        &["pattern", "chevron", "--colors", "red", "-o", "-"],
        "--colors: expected a colour like #1d3557, got \"red\"",
    );
    fails_with(
        &["pattern", "chevron", "--size", "8", "-o", "-"],
        "width must be 16 to",
    );
    fails_with(&["pattern", "chevron"], "give the output file with -o");
}

/// `marbling render design --width 96` into `dir/name`, decoded.
fn render_at_96(dir: &std::path::Path, design: &str, name: &str) -> RgbaImage {
    let out = dir.join(name);
    ok(&[
        "render",
        design,
        "-o",
        out.to_str().expect("utf-8 path"),
        "--width",
        "96",
    ]);
    RgbaImage::from_png(&std::fs::read(&out).expect("png")).expect("decode")
}

/// Decodes every frame of an APNG.
pub(crate) fn apng_frames(bytes: &[u8]) -> (u32, Vec<RgbaImage>) {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("png");
    let declared = reader
        .info()
        .animation_control()
        .expect("animated")
        .num_frames;
    let mut frames = Vec::new();
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    while let Ok(info) = reader.next_frame(&mut buf) {
        frames.push(RgbaImage {
            width: info.width,
            height: info.height,
            pixels: buf[..info.buffer_size()].to_vec(),
        });
    }
    (declared, frames)
}

#[test]
fn animate_writes_the_frames_and_ends_on_the_render() {
    let dir = scratch("animate");
    let design = "../../examples/patterns/hearts.json";
    let apng = dir.join("hearts.png");
    let out = ok(&[
        "animate",
        design,
        "-o",
        apng.to_str().expect("utf-8 path"),
        "--fps",
        "3",
        "--seconds",
        "2",
        "--width",
        "96",
    ]);
    assert!(out.contains("6 frames of 96×60 px"), "{out}");
    let (declared, frames) = apng_frames(&std::fs::read(&apng).expect("written"));
    assert_eq!((declared, frames.len()), (6, 6));
    let still = render_at_96(&dir, design, "hearts-still.png");
    let last = frames.last().expect("a frame");
    let diff = compare(&still, last, 2).expect("same size").fraction();
    assert!(
        diff <= 0.01,
        "the last frame differs from the render in {diff}"
    );
    // The first frame is the making's start: the bare tank, nothing like the end.
    assert!(
        compare(&still, &frames[0], 24)
            .expect("same size")
            .fraction()
            > 0.2
    );
    // Half way through (3 of 7 steps at frame 3 of 0..=5 → position 4.2): the render of
    // that moment, by `render --steps`.
    let mid = dir.join("mid.png");
    ok(&[
        "render",
        design,
        "-o",
        mid.to_str().expect("utf-8 path"),
        "--width",
        "96",
        "--steps",
        "4.2",
    ]);
    let mid = RgbaImage::from_png(&std::fs::read(&mid).expect("png")).expect("decode");
    assert!(compare(&mid, &frames[3], 2).expect("same size").fraction() <= 0.01);

    let gif_path = dir.join("hearts.gif");
    ok(&[
        "animate",
        design,
        "-o",
        gif_path.to_str().expect("utf-8 path"),
        "--fps",
        "2",
        "--seconds",
        "2",
        "--width",
        "64",
    ]);
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::fs::File::open(&gif_path).expect("gif"))
        .expect("a gif");
    let mut n = 0;
    while decoder.read_next_frame().expect("frame").is_some() {
        n += 1;
    }
    assert_eq!(n, 4);

    fails_with(
        &["animate", design, "-o", "x.mp4"],
        "-o must name a .png (animated PNG) or .gif file",
    );
    fails_with(
        &["animate", design, "-o", "x.png", "--fps", "0"],
        "--fps must be 1 to 60",
    );
    fails_with(
        &["animate", design, "-o", "x.png", "--seconds", "-1"],
        "--seconds must be a positive number",
    );
    fails_with(
        &[
            "animate",
            design,
            "-o",
            "x.png",
            "--fps",
            "60",
            "--seconds",
            "1000",
        ],
        "frames is more than 3600",
    );
    fails_with(
        &["render", design, "-o", "x.png", "--steps", "99"],
        "--steps must be 0 to 7",
    );
}

#[test]
fn a_looping_animation_holds_the_design_then_plays_back_to_the_start() {
    let dir = scratch("loop");
    let design = "../../examples/patterns/hearts.json";
    let apng = dir.join("loop.png");
    let path = apng.to_str().expect("utf-8 path");
    let out = ok(&[
        "animate",
        design,
        "-o",
        path,
        "--fps",
        "3",
        "--seconds",
        "2",
        "--width",
        "96",
        "--hold",
        "1.5",
        "--reverse",
    ]);
    assert!(
        out.contains("10 frames of 96×60 px") && out.contains("held 1.5 s, then reversed"),
        "{out}"
    );
    let bytes = std::fs::read(&apng).expect("written");
    let (declared, frames) = apng_frames(&bytes);
    // 6 frames of the making, then 4 back: 0 1 2 3 4 5 4 3 2 1 (then the loop to 0).
    assert_eq!((declared, frames.len()), (10, 10));
    for (a, b) in [(6, 4), (7, 3), (8, 2), (9, 1)] {
        assert!(frames[a] == frames[b], "frame {a} is not frame {b} again");
    }
    assert!(
        frames[9] != frames[0],
        "the loop's last frame repeats the first"
    );
    // The turning point is the finished design, shown 1/3 s + the hold.
    let still = render_at_96(&dir, design, "loop-still.png");
    assert!(
        compare(&still, &frames[5], 2)
            .expect("same size")
            .fraction()
            <= 0.01
    );
    let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes))
        .read_info()
        .expect("png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let mut delays = Vec::new();
    while reader.next_frame(&mut buf).is_ok() {
        let fc = reader.info().frame_control().expect("fcTL");
        delays.push(f64::from(fc.delay_num) / f64::from(fc.delay_den));
    }
    assert_eq!(delays.len(), 10);
    assert!((delays[5] - (1.0 / 3.0 + 1.5)).abs() < 1e-3, "{delays:?}");
    assert!(
        delays
            .iter()
            .enumerate()
            .all(|(i, d)| i == 5 || (d - 1.0 / 3.0).abs() < 1e-9),
        "{delays:?}"
    );
    fails_with(
        &["animate", design, "-o", path, "--hold", "90"],
        "--hold must be 0 to 60 seconds, got 90",
    );
}
