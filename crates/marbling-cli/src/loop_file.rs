//! Looping animation files, written frame by frame as they are rendered: an animated PNG
//! (`.png`) or a GIF (`.gif`), repeating forever. Shared by `marbling animate` and
//! `marbling render-3d --turn`.

use anyhow::{Context, Result, bail};
use marbling_core::RgbaImage;
use std::io::Write;

/// Most frames one loop may have.
pub const MAX_FRAMES: usize = 3_600;

/// Refuses a frame count outside 2 to [`MAX_FRAMES`] (`--frames`).
pub fn check_frames(frames: usize) -> Result<()> {
    if !(2..=MAX_FRAMES).contains(&frames) {
        bail!("--frames must be 2 to {MAX_FRAMES}, got {frames}");
    }
    Ok(())
}

/// Refuses a frame rate outside 1 to 60 frames per second (`--fps`).
pub fn check_fps(fps: u32) -> Result<()> {
    if !(1..=60).contains(&fps) {
        bail!("--fps must be 1 to 60, got {fps}");
    }
    Ok(())
}

/// The file format, chosen by the output's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Animated PNG: lossless, every frame in full colour.
    Apng,
    /// GIF: 256 colours a frame (quantised at speed 10), at most 65535 px a side.
    Gif,
}

impl Format {
    /// The format of output `path`, or an error naming what is accepted.
    pub fn from_path(path: &str) -> Result<Self> {
        match path.rsplit('.').next().map(str::to_ascii_lowercase) {
            Some(e) if e == "png" => Ok(Self::Apng),
            Some(e) if e == "gif" => Ok(Self::Gif),
            _ => bail!("-o must name a .png (animated PNG) or .gif file, got '{path}'"),
        }
    }

    /// Refuses frame sizes the format cannot hold.
    pub fn check_size(self, w: u32, h: u32) -> Result<()> {
        if self == Self::Gif && (w > u32::from(u16::MAX) || h > u32::from(u16::MAX)) {
            bail!("a GIF is at most 65535 px a side, this one would be {w}×{h}");
        }
        Ok(())
    }
}

/// Writes `frames` frames of `w`×`h` pixels to `file` (named `path` in messages):
/// frame k is `frame(k)`, shown for `delay(k)` = (numerator, denominator) seconds.
pub fn write_loop(
    file: std::fs::File,
    path: &str,
    format: Format,
    (w, h): (u32, u32),
    frames: usize,
    delay: impl Fn(usize) -> (u16, u16),
    mut frame: impl FnMut(usize) -> Result<RgbaImage>,
) -> Result<()> {
    let mut out = std::io::BufWriter::new(file);
    match format {
        Format::Apng => {
            let mut enc = png::Encoder::new(&mut out, w, h);
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            enc.set_compression(png::Compression::Fast);
            enc.set_animated(frames as u32, 0)?;
            let (num, den) = delay(0);
            enc.set_frame_delay(num, den)?;
            let mut writer = enc.write_header()?;
            for k in 0..frames {
                let (num, den) = delay(k);
                writer.set_frame_delay(num, den)?;
                writer.write_image_data(&frame(k)?.pixels)?;
            }
            writer.finish()?;
        }
        Format::Gif => {
            let mut enc = gif::Encoder::new(&mut out, w as u16, h as u16, &[])?;
            enc.set_repeat(gif::Repeat::Infinite)?;
            for k in 0..frames {
                let mut pixels = frame(k)?.pixels;
                let mut f = gif::Frame::from_rgba_speed(w as u16, h as u16, &mut pixels, 10);
                // Centiseconds.
                let (num, den) = delay(k);
                f.delay = (u32::from(num) * 100 / u32::from(den)).max(1) as u16;
                enc.write_frame(&f)?;
            }
        }
    }
    out.flush()
        .with_context(|| format!("cannot write '{path}'"))
}
