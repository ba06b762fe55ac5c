//! Source curves of outline segments: every vertex and probe of a traced outline is the
//! forward image of a point on one of these (exact for circles and cuts; re-anchored
//! quadratics stand in for the true outline between three exact samples).

use kurbo::{Point, Vec2};
use marbling_core::CompiledOp;

/// A parametrised curve laid down (or cut) at op `op`; its points are carried forward
/// through every later op. Lengths are design pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Curve {
    /// The rim of the drop or spray of op `op`: parameter t is the angle in radians,
    /// point = centre + radius·(cos t, sin t).
    Circle {
        /// Centre, design pixels.
        center: Point,
        /// Radius, design pixels.
        radius: f64,
        /// Index of the drop or spray.
        op: usize,
    },
    /// A straight cut made right after op `op` (where the lossy step pinched an outline
    /// in two): parameter t in [0, 1], point = a + t·(b − a) in post-op-`op` positions.
    Line {
        /// Start, design pixels after op `op`.
        a: Point,
        /// End, design pixels after op `op`.
        b: Point,
        /// Index of the op after which the cut was made.
        op: usize,
    },
    /// A quadratic Bézier from `a` (t = 0) to `b` (t = 1) with control point `c`, in
    /// positions after op `op`: an outline segment re-anchored there (the lossy
    /// shortcut that bounds how many ops a new point must be carried through).
    Quad {
        /// Start, design pixels after op `op`.
        a: Point,
        /// Control point.
        c: Point,
        /// End.
        b: Point,
        /// Index of the op after which the segment was re-anchored.
        op: usize,
    },
}

impl Curve {
    /// The quadratic through `a` (t = 0), `m` (t = 1/2) and `b` (t = 1), anchored after
    /// op `op`.
    pub fn through(a: Point, m: Point, b: Point, op: usize) -> Self {
        let c = m + (m - a.midpoint(b));
        Self::Quad { a, c, b, op }
    }

    /// The length of the parameter range (2π for a circle, 1 otherwise).
    pub fn range(&self) -> f64 {
        match self {
            Self::Circle { .. } => std::f64::consts::TAU,
            Self::Line { .. } | Self::Quad { .. } => 1.0,
        }
    }

    /// The point of parameter `t`, before any op after [`Curve::op`].
    pub fn eval(&self, t: f64) -> Point {
        match *self {
            Self::Circle { center, radius, .. } => {
                let (s, c) = t.sin_cos();
                center + Vec2::new(c, s) * radius
            }
            Self::Line { a, b, .. } => a.lerp(b, t),
            Self::Quad { a, c, b, .. } => {
                let u = 1.0 - t;
                Point::new(
                    u * u * a.x + 2.0 * u * t * c.x + t * t * b.x,
                    u * u * a.y + 2.0 * u * t * c.y + t * t * b.y,
                )
            }
        }
    }

    /// The op the curve's parameter positions belong to (they move with every later op).
    pub fn op(&self) -> usize {
        match *self {
            Self::Circle { op, .. } | Self::Line { op, .. } | Self::Quad { op, .. } => op,
        }
    }

    /// The point of parameter `t` carried forward through ops `op + 1 ..= upto` of
    /// `ops` (the whole design, compiled).
    pub fn map(&self, t: f64, ops: &[CompiledOp], upto: usize) -> Point {
        let from = self.op() + 1;
        let p = self.eval(t);
        if from > upto {
            return p;
        }
        ops[from..=upto].iter().fold(p, |p, op| op.forward(p))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_passes_through_its_three_points() {
        let (a, m, b) = (
            Point::new(0.0, 0.0),
            Point::new(2.0, 3.0),
            Point::new(5.0, 1.0),
        );
        let q = Curve::through(a, m, b, 3);
        for (t, p) in [(0.0, a), (0.5, m), (1.0, b)] {
            assert!((q.eval(t) - p).hypot() < 1e-12, "t {t}");
        }
        assert_eq!(q.op(), 3);
        // No op after op 3 up to op 3: the point stays.
        assert_eq!(q.map(0.5, &[], 3), m);
    }
}
