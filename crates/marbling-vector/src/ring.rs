//! A traced ring: a closed polygon whose every vertex and segment probe is the exact
//! forward image of a point on a source [`Curve`], carried op by op and refined where
//! the current op stretched or bent it beyond the tolerance.

use crate::canvas::Canvas;
use crate::curve::Curve;
use crate::reference::distance_to_segment;
use kurbo::Point;
use marbling_core::CompiledOp;

/// One vertex and the segment leaving it (towards the next node of the ring).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// The vertex, design pixels after the current op.
    pub p: Point,
    /// The segment's midpoint on its source curve (parameter (ta + tb)/2), carried
    /// forward like `p`: how far it lies from the chord measures the segment's bend.
    pub probe: Point,
    /// Index of the segment's source curve in the region's curve list.
    pub src: u32,
    /// Parameter of the segment's start on the source curve.
    pub ta: f64,
    /// Parameter of the segment's end on the source curve.
    pub tb: f64,
}

/// How finely rings are refined; lengths are design pixels.
#[derive(Clone, Copy, Debug)]
pub struct Refine<'a> {
    /// Every op of the design, compiled.
    pub ops: &'a [CompiledOp],
    /// Longest chord on the canvas.
    pub spacing: f64,
    /// Furthest a segment's probe may lie from its chord on the canvas.
    pub deviation: f64,
    /// Beyond this enlarged canvas, chords may be as long as their distance from it
    /// (`None`: refine everywhere alike).
    pub canvas: Option<Canvas>,
    /// Smallest parameter interval that is still bisected, as a fraction of the
    /// source curve's whole range (2^−max_depth of an initial segment).
    pub min_fraction: f64,
}

/// What refinement did, summed over rings.
#[derive(Clone, Copy, Debug, Default)]
pub struct RefineCount {
    /// Segments left too coarse because their parameter interval reached the minimum.
    pub capped: usize,
    /// Pairs of segments merged back into one.
    pub merged: usize,
    /// Points carried forward from their source curve through many ops (new vertices'
    /// probes).
    pub mapped: usize,
}

impl Refine<'_> {
    /// Whether the segment `a`–`b` with probe `m` must be split.
    fn too_coarse(&self, a: Point, m: Point, b: Point) -> bool {
        self.exceeds(a, &[m], b, 1.0)
    }

    /// Whether the chord `a`–`b` is longer than `factor` times the spacing or one of
    /// `inner` lies further than `factor` times the deviation from it (both relaxed off
    /// the canvas).
    fn exceeds(&self, a: Point, inner: &[Point], b: Point, factor: f64) -> bool {
        let ab = b - a;
        let len2 = ab.hypot2();
        let within = |spacing: f64, deviation: f64| {
            let (s, d) = (factor * spacing, factor * deviation);
            len2 <= s * s && inner.iter().all(|&m| near_segment(m, a, ab, len2, d))
        };
        // The canvas only relaxes the limits: test the strict ones first.
        if within(self.spacing, self.deviation) {
            return false;
        }
        let Some(canvas) = &self.canvas else {
            return true;
        };
        let k = inner.len().min(3);
        let mut pts = [a; 5];
        pts[1] = b;
        pts[2..2 + k].copy_from_slice(&inner[..k]);
        let depth = canvas.common_depth(&pts[..2 + k]);
        depth <= 0.0 || !within(self.spacing.max(depth), self.deviation.max(depth / 2.0))
    }

    /// The two nodes `a`, `b` (consecutive, `b` ending at `c`) as one node, when they
    /// are the halves of one source interval and together are well within the limits
    /// (half of them, so that merging and splitting do not alternate).
    fn merge(&self, a: &Node, b: &Node, c: Point) -> Option<Node> {
        let (wa, wb) = (a.tb - a.ta, b.tb - b.ta);
        let halves = a.src == b.src && a.tb == b.ta && (wa - wb).abs() <= 1e-9 * wa.abs();
        if !halves || self.exceeds(a.p, &[a.probe, b.p, b.probe], c, 0.5) {
            return None;
        }
        Some(Node {
            p: a.p,
            probe: b.p,
            src: a.src,
            ta: a.ta,
            tb: b.tb,
        })
    }

    /// A node for the source-curve interval `ta..tb` starting at `p`, its probe mapped
    /// through ops up to `upto`.
    fn node(&self, curves: &[Curve], src: u32, ta: f64, tb: f64, p: Point, upto: usize) -> Node {
        let probe = curves[src as usize].map(0.5 * (ta + tb), self.ops, upto);
        Node {
            p,
            probe,
            src,
            ta,
            tb,
        }
    }

    /// Appends `node` to `out`, bisecting its segment (ending at `end`) until every
    /// piece is fine enough after op `upto`.
    fn push_refined(
        &self,
        curves: &[Curve],
        node: Node,
        end: Point,
        upto: usize,
        out: &mut Vec<Node>,
        count: &mut RefineCount,
    ) {
        if !self.too_coarse(node.p, node.probe, end) {
            out.push(node);
            return;
        }
        let range = curves[node.src as usize].range();
        if (node.tb - node.ta).abs() <= range * self.min_fraction {
            count.capped += 1;
            out.push(node);
            return;
        }
        let tm = 0.5 * (node.ta + node.tb);
        let left = self.node(curves, node.src, node.ta, tm, node.p, upto);
        let right = self.node(curves, node.src, tm, node.tb, node.probe, upto);
        count.mapped += 2;
        self.push_refined(curves, left, right.p, upto, out, count);
        self.push_refined(curves, right, end, upto, out, count);
    }

    /// Refines `ring` (already carried through op `upto`) so that every segment is fine
    /// enough; returns the refined ring.
    pub fn refine(
        &self,
        curves: &[Curve],
        ring: &[Node],
        upto: usize,
        count: &mut RefineCount,
    ) -> Vec<Node> {
        let n = ring.len();
        let mut out = Vec::with_capacity(n + n / 8 + 4);
        // Merging is tried every fourth op: contraction is slow, stretching is not.
        let try_merge = upto.is_multiple_of(4);
        let mut i = 0;
        while i < n {
            if try_merge
                && n > 4
                && i + 1 < n
                && let Some(merged) = self.merge(&ring[i], &ring[i + 1], ring[(i + 2) % n].p)
            {
                out.push(merged);
                count.merged += 1;
                i += 2;
                continue;
            }
            let end = ring[(i + 1) % n].p;
            self.push_refined(curves, ring[i], end, upto, &mut out, count);
            i += 1;
        }
        out
    }
}

/// Whether `m` lies within `d` of the segment from `a` along `ab` (`len2` = |ab|²):
/// without square roots when `m` projects inside the segment.
#[inline]
fn near_segment(m: Point, a: Point, ab: kurbo::Vec2, len2: f64, d: f64) -> bool {
    let am = m - a;
    let t = am.dot(ab);
    if len2 > 0.0 && (0.0..=len2).contains(&t) {
        let c = ab.cross(am);
        c * c <= d * d * len2
    } else {
        distance_to_segment(m, a, a + ab) <= d
    }
}

/// Carries every vertex and probe of `ring` through `op`.
pub fn carry(ring: &mut [Node], op: &CompiledOp) {
    for node in ring {
        node.p = op.forward(node.p);
        node.probe = op.forward(node.probe);
    }
}

/// The regular `sides`-gon on the rim of curve `src` (a circle laid by op `op`, no
/// later op applied yet), with probes at the mid-angles.
pub fn initial_ring(curve: &Curve, src: u32, sides: usize) -> Vec<Node> {
    let sides = sides.max(3);
    let step = std::f64::consts::TAU / sides as f64;
    (0..sides)
        .map(|i| {
            let (ta, tb) = (step * i as f64, step * (i + 1) as f64);
            Node {
                p: curve.eval(ta),
                probe: curve.eval(0.5 * (ta + tb)),
                src,
                ta,
                tb,
            }
        })
        .collect()
}

/// Twice the signed area (shoelace) and the perimeter of a closed polygon.
pub fn area2_and_perimeter(points: impl Iterator<Item = Point> + Clone) -> (f64, f64) {
    let mut it = points.clone();
    let Some(first) = it.next() else {
        return (0.0, 0.0);
    };
    let (mut a2, mut per, mut prev) = (0.0, 0.0, first);
    for p in it.chain(std::iter::once(first)) {
        a2 += prev.x * p.y - p.x * prev.y;
        per += (p - prev).hypot();
        prev = p;
    }
    (a2, per)
}

/// Re-anchors every segment of `rings` after op `op`: its source becomes the quadratic
/// through its start, probe and end ([`Curve::through`]), so later refinement carries
/// new points through the ops after `op` only. Returns the new curve list.
pub fn reanchor(rings: &mut [Vec<Node>], op: usize) -> Vec<Curve> {
    let mut curves = Vec::with_capacity(rings.iter().map(Vec::len).sum());
    for ring in rings {
        let n = ring.len();
        for i in 0..n {
            let next = ring[(i + 1) % n].p;
            let node = &mut ring[i];
            curves.push(Curve::through(node.p, node.probe, next, op));
            node.src = (curves.len() - 1) as u32;
            node.ta = 0.0;
            node.tb = 1.0;
        }
    }
    curves
}
