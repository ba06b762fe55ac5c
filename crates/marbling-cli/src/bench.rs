//! `marbling bench`: renderer throughput in op-samples per second
//! (output pixels × samples per pixel × ops ÷ seconds) on synthetic designs.

use anyhow::{Result, bail};
use clap::Args;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions, render};
use std::time::Instant;

/// Arguments of `marbling bench`.
#[derive(Args)]
pub struct BenchArgs {
    /// Side of the square output, pixels.
    #[arg(long, default_value_t = 1024)]
    size: u32,
    /// Op counts to measure, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "10,100,1000,10000")]
    ops: Vec<usize>,
    /// Antialiasing mode.
    #[arg(long, default_value = "none")]
    aa: Antialias,
    /// Renders per case; the fastest is reported.
    #[arg(long, default_value_t = 1)]
    repeat: u32,
}

/// Runs every case and prints a table.
pub fn run(args: &BenchArgs) -> Result<()> {
    if args.size == 0 || args.repeat == 0 {
        bail!("--size and --repeat must be at least 1");
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "backend cpu, {threads} threads, {0}×{0} px, aa {1} ({2} samples/px)",
        args.size,
        args.aa,
        args.aa.samples().len()
    );
    println!(
        "{:<12} {:>7} {:>10} {:>18}",
        "design", "ops", "seconds", "op-samples/s"
    );
    for (name, mix) in [
        ("comb-heavy", Mix::CombHeavy),
        ("drop-heavy", Mix::DropHeavy),
    ] {
        for &n in &args.ops {
            let design = random_design(7, args.size, args.size, n, mix);
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
            let work = f64::from(args.size).powi(2) * args.aa.samples().len() as f64 * n as f64;
            println!("{name:<12} {n:>7} {best:>10.3} {:>18.3e}", work / best);
        }
    }
    Ok(())
}
