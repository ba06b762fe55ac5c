//! Exact adaptive refinement of one circle mapped through all later ops at once:
//! bisect the original arc wherever the mapped outline is too coarse. Tracing itself
//! goes op by op (see the crate docs); this whole-map refiner is the reference the
//! tolerance tests measure against, and provides [`distance_to_segment`].

use crate::VectorError;
use crate::canvas::Canvas;
use kurbo::{Point, Vec2};
use marbling_core::CompiledOp;
use std::f64::consts::TAU;

/// Traces the circle of `center` and `radius` forward through `ops` (oldest first).
///
/// Lengths are design pixels: `spacing` is the longest allowed mapped chord and
/// `deviation` the furthest the mapped arc midpoint may lie from it.
#[derive(Clone, Copy, Debug)]
pub struct Refiner<'a> {
    /// The ops after the one that laid the ink, oldest first, compiled.
    pub ops: &'a [CompiledOp],
    /// Centre of the original circle, design pixels.
    pub center: Point,
    /// Radius of the original circle, design pixels.
    pub radius: f64,
    /// Longest mapped chord, design pixels.
    pub spacing: f64,
    /// Furthest mapped arc midpoint from its chord, design pixels.
    pub deviation: f64,
    /// Where off-canvas relaxation applies (`None`: refine everywhere alike).
    pub canvas: Option<Canvas>,
    /// Most bisections of one initial segment.
    pub max_depth: u32,
    /// Most vertices of the refined outline.
    pub max_vertices: usize,
}

/// A refined closed outline.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Refined {
    /// Mapped vertices in order of angle on the original circle (closed polygon).
    pub points: Vec<Point>,
    /// Original-circle angle of each vertex, radians in [0, 2π).
    pub angles: Vec<f64>,
    /// Segments left coarser than required because `max_depth` was reached.
    pub capped: usize,
    /// Points mapped forward (vertices plus rejected midpoints).
    pub mapped: usize,
}

/// Distance from `p` to the segment `a`–`b`.
pub fn distance_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let ab: Vec2 = b - a;
    let len2 = ab.hypot2();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).hypot()
}

impl Refiner<'_> {
    /// The point of the original circle at angle `theta`, mapped through every op.
    pub fn map(&self, theta: f64) -> Point {
        let (s, c) = theta.sin_cos();
        let p = self.center + Vec2::new(c, s) * self.radius;
        self.ops.iter().fold(p, |p, op| op.forward(p))
    }

    /// Whether the mapped segment `a`–`b` must be split, given the mapped points `q`
    /// at a quarter, half and three quarters of its original arc.
    fn too_coarse(&self, a: Point, q: [Point; 3], b: Point) -> bool {
        let (mut spacing, mut deviation) = (self.spacing, self.deviation);
        if let Some(canvas) = &self.canvas {
            let depth = canvas.common_depth(&[a, q[0], q[1], q[2], b]);
            if depth > 0.0 {
                spacing = spacing.max(depth);
                deviation = deviation.max(depth / 2.0);
            }
        }
        (b - a).hypot() > spacing || q.iter().any(|&p| distance_to_segment(p, a, b) > deviation)
    }

    /// Starts from the regular `sides`-gon at angles 2πi/sides and refines it.
    pub fn refine(&self, sides: usize) -> Result<Refined, VectorError> {
        let sides = sides.max(3);
        let mut out = Refined::default();
        let step = TAU / sides as f64;
        let first = self.map(0.0);
        out.mapped += 1;
        let (mut ta, mut pa) = (0.0, first);
        for i in 1..=sides {
            let (tb, pb) = if i == sides {
                (TAU, first)
            } else {
                let t = step * i as f64;
                out.mapped += 1;
                (t, self.map(t))
            };
            check_finite(pb)?;
            out.points.push(pa);
            out.angles.push(ta);
            let tm = 0.5 * (ta + tb);
            let pm = self.map_checked(tm, &mut out)?;
            self.subdivide(ta, pa, tb, pb, pm, 0, &mut out)?;
            (ta, pa) = (tb, pb);
        }
        Ok(out)
    }

    fn map_checked(&self, theta: f64, out: &mut Refined) -> Result<Point, VectorError> {
        let p = self.map(theta);
        out.mapped += 1;
        check_finite(p)?;
        Ok(p)
    }

    /// Appends the refined vertices strictly between `a` and `b`, given the mapped
    /// midpoint `pm` of their original arc.
    #[allow(clippy::too_many_arguments)]
    fn subdivide(
        &self,
        ta: f64,
        pa: Point,
        tb: f64,
        pb: Point,
        pm: Point,
        depth: u32,
        out: &mut Refined,
    ) -> Result<(), VectorError> {
        let tm = 0.5 * (ta + tb);
        let q1 = self.map_checked(0.5 * (ta + tm), out)?;
        let q3 = self.map_checked(0.5 * (tm + tb), out)?;
        if !self.too_coarse(pa, [q1, pm, q3], pb) {
            return Ok(());
        }
        if out.points.len() >= self.max_vertices {
            return Err(VectorError::TooComplex {
                limit: self.max_vertices,
            });
        }
        if depth + 1 >= self.max_depth {
            out.points.push(pm);
            out.angles.push(tm);
            out.capped += 1;
            return Ok(());
        }
        self.subdivide(ta, pa, tm, pm, q1, depth + 1, out)?;
        out.points.push(pm);
        out.angles.push(tm);
        self.subdivide(tm, pm, tb, pb, q3, depth + 1, out)
    }
}

fn check_finite(p: Point) -> Result<(), VectorError> {
    if p.x.is_finite() && p.y.is_finite() {
        Ok(())
    } else {
        Err(VectorError::Untraceable(
            "an outline point maps to a non-finite position".into(),
        ))
    }
}
