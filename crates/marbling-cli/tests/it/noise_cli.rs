//! `marbling noise`: PNG output (greyscale and coloured, file and stdin) and every error
//! path with its message.

use std::path::PathBuf;

use crate::common::marbling as run;

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-noise-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn png_info(path: &PathBuf) -> (u32, u32, png::ColorType, Vec<u8>) {
    let bytes = std::fs::read(path).expect("png written");
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("frame");
    buf.truncate(info.buffer_size());
    (info.width, info.height, info.color_type, buf)
}

fn spec_file(name: &str, text: &str) -> String {
    let p = temp(name);
    std::fs::write(&p, text).expect("write spec");
    p.to_string_lossy().into_owned()
}

const GABOR: &str = r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#;

#[test]
fn gabor_spec_writes_greyscale_png() {
    let spec = spec_file("gabor.json", GABOR);
    let out = temp("gabor.png");
    let o = run(
        &["noise", &spec, "-o", &out.to_string_lossy(), "--size", "64"],
        None,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, h, color, data) = png_info(&out);
    assert_eq!((w, h, color), (64, 64, png::ColorType::Grayscale));
    // 0.5 + n/6: the mean grey is near 128 and the image is not flat.
    let mean = data.iter().map(|&v| f64::from(v)).sum::<f64>() / data.len() as f64;
    assert!((mean - 127.5).abs() < 20.0, "{mean}");
    assert!(data.iter().max() > data.iter().min());
}

#[test]
fn palette_spec_from_stdin_writes_rgb_png() {
    let out = temp("palette.png");
    let o = run(
        &["noise", "-", "-o", &out.to_string_lossy(), "--size", "32"],
        Some(r#"{"type":"perlin","frequency":0.05,"octaves":5,"palette":"ocean"}"#),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, _, color, _) = png_info(&out);
    assert_eq!((w, color), (32, png::ColorType::Rgb));
}

fn failure(spec: &str) -> String {
    let path = spec_file("bad.json", spec);
    let out = temp("bad.png");
    let o = run(
        &["noise", &path, "-o", &out.to_string_lossy(), "--size", "16"],
        None,
    );
    assert!(!o.status.success(), "{spec} was accepted");
    String::from_utf8_lossy(&o.stderr).replace(&path, "SPEC")
}

#[test]
fn path_named_errors() {
    let e = failure(r#"{"type":"gabor","frequency":-3,"bandwidth":0.05}"#);
    assert!(e.contains("SPEC: frequency: must be > 0, got -3"), "{e}");
    let e = failure(r#"{"type":"plasma"}"#);
    assert!(e.contains("SPEC: type: unknown noise type 'plasma'"), "{e}");
    let e = failure(r#"{"type":"worley","frequency":0.1,"distance":"l2"}"#);
    assert!(e.contains("SPEC: distance: unknown field"), "{e}");
    let e = failure(r#"{"type":"worley","frequency":0.1,"metric":"l2"}"#);
    assert!(
        e.contains("SPEC: metric: must be one of euclidean, manhattan, chebyshev"),
        "{e}"
    );
    let e = failure(
        r#"{"type":"product","inputs":[{"type":"white"},{"type":"perlin","frequency":2}]}"#,
    );
    assert!(
        e.contains("SPEC: inputs[1].frequency: must be ≤ 1, got 2"),
        "{e}"
    );
    let e = failure(r#"{"type":"paper","palette":"neon"}"#);
    assert!(e.contains("SPEC: palette: unknown palette 'neon'"), "{e}");
    let e = failure(r#"{"type":"gabor","frequency":0.1"#);
    assert!(e.contains("SPEC:1:") && e.contains("invalid JSON"), "{e}");
}

#[test]
fn io_and_size_errors() {
    let out = temp("x.png");
    let o = run(
        &[
            "noise",
            "/nonexistent/spec.json",
            "-o",
            &out.to_string_lossy(),
        ],
        None,
    );
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot read '/nonexistent/spec.json'"));
    let spec = spec_file("ok.json", GABOR);
    let o = run(
        &["noise", &spec, "-o", &out.to_string_lossy(), "--size", "0"],
        None,
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("--size must be in 1..=8192, got 0"));
    let o = run(
        &[
            "noise",
            &spec,
            "-o",
            "/nonexistent/dir/out.png",
            "--size",
            "8",
        ],
        None,
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("cannot write '/nonexistent/dir/out.png'"));
}
