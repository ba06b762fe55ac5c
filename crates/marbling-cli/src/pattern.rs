//! `marbling pattern`: writes a traditional pattern's recipe (a design document with
//! its name, history and step captions), at its defaults or with another size,
//! colours, comb spacing or seed; `--list` names them, `--all DIR` writes every one.

use crate::size::Size;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::Rgb8;
use marbling_core::patterns::{self, Params};
use std::path::{Path, PathBuf};

/// Arguments of `marbling pattern`.
#[derive(Args)]
pub struct PatternArgs {
    /// The pattern's name (see `--list`).
    pub name: Option<String>,
    /// Lists the patterns with their names and histories.
    #[arg(long)]
    pub list: bool,
    /// Writes every pattern at its defaults to DIR/NAME.json.
    #[arg(long, value_name = "DIR")]
    pub all: Option<PathBuf>,
    /// Tank size in design pixels: `N` (square) or `WxH` (default 640x400).
    #[arg(long)]
    pub size: Option<Size>,
    /// Inks in throwing order, comma separated `#rrggbb` (cycled where more are needed).
    #[arg(long, value_delimiter = ',')]
    pub colors: Option<Vec<String>>,
    /// Bath colour `#rrggbb`.
    #[arg(long)]
    pub background: Option<String>,
    /// Spacing of the finest comb, design pixels.
    #[arg(long)]
    pub spacing: Option<f64>,
    /// Seed of the throws' scatter.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Output JSON file (`-` for standard output).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

fn color(flag: &str, s: &str) -> Result<Rgb8> {
    s.trim()
        .parse()
        .map_err(|_| anyhow::anyhow!("{flag}: expected a colour like #1d3557, got {s:?}"))
}

fn write(path: &Path, json: &str) -> Result<()> {
    if path.as_os_str() == "-" {
        print!("{json}");
        return Ok(());
    }
    std::fs::write(path, json).with_context(|| format!("cannot write '{}'", path.display()))
}

/// Lists, writes one, or writes all.
pub fn run(args: &PatternArgs) -> Result<()> {
    if args.list {
        for p in patterns::all() {
            println!("{:<20} {} — {}", p.id, p.name, p.history);
        }
        return Ok(());
    }
    if let Some(dir) = &args.all {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("cannot create '{}'", dir.display()))?;
        for p in patterns::all() {
            let d = p.design(&Params::default()).map_err(anyhow::Error::msg)?;
            write(&dir.join(format!("{}.json", p.id)), &d.to_json_pretty())?;
        }
        return Ok(());
    }
    let Some(name) = &args.name else {
        bail!("name a pattern (see `marbling pattern --list`), or give --list or --all DIR");
    };
    let Some(output) = &args.output else {
        bail!("give the output file with -o FILE.json (`-` for standard output)");
    };
    let pattern = patterns::find(name).map_err(anyhow::Error::msg)?;
    let mut params = Params {
        seed: args.seed,
        spacing: args.spacing,
        ..Params::default()
    };
    if let Some(size) = args.size {
        (params.width, params.height) = (size.width, size.height);
    }
    if let Some(list) = &args.colors {
        params.colors = Some(
            list.iter()
                .map(|c| color("--colors", c))
                .collect::<Result<_>>()?,
        );
    }
    if let Some(b) = &args.background {
        params.background = Some(color("--background", b)?);
    }
    let design = pattern.design(&params).map_err(anyhow::Error::msg)?;
    write(output, &design.to_json_pretty())
}
