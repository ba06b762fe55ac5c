//! `marbling noise`: evaluates a noise spec (JSON) to an 8-bit PNG, greyscale 0.5 + n/6
//! (n at zero mean and unit variance, clamped) or coloured when the spec has a palette or
//! blend.

use crate::input::{display_name, read_text};
use anyhow::{Context, Result, bail};
use clap::Args;
use marbling_noise::{MAX_SIZE, NoiseSpec, Renderer, SpecError};

/// Arguments of `marbling noise`.
#[derive(Args)]
pub struct NoiseArgs {
    /// Noise spec JSON file, or `-` for standard input.
    spec: String,
    /// Output PNG path.
    #[arg(short, long)]
    output: String,
    /// Side of the square output, pixels.
    #[arg(long, default_value_t = 256)]
    size: u32,
}

/// Reads a spec, reporting every problem prefixed with the input name.
fn read_spec(path: &str) -> Result<NoiseSpec> {
    let text = read_text(path)?;
    let name = display_name(path);
    match NoiseSpec::from_json(&text) {
        Ok(s) => Ok(s),
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

/// Renders rows in parallel on all cores.
fn render(renderer: &Renderer) -> Vec<[u8; 3]> {
    let size = renderer.size();
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get())
        .min(size as usize) as u32;
    let chunk = size.div_ceil(threads);
    std::thread::scope(|s| {
        let handles: Vec<_> = (0..threads)
            .map(|t| {
                let rows = (t * chunk).min(size)..((t + 1) * chunk).min(size);
                s.spawn(move || renderer.render_rows(rows))
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap_or_default())
            .collect()
    })
}

fn encode(size: u32, greyscale: bool, pixels: &[[u8; 3]]) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, size, size);
        enc.set_color(if greyscale {
            png::ColorType::Grayscale
        } else {
            png::ColorType::Rgb
        });
        enc.set_depth(png::BitDepth::Eight);
        let data: Vec<u8> = if greyscale {
            pixels.iter().map(|p| p[0]).collect()
        } else {
            pixels.iter().flatten().copied().collect()
        };
        let mut writer = enc.write_header().context("cannot encode PNG")?;
        writer
            .write_image_data(&data)
            .context("cannot encode PNG")?;
    }
    Ok(out)
}

/// Runs `marbling noise`.
pub fn run(args: &NoiseArgs) -> Result<()> {
    if args.size == 0 || args.size > MAX_SIZE {
        bail!("--size must be in 1..={MAX_SIZE}, got {}", args.size);
    }
    let spec = read_spec(&args.spec)?;
    let renderer = Renderer::new(&spec, args.size)?;
    let pixels = render(&renderer);
    if pixels.len() != (args.size as usize).pow(2) {
        bail!("rendering failed (a worker thread panicked)");
    }
    let png = encode(args.size, renderer.greyscale(), &pixels)?;
    std::fs::write(&args.output, png).with_context(|| format!("cannot write '{}'", args.output))
}
