//! `cargo bench -p marbling-noise --bench noise`: ns/point of 2D Perlin and 5-octave fBm
//! against the `fastnoise-lite` crate on the same grid in the same run, and Gabor
//! milliseconds per megapixel on the CPU (one thread) and, when an adapter exists, on
//! the GPU through `sample_noise` (set WGPU_BACKEND=vulkan for lavapipe).
//!
//! `-- --grids`: whole grids as FastNoise2 times them (`make bench-fastnoise2` prints
//! its figures first): M points/s at one thread on a 2048² grid with 0.01 between
//! points (a 128³ grid for 3D), through the row kernels and point by point.

#[path = "../tests/it/common/gpu.rs"]
mod gpu;

use fastnoise_lite::{FastNoiseLite, FractalType, NoiseType};
use marbling_noise::noise_gpu::NoiseGpu;
use marbling_noise::rows::{perlin2_row, worley2_row};
use marbling_noise::{
    Fbm, FbmParams, Gabor, GaborKind, GaborParams, Metric, NoiseSpec, perlin2, perlin3, value2,
    worley2,
};
use std::hint::black_box;
use std::time::Instant;

/// Grid side: 1024² points per pass.
const N: usize = 1024;
/// Frequency, cycles per grid step (fastnoise-lite's default).
const FREQ: f32 = 0.01;
/// Passes per measurement; the fastest is kept.
const REPEAT: usize = 9;

/// Seconds for one pass of `f` over the N×N grid.
fn pass(f: &mut impl FnMut(f32, f32) -> f32) -> f64 {
    let start = Instant::now();
    let mut acc = 0.0_f32;
    for j in 0..N {
        for i in 0..N {
            acc += f(i as f32, j as f32);
        }
    }
    black_box(acc);
    start.elapsed().as_secs_f64()
}

/// Best-of-`REPEAT` nanoseconds per point of `a` and `b`, passes interleaved so that load
/// from other processes hits both alike.
fn ns_per_point_pair(
    mut a: impl FnMut(f32, f32) -> f32,
    mut b: impl FnMut(f32, f32) -> f32,
) -> (f64, f64) {
    let (mut best_a, mut best_b) = (f64::INFINITY, f64::INFINITY);
    for _ in 0..REPEAT {
        best_a = best_a.min(pass(&mut a));
        best_b = best_b.min(pass(&mut b));
    }
    let per = 1e9 / (N * N) as f64;
    (best_a * per, best_b * per)
}

/// Passes per `--grids` measurement; the fastest is kept (FastNoise2's driver: the same).
const GRID_PASSES: usize = 15;

/// Best-of-[`GRID_PASSES`] M points/s of `pass`, which computes `points` values.
fn rate(points: usize, mut pass: impl FnMut() -> f32) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..GRID_PASSES {
        let start = Instant::now();
        black_box(pass());
        best = best.min(start.elapsed().as_secs_f64());
    }
    points as f64 / best / 1e6
}

/// The `--grids` table (see the module doc).
fn grids() {
    const SIDE: usize = 2048;
    const STEP: f32 = 0.01;
    println!(
        "ours       simd {}, 1 thread, best of {GRID_PASSES}",
        if is_avx2() { "AVX2" } else { "baseline" }
    );
    let xs: Vec<f32> = (0..SIDE).map(|i| (i as f32 + 0.5) * STEP).collect();
    let ys = xs.clone();
    let mut row = vec![0.0_f32; SIDE];
    let mut row2 = vec![0.0_f32; SIDE];
    let points = SIDE * SIDE;
    let print = |name: &str, mps: f64| println!("ours       {name:<24} {mps:8.1} M points/s");
    print(
        "perlin2 (row kernel)",
        rate(points, || {
            ys.iter().fold(0.0, |acc, &y| {
                perlin2_row(&xs, y, 1337, [0, 0], &mut row);
                acc + row[7]
            })
        }),
    );
    print(
        "perlin2 (point)",
        rate(points, || {
            ys.iter()
                .map(|&y| xs.iter().map(|&x| perlin2(x, y, 1337)).sum::<f32>())
                .sum()
        }),
    );
    print(
        "cellular2 (row kernel)",
        rate(points, || {
            ys.iter().fold(0.0, |acc, &y| {
                worley2_row(&xs, y, 1337, Metric::Euclidean, [0, 0], &mut row, &mut row2);
                acc + row[7]
            })
        }),
    );
    print(
        "cellular2 (point)",
        rate(points, || {
            ys.iter()
                .map(|&y| {
                    xs.iter()
                        .map(|&x| worley2(x, y, 1337, Metric::Euclidean, [0, 0])[0])
                        .sum::<f32>()
                })
                .sum()
        }),
    );
    let fbm = Fbm::new(FbmParams {
        frequency: STEP,
        octaves: 5,
        seed: 1337,
        ..FbmParams::default()
    });
    let pixels: Vec<f32> = (0..SIDE).map(|i| i as f32 + 0.5).collect();
    print(
        "fbm5-perlin2 (row kernel)",
        rate(points, || {
            pixels.iter().fold(0.0, |acc, &y| {
                fbm.eval_row(&pixels, y, &mut row);
                acc + row[7]
            })
        }),
    );
    print(
        "fbm5-perlin2 (point)",
        rate(points, || {
            pixels
                .iter()
                .map(|&y| pixels.iter().map(|&x| fbm.eval(x, y)).sum::<f32>())
                .sum()
        }),
    );
    print(
        "value2 (point)",
        rate(points, || {
            ys.iter()
                .map(|&y| xs.iter().map(|&x| value2(x, y, 1337)).sum::<f32>())
                .sum()
        }),
    );
    let side3 = 128;
    print(
        "perlin3 (point)",
        rate(side3 * side3 * side3, || {
            let mut acc = 0.0;
            for k in 0..side3 {
                for j in 0..side3 {
                    for &x in &xs[..side3] {
                        acc += perlin3([x, xs[j], xs[k]], 1337);
                    }
                }
            }
            acc
        }),
    );
}

fn is_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

fn main() {
    if std::env::args().any(|a| a == "--grids") {
        grids();
        return;
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "marbling-noise benchmark: {N}×{N} grid, best of {REPEAT}, 1 thread (nproc {threads})"
    );

    let mut fnl = FastNoiseLite::with_seed(1337);
    fnl.set_noise_type(Some(NoiseType::Perlin));
    fnl.set_frequency(Some(FREQ));
    let (ours, theirs) = ns_per_point_pair(
        |x, y| perlin2(x * FREQ, y * FREQ, 1337),
        |x, y| fnl.get_noise_2d(x, y),
    );
    println!(
        "perlin 2D          marbling-noise {ours:6.2} ns/pt   fastnoise-lite {theirs:6.2} ns/pt   ratio {:.2}",
        ours / theirs
    );

    fnl.set_fractal_type(Some(FractalType::FBm));
    fnl.set_fractal_octaves(Some(5));
    let fbm = Fbm::new(FbmParams {
        frequency: FREQ,
        octaves: 5,
        seed: 1337,
        ..FbmParams::default()
    });
    let (ours, theirs) =
        ns_per_point_pair(|x, y| fbm.eval_bounded(x, y), |x, y| fnl.get_noise_2d(x, y));
    println!(
        "fBm 5 octaves      marbling-noise {ours:6.2} ns/pt   fastnoise-lite {theirs:6.2} ns/pt   ratio {:.2}",
        ours / theirs
    );

    let gabor_json = r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#;
    let g = Gabor::new(GaborParams {
        kind: GaborKind::Anisotropic,
        frequency: 0.0625,
        orientation: std::f32::consts::FRAC_PI_4,
        bandwidth: 0.05,
        impulses: 64.0,
        seed: 7,
        period: None,
        orientation_drive: None,
        frequency_drive: None,
        profile: None,
    });
    // 512² points are enough for a stable per-megapixel time.
    let side = 512;
    let mut best = f64::INFINITY;
    for _ in 0..3 {
        let start = Instant::now();
        let mut acc = 0.0;
        for j in 0..side {
            for i in 0..side {
                acc += g.eval(i as f32 + 0.5, j as f32 + 0.5);
            }
        }
        black_box(acc);
        best = best.min(start.elapsed().as_secs_f64());
    }
    let cpu_ms_per_mp = best * 1e3 / ((side * side) as f64 / 1e6);
    println!(
        "gabor (F0 1/16, a 0.05, N 64) CPU 1 thread {cpu_ms_per_mp:8.1} ms/MP ({:.1} ms/MP over {threads} threads, ideal)",
        cpu_ms_per_mp / threads as f64
    );

    if marbling_testkit::skip_requested() {
        println!("gabor GPU: skipped (MARBLING_SKIP_GPU=1)");
        return;
    }
    match gpu::GpuNoise::new() {
        Ok(dev) => {
            let spec = NoiseSpec::from_json(gabor_json).expect("valid");
            let size = 512;
            let u = NoiseGpu::from_spec(&spec, size).expect("gpu form");
            let _ = dev.run(&u, size); // warm-up (pipeline compilation)
            let best = (0..3)
                .map(|_| dev.run(&u, size).1.as_secs_f64())
                .fold(f64::INFINITY, f64::min);
            let mp = f64::from(size * size) / 1e6;
            println!(
                "gabor GPU {:40} {:8.2} ms/MP ({size}², {:.1} ms; 1680×988 would take {:.1} ms)",
                dev.adapter,
                best * 1e3 / mp,
                best * 1e3,
                best * 1e3 / mp * 1.659_84
            );
        }
        Err(e) => println!("gabor GPU: skipped ({e})"),
    }
}
