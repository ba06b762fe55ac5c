//! The noise playground's picture of a whole spec (layers, curves, spline decay, blend,
//! data, tiling) where a design's noise background, which the GPU draws, holds only its
//! base noise: rendered on the CPU by `marbling_noise::Renderer`, coarse while the spec
//! changes and finer once it settles, and drawn over the sheet — or, for a tiling spec,
//! as 2×2 copies of one tile so the seams show.

use crate::noise::Noise;
use egui::{Color32, Rect, TextureOptions, pos2};
use marbling_noise::{NoiseSpec, Renderer, Tile};

/// Texels on the long side while the spec changes (a frame's worth of Gabor on a phone).
pub const COARSE: usize = 96;
/// Texels on the long side once the spec has settled.
pub const FINE: usize = 256;

/// What is drawn: a whole-sheet picture, or one tile repeated 2×2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Coverage {
    /// The sheet, `[0, W] × [0, H]` design pixels.
    Sheet,
    /// One tile `[0, P]²`, shown as 2×2 copies.
    Tiles(u32),
}

/// What a preview picture was made for: the settings' revision, the zoom rule's factor,
/// the sheet (design pixels) and the coverage.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PreviewKey {
    revision: u64,
    factor: f64,
    size: [u32; 2],
    coverage: Coverage,
}

/// The preview texture and what it shows.
pub struct NoisePreview {
    key: PreviewKey,
    fine: bool,
    texture: egui::TextureHandle,
    /// What the texture covers.
    pub coverage: Coverage,
    /// Texels (width, height).
    pub texels: [usize; 2],
}

/// The spec's colours over `coverage` of a `sheet` (W, H design pixels) at `long` texels
/// on the long side; a tile is square.
pub fn picture(
    spec: &NoiseSpec,
    sheet: [u32; 2],
    coverage: Coverage,
    long: usize,
) -> Result<egui::ColorImage, String> {
    let frame = [sheet[0] as f32, sheet[1] as f32];
    let (size, extent) = match coverage {
        Coverage::Sheet => (sheet[0].max(sheet[1]), frame),
        Coverage::Tiles(p) => (p, [p as f32; 2]),
    };
    let renderer = Renderer::with_frame(spec, size.max(1), frame).map_err(|e| e.to_string())?;
    let scale = long as f32 / extent[0].max(extent[1]);
    let w = ((extent[0] * scale).round() as usize).max(1);
    let h = ((extent[1] * scale).round() as usize).max(1);
    let mut pixels = Vec::with_capacity(w * h);
    let xs: Vec<f32> = (0..w)
        .map(|i| (i as f32 + 0.5) * extent[0] / w as f32)
        .collect();
    for j in 0..h {
        let y = (j as f32 + 0.5) * extent[1] / h as f32;
        for c in renderer.color_row(&xs, y) {
            let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
            pixels.push(Color32::from_rgb(r, g, b));
        }
    }
    Ok(egui::ColorImage::new([w, h], pixels))
}

impl Noise {
    /// Keeps the preview in step with the noise settings (coarse on a change, fine on the
    /// next frame without one) and draws it over `sheet` (a `size` design-pixel sheet
    /// at zoom rule `factor`); nothing when the design's noise background already shows
    /// the whole spec. An error is the spec's problem, for the status line.
    pub(crate) fn paint_preview(
        &mut self,
        ui: &egui::Ui,
        painter: &egui::Painter,
        sheet: Rect,
        size: [u32; 2],
        factor: f64,
    ) -> Result<(), String> {
        let s = self.settings();
        if !s.needs_preview() {
            self.preview = None;
            return Ok(());
        }
        let spec = s.shown_spec(factor);
        let coverage = match spec.tile {
            Tile::Period(p) if s.show_tiles => Coverage::Tiles(p),
            _ => Coverage::Sheet,
        };
        let key = PreviewKey {
            revision: self.revision(),
            factor,
            size,
            coverage,
        };
        let stale = self.preview.as_ref().map(|p| (p.key != key, p.fine));
        let long = match stale {
            None | Some((true, _)) => Some(COARSE),
            Some((false, false)) => Some(FINE),
            Some((false, true)) => None,
        };
        if let Some(long) = long {
            match picture(&spec, size, coverage, long) {
                Ok(image) => {
                    let texels = image.size;
                    let options = TextureOptions {
                        wrap_mode: egui::TextureWrapMode::Repeat,
                        ..TextureOptions::LINEAR
                    };
                    let texture = ui.ctx().load_texture("noise-preview", image, options);
                    self.preview = Some(NoisePreview {
                        key,
                        fine: long == FINE,
                        texture,
                        coverage,
                        texels,
                    });
                    // The fine picture follows on the next frame.
                    ui.ctx().request_repaint();
                }
                Err(e) => {
                    self.preview = None;
                    return Err(format!("noise: {e}"));
                }
            }
        }
        let Some(p) = &self.preview else {
            return Ok(());
        };
        let (rect, uv) = match p.coverage {
            Coverage::Sheet => (sheet, Rect::from_min_max(pos2(0.0, 0.0), pos2(1.0, 1.0))),
            Coverage::Tiles(_) => {
                let side = sheet.width().min(sheet.height());
                (
                    Rect::from_min_size(sheet.min, egui::vec2(side, side)),
                    Rect::from_min_max(pos2(0.0, 0.0), pos2(2.0, 2.0)),
                )
            }
        };
        painter.image(p.texture.id(), rect, uv, Color32::WHITE);
        Ok(())
    }

    /// `data-noise-preview`: `off`, `sheet WxH` or `tiles WxH` (texels).
    pub(crate) fn preview_hook(&self) -> String {
        match &self.preview {
            None => "off".to_owned(),
            Some(p) => {
                let kind = match p.coverage {
                    Coverage::Sheet => "sheet",
                    Coverage::Tiles(_) => "tiles",
                };
                format!("{kind} {}x{}", p.texels[0], p.texels[1])
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tile_picture_is_square_and_a_sheet_picture_keeps_its_aspect() {
        let spec =
            NoiseSpec::from_json(r#"{"type":"perlin","frequency":0.05,"tile":32}"#).expect("valid");
        let tile = picture(&spec, [300, 200], Coverage::Tiles(32), 64).expect("renders");
        assert_eq!(tile.size, [64, 64]);
        // One period across the texture: the left column continues the right one.
        let (left, right) = (tile.pixels[0], tile.pixels[63]);
        let d = (i32::from(left.r()) - i32::from(right.r())).abs();
        assert!(d <= 12, "seam {d}");
        let sheet = picture(&spec, [300, 200], Coverage::Sheet, 96).expect("renders");
        assert_eq!(sheet.size, [96, 64]);
    }
}
