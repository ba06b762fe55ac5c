//! `cargo bench -p marbling-noise --bench export` (`make bench-noise-export`): seconds to
//! evaluate a SIZE² export (default 4096², `EXPORT_SIZE` to change) of each noise type,
//! on the CPU (every row through `Renderer::png_row`, 16-bit, rows split across all
//! cores, as `marbling noise` does before PNG encoding) and on the GPU (`sample_noise`
//! over the same grid, read back), when an adapter exists (WGPU_BACKEND=vulkan for
//! lavapipe).

#[path = "../tests/it/common/gpu.rs"]
mod gpu;

use marbling_noise::noise_gpu::NoiseGpu;
use marbling_noise::{Depth, NoiseSpec, Renderer};
use std::time::Instant;

/// One spec per noise type, at the parameters of the crate README's examples.
const SPECS: &[(&str, &str)] = &[
    (
        "gabor",
        r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#,
    ),
    (
        "perlin fBm ×5",
        r#"{"type":"perlin","frequency":0.01,"octaves":5,"seed":4}"#,
    ),
    (
        "value fBm ×4",
        r#"{"type":"value","frequency":0.03,"octaves":4,"seed":4}"#,
    ),
    (
        "worley f2-f1",
        r#"{"type":"worley","frequency":0.05,"feature":"f2-f1","seed":1}"#,
    ),
    ("white", r#"{"type":"white","seed":5}"#),
    (
        "curl ×3",
        r#"{"type":"curl","frequency":0.02,"octaves":3,"seed":6}"#,
    ),
    (
        "paper",
        r#"{"type":"paper","length":14,"width":1.5,"density":0.25,"seed":8}"#,
    ),
    (
        "canvas",
        r#"{"type":"canvas","length":10,"width":2.5,"density":0.25,"seed":8}"#,
    ),
];

/// Seconds to evaluate every row of a `size`² 16-bit export on all cores.
fn cpu_seconds(spec: &NoiseSpec, size: u32) -> f64 {
    let renderer = Renderer::new(spec, size).expect("size");
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u32;
    let start = Instant::now();
    let bytes: usize = std::thread::scope(|s| {
        let r = &renderer;
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                s.spawn(move || {
                    (t..size)
                        .step_by(threads as usize)
                        .map(|j| r.png_row(j, Depth::Sixteen).len())
                        .sum::<usize>()
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap_or(0)).sum()
    });
    assert_eq!(bytes, (size * size * 2) as usize);
    start.elapsed().as_secs_f64()
}

fn main() {
    let size: u32 = std::env::var("EXPORT_SIZE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4096);
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let gpu = if marbling_testkit::skip_requested() {
        None
    } else {
        gpu::GpuNoise::new().ok()
    };
    let adapter = gpu.as_ref().map_or("none", |g| g.adapter.as_str());
    println!("noise export {size}², CPU {threads} threads, GPU {adapter}");
    println!("| noise | CPU s | GPU s |");
    println!("|---|---:|---:|");
    for (name, json) in SPECS {
        let spec = NoiseSpec::from_json(json).expect("valid");
        let cpu = cpu_seconds(&spec, size);
        let gpu_s = gpu.as_ref().map(|dev| {
            let u = NoiseGpu::from_spec(&spec, size).expect("gpu form");
            let _ = dev.run(&u, 64.min(size)); // warm-up: pipeline compilation
            dev.run(&u, size).1.as_secs_f64()
        });
        let gpu_text = gpu_s.map_or_else(|| "—".to_owned(), |s| format!("{s:.2}"));
        println!("| {name} | {cpu:.2} | {gpu_text} |");
    }
}
