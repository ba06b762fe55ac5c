//! Height and normal maps of a noise spec, for relief in 3D tools: the spec's intensity
//! h(x, y) ∈ [0, 1] (after its transfer and layers, before any palette) is the height,
//! and the surface z = relief·h, `relief` in output pixels, gives the normal
//! n = normalise(−relief·∂h/∂x, relief·∂h/∂y, 1) in tangent space, OpenGL convention
//! (x right, y **up** — the image's y runs down, hence the sign — z out of the sheet),
//! stored as (n + 1)/2. The slopes are central differences half a pixel either side.
//! Both maps are written at 16 bits per sample (big-endian, round(v·65535)).

use crate::render::{Depth, Renderer};

/// Which surface map to write.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceMap {
    /// The intensity as a greyscale height, 0 black (low) to 1 white (high).
    Height,
    /// The tangent-space normal of z = relief·h as RGB.
    Normal {
        /// Height of intensity 1 above intensity 0, output pixels (> 0).
        relief: f32,
    },
}

/// Names of the maps on the command line and in file names.
pub const SURFACE_MAPS: [&str; 2] = ["height", "normal"];

/// The unit tangent-space normal of z = relief·h where h rises by `hx` per pixel to the
/// right and by `hy` per pixel downwards (image y).
#[inline]
#[must_use]
pub fn surface_normal(hx: f32, hy: f32, relief: f32) -> [f32; 3] {
    let (x, y) = (-relief * hx, relief * hy);
    let k = 1.0 / (x * x + y * y + 1.0).sqrt();
    [x * k, y * k, k]
}

impl SurfaceMap {
    /// The map's name in [`SURFACE_MAPS`].
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            SurfaceMap::Height => SURFACE_MAPS[0],
            SurfaceMap::Normal { .. } => SURFACE_MAPS[1],
        }
    }

    /// Samples per pixel: 1 (grey) or 3 (RGB).
    #[must_use]
    pub fn channels(self) -> usize {
        match self {
            SurfaceMap::Height => 1,
            SurfaceMap::Normal { .. } => 3,
        }
    }
}

/// What a PNG of a spec holds: the image at a depth, or a surface map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PngContent {
    /// The intensity or colour ([`Renderer::png_row`]).
    Image(Depth),
    /// A 16-bit height or normal map ([`Renderer::map_row`]).
    Map(SurfaceMap),
}

impl PngContent {
    /// A file name for `type_name` noise at `size`²: `noise-gabor-1024-16bit.png`,
    /// `noise-gabor-1024-normal.png`.
    #[must_use]
    pub fn file_name(self, type_name: &str, size: u32) -> String {
        let what = match self {
            PngContent::Image(Depth::Eight) => "8bit",
            PngContent::Image(Depth::Sixteen) => "16bit",
            PngContent::Map(map) => map.name(),
        };
        format!("noise-{type_name}-{size}-{what}.png")
    }
}

impl Renderer {
    /// Row `j` of `content` as PNG sample bytes.
    #[must_use]
    pub fn content_row(&self, j: u32, content: PngContent) -> Vec<u8> {
        match content {
            PngContent::Image(depth) => self.png_row(j, depth),
            PngContent::Map(map) => self.map_row(j, map),
        }
    }

    /// A PNG encoder for `content` (feed it [`Renderer::content_row`]s).
    pub fn content_encoder<W: std::io::Write>(
        &self,
        out: W,
        content: PngContent,
    ) -> png::Encoder<'static, W> {
        match content {
            PngContent::Image(depth) => self.png_encoder(out, depth),
            PngContent::Map(map) => self.map_encoder(out, map),
        }
    }

    /// The unit normal of z = relief·h at (x, y), output pixels (see the module).
    #[must_use]
    pub fn normal_at(&self, x: f32, y: f32, relief: f32) -> [f32; 3] {
        let hx = self.intensity(x + 0.5, y) - self.intensity(x - 0.5, y);
        let hy = self.intensity(x, y + 0.5) - self.intensity(x, y - 0.5);
        surface_normal(hx, hy, relief)
    }

    /// Row `j` of `map` as 16-bit big-endian PNG samples.
    #[must_use]
    pub fn map_row(&self, j: u32, map: SurfaceMap) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.size() as usize * map.channels() * 2);
        let mut push = |v: f32| {
            let q = (v.clamp(0.0, 1.0) * 65535.0).round() as u16;
            out.extend_from_slice(&q.to_be_bytes());
        };
        for i in 0..self.size() {
            let (x, y) = (i as f32 + 0.5, j as f32 + 0.5);
            match map {
                SurfaceMap::Height => push(self.intensity(x, y)),
                SurfaceMap::Normal { relief } => {
                    for c in self.normal_at(x, y, relief) {
                        push(0.5 * (c + 1.0));
                    }
                }
            }
        }
        out
    }

    /// A PNG encoder for `map` of this output: size² pixels, 16-bit grey or RGB as
    /// [`Renderer::map_row`] writes them.
    pub fn map_encoder<W: std::io::Write>(
        &self,
        out: W,
        map: SurfaceMap,
    ) -> png::Encoder<'static, W> {
        let mut enc = png::Encoder::new(out, self.size(), self.size());
        enc.set_color(match map {
            SurfaceMap::Height => png::ColorType::Grayscale,
            SurfaceMap::Normal { .. } => png::ColorType::Rgb,
        });
        enc.set_depth(png::BitDepth::Sixteen);
        enc
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NoiseSpec;

    #[test]
    fn normal_of_a_flat_and_a_sloped_surface() {
        assert_eq!(surface_normal(0.0, 0.0, 8.0), [0.0, 0.0, 1.0]);
        // Rising to the right: the normal leans left; rising downwards (image y): the
        // normal leans up (+y, OpenGL).
        let [x, y, z] = surface_normal(0.125, 0.0, 8.0);
        assert!((x + 0.5f32.sqrt()).abs() < 1e-6 && y == 0.0 && (z - 0.5f32.sqrt()).abs() < 1e-6);
        let [_, y, _] = surface_normal(0.0, 0.1, 8.0);
        assert!(y > 0.0);
    }

    /// A Perlin fBm's normal map agrees with its own height map: the slope read back from
    /// the normal, −n_x/n_z / relief, equals the height map's finite difference (1e-3).
    #[test]
    fn normal_map_matches_height_map_slopes() {
        let spec =
            NoiseSpec::from_json(r#"{"type":"perlin","frequency":0.01,"octaves":2,"seed":2}"#)
                .expect("valid");
        let r = Renderer::new(&spec, 64).expect("renderer");
        let relief = 40.0;
        let decode = |row: &[u8], k: usize| {
            f32::from(u16::from_be_bytes([row[2 * k], row[2 * k + 1]])) / 65535.0
        };
        let heights: Vec<Vec<u8>> = (0..64).map(|j| r.map_row(j, SurfaceMap::Height)).collect();
        let normals = r.map_row(20, SurfaceMap::Normal { relief });
        assert_eq!(normals.len(), 64 * 3 * 2);
        let mut worst = 0.0_f32;
        for i in 1..63 {
            let n: Vec<f32> = (0..3)
                .map(|c| 2.0 * decode(&normals, 3 * i + c) - 1.0)
                .collect();
            let slope = -n[0] / n[2] / relief;
            let from_heights = 0.5 * (decode(&heights[20], i + 1) - decode(&heights[20], i - 1));
            worst = worst.max((slope - from_heights).abs());
        }
        assert!(worst < 1e-3, "worst slope difference {worst}");
        assert!(heights.iter().flatten().any(|b| *b != heights[0][0]));
    }
}
