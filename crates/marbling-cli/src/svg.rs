//! `marbling svg`: the design as an SVG of ink outlines (forward-traced, or read off the
//! exact label raster past the vertex budget) with raster layers where outlines cannot
//! hold the picture.

use crate::input::read_design;
use crate::render::LazyProgress;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_vector::{TraceOptions, to_svg, trace_with_progress};
use std::io::Write;
use std::path::Path;
use std::time::Instant;

/// Arguments of `marbling svg`.
#[derive(Args)]
pub struct SvgArgs {
    /// Design document (JSON); `-` reads standard input.
    design: String,
    /// Output SVG; `-` writes to standard output. Written only once complete.
    #[arg(short, long)]
    output: String,
    /// Tolerance T in output pixels: forward-traced outlines stay within about T/12 of
    /// the true ones, contour outlines within T/2 (see marbling_vector's docs).
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    tolerance: f64,
    /// Output pixels per design pixel: the SVG's width/height attributes and the unit of
    /// the tolerance (default 1).
    #[arg(long, conflicts_with = "width")]
    scale: Option<f64>,
    /// Output width in pixels (the height follows the design's aspect ratio).
    #[arg(long)]
    width: Option<u32>,
    /// Keep every refined vertex (no simplification, no off-canvas collapse).
    #[arg(long)]
    no_simplify: bool,
    /// Exact forward tracing of every region: no re-anchoring, no vertex budget (so no
    /// contour method). Vertex counts then grow geometrically with the op count.
    #[arg(long)]
    exact: bool,
    /// Refuse designs needing more refined vertices than this.
    #[arg(long, default_value_t = TraceOptions::default().max_vertices)]
    max_vertices: usize,
}

/// The output scale from `--scale` or `--width`.
pub fn scale_of(scale: Option<f64>, width: Option<u32>, design_width: u32) -> Result<f64> {
    Ok(match (scale, width) {
        (Some(s), _) => s,
        (None, Some(0)) => bail!("--width must be at least 1"),
        (None, Some(w)) => f64::from(w) / f64::from(design_width),
        (None, None) => 1.0,
    })
}

/// Writes `bytes` to `path` atomically: a temporary file beside it, then a rename, so a
/// failure never leaves a partial file.
pub fn write_atomically(path: &str, bytes: &[u8]) -> Result<()> {
    let target = Path::new(path);
    let name = target
        .file_name()
        .with_context(|| format!("cannot write '{path}': not a file name"))?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".{}.tmp", std::process::id()));
    let tmp = target.with_file_name(tmp_name);
    let result = std::fs::File::create(&tmp)
        .and_then(|mut f| f.write_all(bytes).and_then(|()| f.sync_all()))
        .and_then(|()| std::fs::rename(&tmp, target));
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(e).with_context(|| format!("cannot write '{path}'"));
    }
    Ok(())
}

/// Traces the design and writes the SVG.
pub fn run(args: &SvgArgs) -> Result<()> {
    let design = read_design(&args.design)?;
    let defaults = TraceOptions::default();
    let opts = TraceOptions {
        tolerance: args.tolerance,
        scale: scale_of(args.scale, args.width, design.width)?,
        simplify: !args.no_simplify,
        max_vertices: args.max_vertices,
        anchor: if args.exact { 0 } else { defaults.anchor },
        contour_all: if args.exact {
            0.0
        } else {
            defaults.contour_all
        },
        max_live: if args.exact {
            usize::MAX
        } else {
            defaults.max_live
        },
        ..defaults
    };
    opts.validate()?;
    let start = Instant::now();
    let progress = LazyProgress::new();
    let traced = trace_with_progress(&design, &opts, &|d, t| progress.update(d, t));
    progress.finish();
    let vector = traced?;
    let svg = to_svg(&vector);
    let elapsed = start.elapsed();
    if args.output == "-" {
        let mut out = std::io::stdout().lock();
        out.write_all(svg.as_bytes())
            .and_then(|()| out.flush())
            .context("cannot write standard output")?;
    } else {
        write_atomically(&args.output, svg.as_bytes())?;
    }
    let s = vector.stats;
    let summary = format!(
        "{}: {} ops, {} regions ({} culled, {} by contour) in {} rings, {} vertices ({} refined, peak {}), {} pixels in the raster patch, {} bytes, T {} px at scale {}, traced in {:.3} s",
        args.output,
        design.ops.len(),
        s.regions - s.culled,
        s.culled,
        s.contour_regions,
        s.rings,
        s.vertices,
        s.refined_vertices,
        s.peak_vertices,
        s.dense_pixels,
        svg.len(),
        opts.tolerance,
        opts.scale,
        elapsed.as_secs_f64()
    );
    crate::output::say(&args.output, &summary);
    Ok(())
}
