//! `marbling render-3d`: the design on a 3D object, every sample walked back through
//! every op (or, with `--texture`, sampled from a baked raster for comparison).

use crate::backend::{Backend, gpu_renderer};
use crate::input::read_design;
use crate::size::Size;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::view3d::{Camera, Shape, View3d, render_3d};
use marbling_core::{Antialias, Point};
use std::time::Instant;

/// Arguments of `marbling render-3d`.
#[derive(Args)]
pub struct Render3dArgs {
    /// Design document (JSON); `-` reads standard input.
    design: String,
    /// Output PNG.
    #[arg(short, long)]
    output: String,
    /// The object: sphere, vase, cylinder, book or plane.
    #[arg(long, default_value = "vase", value_parser = parse_shape)]
    surface: Shape,
    /// Output size, `WxH` or `N` (square).
    #[arg(long, default_value = "1280x720")]
    size: Size,
    /// Magnification: 1 fits the object in the frame; 200 is an extreme close-up.
    #[arg(long, default_value_t = 1.0)]
    zoom: f64,
    /// Design point `X,Y` (design pixels) the camera centres on, seen head-on unless
    /// --yaw/--pitch say otherwise.
    #[arg(long, value_name = "X,Y", value_parser = parse_point)]
    look_at: Option<Point>,
    /// Camera turn about the vertical axis, degrees (0: in front).
    #[arg(long, allow_negative_numbers = true)]
    yaw: Option<f64>,
    /// Camera elevation, degrees (−90 to 90, exclusive).
    #[arg(long, allow_negative_numbers = true)]
    pitch: Option<f64>,
    /// Antialiasing: none, rgss, grid4, quincunx, rooks8, adaptive.
    #[arg(long, default_value = "rgss")]
    aa: Antialias,
    /// Sample the design from a raster of this longest side (e.g. 2048) instead of
    /// walking every sample: the blur of texture mapping, for comparison.
    #[arg(long, value_name = "N")]
    texture: Option<u32>,
    /// Renderer: cpu (the exact f64 reference) or gpu (the app's WGSL, f32).
    #[arg(long, value_enum, default_value_t = Backend::Cpu)]
    backend: Backend,
    /// Render the frame this many times and report the fastest and median times (a
    /// benchmark of 3D frame time; the GPU backend's device is opened once).
    #[arg(long, default_value_t = 1, value_name = "N")]
    repeat: u32,
}

fn parse_shape(s: &str) -> Result<Shape, String> {
    Shape::from_name(s).ok_or_else(|| {
        let names: Vec<&str> = Shape::ALL.iter().map(|s| s.name()).collect();
        format!(
            "unknown surface {s:?}; expected one of {}",
            names.join(", ")
        )
    })
}

fn parse_point(s: &str) -> Result<Point, String> {
    let bad = || format!("expected a design point like 512,384, got {s:?}");
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    let x: f64 = x.trim().parse().map_err(|_| bad())?;
    let y: f64 = y.trim().parse().map_err(|_| bad())?;
    Ok(Point::new(x, y))
}

/// Renders the view and writes the PNG.
pub fn run(args: &Render3dArgs) -> Result<()> {
    let design = read_design(&args.design)?;
    let view = View3d {
        shape: args.surface,
        camera: Camera {
            yaw: args.yaw,
            pitch: args.pitch,
            zoom: args.zoom,
            look_at: args.look_at,
        },
        width: args.size.width,
        height: args.size.height,
        antialias: args.aa,
        texture: args.texture,
    };
    if let Err(e) = view.check(&design) {
        bail!("{e}");
    }
    let mut out = std::fs::File::create(&args.output)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    let gpu = match args.backend {
        Backend::Cpu => None,
        Backend::Gpu => Some(gpu_renderer()?),
        Backend::Vector => bail!("render-3d draws with --backend cpu or gpu"),
    };
    let mut times = Vec::new();
    let mut image = None;
    for _ in 0..args.repeat.max(1) {
        let start = Instant::now();
        image = Some(match &gpu {
            None => render_3d(&design, &view)?,
            Some(gpu) => gpu.render_3d(&design, &view)?,
        });
        times.push(start.elapsed().as_secs_f64());
    }
    let image = image.unwrap_or_else(|| unreachable!("at least one frame is rendered"));
    times.sort_by(f64::total_cmp);
    let elapsed = times[times.len() / 2];
    std::io::Write::write_all(&mut out, &image.to_png()?)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    println!(
        "{}: {} on a {}, {} px, zoom {}, {} ops, aa {}, {}, backend {}, rendered in {:.3} s{}",
        args.output,
        if args.texture.is_some() {
            "texture-mapped design"
        } else {
            "exact design"
        },
        args.surface.name(),
        args.size,
        args.zoom,
        design.ops.len(),
        args.aa,
        match args.texture {
            Some(n) => format!("baked at {n} px"),
            None => "every sample walked".to_owned(),
        },
        args.backend.name(),
        elapsed,
        if times.len() > 1 {
            format!(" (median of {}, fastest {:.3} s)", times.len(), times[0])
        } else {
            String::new()
        }
    );
    Ok(())
}
