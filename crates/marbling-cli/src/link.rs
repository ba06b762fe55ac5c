//! `marbling link`: make a share link for a design, or turn a link back into JSON.

use crate::input::read_design;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::{
    MAX_PICTURE_LINK_CHARS, decode_share, share_fragment, with_link_sized_picture,
};

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
    /// With a picture background too large for a link (about 64 KB): downscale the
    /// picture until the link fits, instead of failing.
    #[arg(long, conflicts_with = "decode")]
    downscale: bool,
    /// With --decode: write the JSON here instead of standard output.
    #[arg(short, long, requires = "decode")]
    output: Option<String>,
}

/// Prints the link, or the decoded design.
pub fn run(args: &LinkArgs) -> Result<()> {
    if !args.decode {
        let mut design = read_design(&args.input)?;
        let fragment = share_fragment(&design);
        if design.background_image.is_some() && fragment.len() > MAX_PICTURE_LINK_CHARS {
            if !args.downscale {
                bail!(
                    "the picture makes the link {} KB; links hold about {} KB: pass --downscale \
                     to shrink the picture for the link, or share the JSON file",
                    fragment.len() / 1024,
                    MAX_PICTURE_LINK_CHARS / 1024
                );
            }
            design = with_link_sized_picture(&design, MAX_PICTURE_LINK_CHARS).with_context(
                || "even a 96-pixel picture does not fit a link with these ops: share the JSON file",
            )?;
            let p = design.background_image.as_ref().map(|b| b.pixels());
            if let Some(p) = p {
                eprintln!(
                    "picture downscaled to {}×{} for the link",
                    p.width, p.height
                );
            }
        }
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
