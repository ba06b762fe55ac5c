//! `marbling bench-svg`: vector export time, vertex count, SVG size and, with
//! `--check`, agreement of the SVG (rendered by resvg) with the exact 4×4-supersampled
//! CPU render, on synthetic designs and design files.

use crate::input::read_design;
use anyhow::{Context, Result, bail};
use clap::{Args, ValueEnum};
use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, Design, RenderOptions, RgbaImage, render};
use marbling_vector::{TraceOptions, to_svg, trace};
use std::time::Instant;

/// Pixels differing by more than this (of 255) count as mismatches in `--check`.
pub const MISMATCH_THRESHOLD: u8 = 48;

/// Which synthetic designs to export.
#[derive(Clone, Copy, ValueEnum)]
pub enum MixArg {
    /// All seven op types in roughly equal parts.
    Mixed,
    /// About 80 % drops and sprays.
    DropHeavy,
    /// A few drops, then about 90 % combs at full strength: chaotic beyond a few
    /// hundred ops.
    CombHeavy,
    /// All fourteen op types (schema v3 among them).
    AllTypes,
}

/// Arguments of `marbling bench-svg`.
#[derive(Args)]
pub struct BenchSvgArgs {
    /// Design files to export (instead of synthetic designs), each at its own size
    /// times `--scale`.
    designs: Vec<String>,
    /// Width of the synthetic designs, pixels (the height is `--aspect` times it).
    #[arg(long, default_value_t = 800)]
    size: u32,
    /// Height of the synthetic designs as a fraction of their width.
    #[arg(long, default_value_t = 0.75)]
    aspect: f64,
    /// Op counts of the synthetic designs, comma separated.
    #[arg(long, value_delimiter = ',', default_value = "50,200,1000")]
    ops: Vec<usize>,
    /// Tolerances to measure (output pixels), comma separated.
    #[arg(long, value_delimiter = ',', default_value = "1,0.25")]
    tolerance: Vec<f64>,
    /// Synthetic design mixes, comma separated.
    #[arg(long, value_enum, value_delimiter = ',', default_value = "mixed")]
    mix: Vec<MixArg>,
    /// Seed of the synthetic designs.
    #[arg(long, default_value_t = 7)]
    seed: u64,
    /// Output pixels per design pixel of design files.
    #[arg(long, default_value_t = 1.0)]
    scale: f64,
    /// Also export exactly: no re-anchoring, no vertex budget (as `marbling svg
    /// --exact`; vertex counts then grow geometrically with the op count, so keep --ops
    /// small).
    #[arg(long)]
    lossless: bool,
    /// Vertex budget of forward tracing (see `TraceOptions::max_live`).
    #[arg(long, default_value_t = TraceOptions::default().max_live)]
    max_live: usize,
    /// Render each SVG with resvg and count the pixels that differ by more than 48/255
    /// from the exact CPU render with 4×4 supersampling (slow for big designs).
    #[arg(long)]
    check: bool,
}

/// Runs every case and prints a Markdown table.
pub fn run(args: &BenchSvgArgs) -> Result<()> {
    if args.size < 4 || !(args.aspect > 0.0 && args.aspect <= 4.0) {
        bail!("--size must be at least 4 and --aspect in (0, 4]");
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut cases: Vec<(String, Design, f64)> = Vec::new();
    for path in &args.designs {
        cases.push((path.clone(), read_design(path)?, args.scale));
    }
    if args.designs.is_empty() {
        let (w, h) = (
            args.size,
            ((f64::from(args.size) * args.aspect) as u32).max(1),
        );
        for &mix in &args.mix {
            let (name, mix) = match mix {
                MixArg::Mixed => ("mixed", Mix::Mixed),
                MixArg::DropHeavy => ("drop-heavy", Mix::DropHeavy),
                MixArg::CombHeavy => ("comb-heavy", Mix::CombHeavy),
                MixArg::AllTypes => ("all-types", Mix::AllTypes),
            };
            for &n in &args.ops {
                let design = random_design(args.seed, w, h, n, mix);
                cases.push((format!("{name} {n} {w}×{h}"), design, 1.0));
            }
        }
    }
    println!("vector export, {threads} threads, seed {}", args.seed);
    println!(
        "| design | T px | lossy | seconds | peak vertices | exported vertices | regions | by contour | raster samples | rings | dropped px² | SVG bytes | mismatch |"
    );
    println!("|---|---:|:---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (name, design, scale) in &cases {
        let reference = if args.check {
            Some(render(
                design,
                &RenderOptions {
                    scale: *scale,
                    antialias: Antialias::Grid4,
                },
            )?)
        } else {
            None
        };
        for &t in &args.tolerance {
            let mut modes = vec![true];
            if args.lossless {
                modes.push(false);
            }
            for &lossy in &modes {
                let defaults = TraceOptions::default();
                let opts = TraceOptions {
                    tolerance: t,
                    scale: *scale,
                    anchor: if lossy { defaults.anchor } else { 0 },
                    contour_all: if lossy { defaults.contour_all } else { 0.0 },
                    max_live: if lossy { args.max_live } else { usize::MAX },
                    ..defaults
                };
                let start = Instant::now();
                let vector = trace(design, &opts)?;
                let svg = to_svg(&vector);
                let seconds = start.elapsed().as_secs_f64();
                let mismatch = match &reference {
                    Some(expected) => {
                        let actual = rasterise_svg(&svg)?;
                        let diff = compare(expected, &actual, MISMATCH_THRESHOLD)?;
                        format!("{:.2} %", 100.0 * diff.fraction())
                    }
                    None => "–".to_owned(),
                };
                let s = vector.stats;
                println!(
                    "| {name} | {t} | {} | {seconds:.2} | {} | {} | {} | {} | {} | {} | {:.1} | {} | {mismatch} |",
                    if lossy { "yes" } else { "no" },
                    s.peak_vertices,
                    s.vertices,
                    s.regions - s.culled,
                    s.contour_regions,
                    s.contour_samples,
                    s.rings,
                    s.dropped_area,
                    svg.len(),
                );
            }
        }
    }
    Ok(())
}

/// The SVG rendered by resvg at its own width and height.
pub fn rasterise_svg(svg: &str) -> Result<RgbaImage> {
    let tree = resvg::usvg::Tree::from_str(svg, &resvg::usvg::Options::default())
        .context("the SVG does not parse")?;
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .context("the SVG has no area")?;
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    Ok(RgbaImage {
        width: size.width(),
        height: size.height(),
        pixels: pixmap.take(),
    })
}
