//! A noise's relief lit on the 3D view's plane: a grid of heights (a noise's intensity,
//! [`marbling_noise::SurfaceMap`]) becomes a normal map by the same formula as the
//! exported one ([`marbling_noise::surface_normal`]), and the plane, seen through the 3D
//! view's camera ([`View3d::rig_for`]), is shaded per sample by a directional light:
//! colour × (A + (1 − A)·max(n·L, 0)), A = [`AMBIENT`], in linear light. The plane's
//! tangent frame is the world's (x right, y up, z towards the camera at yaw 0), so the
//! map's OpenGL-convention normals need no turning. Four samples per pixel (2×2 grid).

use super::{AMBIENT, BACKDROP, Material, Object, Shape, Vec3, View3d};
use crate::{Rgb8, RgbaImage};
use marbling_noise::surface_normal;

/// Normals and colours over the unit square, row-major, texel centres at (i + ½)/side.
#[derive(Clone, Debug, PartialEq)]
pub struct ReliefMap {
    side: usize,
    normals: Vec<[f32; 3]>,
    albedo: Vec<[f32; 3]>,
}

impl ReliefMap {
    /// The relief of `heights` (intensity in [0, 1], `side`² row-major) sampled every
    /// `cell` output pixels, raised `relief` output pixels at intensity 1, coloured by
    /// `colors` (sRGB components in [0, 1], one per height). Slopes are central
    /// differences (one-sided at the edges). `None` when the lengths disagree or side < 2.
    #[must_use]
    pub fn from_heights(
        side: usize,
        heights: &[f32],
        colors: &[[f32; 3]],
        cell: f32,
        relief: f32,
    ) -> Option<Self> {
        if side < 2 || heights.len() != side * side || colors.len() != heights.len() {
            return None;
        }
        let h = |i: usize, j: usize| heights[j * side + i];
        let slope = |lo: usize, hi: usize, a: f32, b: f32| (b - a) / ((hi - lo) as f32 * cell);
        let mut normals = Vec::with_capacity(heights.len());
        for j in 0..side {
            let (j0, j1) = (j.saturating_sub(1), (j + 1).min(side - 1));
            for i in 0..side {
                let (i0, i1) = (i.saturating_sub(1), (i + 1).min(side - 1));
                let hx = slope(i0, i1, h(i0, j), h(i1, j));
                let hy = slope(j0, j1, h(i, j0), h(i, j1));
                normals.push(surface_normal(hx, hy, relief));
            }
        }
        let linear =
            |v: f32| crate::color::srgb_to_linear((v.clamp(0.0, 1.0) * 255.0).round() as u8);
        Some(Self {
            side,
            normals,
            albedo: colors.iter().map(|c| c.map(linear)).collect(),
        })
    }

    /// Bilinear normal (renormalised) and linear colour at (u, v) ∈ [0, 1]², clamped.
    fn at(&self, u: f64, v: f64) -> ([f32; 3], [f32; 3]) {
        let n = self.side;
        let fx = (u * n as f64 - 0.5).clamp(0.0, (n - 1) as f64);
        let fy = (v * n as f64 - 0.5).clamp(0.0, (n - 1) as f64);
        let (i, j) = ((fx as usize).min(n - 2), (fy as usize).min(n - 2));
        let (tx, ty) = ((fx - i as f64) as f32, (fy - j as f64) as f32);
        let mix = |grid: &[[f32; 3]]| -> [f32; 3] {
            let (a, b) = (grid[j * n + i], grid[j * n + i + 1]);
            let (c, d) = (grid[(j + 1) * n + i], grid[(j + 1) * n + i + 1]);
            std::array::from_fn(|k| {
                let top = a[k] + (b[k] - a[k]) * tx;
                let bottom = c[k] + (d[k] - c[k]) * tx;
                top + (bottom - top) * ty
            })
        };
        let nm = mix(&self.normals);
        let len = (nm[0] * nm[0] + nm[1] * nm[1] + nm[2] * nm[2])
            .sqrt()
            .max(1e-12);
        (nm.map(|c| c / len), mix(&self.albedo))
    }
}

/// A directional light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Where the light comes from around the sheet, degrees: 0 from the right, 90 from
    /// the top, counter-clockwise as seen head-on.
    pub azimuth: f64,
    /// Height above the sheet, degrees (90: straight on).
    pub elevation: f64,
}

impl Default for Light {
    /// From the top left, 35° above the sheet: the usual light of relief previews.
    fn default() -> Self {
        Self {
            azimuth: 135.0,
            elevation: 35.0,
        }
    }
}

impl Light {
    /// Unit direction towards the light.
    #[must_use]
    pub fn direction(self) -> Vec3 {
        let (a, e) = (self.azimuth.to_radians(), self.elevation.to_radians());
        Vec3::new(a.cos() * e.cos(), a.sin() * e.cos(), e.sin())
    }
}

/// Renders `map` on the 3D view's plane (square) seen by `view`'s camera (its shape is
/// ignored; its look-at point, a design point, is ignored too), lit by `light`.
#[must_use]
pub fn render_relief(map: &ReliefMap, light: Light, view: &View3d) -> RgbaImage {
    let object = Object {
        shape: Shape::Plane,
        aspect: 1.0,
        displace: super::Displace::default(),
    };
    let rig = view.rig_for(&object, None);
    let to_light = light.direction();
    let (w, h) = (f64::from(view.width), f64::from(view.height));
    let backdrop = BACKDROP.map(Rgb8::to_linear);
    let sample = |px: f64, py: f64| -> [f32; 3] {
        let d = rig.ray(px, py, w, h);
        let Some(hit) = object.hit(rig.origin, d) else {
            let t = (py / h).clamp(0.0, 1.0) as f32;
            return std::array::from_fn(|k| backdrop[0][k] + (backdrop[1][k] - backdrop[0][k]) * t);
        };
        let Material::Design(u, v) = hit.material else {
            return backdrop[1];
        };
        let (n, albedo) = map.at(u, v);
        // Seen from behind, the sheet's back faces the camera: mirror the relief.
        let side = if hit.normal.z < 0.0 { -1.0 } else { 1.0 };
        let n = Vec3::new(f64::from(n[0]), f64::from(n[1]), f64::from(n[2]) * side);
        let lit = AMBIENT + (1.0 - AMBIENT) * n.dot(to_light).max(0.0);
        albedo.map(|c| c * lit as f32)
    };
    let mut image = RgbaImage::filled(view.width, view.height, [0, 0, 0, 255]);
    for y in 0..view.height {
        for x in 0..view.width {
            let mut sum = [0.0_f32; 3];
            for (dx, dy) in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
                let c = sample(f64::from(x) + dx, f64::from(y) + dy);
                for k in 0..3 {
                    sum[k] += 0.25 * c[k];
                }
            }
            let i = (y * view.width + x) as usize * 4;
            let e = crate::color::linear_to_srgb;
            image.pixels[i..i + 3].copy_from_slice(&[e(sum[0]), e(sum[1]), e(sum[2])]);
        }
    }
    image
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Antialias;
    use crate::view3d::Camera;

    fn view(yaw: f64, pitch: f64) -> View3d {
        View3d {
            shape: Shape::Plane,
            camera: Camera {
                yaw: Some(yaw),
                pitch: Some(pitch),
                zoom: 1.0,
                look_at: None,
                dolly: 1.0,
            },
            width: 64,
            height: 48,
            antialias: Antialias::None,
            texture: None,
            displace: crate::view3d::Displace::default(),
        }
    }

    fn light(azimuth: f64) -> Light {
        Light {
            azimuth,
            elevation: 30.0,
        }
    }

    fn grey_at(img: &RgbaImage, x: u32, y: u32) -> u8 {
        img.pixels[((y * img.width + x) * 4) as usize]
    }

    /// A ramp rising to the right (0 → 1 over 16 cells of 4 px) with white paper.
    fn ramp(side: usize) -> ReliefMap {
        let heights: Vec<f32> = (0..side * side)
            .map(|k| (k % side) as f32 / (side - 1) as f32)
            .collect();
        ReliefMap::from_heights(side, &heights, &vec![[1.0; 3]; side * side], 4.0, 16.0)
            .expect("map")
    }

    #[test]
    fn flat_sheet_head_on_is_lit_by_the_light_elevation() {
        let side = 8;
        let map =
            ReliefMap::from_heights(side, &[0.5; 64], &[[1.0; 3]; 64], 1.0, 8.0).expect("map");
        let light = Light {
            azimuth: 0.0,
            elevation: 30.0,
        };
        let img = render_relief(&map, light, &view(0.0, 0.0));
        let expected = crate::color::linear_to_srgb((AMBIENT + (1.0 - AMBIENT) * 0.5) as f32);
        assert_eq!(grey_at(&img, 32, 24), expected);
        // Zoom 1 fits the plane's height to the frame: its left and right edges leave
        // the backdrop beside it (64×48 frame, square plane 48 px wide).
        assert_ne!(grey_at(&img, 2, 24), expected);
    }

    #[test]
    fn a_slope_is_bright_towards_the_light_and_dark_away() {
        let map = ramp(16);
        // The ramp rises to the right, so it faces left: bright in light from the left.
        let from_left = render_relief(&map, light(180.0), &view(0.0, 0.0));
        let from_right = render_relief(&map, light(0.0), &view(0.0, 0.0));
        let (l, r) = (grey_at(&from_left, 32, 24), grey_at(&from_right, 32, 24));
        assert!(l > r + 40, "from the left {l}, from the right {r}");
        // Turning the camera does not change the lighting of a point on the sheet.
        let turned = render_relief(&map, light(180.0), &view(20.0, 25.0));
        assert!(grey_at(&turned, 32, 24).abs_diff(l) <= 2);
    }

    #[test]
    fn mismatched_grids_are_refused() {
        assert!(ReliefMap::from_heights(4, &[0.0; 15], &[[0.0; 3]; 15], 1.0, 1.0).is_none());
        assert!(ReliefMap::from_heights(1, &[0.0], &[[0.0; 3]], 1.0, 1.0).is_none());
    }
}
