//! `marbling render --view X,Y,SCALE`: a window of the sheet at any depth, centred on a
//! design point (the same `x,y,scale` a share link's `v=` holds).

use crate::backend::{Backend, gpu_renderer};
use crate::render::RenderArgs;
use anyhow::{Context, Result, anyhow, bail};
use marbling_core::{Design, ViewSpec, Window, render_window};
use std::io::Write;
use std::time::Instant;

/// Renders the window `spec` names (output `--width` wide, or the design's width; the
/// height keeps the design's aspect ratio) and writes the PNG.
pub fn run(args: &RenderArgs, design: &Design, spec: &str) -> Result<()> {
    let view = ViewSpec::parse(spec).map_err(|e| anyhow!("--{e}"))?;
    let width = args.width.unwrap_or(design.width);
    if width == 0 {
        bail!("--width must be at least 1");
    }
    let height = (f64::from(width) * f64::from(design.height) / f64::from(design.width))
        .round()
        .max(1.0) as u32;
    let window = Window::centred(view.centre, view.scale, width, height);
    let start = Instant::now();
    let image = match args.backend {
        Backend::Cpu => render_window(design, &window, args.aa)?,
        Backend::Gpu => {
            let gpu = gpu_renderer()?;
            eprintln!("gpu adapter: {}", gpu.context().describe());
            gpu.render_window(design, &window, args.aa)?
        }
        Backend::Vector => bail!("--view renders with the exact walk: use --backend cpu or gpu"),
    };
    let elapsed = start.elapsed();
    let png = image.to_png()?;
    if args.output == "-" {
        let mut out = std::io::stdout().lock();
        out.write_all(&png).and_then(|()| out.flush())
    } else {
        std::fs::write(&args.output, &png)
    }
    .with_context(|| format!("cannot write '{}'", args.output))?;
    let summary = format!(
        "{}: {width}×{height} px, view {view} ({} design px wide), {} ops, aa {}, backend {}, rendered in {:.3} s",
        args.output,
        f64::from(width) / view.scale,
        design.ops.len(),
        args.aa,
        args.backend.name(),
        elapsed.as_secs_f64()
    );
    crate::output::say(&args.output, &summary);
    Ok(())
}
