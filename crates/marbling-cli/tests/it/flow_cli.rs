//! Schema v4's flow from the command line: a flow design renders (and validates), and
//! the looping colour turbulence — `render --flow TURB.json --time t` and
//! `animate --flow TURB.json --frames N` — repeats after a period, shows at t = 0 the
//! exact render of the design after a flow of half a period (one layer at weight 1: no
//! blur, every edge as sharp as in a still render), blends two exact layers in between,
//! and refuses bad input with its path.

use crate::making_cli::{apng_frames, fails_with, ok};
use marbling_core::RgbaImage;
use std::path::{Path, PathBuf};

fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-flow-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("tmp dir");
    dir
}

fn png(path: &Path) -> RgbaImage {
    RgbaImage::from_png(&std::fs::read(path).expect("png")).expect("decode")
}

/// Writes [`DESIGN`] and [`TURBULENCE`] into `dir`: their paths.
fn design_and_turbulence(dir: &Path) -> (String, String) {
    let (design, turb) = (dir.join("d.json"), dir.join("turb.json"));
    std::fs::write(&design, DESIGN).expect("write");
    std::fs::write(&turb, TURBULENCE).expect("write");
    let path = |p: PathBuf| p.to_str().expect("utf-8").to_owned();
    (path(design), path(turb))
}

const DESIGN: &str = r##"{"version":3,"width":120,"height":90,"background":"#f8f3e6","ops":[
  {"type":"drops","centers":[[30,30],[90,30],[30,65],[90,65],[60,45]],"radius":18,
   "colors":["#1d3557","#e63946","#f1c453","#2a9d8f","#f4a261"]}]}"##;
const TURBULENCE: &str =
    r#"{"noise":{"type":"perlin","frequency":0.02,"octaves":2,"seed":4},"strength":8,"period":2}"#;

#[test]
fn the_turbulence_loops_and_its_layers_are_exact_renders() {
    let dir = scratch();
    let (d, t) = design_and_turbulence(&dir);
    let (d, t) = (d.as_str(), t.as_str());
    let frame = |time: &str, name: &str| {
        let out = dir.join(name);
        let o = out.to_str().expect("utf-8");
        ok(&[
            "render", d, "--flow", t, "--time", time, "--aa", "none", "-o", o,
        ]);
        png(&out)
    };
    let (a, b) = (frame("0.7", "a.png"), frame("2.7", "b.png"));
    assert_eq!(a.pixels, b.pixels, "frame(t) ≠ frame(t + P)");
    // t = 0: layer one has weight 0, layer two weight 1 after a flow of P/2 = 1.
    let zero = frame("0", "zero.png");
    let mut still = marbling_core::Design::from_json(DESIGN).expect("valid");
    let flow = marbling_core::turbulence::Turbulence::from_json(TURBULENCE).expect("valid");
    still.ops.push(marbling_core::Op::Flow(flow.flow(1.0)));
    let flowed = dir.join("flowed.json");
    std::fs::write(&flowed, still.to_json_pretty()).expect("write");
    let exact = dir.join("exact.png");
    ok(&[
        "render",
        flowed.to_str().expect("utf-8"),
        "--aa",
        "none",
        "-o",
        exact.to_str().expect("utf-8"),
    ]);
    assert_eq!(
        zero.pixels,
        png(&exact).pixels,
        "the t = 0 frame is not the exact render"
    );
    // In between, the frame is neither layer alone.
    assert_ne!(a.pixels, zero.pixels);

    // One period as a 4-frame loop: frame 0 is the t = 0 render.
    let apng = dir.join("loop.png");
    let out = ok(&[
        "animate",
        d,
        "--flow",
        t,
        "--frames",
        "4",
        "--width",
        "120",
        "--aa",
        "none",
        "-o",
        apng.to_str().expect("utf-8"),
    ]);
    assert!(out.contains("4 frames of 120×90 px"), "{out}");
    let (declared, frames) = apng_frames(&std::fs::read(&apng).expect("written"));
    assert_eq!((declared, frames.len()), (4, 4));
    assert_eq!(frames[0].pixels, zero.pixels);
    assert_ne!(frames[1].pixels, frames[0].pixels);
}

#[test]
fn bad_turbulence_is_refused_with_its_path() {
    let dir = scratch();
    let design = dir.join("d2.json");
    std::fs::write(&design, DESIGN).expect("write");
    let d = design.to_str().expect("utf-8");
    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"noise":{"type":"worley","frequency":0.02},"strength":8,"period":0}"#,
    )
    .expect("write");
    let b = bad.to_str().expect("utf-8");
    let out = dir.join("x.png");
    let o = out.to_str().expect("utf-8");
    fails_with(
        &["render", d, "--flow", b, "-o", o],
        "bad.json: period: must be a number > 0, got 0",
    );
    fails_with(
        &["render", d, "--flow", b, "-o", o],
        "bad.json: noise: must be a \"perlin\" or \"value\" noise",
    );
    let good = dir.join("good.json");
    std::fs::write(&good, TURBULENCE).expect("write");
    let g = good.to_str().expect("utf-8");
    fails_with(
        &["render", d, "--flow", g, "--backend", "vector", "-o", o],
        "--flow renders with the exact walk: use --backend cpu or gpu",
    );
    fails_with(
        &["animate", d, "--flow", g, "--backend", "vector", "-o", o],
        "animate renders with the exact walk: use --backend cpu or gpu",
    );
    fails_with(
        &["animate", d, "--flow", g, "--frames", "1", "-o", o],
        "--frames must be 2 to",
    );
}

#[test]
fn the_flow_example_validates_as_version_4() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../examples/designs/v4-flow.json"
    );
    let out = ok(&["validate", path]);
    assert!(out.contains("flow"), "{out}");
}

/// `--backend gpu` draws the turbulence's frame as the CPU does (≤ 1 % of pixels off by
/// more than 8 of 255), in `render` and in `animate`.
#[test]
fn the_gpu_draws_the_turbulence_frame_of_the_cpu() {
    let dir = scratch().join("gpu");
    std::fs::create_dir_all(&dir).expect("tmp dir");
    let (d, t) = design_and_turbulence(&dir);
    let (d, t) = (d.as_str(), t.as_str());
    let (cpu, gpu) = (dir.join("cpu.png"), dir.join("gpu.png"));
    let run = |backend: &str, out: &Path| {
        std::process::Command::new(env!("CARGO_BIN_EXE_marbling"))
            .args([
                "render",
                d,
                "--flow",
                t,
                "--time",
                "0.7",
                "--backend",
                backend,
            ])
            .arg("-o")
            .arg(out)
            .output()
            .expect("marbling runs")
    };
    let g = run("gpu", &gpu);
    let stderr = String::from_utf8_lossy(&g.stderr);
    if !g.status.success()
        && stderr.contains("no GPU adapter")
        && marbling_testkit::gpu_or_skip::<(), _>(Err(stderr.trim())).is_none()
    {
        return;
    }
    assert!(g.status.success(), "{stderr}");
    assert!(run("cpu", &cpu).status.success());
    let r = marbling_core::compare::compare(&png(&cpu), &png(&gpu), 8).expect("same size");
    assert!(r.fraction() <= 0.01, "{r:?}");
    let anim = dir.join("loop.png");
    let a = anim.to_str().expect("utf-8");
    ok(&[
        "animate",
        d,
        "--flow",
        t,
        "--frames",
        "3",
        "--width",
        "60",
        "--backend",
        "gpu",
        "-o",
        a,
    ]);
    let (count, frames) = apng_frames(&std::fs::read(&anim).expect("apng"));
    assert_eq!((count, frames.len()), (3, 3));
}
