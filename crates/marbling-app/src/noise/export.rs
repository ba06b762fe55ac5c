//! Export PNG from the noise playground: the whole spec (layers, transfers, blend, data)
//! at a chosen size, 8- or 16-bit, or its 16-bit height or normal map
//! (`marbling_noise::SurfaceMap`), rendered row by row on the CPU within a time budget
//! per frame so the page stays responsive, then encoded and offered as a download. A
//! tiling spec is exported seamless over the exported size (`"tile": true`).

use crate::frame::Frame;
use crate::noise::Noise;
use marbling_noise::{NoiseSpec, PngContent, Renderer, Tile};

/// The sizes offered, pixels per side.
pub const EXPORT_SIZES: [u32; 5] = [512, 1024, 2048, 4096, 8192];
/// What Export PNG can write: the button's label and control name
/// ([`crate::noise::settings::NoiseSettings::export_map`] indexes it; the maps in the order
/// of `marbling_noise::SURFACE_MAPS`).
pub const EXPORT_CONTENTS: [(&str, &str); 3] = [
    ("image", "noise-export-image"),
    ("height map", "noise-export-height"),
    ("normal map", "noise-export-normal"),
];
/// CPU time spent on rows per frame, milliseconds.
pub const FRAME_BUDGET_MS: f64 = 25.0;

/// A running export.
pub struct NoiseExport {
    renderer: Renderer,
    content: PngContent,
    next_row: u32,
    samples: Vec<u8>,
    /// The download's file name.
    pub name: String,
}

impl NoiseExport {
    /// Starts exporting `content` of `spec` at `size`².
    pub fn start(spec: &NoiseSpec, size: u32, content: PngContent) -> Result<Self, String> {
        let mut spec = spec.clone();
        if spec.tile.is_on() {
            spec.tile = Tile::Output;
        }
        let renderer = Renderer::new(&spec, size).map_err(|e| e.to_string())?;
        Ok(Self {
            name: content.file_name(spec.source.type_name(), size),
            renderer,
            content,
            next_row: 0,
            samples: Vec::new(),
        })
    }

    /// Side of the output, pixels.
    pub fn size(&self) -> u32 {
        self.renderer.size()
    }

    /// Renders rows until `now()` passes `budget_ms` from the start; true when every row
    /// is done.
    pub fn advance(&mut self, budget_ms: f64, now: impl Fn() -> f64) -> bool {
        let start = now();
        while self.next_row < self.size() {
            self.samples
                .extend(self.renderer.content_row(self.next_row, self.content));
            self.next_row += 1;
            if now() - start > budget_ms {
                break;
            }
        }
        self.next_row == self.size()
    }

    /// Share of rows done, [0, 1].
    pub fn progress(&self) -> f32 {
        self.next_row as f32 / self.size() as f32
    }

    /// The PNG file of the finished rows.
    pub fn finish(self) -> Result<Vec<u8>, String> {
        let mut out = Vec::new();
        let mut writer = self
            .renderer
            .content_encoder(&mut out, self.content)
            .write_header()
            .map_err(|e| e.to_string())?;
        writer
            .write_image_data(&self.samples)
            .map_err(|e| e.to_string())?;
        writer.finish().map_err(|e| e.to_string())?;
        Ok(out)
    }
}

impl Noise {
    /// Side of the running export, pixels; `None` when none runs.
    pub(crate) fn export_side(&self) -> Option<u32> {
        self.export.as_ref().map(NoiseExport::size)
    }

    /// Export PNG of the whole spec: its size and depth, then the button or the running
    /// export's progress.
    pub(crate) fn export_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.horizontal_wrapped(|ui| {
            self.edit_in(|s| {
                let size = EXPORT_SIZES[s.export_size.min(EXPORT_SIZES.len() - 1)];
                egui::ComboBox::from_id_salt("noise-export-size")
                    .selected_text(format!("{size}²"))
                    .show_ui(ui, |ui| {
                        for (i, n) in EXPORT_SIZES.iter().enumerate() {
                            ui.selectable_value(&mut s.export_size, i, format!("{n}²"));
                        }
                    });
                for (i, (label, control)) in EXPORT_CONTENTS.iter().enumerate() {
                    let r = ui.selectable_value(&mut s.export_map, i, *label);
                    frame.control(*control, &r);
                }
                if s.export_map == 0 {
                    ui.checkbox(&mut s.export_16bit, "16-bit")
                        .on_hover_text("65,536 levels per sample");
                }
            });
            if self.settings().export_map != 0 {
                self.relief.relief_ui(ui, frame);
            }
            match &self.export {
                Some(e) => {
                    ui.label(format!("exporting… {:.0} %", 100.0 * e.progress()));
                }
                None => {
                    let export = ui.button("Export noise PNG").on_hover_text(
                        "The whole spec at this size (a tileable noise repeats over it)",
                    );
                    frame.control("noise-export-png", &export);
                    if export.clicked() {
                        self.start_export(frame);
                    }
                }
            }
        });
        if self.settings().export_map != 0 {
            let s = self.settings();
            let size = EXPORT_SIZES[s.export_size.min(EXPORT_SIZES.len() - 1)];
            let spec = s.export_spec();
            self.relief.view_ui(ui, &spec, size, frame);
        }
    }

    /// Starts Export PNG of the noise at the panel's size and depth.
    fn start_export(&mut self, frame: &mut Frame<'_>) {
        let s = self.settings();
        let size = EXPORT_SIZES[s.export_size.min(EXPORT_SIZES.len() - 1)];
        match NoiseExport::start(
            &s.export_spec(),
            size,
            s.export_content(self.relief.relief()),
        ) {
            Ok(e) => {
                frame.info(format!("exporting {size}×{size} noise PNG…"));
                self.export = Some(e);
            }
            Err(e) => frame.error(format!("Export noise PNG: {e}")),
        }
    }

    /// Moves a running export on by one frame's budget; offers the file when done.
    pub(crate) fn tick_export(&mut self, ctx: &egui::Context, frame: &mut Frame<'_>) {
        let Some(mut export) = self.export.take() else {
            return;
        };
        if !export.advance(FRAME_BUDGET_MS, crate::platform::now_ms) {
            self.export = Some(export);
            ctx.request_repaint();
            return;
        }
        let name = export.name.clone();
        let saved = export
            .finish()
            .and_then(|bytes| crate::platform::save_file(&name, "image/png", &bytes));
        match saved {
            Ok(()) => frame.info(format!("{name} saved")),
            Err(e) => frame.error(format!("Export noise PNG: {e}")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_noise::Depth;

    /// The 16-bit greyscale samples of an exported `spec` at 64², one row per call.
    fn export(spec: &str) -> Vec<f64> {
        let spec = NoiseSpec::from_json(spec).expect("valid");
        let mut e =
            NoiseExport::start(&spec, 64, PngContent::Image(Depth::Sixteen)).expect("starts");
        // A clock that jumps past the budget at every reading: one row per call.
        let clock = std::cell::Cell::new(0.0);
        let now = || {
            clock.set(clock.get() + 100.0);
            clock.get()
        };
        assert!(!e.advance(FRAME_BUDGET_MS, now));
        assert_eq!(e.progress(), 1.0 / 64.0);
        while !e.advance(FRAME_BUDGET_MS, now) {}
        let png = e.finish().expect("encodes");
        let mut reader = png::Decoder::new(std::io::Cursor::new(png))
            .read_info()
            .expect("png");
        let mut buf = vec![0; reader.output_buffer_size().expect("size")];
        let info = reader.next_frame(&mut buf).expect("frame");
        assert_eq!((info.width, info.bit_depth), (64, png::BitDepth::Sixteen));
        buf.chunks_exact(2)
            .map(|b| f64::from(u16::from_be_bytes([b[0], b[1]])))
            .collect()
    }

    /// (the step from the last column to the first, the mean step between neighbours).
    fn seam(v: &[f64]) -> (f64, f64) {
        let step = |a: usize, b: usize| {
            (0..64)
                .map(|j| (v[j * 64 + a] - v[j * 64 + b]).abs())
                .sum::<f64>()
        };
        (
            step(63, 0),
            (0..63).map(|i| step(i, i + 1)).sum::<f64>() / 63.0,
        )
    }

    #[test]
    fn an_export_writes_every_row_and_tiles_over_its_size() {
        let tiled = export(r#"{"type":"perlin","frequency":0.05,"tile":24}"#);
        let (edge, inner) = seam(&tiled);
        assert!(edge <= 1.5 * inner, "seam {edge} vs interior {inner}");
        // The measure sees an untiled noise's seam.
        let untiled = export(r#"{"type":"perlin","frequency":0.05}"#);
        let (edge, inner) = seam(&untiled);
        assert!(
            edge > 3.0 * inner,
            "untiled seam {edge} vs interior {inner}"
        );
    }

    #[test]
    fn the_file_is_named_after_the_noise_size_and_depth() {
        let spec = NoiseSpec::from_json(r#"{"type":"worley","frequency":0.05}"#).expect("valid");
        let e = NoiseExport::start(&spec, 512, PngContent::Image(Depth::Eight)).expect("starts");
        assert_eq!(e.name, "noise-worley-512-8bit.png");
        let normal = PngContent::Map(marbling_noise::SurfaceMap::Normal { relief: 8.0 });
        let e = NoiseExport::start(&spec, 256, normal).expect("starts");
        assert_eq!(e.name, "noise-worley-256-normal.png");
        assert!(NoiseExport::start(&spec, 0, PngContent::Image(Depth::Eight)).is_err());
    }
}
