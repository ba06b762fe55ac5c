//! `marbling palette INPUT [--colors K] [-o OUT.gpl]`: an ink palette from a GIMP
//! `.gpl`, a picture (its K main colours by k-means) or text of hex colours, written as
//! a `.gpl` (the app's *Import palette…* reads the same files the same way).

use anyhow::{Context, Result};
use clap::Args;
use marbling_core::ink_palette::InkPalette;
use std::io::Read;

/// Arguments of `marbling palette`.
#[derive(Args)]
pub struct PaletteArgs {
    /// A GIMP palette (.gpl), a picture (PNG, JPEG, WebP) or text of hex colours
    /// (`#1d3557, #e63946 …`); `-` reads standard input.
    input: String,
    /// Colours taken from a picture, 2 to 10.
    #[arg(long, default_value_t = 5)]
    colors: usize,
    /// The `.gpl` file to write; standard output without it.
    #[arg(short, long)]
    output: Option<String>,
}

/// Reads the palette and writes it as a `.gpl`.
pub fn run(args: &PaletteArgs) -> Result<()> {
    let bytes = if args.input == "-" {
        let mut b = Vec::new();
        std::io::stdin()
            .read_to_end(&mut b)
            .context("cannot read standard input")?;
        b
    } else {
        std::fs::read(&args.input).with_context(|| format!("cannot read '{}'", args.input))?
    };
    let name = if args.input == "-" {
        "palette"
    } else {
        args.input.as_str()
    };
    let palette = InkPalette::import(name, &bytes, args.colors)
        .with_context(|| format!("'{}'", args.input))?;
    let gpl = palette.to_gpl();
    match &args.output {
        Some(out) => {
            std::fs::write(out, &gpl).with_context(|| format!("cannot write '{out}'"))?;
            let hex: Vec<String> = palette.colors.iter().map(ToString::to_string).collect();
            println!("{out}: {} colours: {}", palette.colors.len(), hex.join(" "));
        }
        None => print!("{gpl}"),
    }
    Ok(())
}
