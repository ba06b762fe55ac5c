//! `marbling bench-svg`: vector export time, vertex count and SVG size on synthetic
//! designs, with and without simplification.

use anyhow::{Result, bail};
use clap::{Args, ValueEnum};
use marbling_core::synth::{Mix, random_design};
use marbling_vector::{TraceOptions, to_svg, trace};
use std::time::Instant;

/// Which synthetic designs to export.
#[derive(Clone, Copy, ValueEnum)]
pub enum MixArg {
    /// All seven op types in roughly equal parts.
    Mixed,
    /// About 80 % drops and sprays.
    DropHeavy,
    /// A few drops, then about 90 % combs.
    CombHeavy,
}

/// Arguments of `marbling bench-svg`.
#[derive(Args)]
pub struct BenchSvgArgs {
    /// Width of the design, pixels (the height is 3/4 of it).
    #[arg(long, default_value_t = 800)]
    size: u32,
    /// Op counts to measure, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "50,200,1000")]
    ops: Vec<usize>,
    /// Tolerances to measure (output pixels at scale 1), comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1,0.25")]
    tolerance: Vec<f64>,
    /// Synthetic design mix.
    #[arg(long, value_enum, default_value = "mixed")]
    mix: MixArg,
    /// Seed of the synthetic designs.
    #[arg(long, default_value_t = 7)]
    seed: u64,
    /// Also export without simplification (slow and large for big designs).
    #[arg(long)]
    raw: bool,
    /// Also export exactly: no lossy step, no re-anchoring, no vertex budget (as
    /// `marbling svg --exact`; vertex counts then grow geometrically with the op count,
    /// so keep --ops small).
    #[arg(long)]
    lossless: bool,
    /// Vertex budget of the lossy export (see `TraceOptions::max_live`).
    #[arg(long, default_value_t = TraceOptions::default().max_live)]
    max_live: usize,
    /// Exports per case; the fastest is reported.
    #[arg(long, default_value_t = 1)]
    repeat: u32,
}

/// Runs every case and prints a Markdown table.
pub fn run(args: &BenchSvgArgs) -> Result<()> {
    if args.size < 4 || args.repeat == 0 {
        bail!("--size must be at least 4 and --repeat at least 1");
    }
    let mix = match args.mix {
        MixArg::Mixed => Mix::Mixed,
        MixArg::DropHeavy => Mix::DropHeavy,
        MixArg::CombHeavy => Mix::CombHeavy,
    };
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (w, h) = (args.size, args.size * 3 / 4);
    println!(
        "vector export, {threads} threads, {w}×{h} design px, {mix:?}, seed {}",
        args.seed
    );
    println!(
        "| ops | T px | simplified | lossy | seconds | peak vertices | refined vertices | exported vertices | regions | rings | dropped px² | remapped points | level | SVG bytes |"
    );
    println!("|---:|---:|:---:|:---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for &n in &args.ops {
        let design = random_design(args.seed, w, h, n, mix);
        for &t in &args.tolerance {
            let mut modes = vec![(true, true)];
            if args.raw {
                modes.push((false, true));
            }
            if args.lossless {
                modes.push((true, false));
            }
            for &(simplify, lossy) in &modes {
                let defaults = TraceOptions::default();
                let opts = TraceOptions {
                    tolerance: t,
                    simplify,
                    thin: if lossy { defaults.thin } else { 0.0 },
                    anchor: if lossy { defaults.anchor } else { 0 },
                    max_live: if lossy { args.max_live } else { usize::MAX },
                    ..defaults
                };
                let mut best = f64::INFINITY;
                let mut result = None;
                for _ in 0..args.repeat {
                    let start = Instant::now();
                    let vector = trace(&design, &opts)?;
                    let svg = to_svg(&vector);
                    best = best.min(start.elapsed().as_secs_f64());
                    result = Some((vector.stats, svg.len()));
                }
                if let Some((s, bytes)) = result {
                    println!(
                        "| {n} | {t} | {} | {} | {best:.2} | {} | {} | {} | {} | {} | {:.1} | {} | {} | {bytes} |",
                        if simplify { "yes" } else { "no" },
                        if lossy { "yes" } else { "no" },
                        s.peak_vertices,
                        s.refined_vertices,
                        s.vertices,
                        s.regions - s.culled,
                        s.rings,
                        s.dropped_area,
                        s.mapped_points,
                        s.level,
                    );
                }
            }
        }
    }
    Ok(())
}
