//! `marbling noise`: evaluates a noise spec (JSON) to a PNG of up to 16384² pixels, 8 or
//! 16 bits per sample, greyscale 0.5 + n/6 (n at zero mean and unit variance, clamped; or
//! the spec's transfer) or coloured when the spec has a palette or blend; or, with
//! `--map height|normal`, a 16-bit height or tangent-space normal map of that intensity
//! (`marbling_noise::SurfaceMap`, relief `--relief` pixels). Data sets a
//! spec names (`"data": "wind.png"`, a PNG or a CSV grid) are read from paths relative
//! to the spec file; `weather` is built in.

use crate::input::{display_name, read_text};
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_noise::{
    DataGrid, Depth, MAX_SIZE, NoiseSpec, PngContent, Renderer, SURFACE_MAPS, SpecError,
    SurfaceMap, ranges,
};
use std::path::Path;
use std::sync::Arc;

/// Arguments of `marbling noise`.
#[derive(Args)]
pub struct NoiseArgs {
    /// Noise spec JSON file, or `-` for standard input.
    spec: String,
    /// Output PNG path.
    #[arg(short, long)]
    output: String,
    /// Side of the square output, pixels (a tiling spec repeats with this period).
    #[arg(long, default_value_t = 256)]
    size: u32,
    /// Bits per sample: 8 (the default), or 16 for height maps (greyscale or RGB as the
    /// spec says); a `--map` is always 16-bit.
    #[arg(long)]
    depth: Option<u8>,
    /// Write a 16-bit surface map of the intensity instead of the image: `height`
    /// (greyscale) or `normal` (tangent space, OpenGL: green is up).
    #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(SURFACE_MAPS))]
    map: Option<String>,
    /// Height of intensity 1 above 0 in a normal map, output pixels.
    #[arg(long, default_value_t = ranges::DEFAULT_RELIEF)]
    relief: f64,
}

/// Largest data file read, bytes.
const MAX_DATA_BYTES: u64 = 64 << 20;

/// Reads the data file `name` relative to `dir`: a PNG by its signature, else a CSV grid.
fn load_data(dir: &Path, name: &str) -> std::result::Result<Arc<DataGrid>, String> {
    let path = dir.join(name);
    let size = std::fs::metadata(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?
        .len();
    if size > MAX_DATA_BYTES {
        return Err(format!(
            "{size} bytes; data files are read up to {MAX_DATA_BYTES}"
        ));
    }
    let bytes = std::fs::read(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let grid = if bytes.starts_with(b"\x89PNG") {
        DataGrid::from_png(&bytes)
    } else {
        let text =
            String::from_utf8(bytes).map_err(|_| "neither a PNG nor a CSV text".to_owned())?;
        DataGrid::from_csv(&text, name)
    };
    grid.map(Arc::new).map_err(|e| e.to_string())
}

/// Reads a spec and the data it names, reporting every problem prefixed with the input
/// name.
fn read_spec(path: &str) -> Result<NoiseSpec> {
    let text = read_text(path)?;
    let name = display_name(path);
    let dir = if path == "-" {
        Path::new(".")
    } else {
        Path::new(path).parent().unwrap_or(Path::new("."))
    };
    match NoiseSpec::from_json(&text) {
        Ok(mut s) => {
            s.attach_data(&mut |data| load_data(dir, data))
                .map_err(|e| anyhow::anyhow!("{name}: {e}"))?;
            Ok(s)
        }
        Err(SpecError::Syntax {
            line,
            column,
            message,
        }) => bail!("{name}:{line}:{column}: invalid JSON: {message}"),
        Err(SpecError::Invalid(errors)) => {
            let lines: Vec<String> = errors.iter().map(|e| format!("{name}: {e}")).collect();
            bail!(
                "{} problem(s) in the noise spec:\n{}",
                lines.len(),
                lines.join("\n")
            )
        }
    }
}

/// Rows rendered per thread between writes: bounds memory whatever the size.
const ROWS_PER_THREAD: u32 = 16;

/// Renders the image band by band (rows split across all cores) and streams each band
/// into the PNG encoder, so a 16384² export never holds the whole image.
fn encode(
    renderer: &Renderer,
    content: PngContent,
    out: impl std::io::Write + 'static,
) -> Result<()> {
    let size = renderer.size();
    let mut stream = renderer
        .content_encoder(out, content)
        .write_header()
        .context("cannot encode PNG")?
        .into_stream_writer()
        .context("cannot encode PNG")?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u32;
    let band = threads * ROWS_PER_THREAD;
    for start in (0..size).step_by(band as usize) {
        let rows = start..(start + band).min(size);
        let chunks: Vec<Vec<u8>> = std::thread::scope(|s| {
            let handles: Vec<_> = (0..threads)
                .map(|t| {
                    let lo = (rows.start + t * ROWS_PER_THREAD).min(rows.end);
                    let hi = (lo + ROWS_PER_THREAD).min(rows.end);
                    s.spawn(move || {
                        (lo..hi)
                            .flat_map(|j| renderer.content_row(j, content))
                            .collect::<Vec<u8>>()
                    })
                })
                .collect();
            handles
                .into_iter()
                .map(|h| h.join().unwrap_or_default())
                .collect()
        });
        for chunk in chunks {
            std::io::Write::write_all(&mut stream, &chunk).context("cannot encode PNG")?;
        }
    }
    stream.finish().context("cannot encode PNG")?;
    Ok(())
}

/// Runs `marbling noise`.
pub fn run(args: &NoiseArgs) -> Result<()> {
    if args.size == 0 || args.size > MAX_SIZE {
        bail!("--size must be in 1..={MAX_SIZE}, got {}", args.size);
    }
    let depth = match args.depth.unwrap_or(8) {
        8 => Depth::Eight,
        16 => Depth::Sixteen,
        d => bail!("--depth must be 8 or 16, got {d}"),
    };
    let content = match args.map.as_deref() {
        None => PngContent::Image(depth),
        Some(_) if args.depth == Some(8) => {
            bail!("--map writes 16-bit samples; leave out --depth 8")
        }
        Some("height") => PngContent::Map(SurfaceMap::Height),
        Some(_) => {
            if !ranges::RELIEF.contains(args.relief) {
                bail!(
                    "--relief must be above 0 and at most {} pixels, got {}",
                    ranges::RELIEF.hi,
                    args.relief
                );
            }
            PngContent::Map(SurfaceMap::Normal {
                relief: args.relief as f32,
            })
        }
    };
    let spec = read_spec(&args.spec)?;
    let renderer = Renderer::new(&spec, args.size)?;
    let file = std::fs::File::create(&args.output)
        .with_context(|| format!("cannot write '{}'", args.output))?;
    encode(&renderer, content, std::io::BufWriter::new(file))
        .with_context(|| format!("cannot write '{}'", args.output))
}
