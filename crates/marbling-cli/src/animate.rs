//! `marbling animate`: the making of a design as an animated PNG (APNG) or GIF, every
//! frame an exact render of the design part way through its steps (as the app's step
//! player shows it, `marbling_core::making`); the last frame is the whole design.

use crate::input::read_design;
use anyhow::{Context, Result, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use marbling_core::making::design_at;
use marbling_core::{Antialias, RenderOptions, RgbaImage, output_size, render};
use std::io::Write;

/// Most frames one animation may have.
pub const MAX_FRAMES: usize = 3_600;

/// Arguments of `marbling animate`.
#[derive(Args)]
pub struct AnimateArgs {
    /// Design document (JSON); `-` reads standard input.
    design: String,
    /// Output file: `.png` writes an animated PNG, `.gif` a GIF.
    #[arg(short, long)]
    output: String,
    /// Frames per second.
    #[arg(long, default_value_t = 12)]
    fps: u32,
    /// Length in seconds (default: one second a step, at least two).
    #[arg(long, allow_negative_numbers = true)]
    seconds: Option<f64>,
    /// Output width in pixels (the height follows the design's aspect ratio).
    #[arg(long, default_value_t = 320)]
    width: u32,
    /// Antialiasing of each frame.
    #[arg(long, default_value = "rgss")]
    aa: Antialias,
}

/// The output format, from the file name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    Apng,
    Gif,
}

/// Renders the frames and writes the animation.
pub fn run(args: &AnimateArgs) -> Result<()> {
    let format = match args.output.rsplit('.').next().map(str::to_ascii_lowercase) {
        Some(e) if e == "png" => Format::Apng,
        Some(e) if e == "gif" => Format::Gif,
        _ => bail!(
            "-o must name a .png (animated PNG) or .gif file, got '{}'",
            args.output
        ),
    };
    if !(1..=60).contains(&args.fps) {
        bail!("--fps must be 1 to 60, got {}", args.fps);
    }
    if args.width == 0 {
        bail!("--width must be at least 1");
    }
    let design = read_design(&args.design)?;
    let steps = design.gesture_sizes().len();
    let seconds = args.seconds.unwrap_or((steps as f64).max(2.0));
    if !(seconds.is_finite() && seconds > 0.0) {
        bail!("--seconds must be a positive number, got {seconds}");
    }
    let frames = ((seconds * f64::from(args.fps)).round() as usize).max(2);
    if frames > MAX_FRAMES {
        bail!("{frames} frames is more than {MAX_FRAMES}: lower --fps or --seconds");
    }
    let scale = f64::from(args.width) / f64::from(design.width);
    let (w, h) = output_size(&design, scale)?;
    if format == Format::Gif && (w > u32::from(u16::MAX) || h > u32::from(u16::MAX)) {
        bail!("a GIF is at most 65535 px a side, this one would be {w}×{h}");
    }
    let opts = RenderOptions {
        scale,
        antialias: args.aa,
    };
    // Open the output first so a bad path fails before the long render.
    let file = std::fs::File::create(&args.output)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    let bar = ProgressBar::new(frames as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} frames eta {eta}")
    {
        bar.set_style(style.progress_chars("=> "));
    }
    // Frame i shows the making at i/(frames − 1) of its steps: the last, all of it.
    let frame = |i: usize| -> Result<RgbaImage> {
        let position = steps as f64 * i as f64 / (frames - 1) as f64;
        let image = render(&design_at(&design, position), &opts)?;
        bar.inc(1);
        Ok(image)
    };
    let mut out = std::io::BufWriter::new(file);
    match format {
        Format::Apng => {
            let mut enc = png::Encoder::new(&mut out, w, h);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            enc.set_compression(png::Compression::Fast);
            enc.set_animated(frames as u32, 0)?;
            enc.set_frame_delay(1, args.fps as u16)?;
            let mut writer = enc.write_header()?;
            for i in 0..frames {
                writer.write_image_data(&frame(i)?.pixels)?;
            }
            writer.finish()?;
        }
        Format::Gif => {
            let mut enc = gif::Encoder::new(&mut out, w as u16, h as u16, &[])?;
            enc.set_repeat(gif::Repeat::Infinite)?;
            for i in 0..frames {
                let mut pixels = frame(i)?.pixels;
                let mut f = gif::Frame::from_rgba_speed(w as u16, h as u16, &mut pixels, 10);
                f.delay = (100 / args.fps).max(1) as u16;
                enc.write_frame(&f)?;
            }
        }
    }
    out.flush()
        .with_context(|| format!("cannot write '{}'", args.output))?;
    bar.finish_and_clear();
    println!(
        "{}: {frames} frames of {w}×{h} px, {steps} steps in {seconds} s at {} fps",
        args.output, args.fps
    );
    Ok(())
}
