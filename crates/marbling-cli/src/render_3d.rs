//! `marbling render-3d`: the design on a 3D object, every sample walked back through
//! every op (or, with `--texture`, sampled from a baked raster for comparison). With
//! `--turn`, a loop of the object turning (the camera orbiting about the vertical axis)
//! as an animated PNG or GIF. With `--style`, marks (Bénard et al. 2010) or fibres
//! (Kaplan & Cohen 2005) laid over every frame, flat on the screen yet moving with the
//! object.

use crate::backend::{Backend, gpu_renderer};
use crate::input::read_design;
use crate::loop_file::{Format, check_fps, check_frames, write_loop};
use crate::size::Size;
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_core::view3d::style::style_frame;
use marbling_core::view3d::{Camera, Displace, Shape, View3d, render_3d};
use marbling_core::{Antialias, Design, Point, RgbaImage};
use marbling_noise::{ANCHORINGS, STYLE_KINDS, StyleKind, StyleSpec};
use std::time::Instant;

/// Arguments of `marbling render-3d`.
#[derive(Args)]
pub struct Render3dArgs {
    /// Design document (JSON); `-` reads standard input.
    design: String,
    /// Output PNG; with --turn a `.png` (animated PNG) or `.gif` loop.
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
    /// Camera distance as a share of the framing distance (0.7 to 5): below 1 the
    /// camera moves in, the object looks larger and its perspective stronger.
    #[arg(long, default_value_t = 1.0)]
    dolly: f64,
    /// Perlin displacement `S,F[,OCTAVES,LACUNARITY,PERSISTENCE]` (Kung 2019, ch. 3):
    /// each surface point moves along its normal by S·fbm(F·p), S in object units (the
    /// sphere's radius is 1; 0 to 0.5), F lattice cells per unit (0 to 12); one octave
    /// unless given (lacunarity 2, persistence 0.5).
    #[arg(long, value_name = "S,F", value_parser = parse_displace)]
    displace: Option<Displace>,
    /// Style of the object: hatching, stipple, crosshatch or graphite (Gabor marks in
    /// ink, sized in screen pixels, anchored on the surface), watercolor, felt or
    /// painterly (the marks working the design's colour), paper or canvas (fibres of a
    /// constant screen length), or none.
    #[arg(long, value_name = "STYLE")]
    style: Option<String>,
    /// A style spec (JSON, grammar in marbling-noise's README): its `style` names the
    /// preset, its other fields override it.
    #[arg(long, value_name = "STYLE.json")]
    style_spec: Option<String>,
    /// Bénard et al. 2010's figure 1: the frame three times side by side, the marks
    /// anchored on the surface (theirs), on the screen (2D noise, "shower door") and in
    /// texture space (texture mapping). Needs a mark style.
    #[arg(long)]
    anchorings: bool,
    /// Write a loop of the camera turning this many degrees about the vertical axis
    /// (360: once round; negative: the other way), frame k at yaw + DEG·k/N.
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        conflicts_with = "repeat"
    )]
    turn: Option<f64>,
    /// Frames N of the --turn loop.
    #[arg(long, default_value_t = 36, requires = "turn")]
    frames: usize,
    /// Frames per second of the --turn loop.
    #[arg(long, default_value_t = 24, requires = "turn")]
    fps: u32,
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

fn parse_displace(s: &str) -> Result<Displace, String> {
    let bad =
        || format!("expected --displace S,F or S,F,OCTAVES,LACUNARITY,PERSISTENCE, got {s:?}");
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 2 && parts.len() != 5 {
        return Err(bad());
    }
    let number = |i: usize| -> Result<f64, String> { parts[i].parse().map_err(|_| bad()) };
    let mut d = Displace {
        amount: number(0)?,
        frequency: number(1)?,
        ..Displace::default()
    };
    if parts.len() == 5 {
        d.octaves = parts[2].parse().map_err(|_| bad())?;
        d.lacunarity = number(3)?;
        d.persistence = number(4)?;
    }
    d.problem().map_or(Ok(d), Err)
}

fn parse_point(s: &str) -> Result<Point, String> {
    let bad = || format!("expected a design point like 512,384, got {s:?}");
    let (x, y) = s.split_once(',').ok_or_else(bad)?;
    let x: f64 = x.trim().parse().map_err(|_| bad())?;
    let y: f64 = y.trim().parse().map_err(|_| bad())?;
    Ok(Point::new(x, y))
}

/// The GPU renderer for `--backend gpu`, none for the CPU.
fn renderer(backend: Backend) -> Result<Option<marbling_gpu::GpuRenderer>> {
    match backend {
        Backend::Cpu => Ok(None),
        Backend::Gpu => Ok(Some(gpu_renderer()?)),
        Backend::Vector => bail!("render-3d draws with --backend cpu or gpu"),
    }
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
            dolly: args.dolly,
        },
        width: args.size.width,
        height: args.size.height,
        antialias: args.aa,
        texture: args.texture,
        displace: args.displace.unwrap_or_default(),
    };
    if let Err(e) = view.check(&design) {
        bail!("{e}");
    }
    let style = read_style(args)?;
    if args.anchorings {
        return write_anchorings(args, &design, &view, style.as_ref());
    }
    if let Some(turn) = args.turn {
        return write_turn(args, &design, &view, style.as_ref(), turn);
    }
    let mut out = std::fs::File::create(&args.output)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    let gpu = renderer(args.backend)?;
    let mut times = Vec::new();
    let mut image = None;
    let mut marks = String::new();
    for _ in 0..args.repeat.max(1) {
        let start = Instant::now();
        let (frame, what) = draw(gpu.as_ref(), &design, &view, style.as_ref())?;
        image = Some(frame);
        marks = what;
        times.push(start.elapsed().as_secs_f64());
    }
    let image = image.unwrap_or_else(|| unreachable!("at least one frame is rendered"));
    times.sort_by(f64::total_cmp);
    let elapsed = times[times.len() / 2];
    std::io::Write::write_all(&mut out, &image.to_png()?)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    println!(
        "{}: {} on a {}, {} px, zoom {}, {} ops, aa {}, {}, backend {}{marks}, rendered in {:.3} s{}",
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

/// Writes the frame with the marks on the surface, on the screen and as a texture, side
/// by side (`--anchorings`).
fn write_anchorings(
    args: &Render3dArgs,
    design: &Design,
    view: &View3d,
    style: Option<&StyleSpec>,
) -> Result<()> {
    let Some(spec) = style.filter(|s| !s.kind.is_fibres()) else {
        bail!("--anchorings compares where marks live: give a mark style (--style hatching, …)");
    };
    if args.turn.is_some() {
        bail!("--anchorings writes one still: leave out --turn");
    }
    let gpu = renderer(args.backend)?;
    let (w, h) = (view.width as usize, view.height as usize);
    let mut sheet = RgbaImage::filled(3 * view.width, view.height, [0, 0, 0, 255]);
    let mut names = Vec::new();
    for (k, (name, anchoring)) in ANCHORINGS.into_iter().enumerate() {
        let spec = StyleSpec { anchoring, ..*spec };
        let (frame, _) = draw(gpu.as_ref(), design, view, Some(&spec))?;
        for y in 0..h {
            let to = (y * 3 * w + k * w) * 4;
            sheet.pixels[to..to + 4 * w].copy_from_slice(&frame.pixels[y * w * 4..(y + 1) * w * 4]);
        }
        names.push(name);
    }
    std::fs::write(&args.output, sheet.to_png()?)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    println!(
        "{}: {} anchored {} side by side, {}×{} px each",
        args.output,
        spec.kind.name(),
        names.join(", "),
        view.width,
        view.height
    );
    Ok(())
}

/// The style of `--style` and `--style-spec`, if any.
fn read_style(args: &Render3dArgs) -> Result<Option<StyleSpec>> {
    let named = match args.style.as_deref() {
        None | Some("none") => None,
        Some(name) => match StyleKind::from_name(name) {
            Some(kind) => Some(kind),
            None => {
                let names: Vec<&str> = STYLE_KINDS.iter().map(|(n, _)| *n).collect();
                bail!(
                    "--style must be one of {}, none, got {name:?}",
                    names.join(", ")
                );
            }
        },
    };
    let Some(path) = &args.style_spec else {
        return Ok(named.map(StyleSpec::preset));
    };
    let text = std::fs::read_to_string(path).with_context(|| format!("cannot read '{path}'"))?;
    let spec = StyleSpec::from_json(&text).map_err(|e| anyhow::anyhow!("{path}: {e}"))?;
    if let Some(kind) = named
        && kind != spec.kind
    {
        bail!(
            "--style {} disagrees with {path}'s \"style\": \"{}\"",
            kind.name(),
            spec.kind.name()
        );
    }
    Ok(Some(spec))
}

/// One frame of `view`, styled; and what the style drew, for the report.
fn draw(
    gpu: Option<&marbling_gpu::GpuRenderer>,
    design: &Design,
    view: &View3d,
    style: Option<&StyleSpec>,
) -> Result<(RgbaImage, String)> {
    let Some(spec) = style else {
        let image = match gpu {
            None => render_3d(design, view)?,
            Some(gpu) => gpu.render_3d(design, view)?,
        };
        return Ok((image, String::new()));
    };
    let start = Instant::now();
    let frame = style_frame(design, view, spec)?;
    let seconds = start.elapsed().as_secs_f64();
    // The GPU blends the overlay in its shader; the CPU composites it after the render.
    let image = match gpu {
        None => {
            let mut image = render_3d(design, view)?;
            frame.composite(&mut image);
            image
        }
        Some(gpu) => gpu.render_3d_styled(design, view, Some(&frame))?,
    };
    let what = if spec.kind.is_fibres() {
        format!(
            ", style {} ({} fibres, {seconds:.3} s)",
            spec.kind.name(),
            frame.fibres.len()
        )
    } else {
        format!(
            ", style {} ({} kernels, {seconds:.3} s)",
            spec.kind.name(),
            frame.kernels
        )
    };
    Ok((image, what))
}

/// Writes the loop of `view` turning `turn` degrees over `args.frames` frames.
fn write_turn(
    args: &Render3dArgs,
    design: &Design,
    view: &View3d,
    style: Option<&StyleSpec>,
    turn: f64,
) -> Result<()> {
    let format = Format::from_path(&args.output)?;
    if !(turn.is_finite() && turn.abs() <= 3600.0) {
        bail!("--turn must be a number of degrees from -3600 to 3600, got {turn}");
    }
    check_frames(args.frames)?;
    check_fps(args.fps)?;
    format.check_size(view.width, view.height)?;
    let file = std::fs::File::create(&args.output)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    let gpu = renderer(args.backend)?;
    let n = args.frames;
    let start = Instant::now();
    write_loop(
        file,
        &args.output,
        format,
        (view.width, view.height),
        n,
        |_| (1, args.fps as u16),
        |k| {
            let frame = view.turned(design, turn * k as f64 / n as f64);
            Ok(draw(gpu.as_ref(), design, &frame, style)?.0)
        },
    )?;
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{}: {n} frames of a {} turning {turn}° at {} fps, {} px, backend {}, rendered and \
         encoded in {seconds:.3} s ({:.2} frames/s)",
        args.output,
        args.surface.name(),
        args.fps,
        args.size,
        args.backend.name(),
        n as f64 / seconds
    );
    Ok(())
}
