//! `marbling noise`: PNG output (greyscale and coloured, file and stdin), phasor noise,
//! height and normal maps, and every error path with its message.

use std::path::PathBuf;

use crate::common::marbling as run;

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-noise-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn png_info(path: &PathBuf) -> (u32, u32, png::ColorType, Vec<u8>) {
    let (w, h, color, _, data) = png_full(path);
    (w, h, color, data)
}

/// Width, height, colour type, bit depth and the raw samples (16-bit ones big-endian).
fn png_full(path: &PathBuf) -> (u32, u32, png::ColorType, png::BitDepth, Vec<u8>) {
    let bytes = std::fs::read(path).expect("png written");
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .expect("png");
    let mut buf = vec![0; reader.output_buffer_size().expect("size")];
    let info = reader.next_frame(&mut buf).expect("frame");
    buf.truncate(info.buffer_size());
    (
        info.width,
        info.height,
        info.color_type,
        info.bit_depth,
        buf,
    )
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
    assert!(String::from_utf8_lossy(&o.stderr).contains("--size must be in 1..=16384, got 0"));
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

/// Exports `spec` at `size` with `extra` arguments; the decoded PNG.
fn export(
    name: &str,
    spec: &str,
    size: u32,
    extra: &[&str],
) -> (png::ColorType, png::BitDepth, Vec<u8>) {
    let path = spec_file(&format!("{name}.json"), spec);
    let out = temp(&format!("{name}.png"));
    let size = size.to_string();
    let mut args = vec![
        "noise",
        &path,
        "-o",
        out.to_str().expect("utf-8"),
        "--size",
        &size,
    ];
    args.extend_from_slice(extra);
    let o = run(&args, None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (_, _, color, depth, data) = png_full(&out);
    (color, depth, data)
}

#[test]
fn sixteen_bit_exports_hold_the_intensity_to_one_part_in_65535() {
    let (color, depth, data) = export("deep", GABOR, 40, &["--depth", "16"]);
    assert_eq!(
        (color, depth),
        (png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    let spec = marbling_noise::NoiseSpec::from_json(GABOR).expect("spec");
    let renderer = marbling_noise::Renderer::new(&spec, 40).expect("renderer");
    let values: Vec<u16> = data
        .chunks_exact(2)
        .map(|b| u16::from_be_bytes([b[0], b[1]]))
        .collect();
    assert_eq!(values.len(), 40 * 40);
    for (k, &v) in values.iter().enumerate() {
        let (i, j) = ((k % 40) as f32 + 0.5, (k / 40) as f32 + 0.5);
        let expected = (renderer.intensity(i, j).clamp(0.0, 1.0) * 65535.0).round() as u16;
        assert_eq!(v, expected, "pixel {k}");
    }
    // More levels than 8 bits hold, and the 8-bit export is the same picture.
    let distinct: std::collections::HashSet<u16> = values.iter().copied().collect();
    assert!(distinct.len() > 256, "{} levels", distinct.len());
    let (_, _, eight) = export("shallow", GABOR, 40, &[]);
    for (v16, v8) in values.iter().zip(&eight) {
        assert!((f64::from(*v16) / 257.0 - f64::from(*v8)).abs() <= 0.51);
    }
    let (color, depth, rgb) = export(
        "deep-rgb",
        r#"{"type":"perlin","frequency":0.05,"octaves":3,"palette":"ocean"}"#,
        16,
        &["--depth", "16"],
    );
    assert_eq!(
        (color, depth, rgb.len()),
        (png::ColorType::Rgb, png::BitDepth::Sixteen, 16 * 16 * 6)
    );
    let e = run(&["noise", "-", "-o", "x.png", "--depth", "12"], Some(GABOR));
    assert!(String::from_utf8_lossy(&e.stderr).contains("--depth must be 8 or 16, got 12"));
}

/// `--map height` is the 16-bit intensity; `--map normal` the tangent-space normal of
/// z = relief·h (OpenGL: a slope rising to the right leans red low, a flat sheet is
/// (0.5, 0.5, 1)), on a phasor noise whose square profile makes sharp ridges.
#[test]
fn height_and_normal_maps_of_a_phasor_noise() {
    const PHASOR: &str = r#"{"type":"phasor","profile":"sine","frequency":0.05,"orientation":0,"bandwidth":0.02,"impulses":32,"seed":4}"#;
    let (color, depth, heights) = export("height", PHASOR, 32, &["--map", "height"]);
    assert_eq!(
        (color, depth),
        (png::ColorType::Grayscale, png::BitDepth::Sixteen)
    );
    let (_, _, image) = export("image16", PHASOR, 32, &["--depth", "16"]);
    assert_eq!(heights, image, "the height map is the 16-bit intensity");
    let (color, depth, normals) =
        export("normal", PHASOR, 32, &["--map", "normal", "--relief", "20"]);
    assert_eq!(
        (color, depth, normals.len()),
        (png::ColorType::Rgb, png::BitDepth::Sixteen, 32 * 32 * 6)
    );
    let sample = |data: &[u8], k: usize| {
        f64::from(u16::from_be_bytes([data[2 * k], data[2 * k + 1]])) / 65535.0
    };
    // Along a row, where the height rises to the right the normal's x is below ½ (98 %:
    // near a crest the slope over ±1 px and over ±½ px, the normal's, can differ in sign).
    let mut agree = 0;
    let mut total = 0;
    for j in 0..32 {
        for i in 1..31 {
            let rise = sample(&heights, j * 32 + i + 1) - sample(&heights, j * 32 + i - 1);
            let nx = sample(&normals, 3 * (j * 32 + i)) - 0.5;
            if rise.abs() > 0.02 {
                total += 1;
                agree += usize::from((rise > 0.0) == (nx < 0.0));
            }
        }
    }
    assert!(
        total > 100 && agree * 50 >= total * 49,
        "{agree} of {total} slopes agree"
    );
    // Every normal is a unit vector facing out of the sheet.
    for k in 0..32 * 32 {
        let n: Vec<f64> = (0..3)
            .map(|c| 2.0 * sample(&normals, 3 * k + c) - 1.0)
            .collect();
        let len = n.iter().map(|v| v * v).sum::<f64>().sqrt();
        assert!((len - 1.0).abs() < 1e-3 && n[2] > 0.0, "{n:?}");
    }
    let e = run(
        &[
            "noise", "-", "-o", "x.png", "--map", "normal", "--relief", "0",
        ],
        Some(PHASOR),
    );
    assert!(String::from_utf8_lossy(&e.stderr).contains("--relief must be above 0"));
    let e = run(
        &[
            "noise", "-", "-o", "x.png", "--map", "height", "--depth", "8",
        ],
        Some(PHASOR),
    );
    assert!(String::from_utf8_lossy(&e.stderr).contains("--map writes 16-bit samples"));
    let e = run(
        &["noise", "-", "-o", "x.png", "--map", "bump"],
        Some(PHASOR),
    );
    assert!(!e.status.success() && String::from_utf8_lossy(&e.stderr).contains("bump"));
    let e = run(
        &["noise", "-", "-o", "x.png"],
        Some(r#"{"type":"phasor","frequency":0.05,"bandwidth":0.02,"profile":"wave"}"#),
    );
    let msg = String::from_utf8_lossy(&e.stderr);
    assert!(msg.contains("profile") && msg.contains("sine"), "{msg}");
}

/// Mean absolute difference across the wrap-around seams (last column to first, last
/// row to first) and between interior neighbours, of a `size`² 16-bit greyscale export.
fn seam_and_interior(data: &[u8], size: usize) -> (f64, f64) {
    let v = |i: usize, j: usize| {
        let k = 2 * (j * size + i);
        f64::from(u16::from_be_bytes([data[k], data[k + 1]]))
    };
    let (mut seam, mut inner) = (0.0, 0.0);
    for t in 0..size {
        seam += (v(size - 1, t) - v(0, t)).abs() + (v(t, size - 1) - v(t, 0)).abs();
        for u in 0..size - 1 {
            inner += (v(u + 1, t) - v(u, t)).abs() + (v(t, u + 1) - v(t, u)).abs();
        }
    }
    (
        seam / (2 * size) as f64,
        inner / (2 * size * (size - 1)) as f64,
    )
}

#[test]
fn tileable_exports_continue_across_opposite_edges() {
    // Budget: the seam's mean difference at most 1.25× the interior neighbours' (a seam
    // is one more pair of neighbours; nothing marks it).
    let specs = [
        r#"{"type":"perlin","frequency":0.04,"octaves":4,"seed":3,"tile":true}"#,
        r#"{"type":"gabor","frequency":0.06,"orientation":0.5,"bandwidth":0.05,"seed":7,"tile":true}"#,
        r#"{"type":"worley","frequency":0.05,"feature":"f2-f1","seed":2,"tile":true}"#,
        r#"{"type":"curl","frequency":0.03,"octaves":3,"seed":6,"tile":true}"#,
        r#"{"type":"canvas","length":10,"width":2,"density":0.25,"seed":8,"tile":true}"#,
    ];
    let size = 96;
    for (k, spec) in specs.iter().enumerate() {
        let (_, _, data) = export(&format!("tile{k}"), spec, size as u32, &["--depth", "16"]);
        let (seam, inner) = seam_and_interior(&data, size);
        assert!(
            seam <= 1.25 * inner,
            "{spec}: seam {seam:.0} vs interior {inner:.0}"
        );
    }
    // The measure sees a seam: the same Perlin noise untiled breaks at the edges.
    let untiled = specs[0].replace(r#","tile":true"#, "");
    let (_, _, data) = export("untiled", &untiled, size as u32, &["--depth", "16"]);
    let (seam, inner) = seam_and_interior(&data, size);
    assert!(
        seam > 3.0 * inner,
        "untiled: seam {seam:.0} vs interior {inner:.0}"
    );
}

/// Khlebnikov et al. 2013 from the command line: a spec whose drives, decay and colour read a CSV grid
/// and a PNG beside it; a missing or corrupt data file is named.
#[test]
fn data_driven_specs_read_their_data_beside_the_spec() {
    std::fs::write(temp("speed.csv"), "0,1,2\n3,4,5\n").expect("csv");
    let png = {
        let mut bytes = Vec::new();
        let mut enc = png::Encoder::new(&mut bytes, 2, 2);
        enc.set_color(png::ColorType::Rgb);
        enc.write_header()
            .expect("header")
            .write_image_data(&[0, 64, 255, 30, 90, 0, 200, 10, 128, 255, 255, 60])
            .expect("data");
        bytes
    };
    std::fs::write(temp("fields.png"), png).expect("png");
    let spec = spec_file(
        "driven.json",
        r#"{"type":"gabor","kind":"random-phase","frequency":0.05,"bandwidth":0.05,"impulses":16,
            "frequency_field":{"data":"speed.csv","channel":1,"amount":2},
            "orientation_field":{"data":"fields.png","channel":2,"amount":3.14},
            "transfer":{"type":"spline-decay","value":{"data":"speed.csv","channel":1}},
            "blend":{"beta":0.6,"palette":"viridis","value":{"data":"fields.png","channel":3}}}"#,
    );
    let out = temp("driven.png");
    let o = run(
        &["noise", &spec, "-o", &out.to_string_lossy(), "--size", "48"],
        None,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (w, _, color, data) = png_info(&out);
    assert_eq!((w, color), (48, png::ColorType::Rgb));
    assert!(data.iter().max() > data.iter().min());

    let e = failure(
        r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"nowhere.png","amount":1}}"#,
    );
    assert!(e.contains("SPEC: data: 'nowhere.png': cannot read"), "{e}");
    std::fs::write(temp("broken.csv"), "1,2\nthree,4\n").expect("csv");
    let e = failure(
        r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"broken.csv","amount":1}}"#,
    );
    assert!(
        e.contains("SPEC: data: 'broken.csv': line 2: 'three' is not a finite number"),
        "{e}"
    );
}
