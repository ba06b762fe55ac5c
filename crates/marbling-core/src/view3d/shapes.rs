//! The objects of the 3D view and where a ray meets them (keep in sync with
//! `view3d.wgsl` in marbling-gpu).
//!
//! Every object is centred on the origin, y up, facing +z at yaw 0, and carries the
//! design through texture coordinates (u, v) ∈ [0, 1]², design point (u·W, v·H):
//! - **plane**: the rectangle |x| ≤ a, |y| ≤ 1 at z = 0 (a = W/H), u = (x + a)/2a,
//!   v = (1 − y)/2, seen from both sides;
//! - **sphere**: radius 1, u = ½ + atan2(x, z)/2π, v = acos(y)/π;
//! - **cylinder**: radius 1, |y| ≤ π/a (so the design is not stretched), u as the
//!   sphere, v = (h − y)/2h; caps of paper colour;
//! - **vase**: the lathe of [`vase_radius`] for |y| ≤ 1, u as the sphere,
//!   v = (1 − y)/2; a paper-coloured base and a dark opening;
//! - **book**: the box |x| ≤ a, |y| ≤ 1, |z| ≤ [`BOOK_DEPTH`]; the design on the front
//!   cover and (mirrored, as a wrap-around cover) on the back, pages on three sides
//!   and a spine on the left.

use super::displace::Displace;
use super::vec3::Vec3;
use std::f64::consts::PI;

/// Half the thickness of the book.
pub const BOOK_DEPTH: f64 = 0.18;
/// Radius of the vase's bounding cylinder (≥ [`vase_radius`] everywhere).
pub const VASE_BOUND: f64 = 0.65;
/// Steps of the march along a ray through the vase's bounding cylinder.
pub const VASE_STEPS: u32 = 96;
/// Bisection steps refining a vase hit (the hit is within 2⁻²⁴ of a step).
pub const VASE_BISECTIONS: u32 = 24;
/// Colour of the book's pages, sRGB.
pub const PAGES: [u8; 3] = [0xef, 0xe8, 0xd8];

/// The objects the design can be shown on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Shape {
    /// A sphere (equirectangular mapping).
    Sphere,
    /// A vase (a lathe profile), the paper's figure 7.
    #[default]
    Vase,
    /// An upright cylinder.
    Cylinder,
    /// A book with the design as its cover.
    Book,
    /// A flat sheet.
    Plane,
}

impl Shape {
    /// Every shape, in the order shown to users.
    pub const ALL: [Shape; 5] = [
        Shape::Sphere,
        Shape::Vase,
        Shape::Cylinder,
        Shape::Book,
        Shape::Plane,
    ];

    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Shape::Sphere => "sphere",
            Shape::Vase => "vase",
            Shape::Cylinder => "cylinder",
            Shape::Book => "book",
            Shape::Plane => "plane",
        }
    }

    /// The shape called `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// Index shared with the WGSL (`shape` in its uniform).
    pub fn code(self) -> u32 {
        match self {
            Shape::Sphere => 0,
            Shape::Vase => 1,
            Shape::Cylinder => 2,
            Shape::Book => 3,
            Shape::Plane => 4,
        }
    }
}

/// The vase's radius at height y ∈ [−1, 1]: a base of 0.31, a belly of 0.6 at
/// y = −0.25, a neck of 0.3 and a lip flaring to 0.4.
pub fn vase_radius(y: f64) -> f64 {
    let belly = (-((y + 0.25) / 0.42).powi(2)).exp();
    let t = ((y - 0.55) / 0.45).clamp(0.0, 1.0);
    0.30 + 0.30 * belly + 0.10 * t * t * (3.0 - 2.0 * t)
}

/// What a ray meets.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// The design at texture coordinates (u, v).
    Design(f64, f64),
    /// The paper colour (caps, the vase's base).
    Paper,
    /// The book's pages.
    Pages,
    /// The book's spine (the paper colour, darker).
    Spine,
    /// The inside of the vase (the paper colour, much darker).
    Inside,
}

/// A ray's first hit: distance along the (unit) ray, unit normal facing the ray, what
/// it met.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Distance from the ray's origin.
    pub t: f64,
    /// Unit normal, facing the ray's origin.
    pub normal: Vec3,
    /// What was hit.
    pub material: Material,
}

/// A shape sized for a design of aspect `a` = W/H.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Object {
    /// Which shape.
    pub shape: Shape,
    /// Design width / height.
    pub aspect: f64,
    /// The Perlin displacement of its design faces (none by default).
    pub displace: Displace,
}

/// The texture coordinate u of a point about the vertical axis.
pub(super) fn around(p: Vec3) -> f64 {
    0.5 + p.x.atan2(p.z) / (2.0 * PI)
}

impl Object {
    /// Half the cylinder's height: π/a.
    pub fn cylinder_half_height(&self) -> f64 {
        PI / self.aspect
    }

    /// Half-width and half-height of the object seen head-on at yaw 0 (what zoom 1
    /// fits into the frame).
    pub fn extent(&self) -> (f64, f64) {
        match self.shape {
            Shape::Plane | Shape::Book => (self.aspect, 1.0),
            Shape::Sphere => (1.0, 1.0),
            Shape::Cylinder => (1.0, self.cylinder_half_height()),
            Shape::Vase => (VASE_BOUND, 1.0),
        }
    }

    /// Radius of a sphere about the origin holding the object.
    /// (The undisplaced object's: a displacement adds [`Displace::reach`].)
    pub fn bound(&self) -> f64 {
        let (ex, ey) = self.extent();
        (ex * ex + ey * ey + BOOK_DEPTH * BOOK_DEPTH)
            .sqrt()
            .max(1.0)
    }

    /// The point and outward normal carrying texture coordinates (u, v) (on the front
    /// cover for the book).
    pub fn surface_point(&self, u: f64, v: f64) -> (Vec3, Vec3) {
        let theta = (u - 0.5) * 2.0 * PI;
        match self.shape {
            Shape::Plane | Shape::Book => {
                let z = if self.shape == Shape::Book {
                    BOOK_DEPTH
                } else {
                    0.0
                };
                let p = Vec3::new((2.0 * u - 1.0) * self.aspect, 1.0 - 2.0 * v, z);
                (p, Vec3::new(0.0, 0.0, 1.0))
            }
            Shape::Sphere => {
                let phi = v.clamp(0.0, 1.0) * PI;
                let p = Vec3::new(phi.sin() * theta.sin(), phi.cos(), phi.sin() * theta.cos());
                (p, p)
            }
            Shape::Cylinder => {
                let h = self.cylinder_half_height();
                let p = Vec3::new(theta.sin(), h - 2.0 * v * h, theta.cos());
                (p, Vec3::new(theta.sin(), 0.0, theta.cos()))
            }
            Shape::Vase => {
                let y = 1.0 - 2.0 * v;
                let r = vase_radius(y);
                let slope = (vase_radius(y + 1e-4) - vase_radius(y - 1e-4)) / 2e-4;
                let p = Vec3::new(r * theta.sin(), y, r * theta.cos());
                let n = Vec3::new(theta.sin(), -slope, theta.cos()).normalized();
                (p, n)
            }
        }
    }

    /// The first hit of the ray from `o` along unit `d`, if any.
    pub fn hit(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        let hit = match self.shape {
            _ if self.displace.is_active() => self.displaced_hit(o, d),
            Shape::Plane => self.plane(o, d),
            Shape::Sphere => sphere(o, d),
            Shape::Cylinder => self.cylinder(o, d),
            Shape::Vase => vase(o, d),
            Shape::Book => self.book(o, d),
        }?;
        let normal = if hit.normal.dot(d) > 0.0 {
            -hit.normal
        } else {
            hit.normal
        };
        Some(Hit { normal, ..hit })
    }

    fn plane(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        if d.z == 0.0 {
            return None;
        }
        let t = -o.z / d.z;
        let p = o + d * t;
        (t > 0.0 && p.x.abs() <= self.aspect && p.y.abs() <= 1.0).then(|| Hit {
            t,
            normal: Vec3::new(0.0, 0.0, 1.0),
            material: Material::Design(
                (p.x + self.aspect) / (2.0 * self.aspect),
                (1.0 - p.y) / 2.0,
            ),
        })
    }

    fn cylinder(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        let h = self.cylinder_half_height();
        let mut best: Option<Hit> = None;
        let (a, b, c) = (
            d.x * d.x + d.z * d.z,
            o.x * d.x + o.z * d.z,
            o.x * o.x + o.z * o.z - 1.0,
        );
        let disc = b * b - a * c;
        if a > 0.0 && disc >= 0.0 {
            for t in [(-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a] {
                let p = o + d * t;
                if t > 0.0 && p.y.abs() <= h {
                    best = Some(Hit {
                        t,
                        normal: Vec3::new(p.x, 0.0, p.z),
                        material: Material::Design(around(p), (h - p.y) / (2.0 * h)),
                    });
                    break;
                }
            }
        }
        for (y, material) in [(h, Material::Paper), (-h, Material::Paper)] {
            best = nearer(best, cap(o, d, y, 1.0, material));
        }
        best
    }

    fn book(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        let half = [self.aspect, 1.0, BOOK_DEPTH];
        let (os, ds) = ([o.x, o.y, o.z], [d.x, d.y, d.z]);
        let (mut near, mut far, mut axis) = (f64::NEG_INFINITY, f64::INFINITY, 0);
        for k in 0..3 {
            if ds[k] == 0.0 {
                if os[k].abs() > half[k] {
                    return None;
                }
                continue;
            }
            let (t0, t1) = ((-half[k] - os[k]) / ds[k], (half[k] - os[k]) / ds[k]);
            let (lo, hi) = (t0.min(t1), t0.max(t1));
            if lo > near {
                (near, axis) = (lo, k);
            }
            far = far.min(hi);
        }
        if near > far || near <= 0.0 {
            return None;
        }
        let p = o + d * near;
        let a = self.aspect;
        let (normal, material) = match axis {
            2 if p.z > 0.0 => (
                Vec3::new(0.0, 0.0, 1.0),
                Material::Design((p.x + a) / (2.0 * a), (1.0 - p.y) / 2.0),
            ),
            2 => (
                Vec3::new(0.0, 0.0, -1.0),
                Material::Design((a - p.x) / (2.0 * a), (1.0 - p.y) / 2.0),
            ),
            0 if p.x < 0.0 => (Vec3::new(-1.0, 0.0, 0.0), Material::Spine),
            0 => (Vec3::new(1.0, 0.0, 0.0), Material::Pages),
            _ => (Vec3::new(0.0, p.y.signum(), 0.0), Material::Pages),
        };
        Some(Hit {
            t: near,
            normal,
            material,
        })
    }
}

fn nearer(a: Option<Hit>, b: Option<Hit>) -> Option<Hit> {
    match (a, b) {
        (Some(a), Some(b)) => Some(if b.t < a.t { b } else { a }),
        (a, b) => a.or(b),
    }
}

/// The disc of `radius` at height `y`.
fn cap(o: Vec3, d: Vec3, y: f64, radius: f64, material: Material) -> Option<Hit> {
    if d.y == 0.0 {
        return None;
    }
    let t = (y - o.y) / d.y;
    let p = o + d * t;
    (t > 0.0 && p.x * p.x + p.z * p.z <= radius * radius).then_some(Hit {
        t,
        normal: Vec3::new(0.0, y.signum(), 0.0),
        material,
    })
}

fn sphere(o: Vec3, d: Vec3) -> Option<Hit> {
    let b = o.dot(d);
    let disc = b * b - (o.dot(o) - 1.0);
    if disc < 0.0 {
        return None;
    }
    let t = [-b - disc.sqrt(), -b + disc.sqrt()]
        .into_iter()
        .find(|&t| t > 0.0)?;
    let p = o + d * t;
    Some(Hit {
        t,
        normal: p,
        material: Material::Design(around(p), p.y.clamp(-1.0, 1.0).acos() / PI),
    })
}

/// Signed distance (radially) of `p` outside the vase's side.
fn vase_gap(p: Vec3) -> f64 {
    (p.x * p.x + p.z * p.z).sqrt() - vase_radius(p.y)
}

fn vase(o: Vec3, d: Vec3) -> Option<Hit> {
    // The ray's span inside the bounding cylinder and the slab |y| ≤ 1.
    let (a, b, c) = (
        d.x * d.x + d.z * d.z,
        o.x * d.x + o.z * d.z,
        o.x * o.x + o.z * o.z - VASE_BOUND * VASE_BOUND,
    );
    let disc = b * b - a * c;
    if a <= 0.0 || disc < 0.0 {
        return None;
    }
    let (mut t0, mut t1) = ((-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a);
    if d.y != 0.0 {
        let (s0, s1) = ((-1.0 - o.y) / d.y, (1.0 - o.y) / d.y);
        t0 = t0.max(s0.min(s1));
        t1 = t1.min(s0.max(s1));
    } else if o.y.abs() > 1.0 {
        return None;
    }
    t0 = t0.max(0.0);
    let mut side = None;
    if t0 < t1 {
        let step = (t1 - t0) / f64::from(VASE_STEPS);
        let mut prev = t0;
        let mut outside = vase_gap(o + d * t0) > 0.0;
        for i in 1..=VASE_STEPS {
            let t = t0 + step * f64::from(i);
            let now = vase_gap(o + d * t) > 0.0;
            if outside && !now {
                let (mut lo, mut hi) = (prev, t);
                for _ in 0..VASE_BISECTIONS {
                    let mid = 0.5 * (lo + hi);
                    if vase_gap(o + d * mid) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let p = o + d * hi;
                let slope = (vase_radius(p.y + 1e-4) - vase_radius(p.y - 1e-4)) / 2e-4;
                let rho = (p.x * p.x + p.z * p.z).sqrt().max(1e-12);
                side = Some(Hit {
                    t: hi,
                    normal: Vec3::new(p.x / rho, -slope, p.z / rho).normalized(),
                    material: Material::Design(around(p), (1.0 - p.y) / 2.0),
                });
                break;
            }
            (prev, outside) = (t, now);
        }
    }
    let top = cap(o, d, 1.0, vase_radius(1.0), Material::Inside);
    let base = cap(o, d, -1.0, vase_radius(-1.0), Material::Paper);
    nearer(nearer(side, top), base)
}
