//! `marbling render`: an exact PNG of a design at any scale.

use crate::backend::{Backend, render_image, render_vector};
use crate::input::read_design;
use anyhow::{Context, Result, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use marbling_core::{Antialias, RenderOptions, output_size};
use std::io::Write;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Arguments of `marbling render`.
#[derive(Args)]
pub struct RenderArgs {
    /// Design document (JSON); `-` reads standard input.
    pub design: String,
    /// Output PNG; `-` writes to standard output.
    #[arg(short, long)]
    pub output: String,
    /// Output pixels per design pixel (default 1).
    #[arg(long, conflicts_with_all = ["width", "print"], allow_negative_numbers = true)]
    scale: Option<f64>,
    /// Output width in pixels (the height follows the design's aspect ratio).
    #[arg(long, conflicts_with = "print")]
    pub width: Option<u32>,
    /// A window of the sheet at any depth: `X,Y,SCALE`, the design point at its centre
    /// and output pixels per design pixel (up to 1e9), --width pixels wide (default: the
    /// design's width). The cpu backend walks it in f64, gpu by perturbation from f64
    /// references; a share link's `v=` holds the same three numbers.
    #[arg(long, value_name = "X,Y,SCALE", conflicts_with_all = ["scale", "print", "flow"])]
    view: Option<String>,
    /// Render for print on a sheet of this size: `297x210mm`, `21x29.7cm`, `8.5x11in`,
    /// or a preset (A4, A3, Letter, Endpaper = 50×70 cm) turned to the design. The
    /// design covers the sheet, centred; rows are streamed, so any size fits in memory;
    /// the PNG carries the DPI.
    #[arg(long, value_name = "SIZE")]
    pub print: Option<String>,
    /// Dots per inch of --print.
    #[arg(long, default_value_t = 300.0, requires = "print")]
    pub dpi: f64,
    /// Bleed of --print on every side: more of the design, cut off after printing
    /// (`3mm`, `0.125in`; a bare number is mm).
    #[arg(long, default_value = "0mm", requires = "print")]
    pub bleed: String,
    /// Antialiasing: none, rgss, grid4, quincunx, rooks8, adaptive.
    #[arg(long, default_value = "rgss")]
    pub aa: Antialias,
    /// Renderer: cpu (the exact f64 reference), gpu (the WGSL renderer, f32) or vector
    /// (outlines traced forward, rasterised with tiny-skia at the same sample positions).
    #[arg(long, value_enum, default_value_t = Backend::Cpu)]
    pub backend: Backend,
    /// Render the design only `K` steps into its making (a step is a gesture; a
    /// fraction eases the next step in, as the app's step player shows it).
    #[arg(long, value_name = "K")]
    steps: Option<f64>,
    /// Tracing tolerance of --backend vector, output pixels.
    #[arg(long, default_value_t = 1.0, allow_negative_numbers = true)]
    tolerance: f64,
    /// Colour turbulence: a JSON `{"noise": SPEC, "strength": U, "period": P}`; the
    /// design streams along its curl noise as two exact layers blended in linear light
    /// (see --time).
    #[arg(long, value_name = "TURB.json", conflicts_with = "print")]
    flow: Option<String>,
    /// The time of the --flow frame (it loops: t and t + P are the same frame).
    #[arg(
        long,
        default_value_t = 0.0,
        requires = "flow",
        allow_negative_numbers = true
    )]
    time: f64,
}

/// A progress bar on stderr that appears only once a render has taken about a second.
pub struct LazyProgress {
    start: Instant,
    bar: Mutex<Option<ProgressBar>>,
}

impl LazyProgress {
    /// Starts the clock.
    pub fn new() -> Self {
        Self {
            start: Instant::now(),
            bar: Mutex::new(None),
        }
    }

    /// Reports `done` of `total` steps.
    pub fn update(&self, done: usize, total: usize) {
        if self.start.elapsed() < Duration::from_secs(1) {
            return;
        }
        let Ok(mut bar) = self.bar.lock() else { return };
        let bar = bar.get_or_insert_with(|| {
            let b = ProgressBar::new(total as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {percent}% eta {eta}")
            {
                b.set_style(style.progress_chars("=> "));
            }
            b
        });
        bar.set_position(done as u64);
    }

    /// Removes the bar, if it was shown.
    pub fn finish(&self) {
        if let Ok(Some(bar)) = self.bar.lock().as_deref() {
            bar.finish_and_clear();
        }
    }
}

/// Renders the design and writes the PNG.
pub fn run(args: &RenderArgs) -> Result<()> {
    let mut design = read_design(&args.design)?;
    if let Some(k) = args.steps {
        let steps = design.gesture_sizes().len();
        if !(k.is_finite() && (0.0..=steps as f64).contains(&k)) {
            bail!("--steps must be 0 to {steps} (the design's steps), got {k}");
        }
        design = marbling_core::making::design_at(&design, k);
    }
    if let Some(spec) = &args.view {
        return crate::view::run(args, &design, spec);
    }
    if let Some(sheet) = &args.print {
        if args.backend != Backend::Cpu {
            bail!("--print renders with the exact CPU walk: leave out --backend");
        }
        return crate::print::run(args, &design, sheet);
    }
    let scale = match (args.scale, args.width) {
        (Some(s), _) => s,
        (None, Some(0)) => bail!("--width must be at least 1"),
        (None, Some(w)) => f64::from(w) / f64::from(design.width),
        (None, None) => 1.0,
    };
    let (w, h) = output_size(&design, scale)?;
    let opts = RenderOptions {
        scale,
        antialias: args.aa,
    };
    let turbulence = match &args.flow {
        Some(path) => {
            if args.backend == Backend::Vector {
                bail!("--flow renders with the exact walk: use --backend cpu or gpu");
            }
            if !args.time.is_finite() {
                bail!("--time must be a finite number, got {}", args.time);
            }
            Some(crate::input::read_turbulence(path)?)
        }
        None => None,
    };
    let start = Instant::now();
    // The vector backend traces before the output is opened, so a design it refuses
    // leaves no file behind.
    let traced = match args.backend {
        Backend::Vector => Some(render_vector(&design, &opts, args.tolerance)?),
        Backend::Cpu | Backend::Gpu => None,
    };
    // Open the output before the (possibly long) render so a bad path fails at once.
    let mut out: Box<dyn Write> = if args.output == "-" {
        Box::new(std::io::stdout().lock())
    } else {
        Box::new(
            std::fs::File::create(&args.output)
                .with_context(|| format!("cannot write '{}'", args.output))?,
        )
    };
    let image = match (traced, &turbulence) {
        (Some(image), _) => image,
        (None, Some(turbulence)) => match args.backend {
            Backend::Gpu => {
                let gpu = crate::backend::gpu_renderer()?;
                eprintln!("gpu adapter: {}", gpu.context().describe());
                gpu.render_turbulence(&design, turbulence, args.time, &opts)?
            }
            _ => turbulence.render(&design, args.time, &opts)?,
        },
        (None, None) => {
            let progress = LazyProgress::new();
            let image = render_image(args.backend, &design, &opts, args.tolerance, &progress)?;
            progress.finish();
            image
        }
    };
    let elapsed = start.elapsed();
    let png = image.to_png()?;
    out.write_all(&png)
        .and_then(|()| out.flush())
        .with_context(|| format!("cannot write '{}'", args.output))?;
    let summary = format!(
        "{}: {w}×{h} px, {} ops, aa {}, backend {}{}, rendered in {:.3} s",
        args.output,
        design.ops.len(),
        args.aa,
        args.backend.name(),
        match args.backend {
            Backend::Vector => format!(" (T {} px)", args.tolerance),
            _ => String::new(),
        },
        elapsed.as_secs_f64()
    );
    crate::output::say(&args.output, &summary);
    Ok(())
}
