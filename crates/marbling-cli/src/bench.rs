//! `marbling bench`: renderer throughput in op-samples per second
//! (output pixels × samples per pixel × ops ÷ seconds) on synthetic designs.

use crate::backend::Backend;
use crate::size::Size;
use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use marbling_core::synth::{KINDS, Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};
use std::time::Instant;

/// Arguments of `marbling bench`.
#[derive(Args)]
pub struct BenchArgs {
    /// Output size: `N` (square) or `WxH`, e.g. 1920x1080.
    #[arg(long, default_value = "1024")]
    pub size: Size,
    /// Op counts to measure, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "10,100,1000,10000")]
    pub ops: Vec<usize>,
    /// Antialiasing mode.
    #[arg(long, default_value = "none")]
    pub aa: Antialias,
    /// Renders per case; the fastest is reported.
    #[arg(long, default_value_t = 1)]
    pub repeat: u32,
    /// Renderer to measure.
    #[arg(long, value_enum, default_value_t = Backend::Cpu)]
    pub backend: Backend,
    /// Synthetic design mixes, comma separated.
    #[arg(
        long,
        value_enum,
        value_delimiter = ',',
        default_value = "comb-heavy,drop-heavy"
    )]
    pub mix: Vec<MixArg>,
    /// GPU only: measure live-editing frames (cached history + one pending op) and the
    /// exact frame they stand in for; `--ops` is the committed history length.
    #[arg(long)]
    pub pending: bool,
    /// With `--pending`: preview frames to average.
    #[arg(long, default_value_t = 200)]
    pub frames: u32,
    /// GPU only: draw exact frames with the fragment pipeline (the app's path, and the
    /// only one on WebGL2) instead of the compute pass headless renders use.
    #[arg(long)]
    pub fragment: bool,
    /// GPU only: exact frames of a window of `--size` centred on the sheet at each of
    /// these zooms (output pixels per design pixel); where f32 cannot place samples
    /// (`marbling_gpu::deep::needs_deep`) by the deep walk, its per-tile f64 reference
    /// walks counted in the frame (what the app pays for each new view).
    #[arg(long, value_delimiter = ',', default_value = "1")]
    pub zoom: Vec<f64>,
    /// CPU only: the walk's vector kernels, comma separated: `auto` (the widest unit
    /// found: AVX2 where the processor has it) and `off` (the build's baseline, SSE2 on
    /// x86-64), each case run under each in turn (`auto,off`: the two side by side).
    #[arg(long, value_enum, value_delimiter = ',', default_value = "auto")]
    pub simd: Vec<SimdArg>,
    /// A cost profile per op kind instead of `--mix`: for each of the 14 kinds a design
    /// of one drop and then `--ops` − 1 ops of that kind, named by the op's type.
    /// Samples that meet a drop's ink stop there, so drop-like kinds count work not done.
    #[arg(long)]
    pub per_kind: bool,
}

/// Which vector kernels the CPU walk may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum SimdArg {
    /// The widest vector unit the processor has.
    Auto,
    /// The build's baseline only.
    Off,
}

/// A synthetic design mix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MixArg {
    /// A few drops, then mostly tines, rakes and wavy combs.
    CombHeavy,
    /// Mostly drops and sprays.
    DropHeavy,
    /// The seven op types of schema v1 in equal parts.
    Mixed,
    /// All fourteen op types (schema v1 and v3: shift, turn, comb, drops, sprays,
    /// jiggle, stylus) in equal parts.
    AllTypes,
    /// A few drop patterns, then free-hand styli (on the CPU also timed walking with and
    /// without the stylus's culling).
    Stylus,
}

/// The designs a run measures, with their names: the `--mix` list, or with
/// `--per-kind` one design mix per op kind.
pub fn cases(args: &BenchArgs) -> Vec<(&'static str, Mix)> {
    if args.per_kind {
        (0..KINDS)
            .map(|k| {
                let d = random_design(7, 64, 64, 2, Mix::Only(k));
                (d.ops[1].type_name(), Mix::Only(k))
            })
            .collect()
    } else {
        args.mix.iter().map(|m| m.mix()).collect()
    }
}

impl MixArg {
    /// The generator's mix and its name.
    pub fn mix(self) -> (&'static str, Mix) {
        match self {
            MixArg::CombHeavy => ("comb-heavy", Mix::CombHeavy),
            MixArg::DropHeavy => ("drop-heavy", Mix::DropHeavy),
            MixArg::Mixed => ("mixed", Mix::Mixed),
            MixArg::AllTypes => ("all-types", Mix::AllTypes),
            MixArg::Stylus => ("stylus", Mix::Stylus),
        }
    }
}

/// Runs every case and prints a table.
pub fn run(args: &BenchArgs) -> Result<()> {
    if args.repeat == 0 || args.frames == 0 {
        bail!("--repeat and --frames must be at least 1");
    }
    match (args.backend, args.pending) {
        (Backend::Gpu, true) => return crate::bench_gpu::pending(args),
        (Backend::Gpu, false) => return crate::bench_gpu::exact(args),
        (Backend::Cpu, true) => bail!("--pending measures GPU preview frames: add --backend gpu"),
        (Backend::Cpu, false) => {}
        (Backend::Vector, _) => bail!("vector export is measured by `marbling bench-svg`"),
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "backend cpu, {threads} threads, {} px, aa {} ({} samples/px)",
        args.size,
        args.aa,
        args.aa.samples().len()
    );
    println!(
        "{:<12} {:>7} {:>5} {:>10} {:>18}",
        "design", "ops", "lanes", "seconds", "op-samples/s"
    );
    let Size { width, height } = args.size;
    for (name, mix) in cases(args) {
        for (&n, &simd) in args
            .ops
            .iter()
            .flat_map(|n| args.simd.iter().map(move |s| (n, s)))
        {
            marbling_core::set_wide_kernels(simd == SimdArg::Auto);
            let lanes = marbling_core::vector_width();
            let design = random_design(7, width, height, n, mix);
            let opts = RenderOptions {
                scale: 1.0,
                antialias: args.aa,
            };
            let mut best = f64::INFINITY;
            for _ in 0..args.repeat {
                let start = Instant::now();
                render(&design, &opts)?;
                best = best.min(start.elapsed().as_secs_f64());
            }
            let work =
                f64::from(width) * f64::from(height) * args.aa.samples().len() as f64 * n as f64;
            println!(
                "{name:<12} {n:>7} {lanes:>5} {best:>10.3} {:>18.3e}",
                work / best
            );
            if mix == Mix::Stylus {
                for cull in [true, false] {
                    let start = Instant::now();
                    walk_every_sample(&design, args.aa, cull);
                    let secs = start.elapsed().as_secs_f64();
                    let label = if cull { "walk culled" } else { "walk unculled" };
                    println!(
                        "{label:<12} {n:>7} {:>5} {secs:>10.3} {:>18.3e}",
                        "",
                        work / secs
                    );
                }
            }
        }
    }
    marbling_core::set_wide_kernels(true);
    Ok(())
}

/// Walks every sample of `design` at scale 1 back through its ops (all threads), the
/// styli with their culling or without it ([`marbling_core::StylusSegment::
/// inverse_unculled`]): the stylus's share of a render, with and without culling.
fn walk_every_sample(design: &marbling_core::Design, aa: marbling_core::Antialias, cull: bool) {
    use marbling_core::{CompiledOp, Point};
    use rayon::prelude::*;
    let steps = CompiledOp::compile(&design.ops);
    let samples = aa.samples();
    let moved: usize = (0..design.height)
        .into_par_iter()
        .map(|y| {
            let mut moved = 0;
            for x in 0..design.width {
                for s in samples {
                    let mut p = Point::new(f64::from(x) + s.dx, f64::from(y) + s.dy);
                    for step in steps.iter().rev() {
                        p = match step {
                            CompiledOp::Stylus { segments } => {
                                segments.iter().rev().fold(p, |p, seg| {
                                    if cull {
                                        seg.inverse(p)
                                    } else {
                                        seg.inverse_unculled(p)
                                    }
                                })
                            }
                            other => match other.inverse(p) {
                                Some(q) => q,
                                None => break,
                            },
                        };
                    }
                    moved += usize::from(p.x != f64::from(x) + s.dx);
                }
            }
            moved
        })
        .sum();
    std::hint::black_box(moved);
}
