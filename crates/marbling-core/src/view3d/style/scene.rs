//! What the style passes know of a frame: for every pixel (one ray through its centre)
//! whether the object shows there, how far away and how lit; the projection of surface
//! points to the screen; the design faces cut into patches that carry the marks' and
//! fibres' anchors.

use super::super::{Object, Rig, Shape, View3d, shapes::Material, vec3::Vec3};
use crate::Design;
use crate::walk::Walker;
use std::f64::consts::PI;

/// A frame's per-pixel facts and its camera.
pub(super) struct Scene {
    pub object: Object,
    pub rig: Rig,
    pub width: u32,
    pub height: u32,
    /// Per pixel: distance along the ray to the object, +∞ where the backdrop shows.
    pub depth: Vec<f32>,
    /// Per pixel: the headlight's cosine max(n·(−forward), 0), 0 on the backdrop.
    pub light: Vec<f32>,
    /// Per pixel: texture coordinates of a design face (NaN elsewhere).
    pub uv: Vec<[f32; 2]>,
    /// Screen pixels per object unit at the camera's target distance at zoom 1 (what
    /// texture-space anchoring fixes its mark sizes to).
    pub reference_scale: f64,
    /// Design width and height, pixels (texture coordinates × these: design points).
    pub design_size: (f64, f64),
    /// The design's walk, for marks that follow its stretch (`None` when none do).
    pub walker: Option<Walker>,
}

impl Scene {
    /// Casts one ray through every pixel centre of `view`.
    pub fn new(design: &Design, view: &View3d) -> Self {
        let object = view.object(design);
        let rig = view.rig(design);
        let (w, h) = (f64::from(view.width), f64::from(view.height));
        let rows: Vec<Vec<(f32, f32, [f32; 2])>> = map_range(view.height as usize, |y| {
            let y = y as u32;
            (0..view.width)
                .map(|x| {
                    let d = rig.ray(f64::from(x) + 0.5, f64::from(y) + 0.5, w, h);
                    match object.hit(rig.origin, d) {
                        None => (f32::INFINITY, 0.0, [f32::NAN; 2]),
                        Some(hit) => {
                            let light = hit.normal.dot(-rig.forward).max(0.0) as f32;
                            let uv = match hit.material {
                                Material::Design(u, v) => [u as f32, v as f32],
                                _ => [f32::NAN; 2],
                            };
                            (hit.t as f32, light, uv)
                        }
                    }
                })
                .collect()
        });
        let n = (view.width * view.height) as usize;
        let (mut depth, mut light, mut uv) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for (d, l, t) in rows.into_iter().flatten() {
            depth.push(d);
            light.push(l);
            uv.push(t);
        }
        let tan_zoom1 = rig.tan_half * view.camera.zoom;
        let reference_scale = 0.5 * h / (tan_zoom1 * View3d::distance(&object));
        Self {
            object,
            rig,
            width: view.width,
            height: view.height,
            depth,
            light,
            uv,
            reference_scale,
            design_size: (f64::from(design.width), f64::from(design.height)),
            walker: None,
        }
    }

    /// Screen position (x right, y down, pixels) and distance from the camera of `p`;
    /// `None` behind the camera.
    pub fn project(&self, p: Vec3) -> Option<(f64, f64, f64)> {
        let v = p - self.rig.origin;
        let z = v.dot(self.rig.forward);
        if z <= 1e-9 {
            return None;
        }
        let k = 0.5 * f64::from(self.height) / (z * self.rig.tan_half);
        Some((
            0.5 * f64::from(self.width) + v.dot(self.rig.right) * k,
            0.5 * f64::from(self.height) - v.dot(self.rig.up) * k,
            v.length(),
        ))
    }

    /// Index of the pixel holding screen point (x, y), if it is in the frame.
    pub fn pixel(&self, x: f64, y: f64) -> Option<usize> {
        let inside =
            x >= 0.0 && y >= 0.0 && x < f64::from(self.width) && y < f64::from(self.height);
        inside.then(|| y as usize * self.width as usize + x as usize)
    }

    /// Object units per screen pixel at distance `t` from the camera.
    pub fn world_per_pixel(&self, t: f64) -> f64 {
        2.0 * self.rig.tan_half * t / f64::from(self.height)
    }

    /// True when a surface point at distance `t` projecting to (x, y) is what the frame
    /// shows there: its pixel shows the object within `tolerance` of `t`.
    pub fn shows(&self, x: f64, y: f64, t: f64, tolerance: f64) -> bool {
        self.pixel(x, y)
            .is_some_and(|i| (f64::from(self.depth[i]) - t).abs() <= tolerance)
    }
}

/// `f` of 0..n in order, on every core off the web; in order on one thread in wasm, where
/// rayon's machinery would only add to the module's size.
pub(super) fn map_range<T: Send>(n: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        use rayon::prelude::*;
        (0..n).into_par_iter().map(f).collect()
    }
    #[cfg(target_arch = "wasm32")]
    {
        (0..n).map(f).collect()
    }
}

/// A design face: the one face of most shapes, and the book's back cover.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Face {
    Front,
    Back,
}

/// The faces of `shape` that show the design.
pub(super) fn faces(shape: Shape) -> &'static [Face] {
    if shape == Shape::Book {
        &[Face::Front, Face::Back]
    } else {
        &[Face::Front]
    }
}

/// The (displaced) point and outward normal of `face` at texture coordinates (u, v).
pub(super) fn face_point(object: &Object, face: Face, u: f64, v: f64) -> (Vec3, Vec3) {
    let (p, n) = match face {
        Face::Front => object.surface_point(u, v),
        Face::Back => (
            Vec3::new(
                (1.0 - 2.0 * u) * object.aspect,
                1.0 - 2.0 * v,
                -super::super::BOOK_DEPTH,
            ),
            Vec3::new(0.0, 0.0, -1.0),
        ),
    };
    if object.displace.is_active() {
        object.displace.moved(p, n)
    } else {
        (p, n)
    }
}

/// Patches per face along u and v: cells of about equal size on the object.
pub(super) fn grid(shape: Shape, aspect: f64) -> (u32, u32) {
    match shape {
        Shape::Sphere | Shape::Vase => (32, 16),
        Shape::Cylinder => (32, (32.0 / aspect).ceil().clamp(4.0, 64.0) as u32),
        Shape::Plane | Shape::Book => {
            let across = (16.0 * aspect).ceil().clamp(4.0, 64.0) as u32;
            (across, 16)
        }
    }
}

/// World extent of a face's u and v (the uv square's lengths on the object), for
/// texture-space anchoring.
pub(super) fn uv_extent(shape: Shape, aspect: f64) -> (f64, f64) {
    match shape {
        Shape::Sphere => (2.0 * PI, PI),
        Shape::Cylinder => (2.0 * PI, 2.0 * PI / aspect),
        Shape::Vase => (2.0 * PI * 0.45, 2.0),
        Shape::Plane | Shape::Book => (2.0 * aspect, 2.0),
    }
}

/// A rectangle [u0, u1] × [v0, v1] of a face's texture coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Patch {
    pub face: Face,
    pub u: [f64; 2],
    pub v: [f64; 2],
    /// A number naming the patch (face, level and cell), seeding its random stream.
    pub id: u32,
}

/// What a patch looks like on screen.
pub(super) struct Projected {
    /// Screen area of the quad of its projected corners, pixels² (0 when back-facing
    /// at its centre or partly behind the camera).
    pub area: f64,
    /// Whether its screen box meets the frame.
    pub on_screen: bool,
}

impl Patch {
    /// Point (s, t) ∈ [0, 1]² of the patch in texture coordinates; on the sphere t is
    /// spaced by area (cos φ uniform), so uniform (s, t) cover the patch's area
    /// uniformly.
    pub fn at(&self, shape: Shape, s: f64, t: f64) -> (f64, f64) {
        let u = self.u[0] + s * (self.u[1] - self.u[0]);
        let v = if shape == Shape::Sphere {
            let (c0, c1) = ((self.v[0] * PI).cos(), (self.v[1] * PI).cos());
            (c0 + t * (c1 - c0)).clamp(-1.0, 1.0).acos() / PI
        } else {
            self.v[0] + t * (self.v[1] - self.v[0])
        };
        (u, v)
    }

    /// Its four sub-patches (Kaplan & Cohen's 1→4 split).
    pub fn split(&self) -> [Patch; 4] {
        let (um, vm) = (0.5 * (self.u[0] + self.u[1]), 0.5 * (self.v[0] + self.v[1]));
        let child = |k: u32, u: [f64; 2], v: [f64; 2]| Patch {
            face: self.face,
            u,
            v,
            id: marbling_noise::hash::pcg_hash(self.id.wrapping_mul(4).wrapping_add(k + 1)),
        };
        [
            child(0, [self.u[0], um], [self.v[0], vm]),
            child(1, [um, self.u[1]], [self.v[0], vm]),
            child(2, [self.u[0], um], [vm, self.v[1]]),
            child(3, [um, self.u[1]], [vm, self.v[1]]),
        ]
    }

    /// Its screen area and whether it faces the camera.
    pub fn project(&self, scene: &Scene) -> Projected {
        let object = &scene.object;
        let (uc, vc) = (0.5 * (self.u[0] + self.u[1]), 0.5 * (self.v[0] + self.v[1]));
        let (centre, normal) = face_point(object, self.face, uc, vc);
        let back = normal.dot(centre - scene.rig.origin) >= 0.0;
        let corners = [
            (self.u[0], self.v[0]),
            (self.u[1], self.v[0]),
            (self.u[1], self.v[1]),
            (self.u[0], self.v[1]),
        ]
        .map(|(u, v)| scene.project(face_point(object, self.face, u, v).0));
        let mut area = 0.0;
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for k in 0..4 {
            let (Some(a), Some(b)) = (corners[k], corners[(k + 1) % 4]) else {
                return Projected {
                    area: 0.0,
                    on_screen: false,
                };
            };
            area += a.0 * b.1 - b.0 * a.1;
            lo = [lo[0].min(a.0), lo[1].min(a.1)];
            hi = [hi[0].max(a.0), hi[1].max(a.1)];
        }
        let on_screen = hi[0] >= 0.0
            && hi[1] >= 0.0
            && lo[0] <= f64::from(scene.width)
            && lo[1] <= f64::from(scene.height);
        Projected {
            area: if back { 0.0 } else { 0.5 * area.abs() },
            on_screen,
        }
    }
}

/// The patches of every design face of `object` at the base level.
pub(super) fn base_patches(object: &Object) -> Vec<Patch> {
    let (nu, nv) = grid(object.shape, object.aspect);
    let mut out = Vec::with_capacity((nu * nv) as usize * faces(object.shape).len());
    for (f, &face) in faces(object.shape).iter().enumerate() {
        for j in 0..nv {
            for i in 0..nu {
                let cell = (f as u32 * nv + j) * nu + i;
                out.push(Patch {
                    face,
                    u: [
                        f64::from(i) / f64::from(nu),
                        f64::from(i + 1) / f64::from(nu),
                    ],
                    v: [
                        f64::from(j) / f64::from(nv),
                        f64::from(j + 1) / f64::from(nv),
                    ],
                    id: marbling_noise::hash::pcg_hash(cell ^ 0x5EED_0000),
                });
            }
        }
    }
    out
}
