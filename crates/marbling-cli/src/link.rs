//! `marbling link`: make a share link for a design, or turn a link back into JSON.

use crate::input::read_design;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::share_qr::{MAX_QR_LINK_BYTES, QrError, link_qr, shortest_for_link};
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
    /// Also write the link's QR code to this PNG file (a link longer than a QR code
    /// holds, 2953 characters, is refused unless --shortest makes it fit).
    #[arg(long, value_name = "PNG", conflicts_with = "decode")]
    qr: Option<String>,
    /// Pixels per QR module in --qr's picture.
    #[arg(long, default_value_t = 8, value_parser = clap::value_parser!(u32).range(1..=64), requires = "qr")]
    qr_module: u32,
    /// Make the link as short as it can be: every op rounded and a picture downscaled
    /// until the link fits a QR code (with --qr) or a link.
    #[arg(long, conflicts_with = "decode")]
    shortest: bool,
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
        if args.shortest {
            // What fits a QR code, counting the base and the `#`.
            let budget = match args.qr {
                Some(_) => MAX_QR_LINK_BYTES.saturating_sub(args.base.len() + 1),
                None => MAX_PICTURE_LINK_CHARS,
            };
            design = shortest_for_link(&design, budget).with_context(|| {
                format!(
                    "even the shortest form of the design makes a link longer than {} characters: share the JSON file",
                    budget + args.base.len() + 1
                )
            })?;
        }
        let link = format!("{}#{}", args.base, share_fragment(&design));
        if let Some(path) = &args.qr {
            let qr = link_qr(&link).map_err(|e| match e {
                QrError::TooLong { .. } if !args.shortest => {
                    anyhow::anyhow!(
                        "{e}; --shortest rounds the ops and shrinks a picture to fit, or share the link or the JSON file"
                    )
                }
                e => anyhow::anyhow!("{e}: share the link or the JSON file"),
            })?;
            let png = qr.to_image(args.qr_module).to_png()?;
            std::fs::write(path, png).with_context(|| format!("cannot write '{path}'"))?;
            eprintln!(
                "QR code version {}, {} modules a side, written to {path}",
                qr.version, qr.side
            );
        }
        println!("{link}");
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
