//! Schema v2 surfaces in a vector export: what no outline can hold becomes a raster at
//! the output size. A noise background is marbled like ink, so its layer is the exact
//! render of the design without grain (the outlines then repaint the ink over it
//! sharply); grain overlays become one grey layer of their factors, multiplied over
//! everything.

use crate::VectorError;
use marbling_core::color::linear_to_srgb;
use marbling_core::sampling::Sample;
use marbling_core::{
    Antialias, Batch, Design, GrainKind, Point, RenderOptions, RgbaImage, Traced, Walker,
    output_size, render,
};
use rayon::prelude::*;

/// A raster layer of a vector export at the output size.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterLayer {
    /// The pixels (opaque).
    pub image: RgbaImage,
    /// The same as a `data:image/png;base64,…` URI.
    pub data_uri: String,
}

/// Which channels of a layer's pixels its PNG keeps.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channels {
    /// Red as grey (grain).
    Grey,
    /// Red, green, blue (opaque layers).
    Rgb,
    /// All four (a patch over part of the picture).
    Rgba,
}

impl RasterLayer {
    /// Encodes `image` keeping `channels`.
    pub fn new(image: RgbaImage, channels: Channels) -> Result<Self, VectorError> {
        let data_uri = png_data_uri(&image, channels)
            .map_err(|e| VectorError::Untraceable(format!("cannot encode a raster layer: {e}")))?;
        Ok(Self { image, data_uri })
    }
}

/// The underlay (designs with a noise or image background) and grain layer (designs with
/// overlays) of `design` at `scale` output pixels per design pixel; `None` for what it
/// lacks.
pub fn surface_layers(
    design: &Design,
    scale: f64,
) -> Result<(Option<RasterLayer>, Option<RasterLayer>), VectorError> {
    let textured = design.background_noise.is_some() || design.background_image.is_some();
    let underlay = if textured {
        let mut bare = design.clone();
        bare.overlays.clear();
        let opts = RenderOptions {
            scale,
            antialias: Antialias::Rgss,
        };
        Some(RasterLayer::new(render(&bare, &opts)?, Channels::Rgb)?)
    } else {
        None
    };
    let grain = if design.overlays.is_empty() {
        None
    } else {
        Some(RasterLayer::new(
            grain_layer(design, scale)?,
            Channels::Grey,
        )?)
    };
    Ok((underlay, grain))
}

/// `image` as a PNG data URI keeping `channels`.
fn png_data_uri(image: &RgbaImage, channels: Channels) -> Result<String, png::EncodingError> {
    use base64::Engine;
    let (color, data): (png::ColorType, Vec<u8>) = match channels {
        Channels::Grey => (
            png::ColorType::Grayscale,
            image.pixels.chunks_exact(4).map(|p| p[0]).collect(),
        ),
        Channels::Rgb => (
            png::ColorType::Rgb,
            image
                .pixels
                .chunks_exact(4)
                .flat_map(|p| [p[0], p[1], p[2]])
                .collect(),
        ),
        Channels::Rgba => (png::ColorType::Rgba, image.pixels.clone()),
    };
    let mut bytes = Vec::new();
    {
        let mut encoder = png::Encoder::new(&mut bytes, image.width, image.height);
        encoder.set_color(color);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(&data)?;
    }
    Ok(format!(
        "data:image/png;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    ))
}

/// Each output pixel's mean grain factor over the RGSS samples, as the CPU renderer
/// applies it: pigment grain at the point where the sample's walk ended, paper grain
/// at the sample itself. Grey, sRGB-encoded, so that an sRGB multiply matches the
/// renderer's multiply in linear light up to the curve's linear toe.
fn grain_layer(design: &Design, scale: f64) -> Result<RgbaImage, VectorError> {
    let (w, h) = output_size(design, scale)?;
    let walker = Walker::new(&design.ops);
    let samples: &[Sample] = Antialias::Rgss.samples();
    let mut image = RgbaImage::filled(w, h, [255, 255, 255, 255]);
    image
        .pixels
        .par_chunks_mut(w as usize * 4)
        .enumerate()
        .for_each(|(y, row)| {
            let mut batch = Batch::default();
            let mut starts = Vec::with_capacity(w as usize * samples.len());
            for x in 0..w {
                for s in samples {
                    let p = Point::new((f64::from(x) + s.dx) / scale, (y as f64 + s.dy) / scale);
                    batch.push(p.x, p.y, starts.len() as u32);
                    starts.push(p);
                }
            }
            let mut traced = vec![Traced::Ink(0); starts.len()];
            let mut ends = vec![Point::ZERO; starts.len()];
            walker.trace_batch_with_ends(&mut batch, &mut traced, &mut ends);
            for (x, px) in row.chunks_exact_mut(4).enumerate() {
                let mut acc = 0.0f32;
                for (k, s) in samples.iter().enumerate() {
                    let i = x * samples.len() + k;
                    let f: f32 = design
                        .overlays
                        .iter()
                        .map(|o| match o.kind {
                            GrainKind::Pigment => o.factor(ends[i].x, ends[i].y),
                            GrainKind::Paper => o.factor(starts[i].x, starts[i].y),
                        })
                        .product();
                    acc += s.weight * f;
                }
                let g = linear_to_srgb(acc);
                px.copy_from_slice(&[g, g, g, 255]);
            }
        });
    Ok(image)
}
