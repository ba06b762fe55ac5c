//! The gallery's prerendered thumbnails: one JPEG atlas, `web/gallery-thumbnails.jpg`,
//! holding the exact CPU render of every gallery entry in the cells of
//! src/gpu/gallery_gpu.rs. `make gallery` writes it (`cargo run -p marbling-app --example
//! gallery_atlas`); this module's tests fail when it no longer matches the entries. The
//! landing shows every card from it on its first frame; the GPU draws thumbnails only
//! where the file cannot be had (src/shell/landing.rs).

use crate::gpu::gallery_gpu::{CELL, COLUMNS, ROWS, cell_pixels};
use marbling_core::{Antialias, Design, RenderOptions, RgbaImage, render};
use std::sync::{Arc, Mutex};

/// The atlas's file name, beside index.html in dist/ (and in web/ in the repository).
pub const FILE_NAME: &str = "gallery-thumbnails.jpg";

/// JPEG quality of the atlas (1..=100): cards are small; the test's budget allows its loss.
pub const QUALITY: u8 = 60;

/// Atlas size, pixels.
pub const SIZE: [u32; 2] = [CELL[0] * COLUMNS, CELL[1] * ROWS];

/// A design's size, design pixels.
fn size_of(d: &Design) -> (u32, u32) {
    (d.width, d.height)
}

/// The atlas of `designs` (exact renders, RGSS, in their cells) on `surround` (sRGB).
pub fn render_atlas(designs: &[Design], surround: [u8; 3]) -> Result<RgbaImage, String> {
    let [r, g, b] = surround;
    let mut atlas = RgbaImage::filled(SIZE[0], SIZE[1], [r, g, b, 255]);
    for (n, design) in designs.iter().enumerate().take((COLUMNS * ROWS) as usize) {
        let [x, y, w, _] = cell_pixels(n, size_of(design));
        let cell = render(
            design,
            &RenderOptions {
                scale: f64::from(w) / f64::from(design.width),
                antialias: Antialias::Rgss,
            },
        )
        .map_err(|e| format!("thumbnail {n}: {e}"))?;
        let row = (cell.width * 4) as usize;
        for yy in 0..cell.height as usize {
            let at = ((y as usize + yy) * SIZE[0] as usize + x as usize) * 4;
            atlas.pixels[at..at + row].copy_from_slice(&cell.pixels[yy * row..][..row]);
        }
    }
    Ok(atlas)
}

/// The atlas encoded as the JPEG the app ships.
pub fn encode(atlas: &RgbaImage) -> Result<Vec<u8>, String> {
    let pixels = marbling_core::image_background::ImagePixels::from_rgba(
        atlas.width,
        atlas.height,
        atlas.pixels.clone(),
    )
    .map_err(|e| e.to_string())?;
    Ok(pixels.to_jpeg(SIZE[0].max(SIZE[1]), QUALITY))
}

/// What the atlas's loading has come to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Loaded {
    /// Still on its way.
    Waiting,
    /// Decoded: the atlas's RGBA pixels.
    Pixels(Arc<marbling_core::image_background::ImagePixels>),
    /// It could not be had (the reason): the GPU draws the thumbnails instead.
    Failed(String),
}

/// The atlas being loaded, shared with the fetch that fills it in.
#[derive(Clone, Debug)]
pub struct AtlasLoad(Arc<Mutex<Loaded>>);

impl AtlasLoad {
    /// Starts loading the atlas: fetched beside the page on the web (index.html preloads
    /// it), bundled in the desktop app. Repaints `ctx` when it is in.
    pub fn start(ctx: &egui::Context) -> Self {
        let load = Self(Arc::new(Mutex::new(Loaded::Waiting)));
        load.fetch(ctx.clone());
        load
    }

    /// What has come so far.
    pub fn state(&self) -> Loaded {
        self.0.lock().map_or_else(
            |_| Loaded::Failed("the atlas's loader broke".to_owned()),
            |s| s.clone(),
        )
    }

    fn finish(&self, bytes: Result<Vec<u8>, String>) {
        let loaded = match bytes.and_then(|b| {
            marbling_core::image_background::ImagePixels::decode(&b)
                .map_err(|e| format!("{FILE_NAME}: {e}"))
        }) {
            Ok(p) if [p.width, p.height] == SIZE => Loaded::Pixels(Arc::new(p)),
            Ok(p) => Loaded::Failed(format!(
                "{FILE_NAME}: {}×{} pixels, not {}×{}",
                p.width, p.height, SIZE[0], SIZE[1]
            )),
            Err(e) => Loaded::Failed(e),
        };
        if let Ok(mut s) = self.0.lock() {
            *s = loaded;
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn fetch(&self, ctx: egui::Context) {
        self.finish(Ok(
            include_bytes!("../../../../web/gallery-thumbnails.jpg").to_vec()
        ));
        ctx.request_repaint();
    }

    #[cfg(target_arch = "wasm32")]
    fn fetch(&self, ctx: egui::Context) {
        use wasm_bindgen::JsCast;
        use wasm_bindgen_futures::JsFuture;
        let load = self.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let bytes = async {
                let window = web_sys::window().ok_or("no window")?;
                let response: web_sys::Response = JsFuture::from(window.fetch_with_str(FILE_NAME))
                    .await
                    .map_err(|_| "the network refused it")?
                    .dyn_into()
                    .map_err(|_| "not a response")?;
                if !response.ok() {
                    return Err(format!("HTTP {}", response.status()));
                }
                let buffer = JsFuture::from(response.array_buffer().map_err(|_| "no body")?)
                    .await
                    .map_err(|_| "the body broke off")?;
                Ok(js_sys::Uint8Array::new(&buffer).to_vec())
            }
            .await
            .map_err(|e: String| format!("{FILE_NAME}: {e}"));
            load.finish(bytes);
            ctx.request_repaint();
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shell::gallery::entries;

    fn designs() -> Vec<Design> {
        entries()
            .iter()
            .map(|e| e.design().expect("valid"))
            .collect()
    }

    fn shipped() -> marbling_core::image_background::ImagePixels {
        marbling_core::image_background::ImagePixels::decode(include_bytes!(
            "../../../../web/gallery-thumbnails.jpg"
        ))
        .expect("the shipped atlas decodes")
    }

    /// Fraction of the pixels of cell `n` differing by more than `threshold` (0..=255).
    fn cell_diff(a: &[u8], b: &[u8], n: usize, design: &Design, threshold: u8) -> f64 {
        let [x, y, w, h] = cell_pixels(n, size_of(design));
        let mut over = 0;
        for yy in y..y + h {
            for xx in x..x + w {
                let i = ((yy * SIZE[0] + xx) * 4) as usize;
                if (0..3).any(|c| a[i + c].abs_diff(b[i + c]) > threshold) {
                    over += 1;
                }
            }
        }
        f64::from(over) / f64::from(w * h)
    }

    /// The shipped atlas is the exact render of the current gallery within JPEG's loss
    /// (quality 60): under 5 % of each checked cell's pixels off by more than 48/255. A pattern edited
    /// without `make gallery` fails here (checked: a neighbour's cell fails by far). Three
    /// cells are rendered here (about 1 s); every cell is checked by its content's mean.
    #[test]
    fn the_shipped_atlas_is_the_exact_render_of_the_gallery() {
        let designs = designs();
        let shipped = shipped();
        assert_eq!([shipped.width, shipped.height], SIZE);
        let checked = [0, 8, designs.len() - 1];
        let some: Vec<Design> = checked.iter().map(|&n| designs[n].clone()).collect();
        let cpu = render_atlas(&some, crate::gpu::canvas_gpu::SURROUND).expect("renders");
        let mut moved = RgbaImage::filled(SIZE[0], SIZE[1], [0, 0, 0, 255]);
        // Cell k of `cpu` holds entry checked[k]: compare it with that entry's cell.
        for (k, &n) in checked.iter().enumerate() {
            let [x0, y0, w, h] = cell_pixels(k, size_of(&designs[n]));
            let [x1, y1, _, _] = cell_pixels(n, size_of(&designs[n]));
            for yy in 0..h {
                let from = (((y0 + yy) * SIZE[0] + x0) * 4) as usize;
                let to = (((y1 + yy) * SIZE[0] + x1) * 4) as usize;
                let row = (w * 4) as usize;
                moved.pixels[to..to + row].copy_from_slice(&cpu.pixels[from..from + row]);
            }
            let frac = cell_diff(&moved.pixels, &shipped.rgba, n, &designs[n], 48);
            println!(
                "cell {n}: {:.2} % of its pixels off by > 48/255",
                100.0 * frac
            );
            assert!(
                frac < 0.05,
                "cell {n} ({}): {:.1} % of its pixels differ from the exact render: run make gallery",
                entries()[n].id,
                100.0 * frac
            );
        }
        // The comparator tells patterns apart: entry 0's render against entry 1's cell.
        let [x0, y0, w, h] = cell_pixels(0, size_of(&designs[0]));
        let [x1, y1, ..] = cell_pixels(1, size_of(&designs[1]));
        let mut swapped = RgbaImage::filled(SIZE[0], SIZE[1], [0, 0, 0, 255]);
        for yy in 0..h {
            let from = (((y0 + yy) * SIZE[0] + x0) * 4) as usize;
            let to = (((y1 + yy) * SIZE[0] + x1) * 4) as usize;
            let row = (w * 4) as usize;
            swapped.pixels[to..to + row].copy_from_slice(&cpu.pixels[from..from + row]);
        }
        assert!(cell_diff(&swapped.pixels, &shipped.rgba, 1, &designs[1], 48) > 0.2);
    }

    /// Every cell of the shipped atlas holds its entry: the cell's mean colour (in linear
    /// light) is within 6/255 of the entry's render at 1/8 of the cell's scale (cheap for
    /// all 27).
    #[test]
    fn every_cell_of_the_shipped_atlas_holds_its_entry() {
        let designs = designs();
        let shipped = shipped();
        let mut misses = Vec::new();
        let mut wants = Vec::new();
        let mut gots = Vec::new();
        for (n, d) in designs.iter().enumerate() {
            let [x, y, w, h] = cell_pixels(n, size_of(d));
            let small = render(
                d,
                &RenderOptions {
                    scale: f64::from(w) / f64::from(d.width) / 8.0,
                    antialias: Antialias::Grid4,
                },
            )
            .expect("renders");
            // In linear light, as the renderer averages its samples; then back to sRGB
            // levels (0..=255).
            let mean = |px: &mut dyn Iterator<Item = [u8; 3]>| {
                let (mut s, mut k) = ([0.0f64; 3], 0.0);
                for p in px {
                    (0..3).for_each(|c| {
                        s[c] += f64::from(marbling_core::surface::srgb_unit_to_linear(
                            f32::from(p[c]) / 255.0,
                        ))
                    });
                    k += 1.0;
                }
                s.map(|v| 255.0 * (v / k).powf(1.0 / 2.2))
            };
            let want = mean(&mut small.pixels.chunks(4).map(|p| [p[0], p[1], p[2]]));
            let got = mean(&mut (y..y + h).flat_map(|yy| {
                let rgba = &shipped.rgba;
                (x..x + w).map(move |xx| {
                    let i = ((yy * SIZE[0] + xx) * 4) as usize;
                    [rgba[i], rgba[i + 1], rgba[i + 2]]
                })
            }));
            if (0..3).any(|c| (want[c] - got[c]).abs() > 6.0) {
                misses.push(format!(
                    "{} (want {want:.0?}, got {got:.0?})",
                    entries()[n].id
                ));
            }
            wants.push(want);
            gots.push(got);
        }
        assert!(
            misses.is_empty(),
            "stale cells, run make gallery: {misses:?}"
        );
        // The check sees a shuffled atlas: most cells fail against their neighbour's entry.
        let shuffled = (0..designs.len())
            .filter(|&n| {
                let (w, g) = (wants[(n + 1) % wants.len()], gots[n]);
                (0..3).any(|c| (w[c] - g[c]).abs() > 6.0)
            })
            .count();
        assert!(
            shuffled > designs.len() / 2,
            "only {shuffled} cells tell their neighbours apart"
        );
    }

    #[test]
    fn a_file_of_another_size_or_no_picture_is_refused_with_its_name() {
        let load = AtlasLoad(Arc::new(Mutex::new(Loaded::Waiting)));
        load.finish(Ok(b"not a picture".to_vec()));
        assert!(matches!(load.state(), Loaded::Failed(e) if e.starts_with(FILE_NAME)));
        let tiny = marbling_core::image_background::ImagePixels::from_rgba(2, 2, vec![9; 16])
            .expect("pixels");
        load.finish(Ok(tiny.to_jpeg(2, 90)));
        assert!(matches!(load.state(), Loaded::Failed(e) if e.contains("2×2 pixels")));
        load.finish(Err("gone".to_owned()));
        assert_eq!(load.state(), Loaded::Failed("gone".to_owned()));
    }
}
