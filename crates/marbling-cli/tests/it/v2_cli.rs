//! Schema v2 designs (noise background, grain overlays) from the outside: `render`
//! draws them on the CPU; vector exports (`svg`, `render --backend vector`) hold the
//! noise and grain as raster layers under and over the ink outlines.

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
fn vector_exports_put_noise_and_grain_in_raster_layers() {
    let dir = workdir("svg");
    let o = marbling(&dir, &["svg", "design.json", "-o", "out.svg"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let svg = std::fs::read_to_string(dir.join("out.svg")).expect("written");
    assert_eq!(svg.matches("<image ").count(), 2, "underlay and grain");
    assert!(svg.contains("href=\"data:image/png;base64,"));
    assert!(svg.contains("style=\"mix-blend-mode:multiply\""));
    assert!(svg.contains("<path data-method=\"contour\""));
    let o = marbling(
        &dir,
        &[
            "render",
            "design.json",
            "-o",
            "vec.png",
            "--backend",
            "vector",
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let img = marbling_core::RgbaImage::from_png(&std::fs::read(dir.join("vec.png")).expect("png"))
        .expect("png");
    assert_eq!((img.width, img.height), (120, 90));
    let first = img.pixel(0, 0);
    assert!(
        (0..90).any(|y| img.pixel(5, y) != first),
        "the noise background is flat"
    );
}
