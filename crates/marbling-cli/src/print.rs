//! `marbling render --print SIZE [--dpi D] [--bleed B]`: a print-sized PNG, rendered band
//! by band of rows and streamed to the file, so any size fits in memory; the PNG's
//! `pHYs` chunk carries the DPI.

use crate::render::{LazyProgress, RenderArgs};
use anyhow::{Context, Result};
use marbling_core::print::{PaperPreset, Print, SheetSize, parse_bleed};
use marbling_core::{Design, render_window_rows};
use std::io::Write;
use std::time::Instant;

/// Reads the sheet: a preset (turned to the design) or `WxH` with a unit.
pub fn sheet_for(design: &Design, text: &str) -> Result<SheetSize> {
    if let Some(preset) = PaperPreset::named(text) {
        return Ok(preset.for_design(design));
    }
    text.parse::<SheetSize>()
        .with_context(|| format!("--print {text:?}"))
}

/// Renders `design` for print on `sheet` and writes the PNG.
pub fn run(args: &RenderArgs, design: &Design, sheet: &str) -> Result<()> {
    let print = Print {
        sheet: sheet_for(design, sheet)?,
        dpi: args.dpi,
        bleed_mm: parse_bleed(&args.bleed).context("--bleed")?,
    };
    print.check().context("--print")?;
    let window = print.window(design);
    let start = Instant::now();
    let out: Box<dyn Write> = if args.output == "-" {
        Box::new(std::io::stdout().lock())
    } else {
        Box::new(
            std::fs::File::create(&args.output)
                .with_context(|| format!("cannot write '{}'", args.output))?,
        )
    };
    let mut enc = png::Encoder::new(std::io::BufWriter::new(out), window.width, window.height);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    let ppm = print.pixels_per_metre();
    enc.set_pixel_dims(Some(png::PixelDimensions {
        xppu: ppm,
        yppu: ppm,
        unit: png::Unit::Meter,
    }));
    let cannot = || format!("cannot write '{}'", args.output);
    let mut writer = enc.write_header().with_context(cannot)?;
    let mut stream = writer.stream_writer().with_context(cannot)?;
    let progress = LazyProgress::new();
    let mut rgb = Vec::new();
    render_window_rows::<anyhow::Error>(
        design,
        &window,
        args.aa,
        &|d, t| progress.update(d, t),
        |_, rows| {
            rgb.clear();
            rgb.extend(rows.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]));
            stream.write_all(&rgb).with_context(cannot)
        },
    )?;
    stream.finish().with_context(cannot)?;
    progress.finish();
    let summary = format!(
        "{}: {}×{} px, {print} (design scaled {:.4}×, centred), {} ops, aa {}, rendered in {:.3} s",
        args.output,
        window.width,
        window.height,
        window.scale,
        design.ops.len(),
        args.aa,
        start.elapsed().as_secs_f64()
    );
    crate::output::say(&args.output, &summary);
    Ok(())
}
