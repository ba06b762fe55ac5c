//! `marbling animate`: the making of a design as an animated PNG (APNG) or GIF, every
//! frame an exact render of the design part way through its steps (as the app's step
//! player shows it, `marbling_core::making`); the last frame is the whole design. With
//! `--flow`, one period of a looping colour turbulence of the finished design instead
//! (`marbling_core::turbulence`).

use crate::backend::{Backend, gpu_renderer};
use crate::input::{read_design, read_turbulence};
use crate::loop_file::{Format, MAX_FRAMES, check_fps, check_frames, write_loop};
use anyhow::{Context, Result, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use marbling_core::making::design_at;
use marbling_core::{Antialias, RenderOptions, RgbaImage, output_size, render};

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
    /// Seconds the finished design stays on screen before the animation goes on (or
    /// loops).
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    hold: f64,
    /// After the making (and the hold), the making backwards to the start, so the loop
    /// has no jump: frames 0 … N−1, then N−2 … 1.
    #[arg(long)]
    reverse: bool,
    /// Colour turbulence: a JSON `{"noise": SPEC, "strength": U, "period": P}`; the
    /// animation is one period of the finished design streaming along its curl noise,
    /// frame i at t = i·P/N, so it loops without a jump.
    #[arg(long, value_name = "TURB.json", conflicts_with_all = ["seconds", "hold", "reverse"])]
    flow: Option<String>,
    /// Frames N of the --flow loop.
    #[arg(long, default_value_t = 24, requires = "flow")]
    frames: usize,
    /// Renderer of the frames: cpu (the exact f64 reference) or gpu (the WGSL renderer,
    /// f32).
    #[arg(long, value_enum, default_value_t = Backend::Cpu)]
    backend: Backend,
}

/// The frame order of a loop of `made` frames of the making (0 the start, `made − 1`
/// the finished design): forward, then with `reverse` back down to frame 1, so that
/// looping to frame 0 moves on by one frame like every other.
pub fn loop_order(made: usize, reverse: bool) -> Vec<usize> {
    let forward = 0..made;
    if reverse && made > 2 {
        forward.chain((1..made - 1).rev()).collect()
    } else {
        forward.collect()
    }
}

/// Renders the frames and writes the animation.
pub fn run(args: &AnimateArgs) -> Result<()> {
    let format = Format::from_path(&args.output)?;
    check_fps(args.fps)?;
    if args.width == 0 {
        bail!("--width must be at least 1");
    }
    if args.backend == Backend::Vector {
        bail!("animate renders with the exact walk: use --backend cpu or gpu");
    }
    let design = read_design(&args.design)?;
    let turbulence = args.flow.as_deref().map(read_turbulence).transpose()?;
    if turbulence.is_some() {
        check_frames(args.frames)?;
    }
    let steps = design.gesture_sizes().len();
    let seconds = args.seconds.unwrap_or((steps as f64).max(2.0));
    if !(seconds.is_finite() && seconds > 0.0) {
        bail!("--seconds must be a positive number, got {seconds}");
    }
    if !(args.hold.is_finite() && (0.0..=60.0).contains(&args.hold)) {
        bail!("--hold must be 0 to 60 seconds, got {}", args.hold);
    }
    let made = match &turbulence {
        Some(_) => args.frames,
        None => ((seconds * f64::from(args.fps)).round() as usize).max(2),
    };
    let order = loop_order(made, args.reverse);
    let frames = order.len();
    if frames > MAX_FRAMES {
        bail!("{frames} frames is more than {MAX_FRAMES}: lower --fps or --seconds");
    }
    let scale = f64::from(args.width) / f64::from(design.width);
    let (w, h) = output_size(&design, scale)?;
    format.check_size(w, h)?;
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
    let gpu = match args.backend {
        Backend::Gpu => {
            let gpu = gpu_renderer()?;
            eprintln!("gpu adapter: {}", gpu.context().describe());
            Some(gpu)
        }
        _ => None,
    };
    let start = std::time::Instant::now();
    // Frame i of the making shows it at i/(made − 1) of its steps: the last, all of it.
    // A reversed loop shows each again on the way back: rendered once, kept.
    let mut rendered: Vec<Option<RgbaImage>> = vec![None; made];
    let mut frame = |i: usize| -> Result<RgbaImage> {
        if let Some(image) = &rendered[i] {
            bar.inc(1);
            return Ok(image.clone());
        }
        let image = match (&turbulence, &gpu) {
            (Some(t), None) => t.render(&design, t.period * i as f64 / made as f64, &opts)?,
            (Some(t), Some(gpu)) => {
                gpu.render_turbulence(&design, t, t.period * i as f64 / made as f64, &opts)?
            }
            (None, gpu) => {
                let position = steps as f64 * i as f64 / (made - 1) as f64;
                let at = design_at(&design, position);
                match gpu {
                    Some(gpu) => gpu.render(&at, &opts)?,
                    None => render(&at, &opts)?,
                }
            }
        };
        bar.inc(1);
        if args.reverse {
            rendered[i] = Some(image.clone());
        }
        Ok(image)
    };
    // Each frame shows for 1/fps s (num/den seconds); the finished design for the hold
    // more, in ms.
    let delay = |i: usize| -> (u16, u16) {
        if i == made - 1 && args.hold > 0.0 {
            let ms = (1.0 / f64::from(args.fps) + args.hold) * 1000.0;
            (ms.round() as u16, 1000)
        } else {
            (1, args.fps as u16)
        }
    };
    write_loop(
        file,
        &args.output,
        format,
        (w, h),
        frames,
        |k| delay(order[k]),
        |k| frame(order[k]),
    )?;
    bar.finish_and_clear();
    let seconds_taken = start.elapsed().as_secs_f64();
    eprintln!(
        "rendered and encoded {frames} frames in {seconds_taken:.3} s ({:.2} frames/s, backend {})",
        frames as f64 / seconds_taken,
        args.backend.name()
    );
    if let Some(t) = &turbulence {
        println!(
            "{}: {frames} frames of {w}×{h} px, one period ({}) of the flow at {} fps, looping",
            args.output, t.period, args.fps
        );
        return Ok(());
    }
    println!(
        "{}: {frames} frames of {w}×{h} px, {steps} steps in {seconds} s at {} fps{}{}",
        args.output,
        args.fps,
        if args.hold > 0.0 {
            format!(", the design held {} s", args.hold)
        } else {
            String::new()
        },
        if args.reverse {
            ", then reversed to loop"
        } else {
            ""
        }
    );
    Ok(())
}
