//! `marbling bench --backend gpu`: exact frames (every sample through every op) and,
//! with `--pending`, live-editing frames (cached history + one pending op).
//!
//! A frame is timed from submitting the draw into an offscreen target of the output
//! size to the GPU finishing it (no readback), i.e. what the app pays per frame.

use crate::backend::gpu_renderer;
use crate::bench::BenchArgs;
use anyhow::Result;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, Design, Op, Point, Tine, Vec2};
use marbling_gpu::deep::{DeepView, needs_deep};
use marbling_gpu::{
    GpuRenderer, OUTPUT_FORMAT, PreparedDesign, PreviewRenderer, RenderTarget, View,
};
use std::time::Instant;

/// The renderer `args` ask for (`--fragment`: the fragment pipeline).
fn renderer(args: &BenchArgs) -> Result<GpuRenderer> {
    let gpu = gpu_renderer()?;
    Ok(if args.fragment {
        gpu.with_fragment_path()
    } else {
        gpu
    })
}

fn header(gpu: &GpuRenderer, args: &BenchArgs, what: &str) {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "backend gpu ({what}, {} path), adapter {}, {threads} CPU threads, {} px, aa {} ({} samples/px)",
        gpu.path(),
        gpu.context().describe(),
        args.size,
        args.aa,
        args.aa.samples().len()
    );
}

/// Seconds of the fastest of `repeat` runs of `f` (after one untimed run on a tiny
/// target, so shader compilation is not counted).
fn best_of(repeat: u32, mut f: impl FnMut() -> Result<()>) -> Result<f64> {
    let mut best = f64::INFINITY;
    for _ in 0..repeat {
        let start = Instant::now();
        f()?;
        best = best.min(start.elapsed().as_secs_f64());
    }
    Ok(best)
}

/// Exact frames: op-samples/s and frames/s per design.
pub fn exact(args: &BenchArgs) -> Result<()> {
    let gpu = renderer(args)?;
    header(&gpu, args, "exact frames");
    println!(
        "{:<12} {:>7} {:>9} {:>10} {:>9} {:>18}",
        "design", "ops", "zoom", "seconds", "fps", "op-samples/s"
    );
    let (w, h) = (args.size.width, args.size.height);
    let target = gpu.target(w, h);
    let warm = gpu.target(8, 8);
    for (name, mix) in crate::bench::cases(args) {
        for &n in &args.ops {
            let design = random_design(7, w, h, n, mix);
            let mut prepared = gpu.prepare(&design)?;
            for &zoom in &args.zoom {
                let best = exact_frame(&gpu, &mut prepared, &design, args, zoom, &target, &warm)?;
                let work = f64::from(w) * f64::from(h) * args.aa.samples().len() as f64 * n as f64;
                let deep = if needs_deep(f64::from(w.max(h)), zoom) {
                    " deep"
                } else {
                    ""
                };
                println!(
                    "{name:<12} {n:>7} {:>9} {best:>10.4} {:>9.2} {:>18.3e}{deep}",
                    format!("{zoom:e}"),
                    1.0 / best,
                    work / best
                );
            }
        }
    }
    Ok(())
}

/// Seconds of the best exact frame of `design` at `zoom` (a window of the target's size
/// centred on the sheet): the view set (deep: the reference walks) and the draw.
fn exact_frame(
    gpu: &GpuRenderer,
    prepared: &mut PreparedDesign,
    design: &Design,
    args: &BenchArgs,
    zoom: f64,
    target: &RenderTarget,
    warm: &RenderTarget,
) -> Result<f64> {
    let (w, h) = (args.size.width, args.size.height);
    let centre = Point::new(
        f64::from(design.width) / 2.0,
        f64::from(design.height) / 2.0,
    );
    let origin = Point::new(
        centre.x - f64::from(w) / (2.0 * zoom),
        centre.y - f64::from(h) / (2.0 * zoom),
    );
    let ctx = gpu.context();
    let deep = needs_deep(f64::from(design.width.max(design.height)), zoom);
    let set = |prepared: &mut PreparedDesign| -> Result<()> {
        if deep {
            let view = DeepView {
                origin,
                scale: zoom,
                size: [w, h],
                antialias: args.aa,
            };
            gpu.exact()
                .set_deep_view(&ctx.device, &ctx.queue, prepared, &view)?;
        } else {
            let view = View {
                scale: zoom,
                offset: [origin.x * zoom, origin.y * zoom],
                antialias: args.aa,
            };
            prepared.set_view(&ctx.queue, &view);
        }
        Ok(())
    };
    set(prepared)?;
    gpu.record_draw(prepared, warm);
    gpu.wait()?;
    best_of(args.repeat, || {
        set(prepared)?;
        gpu.record_draw(prepared, target);
        Ok(gpu.wait()?)
    })
}

/// The op being "dragged" in frame `i`: a tine sweeping across the canvas.
fn dragged_tine(i: u32, w: f64, h: f64) -> Op {
    let t = f64::from(i % 100) / 100.0;
    Op::Tine(Tine {
        origin: Point::new(0.0, h * (0.2 + 0.6 * t)),
        direction: Vec2::new(1.0, 0.1),
        alpha: 0.05 * w,
        lambda: 0.02 * w,
    })
}

/// Live-editing frames per committed history length: the one-off cache build, the
/// mean preview frame over `--frames` frames, and the exact frame it stands in for.
pub fn pending(args: &BenchArgs) -> Result<()> {
    let gpu = renderer(args)?;
    header(&gpu, args, "live editing: cached history + one pending op");
    println!(
        "{:>7} {:>11} {:>10} {:>12} {:>11} {:>14} {:>10}",
        "history", "cache px", "cache s", "preview ms", "preview fps", "exact frame s", "exact fps"
    );
    let ctx = gpu.context();
    let (device, queue) = (&ctx.device, &ctx.queue);
    let (w, h) = (args.size.width, args.size.height);
    let preview = PreviewRenderer::new(device, OUTPUT_FORMAT);
    let target = gpu.target(w, h);
    let mix = args.mix.first().map_or(Mix::Mixed, |m| m.mix().1);
    for &n in &args.ops {
        let committed = random_design(7, w, h, n, mix);
        let start = Instant::now();
        let mut cache = preview.build_cache(device, queue, &committed, 1.0, args.aa)?;
        gpu.wait()?;
        let cache_s = start.elapsed().as_secs_f64();
        let (cw, ch) = cache.cache_size();
        // One untimed frame, then `frames` frames, each with the dragged op moved.
        let frame = |cache: &mut marbling_gpu::PreviewCache, i: u32| -> Result<()> {
            let op = dragged_tine(i, f64::from(w), f64::from(h));
            cache.set_frame(queue, Some(&op), [0.0; 2], 1.0, args.aa);
            let mut encoder = device.create_command_encoder(&wgpu_encoder_descriptor());
            {
                let mut pass = target.begin_pass(&mut encoder);
                preview.draw(&mut pass, cache);
            }
            queue.submit([encoder.finish()]);
            Ok(gpu.wait()?)
        };
        frame(&mut cache, 0)?;
        let start = Instant::now();
        for i in 0..args.frames {
            frame(&mut cache, i)?;
        }
        let per_frame = start.elapsed().as_secs_f64() / f64::from(args.frames);
        // The exact frame shown once the op is committed.
        let mut full = committed.clone();
        full.ops.push(dragged_tine(0, f64::from(w), f64::from(h)));
        let mut prepared = gpu.prepare(&full)?;
        let view = View {
            scale: 1.0,
            offset: [0.0; 2],
            antialias: args.aa,
        };
        let exact_s = best_of(args.repeat, || {
            gpu.draw(&mut prepared, &target, &view);
            Ok(gpu.wait()?)
        })?;
        println!(
            "{n:>7} {:>11} {cache_s:>10.3} {:>12.3} {:>11.1} {exact_s:>14.4} {:>10.2}",
            format!("{cw}×{ch}"),
            1e3 * per_frame,
            1.0 / per_frame,
            1.0 / exact_s
        );
    }
    if args.aa.samples().len() > 4 || args.aa == Antialias::Adaptive {
        println!("(preview frames sample RGSS; patterns of more than 4 samples fall back to it)");
    }
    Ok(())
}

fn wgpu_encoder_descriptor() -> marbling_gpu::wgpu::CommandEncoderDescriptor<'static> {
    marbling_gpu::wgpu::CommandEncoderDescriptor { label: None }
}
