//! 8-bit RGBA images and their PNG encoding.

use std::io::Cursor;

/// An 8-bit sRGB RGBA image, rows top to bottom, no padding.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RgbaImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height × 4` bytes, RGBA.
    pub pixels: Vec<u8>,
}

/// A PNG that could not be encoded or decoded.
#[derive(Debug, thiserror::Error)]
pub enum PngError {
    /// The PNG encoder failed.
    #[error("cannot encode PNG: {0}")]
    Encode(#[from] png::EncodingError),
    /// The bytes are not a PNG this reader handles.
    #[error("cannot decode PNG: {0}")]
    Decode(#[from] png::DecodingError),
    /// A PNG whose pixel format is not 8-bit RGB or RGBA.
    #[error("unsupported PNG format {0:?} (8-bit RGB or RGBA expected)")]
    Format(png::ColorType),
}

impl RgbaImage {
    /// An image of one colour.
    pub fn filled(width: u32, height: u32, rgba: [u8; 4]) -> Self {
        let n = width as usize * height as usize;
        Self {
            width,
            height,
            pixels: rgba.repeat(n),
        }
    }

    /// The pixel at (x, y).
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        let i = (y as usize * self.width as usize + x as usize) * 4;
        [
            self.pixels[i],
            self.pixels[i + 1],
            self.pixels[i + 2],
            self.pixels[i + 3],
        ]
    }

    /// Sets the pixel at (x, y).
    pub fn set_pixel(&mut self, x: u32, y: u32, rgba: [u8; 4]) {
        let i = (y as usize * self.width as usize + x as usize) * 4;
        self.pixels[i..i + 4].copy_from_slice(&rgba);
    }

    /// Encodes the image as an RGBA PNG.
    pub fn to_png(&self) -> Result<Vec<u8>, PngError> {
        self.to_png_at(None)
    }

    /// Encodes as an 8-bit RGBA PNG carrying its resolution in a `pHYs` chunk
    /// (`pixels_per_metre`, e.g. [`crate::print::Print::pixels_per_metre`]) when given.
    pub fn to_png_at(&self, pixels_per_metre: Option<u32>) -> Result<Vec<u8>, PngError> {
        let mut out = Vec::new();
        {
            let mut enc = png::Encoder::new(&mut out, self.width, self.height);
            enc.set_pixel_dims(pixels_per_metre.map(|ppm| png::PixelDimensions {
                xppu: ppm,
                yppu: ppm,
                unit: png::Unit::Meter,
            }));
            enc.set_color(png::ColorType::Rgba);
            enc.set_depth(png::BitDepth::Eight);
            enc.set_compression(png::Compression::Fast);
            let mut writer = enc.write_header()?;
            writer.write_image_data(&self.pixels)?;
        }
        Ok(out)
    }

    /// Decodes an 8-bit RGB or RGBA PNG.
    pub fn from_png(bytes: &[u8]) -> Result<Self, PngError> {
        let mut reader = png::Decoder::new(Cursor::new(bytes)).read_info()?;
        let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
        let info = reader.next_frame(&mut buf)?;
        buf.truncate(info.buffer_size());
        let pixels = match (info.color_type, info.bit_depth) {
            (png::ColorType::Rgba, png::BitDepth::Eight) => buf,
            (png::ColorType::Rgb, png::BitDepth::Eight) => buf
                .chunks_exact(3)
                .flat_map(|c| [c[0], c[1], c[2], 255])
                .collect(),
            (other, _) => return Err(PngError::Format(other)),
        };
        Ok(Self {
            width: info.width,
            height: info.height,
            pixels,
        })
    }
}
