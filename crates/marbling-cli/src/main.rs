//! `marbling`: validate, render, export and benchmark marbling design documents.

mod animate;
mod backend;
mod bench;
mod bench_gpu;
mod bench_svg;
mod input;
mod link;
mod loop_file;
mod noise;
mod output;
mod palette;
mod pattern;
mod print;
mod random;
mod render;
mod render_3d;
mod size;
mod svg;
mod validate;
mod view;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Mathematical marbling from the command line.
#[derive(Parser)]
#[command(name = "marbling", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a design to a PNG exactly (every pixel walks back through every op).
    Render(render::RenderArgs),
    /// Render a design on a 3D object (sphere, vase, cylinder, book, plane), exactly.
    #[command(name = "render-3d")]
    Render3d(render_3d::Render3dArgs),
    /// Check a design and summarise its ops, or list every error with its JSON path.
    Validate(validate::ValidateArgs),
    /// Make a share link (`…#d=…`) for a design, or decode one back to JSON.
    Link(link::LinkArgs),
    /// Measure renderer throughput in op-samples per second on synthetic designs.
    Bench(bench::BenchArgs),
    /// Evaluate a procedural noise spec (Gabor, Perlin fBm, Worley, paper, …) to a PNG.
    Noise(noise::NoiseArgs),
    /// Export a design as SVG: each ink region's outline traced forward through later ops.
    Svg(svg::SvgArgs),
    /// Write a random design (the benchmarks' synthetic designs) as JSON.
    Random(random::RandomArgs),
    /// Animate the making of a design step by step as an animated PNG or GIF.
    Animate(animate::AnimateArgs),
    /// Make an ink palette (.gpl) from a GIMP palette, a picture or hex colours.
    Palette(palette::PaletteArgs),
    /// Write a traditional pattern's recipe (stone, chevron, nonpareil, …) as JSON.
    Pattern(pattern::PatternArgs),
    /// Measure vector export time, vertex count and SVG size on synthetic designs.
    BenchSvg(bench_svg::BenchSvgArgs),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render(args) => render::run(&args),
        Command::Render3d(args) => render_3d::run(&args),
        Command::Validate(args) => validate::run(&args),
        Command::Bench(args) => bench::run(&args),
        Command::Link(args) => link::run(&args),
        Command::Noise(args) => noise::run(&args),
        Command::Svg(args) => svg::run(&args),
        Command::BenchSvg(args) => bench_svg::run(&args),
        Command::Random(args) => random::run(&args),
        Command::Pattern(args) => pattern::run(&args),
        Command::Palette(args) => palette::run(&args),
        Command::Animate(args) => animate::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
