//! Schema v2 designs (noise background, grain overlays) from the outside: `render`
//! draws them on the CPU; vector exports (`svg`, `render --backend vector`) refuse them
//! with a clear message and a non-zero exit, writing nothing.

use std::path::PathBuf;
use std::process::{Command, Output};

const DESIGN: &str = r##"{"version":2,"width":120,"height":90,
  "background":{"noise":{"type":"perlin","frequency":0.03,"octaves":4,"seed":4},"palette":"marble"},
  "overlays":[{"type":"pigment-grain","noise":{"type":"worley","frequency":0.1,"seed":1},"strength":0.3}],
  "ops":[
    {"type":"drop","center":[60,45],"radius":25,"color":"#1d3557"},
    {"type":"tine","origin":[0,45],"direction":[1,0],"alpha":20,"lambda":6}]}"##;

fn workdir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-v2-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("design.json"), DESIGN).expect("write design");
    dir
}

fn marbling(dir: &PathBuf, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_marbling"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("runs")
}

#[test]
fn cpu_render_draws_a_v2_design() {
    let dir = workdir("cpu");
    let o = marbling(&dir, &["render", "design.json", "-o", "out.png"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let png = std::fs::read(dir.join("out.png")).expect("written");
    let img = marbling_core::RgbaImage::from_png(&png).expect("png");
    assert_eq!((img.width, img.height), (120, 90));
    let first = img.pixel(0, 0);
    assert!(
        (0..90).any(|y| img.pixel(5, y) != first),
        "the noise background is flat"
    );
}

#[test]
fn validate_names_the_surface() {
    let dir = workdir("validate");
    let o = marbling(&dir, &["validate", "design.json"]);
    assert!(o.status.success());
    assert_eq!(
        String::from_utf8_lossy(&o.stdout).trim(),
        "design.json: valid, 120×90, 2 ops: 1 drop, 1 tine; perlin noise background, pigment-grain"
    );
}

#[test]
fn vector_exports_refuse_noise_and_write_nothing() {
    let dir = workdir("svg");
    for args in [
        &["svg", "design.json", "-o", "out.svg"][..],
        &[
            "render",
            "design.json",
            "-o",
            "out.png",
            "--backend",
            "vector",
        ][..],
    ] {
        let o = marbling(&dir, args);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success(), "{args:?} succeeded");
        assert!(
            err.contains(
                "a noise background and 1 grain overlay(s), which only raster renders draw"
            ),
            "{args:?}: {err}"
        );
        assert_eq!(err.trim().lines().count(), 1, "{err}");
    }
    let left: Vec<_> = std::fs::read_dir(&dir)
        .expect("dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(left, ["design.json"], "files were written");
}
