//! Thumbnails of recent designs, drawn exactly by the CPU renderer (small and few;
//! the gallery's are drawn by the GPU, see src/gpu/gallery_gpu.rs).

use egui::ColorImage;

/// Largest op-samples (pixels × ops) spent on one recent-design thumbnail: about a
/// tenth of a second of the CPU renderer in a browser.
pub const MAX_THUMBNAIL_WORK: f64 = 2.0e7;

/// A 64 × 48 px (or less) thumbnail of recent design `i`, drawn exactly by the CPU
/// renderer with one sample per pixel; `None` when it cannot be read or would take
/// more than [`MAX_THUMBNAIL_WORK`].
pub fn recent_thumbnail(recent: &crate::store::recent::Recent, i: usize) -> Option<ColorImage> {
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

    #[test]
    fn recent_thumbnails_are_exact_and_small_and_huge_ones_are_skipped() {
        use marbling_core::synth::{Mix, random_design};
        let mut recent = crate::store::recent::Recent::default();
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
