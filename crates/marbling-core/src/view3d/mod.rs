//! The 3D view (Lu et al. 2012, figures 6–7): the design on a sphere, vase, cylinder, book or
//! plane, seen through an orbit camera, every sample evaluated **exactly** — the ray's
//! hit gives texture coordinates, hence a design point, which walks back through every
//! op ([`crate::point_color`]), so edges stay sharp however close the camera goes. For
//! comparison, [`View3d::texture`] samples a baked raster instead, as a texture-mapped
//! renderer would (bilinear, linear light), which blurs in close-up.
//!
//! # Conventions (keep in sync with `view3d.wgsl` in marbling-gpu)
//! - Camera: orbits the target T (the object's centre, or the surface point of the
//!   design point [`Camera::look_at`]) at distance [`View3d::distance`], from the
//!   direction (sin yaw·cos pitch, sin pitch, cos yaw·cos pitch); y up.
//! - Output pixel sample (px, py) of a w×h frame looks along
//!   fwd + right·(px − w/2)/(h/2)·k + up·(h/2 − py)/(h/2)·k, k = tan(fov/2): at zoom
//!   1, k fits the object's head-on extent (half-width e_x, half-height e_y) into the
//!   frame at the target's distance D, k = m·max(e_y, e_x·h/w)/D (m = 1 for the plane,
//!   else [`FIT_MARGIN`]); zoom Z divides k by Z.
//! - Light: a headlight, colour × (A + (1 − A)·max(n·(−fwd), 0)), A = [`AMBIENT`], in
//!   linear light, so a plane facing the camera shows the design's own colours.
//! - Antialiasing: the design renderer's sample patterns and adaptive refinement
//!   (where first-pass samples come from different sources), averaged in linear light.
//! - Displacement: [`View3d::displace`] moves the design faces along their normals by
//!   Perlin fBm (module `displace`).

pub mod displace;
mod relief;
mod shapes;
pub mod style;
mod vec3;

pub use displace::Displace;
pub use relief::{Light, ReliefMap, render_relief};
pub use shapes::{
    BOOK_DEPTH, Hit, Material, Object, PAGES, Shape, VASE_BISECTIONS, VASE_BOUND, VASE_STEPS,
    vase_radius,
};
pub use vec3::Vec3;

use crate::image_background::ImagePixels;
use crate::point_color::{PointColors, PointScratch, SOURCE_BACKGROUND};
use crate::sampling::Sample;
use crate::{Antialias, Design, Point, RenderError, RenderOptions, Rgb8, RgbaImage, render};
use rayon::prelude::*;

/// The headlight's ambient share.
pub const AMBIENT: f64 = 0.25;
/// How much larger than their head-on extent solid objects are framed at zoom 1
/// (perspective shows their near parts larger, and pitch shows their tops); the plane
/// is framed exactly, so at zoom 1 facing the camera it is the 2D render.
pub const FIT_MARGIN: f64 = 1.12;
/// Largest zoom.
pub const MAX_ZOOM: f64 = 100_000.0;
/// Nearest [`Camera::dolly`]: 0.7 of the framing distance keeps the camera outside
/// every object wherever it aims (it is 3b + 1 from its target, b the object's bound,
/// and 0.7·(3b + 1) > 2b).
pub const MIN_DOLLY: f64 = 0.7;
/// Farthest [`Camera::dolly`].
pub const MAX_DOLLY: f64 = 5.0;
/// Largest output side of a 3D render, pixels.
pub const MAX_VIEW_SIDE: u32 = 8192;
/// Largest baked texture side for [`View3d::texture`] (the image-background limit).
pub const MAX_TEXTURE_SIDE: u32 = crate::image_background::MAX_IMAGE_SIDE;
/// Backdrop colour at the top and bottom of the frame, sRGB.
pub const BACKDROP: [Rgb8; 2] = [Rgb8::new(0x4a, 0x4a, 0x52), Rgb8::new(0x1e, 0x1e, 0x22)];
/// Shading of the book's spine and of the vase's inside, relative to the paper colour.
pub const SPINE_SHADE: f32 = 0.55;
/// See [`SPINE_SHADE`].
pub const INSIDE_SHADE: f32 = 0.15;

/// Where the camera is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Turn about the vertical axis, degrees (0: in front); `None`: facing
    /// [`Camera::look_at`]'s surface point head-on, or 0.
    pub yaw: Option<f64>,
    /// Elevation, degrees in (−90, 90); `None` as for `yaw`.
    pub pitch: Option<f64>,
    /// Magnification, ≥ 1 is closer (1: the object fills the frame).
    pub zoom: f64,
    /// Design point the camera centres on (its point on the object's surface).
    pub look_at: Option<Point>,
    /// Camera distance as a share of the framing distance [`View3d::distance`], in
    /// [`MIN_DOLLY`, `MAX_DOLLY`]: below 1 the camera moves in (the object looks larger, its
    /// perspective stronger), above 1 out; the lens stays as `zoom` sets it.
    pub dolly: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Self {
            yaw: None,
            pitch: None,
            zoom: 1.0,
            look_at: None,
            dolly: 1.0,
        }
    }
}

/// A 3D view of a design.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View3d {
    /// The object.
    pub shape: Shape,
    /// The camera.
    pub camera: Camera,
    /// Output width, pixels.
    pub width: u32,
    /// Output height, pixels.
    pub height: u32,
    /// Sample pattern.
    pub antialias: Antialias,
    /// `Some(n)`: sample the design baked into a raster of longest side n (bilinear)
    /// instead of walking every sample — the blur the exact view avoids.
    pub texture: Option<u32>,
    /// Perlin displacement of the object's design faces.
    pub displace: Displace,
}

/// Why a 3D view cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum View3dError {
    /// Output size out of range.
    #[error("output size {0}×{1} is out of range (1 to {MAX_VIEW_SIDE} per side)")]
    Size(u32, u32),
    /// Zoom out of range.
    #[error("zoom must be a number from 0.01 to {MAX_ZOOM}, got {0}")]
    Zoom(f64),
    /// Dolly out of range.
    #[error("dolly must be a number from {MIN_DOLLY} to {MAX_DOLLY}, got {0}")]
    Dolly(f64),
    /// Angles out of range.
    #[error("yaw must be finite and pitch within (-90, 90) degrees")]
    Angles,
    /// Look-at point outside the design.
    #[error("look-at point ({0}, {1}) is outside the {2}×{3} design")]
    LookAt(f64, f64, u32, u32),
    /// Texture size out of range.
    #[error("texture side must be 16 to {MAX_TEXTURE_SIDE}, got {0}")]
    Texture(u32),
    /// Displacement out of range (the message names the field).
    #[error("{0}")]
    Displace(String),
    /// Baking the texture failed.
    #[error("cannot bake the texture: {0}")]
    Render(#[from] RenderError),
}

/// The camera resolved for one frame: position, unit basis and tan(fov/2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rig {
    /// Camera position.
    pub origin: Vec3,
    /// Unit view direction.
    pub forward: Vec3,
    /// Unit right.
    pub right: Vec3,
    /// Unit up.
    pub up: Vec3,
    /// tan(vertical fov / 2).
    pub tan_half: f64,
}

impl Rig {
    /// Unit ray direction through output point (px, py) of a w×h frame.
    pub fn ray(&self, px: f64, py: f64, w: f64, h: f64) -> Vec3 {
        let sx = (px - 0.5 * w) / (0.5 * h) * self.tan_half;
        let sy = (0.5 * h - py) / (0.5 * h) * self.tan_half;
        (self.forward + self.right * sx + self.up * sy).normalized()
    }
}

impl View3d {
    /// The object for `design`.
    pub fn object(&self, design: &Design) -> Object {
        Object {
            shape: self.shape,
            aspect: f64::from(design.width) / f64::from(design.height),
            displace: self.displace,
        }
    }

    /// Distance from the camera to its target: well outside the object.
    pub fn distance(object: &Object) -> f64 {
        3.0 * object.bound() + 1.0
    }

    /// Checks the view's numbers against `design`.
    pub fn check(&self, design: &Design) -> Result<(), View3dError> {
        let side = 1..=MAX_VIEW_SIDE;
        if !side.contains(&self.width) || !side.contains(&self.height) {
            return Err(View3dError::Size(self.width, self.height));
        }
        let z = self.camera.zoom;
        if !(z.is_finite() && (0.01..=MAX_ZOOM).contains(&z)) {
            return Err(View3dError::Zoom(z));
        }
        let d = self.camera.dolly;
        if !(d.is_finite() && (MIN_DOLLY..=MAX_DOLLY).contains(&d)) {
            return Err(View3dError::Dolly(d));
        }
        let yaw_ok = self.camera.yaw.is_none_or(f64::is_finite);
        let pitch_ok = self.camera.pitch.is_none_or(|p| p.abs() < 90.0);
        if !yaw_ok || !pitch_ok {
            return Err(View3dError::Angles);
        }
        if let Some(p) = self.camera.look_at {
            let (w, h) = (f64::from(design.width), f64::from(design.height));
            let inside = p.x.is_finite()
                && p.y.is_finite()
                && (0.0..=w).contains(&p.x)
                && (0.0..=h).contains(&p.y);
            if !inside {
                return Err(View3dError::LookAt(p.x, p.y, design.width, design.height));
            }
        }
        if let Some(n) = self.texture
            && !(16..=MAX_TEXTURE_SIDE).contains(&n)
        {
            return Err(View3dError::Texture(n));
        }
        if let Some(problem) = self.displace.problem() {
            return Err(View3dError::Displace(problem));
        }
        Ok(())
    }

    /// The camera for `design`.
    pub fn rig(&self, design: &Design) -> Rig {
        self.rig_for(&self.object(design), self.surface_look_at(design))
    }

    /// This view with the camera turned `degrees` further about the vertical axis (a
    /// frame of a turn: yaw and pitch resolved for `design` first, so a camera facing
    /// its look-at point turns from there).
    pub fn turned(&self, design: &Design, degrees: f64) -> View3d {
        let object = self.object(design);
        let (yaw, pitch) = self.angles(&object, self.surface_look_at(design));
        let mut view = *self;
        view.camera.yaw = Some(yaw.to_degrees() + degrees);
        view.camera.pitch = Some(pitch.to_degrees());
        view
    }

    /// The look-at point as texture coordinates (u, v in [0, 1]).
    fn surface_look_at(&self, design: &Design) -> Option<(f64, f64)> {
        self.camera.look_at.map(|p| {
            (
                p.x / f64::from(design.width),
                p.y / f64::from(design.height),
            )
        })
    }

    /// Yaw and pitch in radians: the camera's, or facing the look-at point's normal.
    fn angles(&self, object: &Object, look_at: Option<(f64, f64)>) -> (f64, f64) {
        let normal = match look_at {
            Some((u, v)) => object.surface_point(u, v).1,
            None => Vec3::new(0.0, 0.0, 1.0),
        };
        let yaw = self
            .camera
            .yaw
            .map_or(normal.x.atan2(normal.z), f64::to_radians);
        let pitch = self
            .camera
            .pitch
            .map_or(normal.y.clamp(-1.0, 1.0).asin(), f64::to_radians)
            .clamp(-1.55, 1.55);
        (yaw, pitch)
    }

    /// The camera for `object`, centred on texture coordinates `look_at` (u, v in
    /// [0, 1]) or on the object's centre.
    pub fn rig_for(&self, object: &Object, look_at: Option<(f64, f64)>) -> Rig {
        let target = match look_at {
            Some((u, v)) => object.surface_point(u, v).0,
            None => Vec3::default(),
        };
        let (yaw, pitch) = self.angles(object, look_at);
        let dir = Vec3::new(
            yaw.sin() * pitch.cos(),
            pitch.sin(),
            yaw.cos() * pitch.cos(),
        );
        let distance = Self::distance(object);
        let origin = target + dir * (distance * self.camera.dolly);
        let forward = -dir;
        let right = forward.cross(Vec3::new(0.0, 1.0, 0.0)).normalized();
        let up = right.cross(forward);
        let (ex, ey) = object.extent();
        let margin = if self.shape == Shape::Plane {
            1.0
        } else {
            FIT_MARGIN
        };
        let fit = margin * ey.max(ex * f64::from(self.height) / f64::from(self.width));
        Rig {
            origin,
            forward,
            right,
            up,
            tan_half: fit / distance / self.camera.zoom,
        }
    }
}

/// How samples are coloured: by the exact walk or from a baked texture.
enum Source {
    Exact(Box<PointColors>),
    Texture(ImagePixels),
}

/// Renders the 3D view of `design`.
pub fn render_3d(design: &Design, view: &View3d) -> Result<RgbaImage, View3dError> {
    view.check(design)?;
    let source = match view.texture {
        None => Source::Exact(Box::new(PointColors::new(design))),
        Some(n) => {
            let scale = f64::from(n) / f64::from(design.width.max(design.height));
            let baked = render(
                design,
                &RenderOptions {
                    scale,
                    antialias: Antialias::Rgss,
                },
            )?;
            let pixels = ImagePixels::from_rgba(baked.width, baked.height, baked.pixels)
                .map_err(|_| View3dError::Texture(n))?;
            Source::Texture(pixels)
        }
    };
    let shader = Shader3d {
        object: view.object(design),
        rig: view.rig(design),
        source,
        size: (f64::from(design.width), f64::from(design.height)),
        frame: (f64::from(view.width), f64::from(view.height)),
        paper: design.background.to_linear(),
        pages: Rgb8::new(PAGES[0], PAGES[1], PAGES[2]).to_linear(),
        backdrop: BACKDROP.map(Rgb8::to_linear),
    };
    let mut image = RgbaImage::filled(view.width, view.height, [0, 0, 0, 255]);
    let row_bytes = view.width as usize * 4;
    image
        .pixels
        .par_chunks_mut(row_bytes)
        .enumerate()
        .for_each_init(PointScratch::default, |scratch, (y, row)| {
            for x in 0..view.width {
                let c = shader.pixel(x, y as u32, view.antialias, scratch);
                let e = crate::color::linear_to_srgb;
                let i = x as usize * 4;
                row[i..i + 3].copy_from_slice(&[e(c[0]), e(c[1]), e(c[2])]);
            }
        });
    Ok(image)
}

/// Source id of a ray that missed (the backdrop) and of flat-coloured faces.
const SOURCE_MISS: u32 = u32::MAX;
const SOURCE_FLAT: u32 = u32::MAX - 2;

struct Shader3d {
    object: Object,
    rig: Rig,
    source: Source,
    /// Design size.
    size: (f64, f64),
    /// Output size.
    frame: (f64, f64),
    paper: [f32; 3],
    pages: [f32; 3],
    backdrop: [[f32; 3]; 2],
}

impl Shader3d {
    /// Linear colour and source of output point (px, py).
    fn sample(&self, px: f64, py: f64, scratch: &mut PointScratch) -> ([f32; 3], u32) {
        let d = self.rig.ray(px, py, self.frame.0, self.frame.1);
        let Some(hit) = self.object.hit(self.rig.origin, d) else {
            let t = (py / self.frame.1).clamp(0.0, 1.0) as f32;
            let [top, bottom] = self.backdrop;
            return (
                std::array::from_fn(|k| top[k] + (bottom[k] - top[k]) * t),
                SOURCE_MISS,
            );
        };
        let (base, source) = match hit.material {
            shapes::Material::Design(u, v) => match &self.source {
                Source::Exact(colors) => {
                    colors.at(Point::new(u * self.size.0, v * self.size.1), scratch)
                }
                Source::Texture(px) => (
                    px.bilinear(u * f64::from(px.width), v * f64::from(px.height)),
                    SOURCE_BACKGROUND,
                ),
            },
            shapes::Material::Paper => (self.paper, SOURCE_FLAT),
            shapes::Material::Pages => (self.pages, SOURCE_FLAT),
            shapes::Material::Spine => (self.paper.map(|c| c * SPINE_SHADE), SOURCE_FLAT),
            shapes::Material::Inside => (self.paper.map(|c| c * INSIDE_SHADE), SOURCE_FLAT),
        };
        let light = AMBIENT + (1.0 - AMBIENT) * hit.normal.dot(-self.rig.forward).max(0.0);
        (base.map(|c| c * light as f32), source)
    }

    fn average(
        &self,
        x: u32,
        y: u32,
        samples: &[Sample],
        scratch: &mut PointScratch,
    ) -> ([f32; 3], bool) {
        let mut acc = [0.0f32; 3];
        let mut first = None;
        let mut mixed = false;
        for s in samples {
            let (c, src) = self.sample(f64::from(x) + s.dx, f64::from(y) + s.dy, scratch);
            for k in 0..3 {
                acc[k] += s.weight * c[k];
            }
            mixed |= *first.get_or_insert(src) != src;
        }
        (acc, mixed)
    }

    /// Linear colour of output pixel (x, y).
    fn pixel(&self, x: u32, y: u32, aa: Antialias, scratch: &mut PointScratch) -> [f32; 3] {
        let (c, mixed) = self.average(x, y, aa.samples(), scratch);
        match aa.refinement() {
            Some(fine) if mixed => self.average(x, y, fine, scratch).0,
            _ => c,
        }
    }
}
