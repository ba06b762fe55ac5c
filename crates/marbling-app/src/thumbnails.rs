//! The gallery's thumbnails packed into one image (one egui texture).
//!
//! Why one texture: egui starts a new draw call wherever the texture changes, and the
//! gallery interleaved ten thumbnail textures with the font texture (image, name, image,
//! …). On a software GPU (SwiftShader, what headless Chromium uses where there is no
//! GPU) each draw call costs about half a millisecond a frame whatever it draws
//! (docs/BENCHMARKS.md). With one atlas, a row of thumbnails is one draw.

use crate::gallery::Example;
use egui::{ColorImage, Pos2, Rect};
use marbling_core::RgbaImage;

/// Thumbnails per atlas row.
pub const ATLAS_COLUMNS: usize = 2;

/// Every thumbnail in one image, and where each lies in it.
pub struct ThumbnailAtlas {
    /// The packed thumbnails (unmultiplied RGBA).
    pub image: ColorImage,
    /// Each example's rectangle in texture coordinates (0..=1), in gallery order.
    pub uv: Vec<Rect>,
}

/// Packs the thumbnails of `examples` in a grid of [`ATLAS_COLUMNS`] columns, each cell
/// the size of the largest thumbnail. Errors name the example whose PNG is unreadable.
pub fn atlas(examples: &[Example]) -> Result<ThumbnailAtlas, String> {
    let images = examples
        .iter()
        .map(|e| {
            RgbaImage::from_png(e.thumbnail_png)
                .map_err(|err| format!("gallery thumbnail {}: {err}", e.name))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let cell_w = images.iter().map(|i| i.width as usize).max().unwrap_or(1);
    let cell_h = images.iter().map(|i| i.height as usize).max().unwrap_or(1);
    let rows = images.len().div_ceil(ATLAS_COLUMNS).max(1);
    let (width, height) = (cell_w * ATLAS_COLUMNS, cell_h * rows);
    let mut pixels = vec![0u8; width * height * 4];
    let mut uv = Vec::with_capacity(images.len());
    for (n, img) in images.iter().enumerate() {
        let (x0, y0) = ((n % ATLAS_COLUMNS) * cell_w, (n / ATLAS_COLUMNS) * cell_h);
        let row_bytes = img.width as usize * 4;
        for y in 0..img.height as usize {
            let src = &img.pixels[y * row_bytes..(y + 1) * row_bytes];
            let at = ((y0 + y) * width + x0) * 4;
            pixels[at..at + row_bytes].copy_from_slice(src);
        }
        uv.push(Rect::from_min_max(
            Pos2::new(x0 as f32 / width as f32, y0 as f32 / height as f32),
            Pos2::new(
                (x0 + img.width as usize) as f32 / width as f32,
                (y0 + img.height as usize) as f32 / height as f32,
            ),
        ));
    }
    Ok(ThumbnailAtlas {
        image: ColorImage::from_rgba_unmultiplied([width, height], &pixels),
        uv,
    })
}

/// Largest op-samples (pixels × ops) spent on one recent-design thumbnail: about a
/// tenth of a second of the CPU renderer in a browser.
pub const MAX_THUMBNAIL_WORK: f64 = 2.0e7;

/// A 64 × 48 px (or less) thumbnail of recent design `i`, drawn exactly by the CPU
/// renderer with one sample per pixel; `None` when it cannot be read or would take
/// more than [`MAX_THUMBNAIL_WORK`].
pub fn recent_thumbnail(recent: &crate::recent::Recent, i: usize) -> Option<ColorImage> {
    let design = recent.design(i).ok()?;
    let scale = (64.0 / f64::from(design.width)).min(48.0 / f64::from(design.height));
    let pixels = f64::from(design.width) * f64::from(design.height) * scale * scale;
    if pixels * design.ops.len() as f64 > MAX_THUMBNAIL_WORK {
        return None;
    }
    let opts = marbling_core::RenderOptions {
        scale,
        antialias: marbling_core::Antialias::None,
    };
    let img = marbling_core::render(&design, &opts).ok()?;
    Some(ColorImage::from_rgba_unmultiplied(
        [img.width as usize, img.height as usize],
        &img.pixels,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gallery::EXAMPLES;

    #[test]
    fn every_thumbnail_is_found_pixel_for_pixel_at_its_uv_rect() {
        let atlas = atlas(&EXAMPLES).expect("thumbnails decode");
        assert_eq!(atlas.uv.len(), EXAMPLES.len());
        let [w, h] = atlas.image.size;
        for (e, uv) in EXAMPLES.iter().zip(&atlas.uv) {
            let img = RgbaImage::from_png(e.thumbnail_png).expect("decodes");
            let x0 = (uv.min.x * w as f32).round() as usize;
            let y0 = (uv.min.y * h as f32).round() as usize;
            assert_eq!((uv.width() * w as f32).round() as usize, img.width as usize);
            assert_eq!(
                (uv.height() * h as f32).round() as usize,
                img.height as usize
            );
            for (y, x) in [
                (0, 0),
                (img.height / 2, img.width / 3),
                (img.height - 1, img.width - 1),
            ] {
                let p = &img.pixels[((y * img.width + x) * 4) as usize..][..4];
                let q = atlas.image.pixels[(y0 + y as usize) * w + x0 + x as usize];
                assert_eq!(
                    egui::Color32::from_rgba_unmultiplied(p[0], p[1], p[2], p[3]),
                    q,
                    "{} at ({x}, {y})",
                    e.name
                );
            }
        }
    }

    #[test]
    fn a_broken_thumbnail_is_named() {
        let broken = [Example {
            name: "broken",
            json: "{}",
            thumbnail_png: b"not a png",
        }];
        let err = atlas(&broken).err().expect("refused");
        assert!(err.starts_with("gallery thumbnail broken:"), "{err}");
    }

    #[test]
    fn recent_thumbnails_are_exact_and_small_and_huge_ones_are_skipped() {
        use marbling_core::synth::{Mix, random_design};
        let mut recent = crate::recent::Recent::default();
        let small = random_design(5, 320, 200, 30, Mix::Mixed);
        recent.push(&small, "small", 0.0);
        let img = recent_thumbnail(&recent, 0).expect("a thumbnail");
        assert_eq!(img.size, [64, 40]);
        let cpu = marbling_core::render(
            &small,
            &marbling_core::RenderOptions {
                scale: 0.2,
                antialias: marbling_core::Antialias::None,
            },
        )
        .expect("render");
        assert_eq!(img.as_raw(), &cpu.pixels[..]);
        let huge = random_design(6, 4000, 3000, 7_000, Mix::DropHeavy);
        recent.push(&huge, "huge", 1.0);
        assert!(recent_thumbnail(&recent, 0).is_none());
    }
}
