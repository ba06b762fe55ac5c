//! The `marbling` command end to end: successes, and every failure path as a one-line
//! (or per-problem) message with a non-zero exit, never a panic.

use marbling_core::RgbaImage;
use std::path::{Path, PathBuf};
use std::process::Output;

use crate::common::marbling;

const GOOD: &str = r##"{"version":1,"width":120,"height":80,"background":"#f3ead7","ops":[
  {"type":"drop","center":[60,40],"radius":20,"color":"#1d3557"},
  {"type":"tine","origin":[0,40],"direction":[1,0],"alpha":20,"lambda":5}]}"##;

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    dir
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p.to_string_lossy().into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A failure: non-zero exit, the message on stderr, no panic.
fn assert_fails_with(o: &Output, needle: &str) {
    let err = stderr(o);
    assert!(!o.status.success(), "succeeded: {}", stdout(o));
    assert!(err.contains(needle), "stderr lacks {needle:?}:\n{err}");
    assert!(!err.contains("panicked"), "{err}");
}

fn png_size(path: &str) -> (u32, u32) {
    let img = RgbaImage::from_png(&std::fs::read(path).expect("png written")).expect("valid png");
    (img.width, img.height)
}

#[test]
fn render_writes_a_png_and_reports_size_and_time() {
    let dir = scratch("render");
    let input = write(&dir, "d.json", GOOD);
    let out = dir.join("o.png").to_string_lossy().into_owned();
    let o = marbling(&["render", &input, "-o", &out], None);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(png_size(&out), (120, 80));
    let line = stdout(&o);
    assert!(
        line.contains("120×80 px") && line.contains("2 ops") && line.contains(" s"),
        "{line}"
    );
}

#[test]
fn render_scale_width_and_aa_options() {
    let dir = scratch("options");
    let input = write(&dir, "d.json", GOOD);
    let out = dir.join("o.png").to_string_lossy().into_owned();
    for (args, size) in [
        (vec!["--scale", "2.5"], (300, 200)),
        (vec!["--width", "60"], (60, 40)),
        (vec!["--width", "1000", "--aa", "adaptive"], (1000, 667)),
        (vec!["--aa", "none"], (120, 80)),
    ] {
        let mut all = vec!["render", input.as_str(), "-o", out.as_str()];
        all.extend(args.iter().copied());
        let o = marbling(&all, None);
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        assert_eq!(png_size(&out), size, "{args:?}");
    }
}

#[test]
fn render_view_shows_a_deep_window_and_refuses_bad_views() {
    let dir = scratch("view");
    let input = write(&dir, "d.json", GOOD);
    let out = dir.join("o.png").to_string_lossy().into_owned();
    // The drop's rim point (80, 40) lies on the tine's line, which moves it αλ/λ = 20
    // along x: at 10⁶× the window on (100, 40) shows the ink left, the paper right.
    let view = ["--view", "100,40,1e6", "--width", "60"];
    let o = marbling(
        &[&["render", input.as_str(), "-o", out.as_str()][..], &view].concat(),
        None,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("view 100,40,1000000 (0.00006 design px wide)"),
        "{}",
        stdout(&o)
    );
    let img = RgbaImage::from_png(&std::fs::read(&out).expect("png written")).expect("valid png");
    assert_eq!((img.width, img.height), (60, 40));
    let at = |x: usize| img.pixels[(20 * 60 + x) * 4..][..3].to_vec();
    assert_eq!(
        (at(10), at(50)),
        (vec![0x1d, 0x35, 0x57], vec![0xf3, 0xea, 0xd7])
    );
    for (args, message) in [
        (
            vec!["--view", "1,2,0"],
            "--view: scale must be 1e-3 to 1e9, got 0",
        ),
        (
            vec!["--view", "1,2"],
            "--view: expected x,y,scale (three numbers)",
        ),
        (
            vec!["--view", "1,2,3", "--backend", "vector"],
            "--view renders with the exact walk",
        ),
    ] {
        let mut all = vec!["render", input.as_str(), "-o", out.as_str()];
        all.extend(args);
        assert_fails_with(&marbling(&all, None), message);
    }
}

#[test]
fn render_reads_stdin_and_writes_stdout() {
    let o = marbling(&["render", "-", "-o", "-"], Some(GOOD));
    assert!(o.status.success(), "{}", stderr(&o));
    let img = RgbaImage::from_png(&o.stdout).expect("png on stdout");
    assert_eq!((img.width, img.height), (120, 80));
    assert!(stderr(&o).contains("120×80 px"));
}

#[test]
fn validate_summarises_ops_per_type() {
    let dir = scratch("validate");
    let input = write(&dir, "d.json", GOOD);
    let o = marbling(&["validate", &input], None);
    assert!(o.status.success());
    assert_eq!(
        stdout(&o).trim(),
        format!("{input}: valid, 120×80, 2 ops: 1 drop, 1 tine")
    );
    let o = marbling(&["validate", "-"], Some(GOOD));
    assert!(stdout(&o).starts_with("<stdin>: valid"), "{}", stdout(&o));
}

#[test]
fn every_example_design_validates() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/designs");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).expect("examples") {
        let path = entry.expect("entry").path().to_string_lossy().into_owned();
        let o = marbling(&["validate", &path], None);
        assert!(o.status.success(), "{path}: {}", stderr(&o));
        n += 1;
    }
    assert!(n >= 6, "only {n} examples");
}

#[test]
fn validate_lists_every_error_with_its_path() {
    let bad = GOOD
        .replace("\"radius\":20", "\"radius\":-3")
        .replace("\"lambda\":5", "\"lambda\":0");
    let o = marbling(&["validate", "-"], Some(&bad));
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("<stdin>: ops[0].radius: must be > 0, got -3"),
        "{err}"
    );
    assert!(
        err.contains("<stdin>: ops[1].lambda: must be > 0, got 0"),
        "{err}"
    );
}

#[test]
fn missing_file_is_one_line() {
    let o = marbling(&["render", "/nonexistent/d.json", "-o", "/tmp/x.png"], None);
    assert_fails_with(&o, "cannot read '/nonexistent/d.json'");
    assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
}

#[test]
fn bad_json_names_line_and_column() {
    let o = marbling(
        &["validate", "-"],
        Some("{\n \"version\": 1,\n \"width\" 3\n}"),
    );
    assert_fails_with(&o, "<stdin>:3:10: invalid JSON: expected `:`");
    let o = marbling(&["render", "-", "-o", "/tmp/never.png"], Some(""));
    assert_fails_with(&o, "<stdin>:1:0: invalid JSON: EOF while parsing a value");
}

#[test]
fn invalid_values_are_refused_before_rendering() {
    let dir = scratch("invalid");
    let out = dir.join("o.png");
    let bad = GOOD.replace("#1d3557", "blue");
    let o = marbling(&["render", "-", "-o", &out.to_string_lossy()], Some(&bad));
    assert_fails_with(
        &o,
        "ops[0].color: must be a colour \"#rrggbb\", got \"blue\"",
    );
    assert!(!out.exists(), "nothing is written for an invalid design");
}

#[test]
fn unwritable_output_is_one_line() {
    let o = marbling(&["render", "-", "-o", "/nonexistent-dir/o.png"], Some(GOOD));
    assert_fails_with(&o, "cannot write '/nonexistent-dir/o.png'");
    assert_eq!(stderr(&o).lines().count(), 1);
}

#[test]
fn bad_options_are_refused() {
    let o = marbling(
        &["render", "-", "-o", "/tmp/o.png", "--aa", "ssaa"],
        Some(GOOD),
    );
    assert_fails_with(&o, "unknown antialiasing mode \"ssaa\"");
    let o = marbling(
        &[
            "render",
            "-",
            "-o",
            "/tmp/o.png",
            "--scale",
            "2",
            "--width",
            "5",
        ],
        Some(GOOD),
    );
    assert_fails_with(&o, "cannot be used with");
    let o = marbling(
        &["render", "-", "-o", "/tmp/o.png", "--scale", "-1"],
        Some(GOOD),
    );
    assert_fails_with(&o, "scale must be a finite number > 0, got -1");
    let o = marbling(
        &["render", "-", "-o", "/tmp/o.png", "--width", "0"],
        Some(GOOD),
    );
    assert_fails_with(&o, "--width must be at least 1");
}

#[test]
fn huge_outputs_are_refused_without_writing() {
    let dir = scratch("huge");
    let out = dir.join("o.png");
    let o = marbling(
        &[
            "render",
            "-",
            "-o",
            &out.to_string_lossy(),
            "--scale",
            "10000",
        ],
        Some(GOOD),
    );
    assert_fails_with(&o, "output of 1200000×800000 pixels is too large");
    assert!(!out.exists());
}

#[test]
fn bench_reports_throughput() {
    let o = marbling(&["bench", "--size", "64", "--ops", "10"], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(
        text.contains("comb-heavy") && text.contains("drop-heavy") && text.contains("op-samples/s"),
        "{text}"
    );
    // `--simd auto,off`: each case twice, the second on the baseline's two lanes.
    let o = marbling(
        &[
            "bench",
            "--size",
            "32",
            "--ops",
            "5",
            "--mix",
            "comb-heavy",
            "--simd",
            "auto,off",
        ],
        None,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let lanes: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("comb-heavy"))
        .filter_map(|l| l.split_whitespace().nth(2))
        .collect();
    assert_eq!(lanes.len(), 2, "{text}");
    assert_eq!(lanes[1], "2", "{text}");
    // `--per-kind`: one row per op kind, named by the op's type.
    let o = marbling(&["bench", "--size", "16", "--ops", "4", "--per-kind"], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    let rows: Vec<&str> = text
        .lines()
        .skip(2)
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert_eq!(rows.len(), 14, "{text}");
    for kind in ["drop", "tine", "shift", "turn", "jiggle", "stylus"] {
        assert!(rows.contains(&kind), "{kind}: {text}");
    }
}

#[test]
fn link_round_trips_and_broken_links_fail() {
    let o = marbling(&["link", "-"], Some(GOOD));
    assert!(o.status.success(), "{}", stderr(&o));
    let link = stdout(&o).trim().to_owned();
    assert!(link.starts_with("http://127.0.0.1:8080/#d="), "{link}");
    let o = marbling(&["link", "--decode", &link], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let back = marbling_core::Design::from_json(&stdout(&o)).expect("decoded JSON");
    assert_eq!(back, marbling_core::Design::from_json(GOOD).expect("good"));
    // Corrupt the middle of the compressed stream (still valid base64url).
    let mid = link.len() / 2;
    let broken = format!("{}{}{}", &link[..mid], "A".repeat(16), &link[mid + 16..]);
    assert_fails_with(
        &marbling(&["link", "--decode", &broken], None),
        "error: share link: ",
    );
    assert_fails_with(
        &marbling(&["link", "--decode", "http://x/#z=1"], None),
        "share link: no \"#d=\" design in it",
    );
}

/// Reads the one QR code in a PNG back to its text (the `rqrr` decoder).
fn read_qr(path: &str) -> String {
    let file = std::fs::File::open(path).expect("the QR PNG");
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .expect("png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("frame");
    let (w, h) = (info.width as usize, info.height as usize);
    let step = info.line_size / w;
    let mut img = rqrr::PreparedImage::prepare_from_greyscale(w, h, |x, y| {
        buf[y * info.line_size + x * step]
    });
    let grids = img.detect_grids();
    assert_eq!(grids.len(), 1, "one QR code in {path}");
    grids[0].decode().expect("decodes").1
}

#[test]
fn a_link_qr_code_reads_back_and_a_long_link_needs_the_shortest_form() {
    let dir = scratch("qr");
    let qr = dir.join("qr.png").to_string_lossy().into_owned();
    let o = marbling(&["link", "-", "--qr", &qr, "--qr-module", "4"], Some(GOOD));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("QR code version"), "{}", stderr(&o));
    assert_eq!(read_qr(&qr), stdout(&o).trim());
    // Drops at 15-digit positions: too long for a QR code as they are, short enough once
    // rounded to 0.01 px (the first such count is looked for, not assumed).
    let base = "http://127.0.0.1:8080/#";
    let design = |n: usize| {
        let mut d = marbling_core::Design::new(640, 480, marbling_core::Rgb8::new(240, 235, 220));
        for i in 0..n {
            let t = i as f64 * 0.618_033_988_749_894_8;
            d.ops.push(marbling_core::Op::Drop(marbling_core::Drop {
                center: marbling_core::Point::new(
                    20.0 + (t * 97.0) % 600.0,
                    20.0 + (t * 61.0) % 440.0,
                ),
                radius: 5.0 + (t * 13.0) % 30.0,
                color: marbling_core::Rgb8::new(29, 53, 87),
            }));
        }
        d
    };
    let length = |d: &marbling_core::Design| base.len() + marbling_core::share_fragment(d).len();
    let limit = marbling_core::share_qr::MAX_QR_LINK_BYTES;
    let long = (10..600)
        .step_by(10)
        .map(design)
        .find(|d| {
            let mut r = d.clone();
            r.ops = r.ops.iter().map(marbling_core::Op::rounded).collect();
            length(d) > limit && length(&r) <= limit
        })
        .expect("a design whose rounding makes its link fit");
    let file = write(&dir, "long.json", &long.to_json_pretty());
    assert_fails_with(
        &marbling(&["link", &file, "--qr", &qr], None),
        "a QR code holds at most 2953; --shortest rounds the ops",
    );
    let o = marbling(&["link", &file, "--qr", &qr, "--shortest"], None);
    assert!(o.status.success(), "{}", stderr(&o));
    let link = stdout(&o).trim().to_owned();
    assert!(link.len() <= limit, "{} characters", link.len());
    assert_eq!(read_qr(&qr), link);
    let back = marbling_core::decode_share(&link).expect("the shortest link reads back");
    assert_eq!(back.ops.len(), long.ops.len());
}

#[test]
fn random_writes_a_valid_reproducible_design() {
    let dir = scratch("random");
    let out = dir.join("r.json").to_string_lossy().into_owned();
    let o = marbling(
        &[
            "random", "--ops", "1000", "--size", "1024x768", "--seed", "3", "-o", &out,
        ],
        None,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).expect("written");
    let d = marbling_core::Design::from_json(&text).expect("valid design");
    assert_eq!((d.width, d.height, d.ops.len()), (1024, 768, 1000));
    let again = marbling(
        &[
            "random", "--ops", "1000", "--size", "1024x768", "--seed", "3", "-o", "-",
        ],
        None,
    );
    assert_eq!(stdout(&again).trim_end(), text.trim_end());
    let other = marbling(&["random", "--ops", "1000", "--seed", "4", "-o", "-"], None);
    assert_ne!(stdout(&other).trim_end(), text.trim_end());
    assert_fails_with(
        &marbling(&["random", "--ops", "100001", "-o", "-"], None),
        "--ops must be at most 100000",
    );
}
