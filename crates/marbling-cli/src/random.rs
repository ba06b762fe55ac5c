//! `marbling random`: writes one of the benchmarks' synthetic designs as JSON, to try
//! the renderers (and the playground) on long histories.

use crate::bench::MixArg;
use crate::size::Size;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::MAX_OPS;
use marbling_core::synth::random_design;
use std::path::PathBuf;

/// Arguments of `marbling random`.
#[derive(Args)]
pub struct RandomArgs {
    /// Number of ops.
    #[arg(long, default_value_t = 100)]
    pub ops: usize,
    /// Design size in design pixels: `N` (square) or `WxH`.
    #[arg(long, default_value = "1024x768")]
    pub size: Size,
    /// Seed of the generator (the same seed gives the same design).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Which ops to favour.
    #[arg(long, value_enum, default_value_t = MixArg::Mixed)]
    pub mix: MixArg,
    /// Output JSON file (`-` for standard output).
    #[arg(short, long)]
    pub output: PathBuf,
}

/// Writes the design.
pub fn run(args: &RandomArgs) -> Result<()> {
    if args.ops > MAX_OPS {
        bail!("--ops must be at most {MAX_OPS}, got {}", args.ops);
    }
    let (_, mix) = args.mix.mix();
    let design = random_design(args.seed, args.size.width, args.size.height, args.ops, mix);
    let json = design.to_json_pretty();
    if args.output.as_os_str() == "-" {
        println!("{json}");
        return Ok(());
    }
    std::fs::write(&args.output, json)
        .with_context(|| format!("cannot write '{}'", args.output.display()))
}
