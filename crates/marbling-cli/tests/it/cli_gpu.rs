//! `--backend gpu` end to end: the GPU render of a design file matches the CPU render
//! within the GPU budget. Needs an adapter (lavapipe here); MARBLING_SKIP_GPU=1 skips.

use marbling_core::RgbaImage;
use marbling_core::compare::compare;
use std::path::Path;
use std::process::{Command, Output};

const DESIGN: &str = r##"{ "version": 1, "width": 120, "height": 90, "background": "#f3ead7",
  "ops": [
    {"type":"drop", "center":[60,45], "radius":25, "color":"#1d3557"},
    {"type":"drop", "center":[60,45], "radius":12, "color":"#e63946"},
    {"type":"tine", "origin":[0,45], "direction":[1,0], "alpha":20, "lambda":6},
    {"type":"wavy", "angle":0.3, "amplitude":5, "wavelength":40, "phase":0.0},
    {"type":"vortex", "center":[80,30], "alpha":20, "lambda":10}
  ] }"##;

fn render(dir: &Path, backend: &str) -> (Output, Vec<u8>) {
    let out = dir.join(format!("{backend}.png"));
    let o = Command::new(env!("CARGO_BIN_EXE_marbling"))
        .arg("render")
        .arg(dir.join("d.json"))
        .arg("-o")
        .arg(&out)
        .args(["--scale", "2", "--backend", backend])
        .output()
        .expect("marbling runs");
    let png = std::fs::read(&out).unwrap_or_default();
    (o, png)
}

#[test]
fn gpu_backend_matches_cpu_backend() {
    let dir = std::env::temp_dir().join(format!("marbling-cli-gpu-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("d.json"), DESIGN).expect("write design");
    let (gpu_run, gpu_png) = render(&dir, "gpu");
    let stderr = String::from_utf8_lossy(&gpu_run.stderr);
    if !gpu_run.status.success()
        && stderr.contains("no GPU adapter")
        && marbling_testkit::gpu_or_skip::<(), _>(Err(stderr.trim())).is_none()
    {
        return;
    }
    assert!(gpu_run.status.success(), "{stderr}");
    assert!(String::from_utf8_lossy(&gpu_run.stdout).contains("backend gpu"));
    let (cpu_run, cpu_png) = render(&dir, "cpu");
    assert!(cpu_run.status.success());
    let g = RgbaImage::from_png(&gpu_png).expect("gpu png");
    let c = RgbaImage::from_png(&cpu_png).expect("cpu png");
    assert_eq!((g.width, g.height), (240, 180));
    let d = compare(&c, &g, 8).expect("same size");
    assert!(d.fraction() <= 0.01, "{d:?}");
    let _ = std::fs::remove_dir_all(&dir);
}
