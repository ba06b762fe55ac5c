//! `marbling link`: make a share link for a design, or turn a link back into JSON.

use crate::input::read_design;
use anyhow::{Context, Result};
use clap::Args;
use marbling_core::{decode_share, share_fragment};

/// Arguments of `marbling link`.
#[derive(Args)]
pub struct LinkArgs {
    /// Design document (JSON; `-` reads stdin), or with --decode a share link.
    input: String,
    /// Address of the playground the link opens.
    #[arg(long, default_value = "http://127.0.0.1:8080/")]
    base: String,
    /// Read a share link (`…#d=…`) and print its design as JSON.
    #[arg(long)]
    decode: bool,
    /// With --decode: write the JSON here instead of standard output.
    #[arg(short, long, requires = "decode")]
    output: Option<String>,
}

/// Prints the link, or the decoded design.
pub fn run(args: &LinkArgs) -> Result<()> {
    if !args.decode {
        let design = read_design(&args.input)?;
        println!("{}#{}", args.base, share_fragment(&design));
        return Ok(());
    }
    let design = decode_share(&args.input)?;
    let json = design.to_json_pretty();
    match &args.output {
        Some(path) => {
            std::fs::write(path, json).with_context(|| format!("cannot write '{path}'"))?
        }
        None => print!("{json}"),
    }
    Ok(())
}
