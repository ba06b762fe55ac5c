//! Perlin displacement of the 3D view's objects (Kung 2019, ch. 3): every surface point p
//! moves along its normal n to p′ = p + s·noise((p + o)·f)·n, the noise Perlin fBm
//! ([`marbling_noise::fbm3`]), and the displaced surface's normal comes from finite
//! differences as in the paper: displace p + ε·t and p + ε·b the same way and take
//! n′ = normalize((P_t − P) × (P_b − P)). The design stays attached to the surface: a
//! sample's design point is the texture coordinate of its undisplaced p.
//!
//! A ray meets the displaced object by a march: the object is a solid g(x) ≤ 0 whose
//! design faces are moved out by the height h = s·noise at their foot point (for the
//! vase, whose side is not a height field along the radius, the radial gap times the
//! profile's cosine: the distance to first order in the slope), marched in
//! [`DISPLACE_STEPS`] steps through the box or upright cylinder holding it (grown by
//! s·[`PERLIN3_BOUND`]) and refined by bisection. Features thinner than a step (1/192
//! of the ray's span there) can be missed. The plane, a sheet with no inside, is met where z − h
//! changes sign over it; the book's gap is that of the cover on the point's side of
//! the book. The height is read once per march sample, so the WGSL twin stays one call
//! of the noise per loop (its compile time on software GPUs grows with the calls). Keep in sync with `view3d.wgsl` in marbling-gpu.

use super::shapes::{BOOK_DEPTH, Hit, Material, Object, Shape, VASE_BOUND, around, vase_radius};
use super::vec3::Vec3;
use marbling_noise::{PERLIN3_BOUND, fbm3};
use std::f64::consts::PI;
use std::ops::RangeInclusive;

/// Range of the amplitude s, object units (the sphere's radius is 1; the paper sweeps
/// 0–0.5).
pub const AMOUNT: RangeInclusive<f64> = 0.0..=0.5;
/// Range of the frequency f, lattice cells per object unit (the paper sweeps 0–6).
pub const FREQUENCY: RangeInclusive<f64> = 0.0..=12.0;
/// Range of the fBm's octaves (the paper: one).
pub const OCTAVES: RangeInclusive<u32> = 1..=6;
/// Range of the fBm's lacunarity (frequency ratio of successive octaves).
pub const LACUNARITY: RangeInclusive<f64> = 1.0..=4.0;
/// Range of the fBm's persistence (amplitude ratio of successive octaves).
pub const PERSISTENCE: RangeInclusive<f64> = 0.0..=1.0;
/// Seed of the displacement noise.
pub const SEED: u32 = 3;
/// Steps of the march through the grown bounding sphere.
pub const DISPLACE_STEPS: u32 = 192;
/// What the march's bounding volume adds to the object's extent besides the reach,
/// object units.
pub const BOUND_MARGIN: f64 = 1e-3;
/// Bisection steps refining a displaced hit.
pub const DISPLACE_BISECTIONS: u32 = 24;
/// The finite-difference step ε of the displaced normal, object units (the paper's
/// 0.01 on its unit objects; a tenth of it for our higher frequencies).
pub const NORMAL_STEP: f64 = 1e-3;

/// A Perlin displacement; amount or frequency 0 leaves the object as it is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Displace {
    /// Amplitude s, object units, in [`AMOUNT`].
    pub amount: f64,
    /// Frequency f, lattice cells per object unit, in [`FREQUENCY`].
    pub frequency: f64,
    /// Octaves of the fBm, in [`OCTAVES`].
    pub octaves: u32,
    /// Lacunarity of the fBm, in [`LACUNARITY`].
    pub lacunarity: f64,
    /// Persistence of the fBm, in [`PERSISTENCE`].
    pub persistence: f64,
    /// Offset o added before scaling (animating it makes the surface flow), object units.
    pub offset: [f64; 3],
}

impl Default for Displace {
    fn default() -> Self {
        Self {
            amount: 0.0,
            frequency: 2.0,
            octaves: 1,
            lacunarity: 2.0,
            persistence: 0.5,
            offset: [0.0; 3],
        }
    }
}

impl Displace {
    /// True when the surface moves (amount and frequency both non-zero).
    pub fn is_active(&self) -> bool {
        self.amount != 0.0 && self.frequency != 0.0
    }

    /// What is out of range, as a message naming the field, or `None`.
    pub fn problem(&self) -> Option<String> {
        let number = |name: &str, v: f64, r: &RangeInclusive<f64>| {
            let ok = v.is_finite() && r.contains(&v);
            (!ok).then(|| {
                format!(
                    "displace {name} must be a number from {} to {}, got {v}",
                    r.start(),
                    r.end()
                )
            })
        };
        let octaves = (!OCTAVES.contains(&self.octaves)).then(|| {
            format!(
                "displace octaves must be {} to {}, got {}",
                OCTAVES.start(),
                OCTAVES.end(),
                self.octaves
            )
        });
        let offset = (!self.offset.iter().all(|c| c.is_finite() && c.abs() <= 1e6))
            .then(|| "displace offset must be finite (at most 1e6)".to_owned());
        number("amount", self.amount, &AMOUNT)
            .or_else(|| number("frequency", self.frequency, &FREQUENCY))
            .or(octaves)
            .or_else(|| number("lacunarity", self.lacunarity, &LACUNARITY))
            .or_else(|| number("persistence", self.persistence, &PERSISTENCE))
            .or(offset)
    }

    /// The height h(p) = s·fbm((p + o)·f) of surface point p, object units;
    /// |h| ≤ s·[`PERLIN3_BOUND`].
    pub fn height(&self, p: Vec3) -> f64 {
        let f = self.frequency;
        let q = [
            ((p.x + self.offset[0]) * f) as f32,
            ((p.y + self.offset[1]) * f) as f32,
            ((p.z + self.offset[2]) * f) as f32,
        ];
        let n = fbm3(
            q,
            self.octaves,
            self.lacunarity as f32,
            self.persistence as f32,
            SEED,
        );
        self.amount * f64::from(n)
    }

    /// The farthest any point moves: s·[`PERLIN3_BOUND`].
    pub fn reach(&self) -> f64 {
        self.amount.abs() * f64::from(PERLIN3_BOUND)
    }

    /// The displaced point p + h(p)·n and the paper's finite-difference normal there.
    pub fn moved(&self, p: Vec3, n: Vec3) -> (Vec3, Vec3) {
        let t = {
            let t = n.cross(Vec3::new(0.0, 1.0, 0.0));
            if t.length() < 1e-6 {
                Vec3::new(1.0, 0.0, 0.0)
            } else {
                t.normalized()
            }
        };
        let b = n.cross(t);
        let at = |q: Vec3| q + n * self.height(q);
        let p0 = at(p);
        let pt = at(p + t * NORMAL_STEP);
        let pb = at(p + b * NORMAL_STEP);
        let m = (pt - p0).cross(pb - p0).normalized();
        (p0, if m.dot(n) < 0.0 { -m } else { m })
    }
}

/// Which face of a displaced solid is nearest the surface at a point.
#[derive(Clone, Copy, Debug)]
enum Face {
    /// A design face: its undisplaced foot point, unit normal and texture coordinates.
    Design {
        foot: Vec3,
        normal: Vec3,
        uv: (f64, f64),
    },
    /// A face left flat (caps, pages, spine): its material and normal.
    Flat(Material, Vec3),
}

/// The larger of two (gap, face) pairs: the face of an intersection of solids.
fn outer(a: (f64, Face), b: (f64, Face)) -> (f64, Face) {
    if b.0 > a.0 { b } else { a }
}

/// True where the gap changes sign between two samples, both on the object's span
/// (the plane's gap is infinite off its rectangle).
fn crossing(a: f64, b: f64) -> bool {
    a.is_finite() && b.is_finite() && (a > 0.0) != (b > 0.0)
}

/// A lathe's side at x: the radial gap, the radial foot on `radius` at x's height, and
/// the normal of a profile of `slope`.
fn lathe(x: Vec3, radius: f64, slope: f64) -> (f64, Vec3, Vec3) {
    let rho = (x.x * x.x + x.z * x.z).sqrt();
    let (sx, sz) = if rho > 1e-12 {
        (x.x / rho, x.z / rho)
    } else {
        (0.0, 1.0)
    };
    let foot = Vec3::new(radius * sx, x.y, radius * sz);
    let normal = Vec3::new(sx, -slope, sz).normalized();
    (rho - radius, foot, normal)
}

impl Object {
    /// The displaced object's gap at x (≤ 0 inside, about a distance near the surface;
    /// for the plane, z − h over its rectangle and +∞ off it) and the face it belongs
    /// to. The design face's height is read once: the book shows the cover on x's side.
    fn displaced_gap(&self, x: Vec3) -> (f64, Face) {
        let a = self.aspect;
        let (y_axis, z_axis) = (Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, 0.0, 1.0));
        // The design face before the displacement: (gap, foot, normal, uv), and the
        // flat faces it is intersected with.
        let (gap, foot, normal, uv, flat) = match self.shape {
            Shape::Sphere => {
                let r = x.length().max(1e-12);
                let foot = x * (1.0 / r);
                let uv = (around(foot), foot.y.clamp(-1.0, 1.0).acos() / PI);
                (r - 1.0, foot, foot, uv, None)
            }
            Shape::Cylinder => {
                let h = self.cylinder_half_height();
                let (gap, foot, normal) = lathe(x, 1.0, 0.0);
                let uv = (around(foot), (h - foot.y) / (2.0 * h));
                let cap = Face::Flat(Material::Paper, y_axis * x.y.signum());
                (gap, foot, normal, uv, Some((x.y.abs() - h, cap)))
            }
            Shape::Vase => {
                let y = x.y.clamp(-1.0, 1.0);
                let slope = (vase_radius(y + 1e-4) - vase_radius(y - 1e-4)) / 2e-4;
                let (gap, foot, normal) = lathe(x, vase_radius(y), slope);
                let cosine = 1.0 / (1.0 + slope * slope).sqrt();
                let lid = if x.y > 0.0 {
                    Face::Flat(Material::Inside, y_axis)
                } else {
                    Face::Flat(Material::Paper, -y_axis)
                };
                let uv = (around(foot), (1.0 - y) / 2.0);
                (gap * cosine, foot, normal, uv, Some((x.y.abs() - 1.0, lid)))
            }
            Shape::Book => {
                let side = if x.z >= 0.0 { 1.0 } else { -1.0 };
                let foot = Vec3::new(x.x, x.y, side * BOOK_DEPTH);
                // The back cover shows the design mirrored (a wrap-around cover).
                let u = (side * x.x + a) / (2.0 * a);
                let edge = if x.x < 0.0 {
                    Material::Spine
                } else {
                    Material::Pages
                };
                let flat = outer(
                    (
                        x.x.abs() - a,
                        Face::Flat(edge, Vec3::new(x.x.signum(), 0.0, 0.0)),
                    ),
                    (
                        x.y.abs() - 1.0,
                        Face::Flat(Material::Pages, y_axis * x.y.signum()),
                    ),
                );
                let uv = (u, (1.0 - x.y) / 2.0);
                (side * x.z - BOOK_DEPTH, foot, z_axis * side, uv, Some(flat))
            }
            Shape::Plane => {
                let foot = Vec3::new(x.x, x.y, 0.0);
                let on = x.x.abs() <= a && x.y.abs() <= 1.0;
                let gap = if on { x.z } else { f64::INFINITY };
                let uv = ((x.x + a) / (2.0 * a), (1.0 - x.y) / 2.0);
                (gap, foot, z_axis, uv, None)
            }
        };
        let design = (
            gap - self.displace.height(foot),
            Face::Design { foot, normal, uv },
        );
        match flat {
            Some(flat) => outer(design, flat),
            None => design,
        }
    }

    /// The span (t0, t1) of the ray from `o` along unit `d` inside the box or upright
    /// cylinder that holds the displaced object: its undisplaced extent grown by
    /// [`Displace::reach`] + [`BOUND_MARGIN`] (the margin keeps the first sample off
    /// a flat face).
    fn march_span(&self, o: Vec3, d: Vec3) -> Option<(f64, f64)> {
        let grow = self.displace.reach() + BOUND_MARGIN;
        let (mut t0, mut t1) = (0.0_f64, f64::INFINITY);
        let mut slab = |o: f64, d: f64, half: f64| {
            if d == 0.0 {
                return o.abs() <= half;
            }
            let (a, b) = ((-half - o) / d, (half - o) / d);
            t0 = t0.max(a.min(b));
            t1 = t1.min(a.max(b));
            true
        };
        let inside = match self.shape {
            Shape::Sphere => {
                let r = 1.0 + grow;
                let b = o.dot(d);
                let disc = b * b - (o.dot(o) - r * r);
                disc >= 0.0 && slab(b, 1.0, disc.sqrt())
            }
            Shape::Cylinder | Shape::Vase => {
                let (r, h) = if self.shape == Shape::Vase {
                    (VASE_BOUND, 1.0)
                } else {
                    (1.0, self.cylinder_half_height())
                };
                let r = r + grow;
                let (a, b) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z);
                let disc = b * b - a * (o.x * o.x + o.z * o.z - r * r);
                let round = if a > 0.0 {
                    disc >= 0.0 && slab(b / a, 1.0, disc.sqrt() / a)
                } else {
                    o.x * o.x + o.z * o.z <= r * r
                };
                round && slab(o.y, d.y, h + BOUND_MARGIN)
            }
            Shape::Book | Shape::Plane => {
                let depth = if self.shape == Shape::Book {
                    BOOK_DEPTH
                } else {
                    0.0
                };
                slab(o.x, d.x, self.aspect + BOUND_MARGIN)
                    && slab(o.y, d.y, 1.0 + BOUND_MARGIN)
                    && slab(o.z, d.z, depth + grow)
            }
        };
        (inside && t0 < t1).then_some((t0, t1))
    }

    /// The first hit of the ray from `o` along unit `d` on the displaced object: the
    /// first sign change of the gap along the march, refined by bisection.
    pub(super) fn displaced_hit(&self, o: Vec3, d: Vec3) -> Option<Hit> {
        let (t0, t1) = self.march_span(o, d)?;
        let step = (t1 - t0) / f64::from(DISPLACE_STEPS);
        let mut prev = self.displaced_gap(o + d * t0).0;
        for i in 1..=DISPLACE_STEPS {
            let t = t0 + step * f64::from(i);
            let now = self.displaced_gap(o + d * t);
            if !crossing(prev, now.0) {
                prev = now.0;
                continue;
            }
            let (mut lo, mut hi, mut at_hi) = (t - step, t, now);
            for _ in 0..DISPLACE_BISECTIONS {
                let mid = 0.5 * (lo + hi);
                let g = self.displaced_gap(o + d * mid);
                if g.0.is_finite() && (g.0 > 0.0) == (prev > 0.0) {
                    lo = mid;
                } else {
                    (hi, at_hi) = (mid, g);
                }
            }
            return Some(match at_hi.1 {
                Face::Design { foot, normal, uv } => Hit {
                    t: hi,
                    normal: self.displace.moved(foot, normal).1,
                    material: Material::Design(uv.0, uv.1),
                },
                Face::Flat(material, normal) => Hit {
                    t: hi,
                    normal,
                    material,
                },
            });
        }
        None
    }
}
