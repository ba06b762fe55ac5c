//! The lossy step: rings are pinched in two wherever two parts of the same ring come
//! closer than a width w, and pieces thinner than w on average are dropped.
//!
//! Pinching is exact: cutting a ring along a short chord i–j gives two rings whose
//! winding numbers add up to the original's everywhere (the chord is traversed once
//! each way), so the nonzero fill of the region is unchanged. Dropping is the only loss:
//! a dropped piece of twice-area |A₂| and perimeter P has mean width |A₂|/P < w, and
//! since every op is area preserving the ink (or gap) it takes away keeps its area
//! |A₂|/2 through all later ops (summed in `TraceStats::dropped_area`).

use crate::cellhash::CellMap;
use crate::curve::Curve;
use crate::reference::distance_to_segment;
use crate::ring::{Node, area2_and_perimeter};
use kurbo::Point;

/// How the lossy step judges thinness; lengths are design pixels.
#[derive(Clone, Copy, Debug)]
pub struct Pinch {
    /// Width w: parts of a ring closer than this are cut apart, pieces of mean width
    /// below it are dropped.
    pub width: f64,
    /// Two points of a ring count as "different parts" only if the ring's arc between
    /// them (the shorter way) is longer than this (≥ 4w and ≥ twice the longest chord,
    /// so neighbouring vertices and tight bends never pinch).
    pub separation: f64,
    /// Longest segment considered when looking for close parts (the refinement
    /// spacing); longer (off-canvas) segments are not searched.
    pub reach: f64,
    /// Index of the op the rings are positioned after (cuts are new source curves
    /// starting there).
    pub op: usize,
}

/// What the lossy step did.
#[derive(Clone, Copy, Debug, Default)]
pub struct PinchCount {
    /// Pieces dropped.
    pub dropped: usize,
    /// Their total area, design px².
    pub area: f64,
    /// Cuts made.
    pub cuts: usize,
}

/// Most rounds of pinching one ring's pieces again (a round cuts a non-crossing set).
const MAX_ROUNDS: u32 = 3;

impl Pinch {
    /// Pinches `ring` apart wherever it is thinner than `width`, drops thin pieces and
    /// appends the others to `out`. New cut curves are appended to `curves`.
    pub fn apply(
        &self,
        ring: Vec<Node>,
        curves: &mut Vec<Curve>,
        out: &mut Vec<Vec<Node>>,
        count: &mut PinchCount,
    ) {
        self.apply_round(ring, curves, out, count, 0);
    }

    fn apply_round(
        &self,
        ring: Vec<Node>,
        curves: &mut Vec<Curve>,
        out: &mut Vec<Vec<Node>>,
        count: &mut PinchCount,
        round: u32,
    ) {
        let cuts = if round < MAX_ROUNDS {
            self.find_cuts(&ring)
        } else {
            Vec::new()
        };
        if cuts.is_empty() {
            let (a2, per) = area2_and_perimeter(ring.iter().map(|n| n.p));
            if ring.len() < 3 || a2.abs() < self.width * per {
                count.dropped += 1;
                count.area += 0.5 * a2.abs();
            } else {
                out.push(ring);
            }
            return;
        }
        count.cuts += cuts.len();
        for piece in split(&ring, &cuts, curves, self.op) {
            self.apply_round(piece, curves, out, count, round + 1);
        }
    }

    /// A laminar (nested or disjoint, never crossing) set of cuts (i, j), i < j: vertex
    /// i lies within `width` of the segment leaving vertex j, with more than
    /// `separation` of arc between them both ways round.
    fn find_cuts(&self, ring: &[Node]) -> Vec<(usize, usize)> {
        let n = ring.len();
        if n < 4 {
            return Vec::new();
        }
        // Arc length from vertex 0 to each vertex.
        let mut arc = Vec::with_capacity(n + 1);
        arc.push(0.0);
        for i in 0..n {
            let d = (ring[(i + 1) % n].p - ring[i].p).hypot();
            arc.push(arc[i] + d);
        }
        let total = arc[n];
        if total <= 2.0 * self.separation {
            return Vec::new();
        }
        let cell = self.width + self.reach;
        let key = |p: Point| ((p.x / cell).floor() as i64, (p.y / cell).floor() as i64);
        let mut grid: CellMap<Vec<u32>> = CellMap::with_capacity_and_hasher(n, Default::default());
        for (j, node) in ring.iter().enumerate() {
            let next = ring[(j + 1) % n].p;
            if (next - node.p).hypot() <= self.reach {
                grid.entry(key(node.p)).or_default().push(j as u32);
            }
        }
        // For each start i, the furthest end j of a cut (i, j).
        let mut best: Vec<Option<usize>> = vec![None; n];
        for (i, node) in ring.iter().enumerate() {
            let (kx, ky) = key(node.p);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    let Some(bucket) = grid.get(&(kx + dx, ky + dy)) else {
                        continue;
                    };
                    for &j in bucket {
                        let j = j as usize;
                        let along = (arc[i] - arc[j]).abs();
                        if along.min(total - along) <= self.separation {
                            continue;
                        }
                        let (a, b) = (ring[j].p, ring[(j + 1) % n].p);
                        if distance_to_segment(node.p, a, b) >= self.width {
                            continue;
                        }
                        let (lo, hi) = (i.min(j), i.max(j));
                        if best[lo].is_none_or(|e| e < hi) {
                            best[lo] = Some(hi);
                        }
                    }
                }
            }
        }
        // Keep a laminar family, outermost first: sweep starts in order, keeping a
        // stack of open intervals; drop any interval that would cross one kept.
        let mut kept = Vec::new();
        let mut open: Vec<(usize, usize)> = Vec::new();
        for (a, b) in best
            .iter()
            .enumerate()
            .filter_map(|(a, b)| Some((a, (*b)?)))
        {
            while open.last().is_some_and(|&(_, e)| e <= a) {
                open.pop();
            }
            if let Some(&(oa, ob)) = open.last()
                && (b >= ob || a == oa)
            {
                continue;
            }
            open.push((a, b));
            kept.push((a, b));
        }
        kept
    }
}

/// Splits `ring` along the laminar cuts `cuts` (sorted by start, outermost first): one
/// piece inside each cut (its vertices from i to j minus those inside nested cuts,
/// closed by the chord j → i) and the remainder (closed as the ring was). Each chord is
/// a new [`Curve::Line`] in `curves`, used by both pieces it separates.
fn split(
    ring: &[Node],
    cuts: &[(usize, usize)],
    curves: &mut Vec<Curve>,
    op: usize,
) -> Vec<Vec<Node>> {
    let n = ring.len();
    let mut end_of = vec![usize::MAX; n];
    for &(a, b) in cuts {
        end_of[a] = b;
    }
    let cut_node = |from: usize, to: usize, curves: &mut Vec<Curve>| {
        let (a, b) = (ring[from].p, ring[to].p);
        curves.push(Curve::Line { a, b, op });
        Node {
            p: a,
            probe: a.midpoint(b),
            src: (curves.len() - 1) as u32,
            ta: 0.0,
            tb: 1.0,
        }
    };
    // Walks from vertex `start` (pushed as it is) to `stop`, jumping over direct
    // children; `stop == n` means the remainder, closed by vertex n − 1's own segment.
    let walk = |start: usize, stop: usize, curves: &mut Vec<Curve>| {
        let mut piece = Vec::new();
        let mut v = start;
        let mut first = true;
        while v < stop.min(n) {
            if !first && end_of[v] != usize::MAX {
                let e = end_of[v];
                piece.push(cut_node(v, e, curves));
                v = e;
                continue;
            }
            if first && stop == n && end_of[v] != usize::MAX {
                first = false;
                continue;
            }
            first = false;
            piece.push(ring[v]);
            v += 1;
        }
        if stop < n {
            piece.push(cut_node(stop, start, curves));
        }
        piece
    };
    let mut pieces = Vec::with_capacity(cuts.len() + 1);
    pieces.push(walk(0, n, curves));
    for &(a, b) in cuts {
        pieces.push(walk(a, b, curves));
    }
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ring of plain nodes (one source curve per ring, parameters by index).
    fn ring(points: &[Point]) -> Vec<Node> {
        let n = points.len();
        (0..n)
            .map(|i| Node {
                p: points[i],
                probe: points[i].midpoint(points[(i + 1) % n]),
                src: 0,
                ta: i as f64,
                tb: (i + 1) as f64,
            })
            .collect()
    }

    /// Winding number of the rings together around `p`.
    fn winding(rings: &[Vec<Node>], p: Point) -> i32 {
        let mut w = 0;
        for r in rings {
            let n = r.len();
            for i in 0..n {
                let (a, b) = (r[i].p, r[(i + 1) % n].p);
                let cross = (b - a).cross(p - a);
                if a.y <= p.y {
                    if b.y > p.y && cross > 0.0 {
                        w += 1;
                    }
                } else if b.y <= p.y && cross < 0.0 {
                    w -= 1;
                }
            }
        }
        w
    }

    /// A 10×10 square with a 40 px long tail 0.1 px wide, vertices every 0.5 px.
    fn square_with_tail() -> Vec<Point> {
        let mut pts = Vec::new();
        let mut line = |a: Point, b: Point| {
            let steps = ((b - a).hypot() / 0.5).ceil() as usize;
            for s in 0..steps {
                pts.push(a.lerp(b, s as f64 / steps as f64));
            }
        };
        line(Point::new(0.0, 0.0), Point::new(10.0, 0.0));
        line(Point::new(10.0, 0.0), Point::new(10.0, 5.0));
        line(Point::new(10.0, 5.0), Point::new(50.0, 5.0));
        line(Point::new(50.0, 5.0), Point::new(50.0, 5.1));
        line(Point::new(50.0, 5.1), Point::new(10.0, 5.1));
        line(Point::new(10.0, 5.1), Point::new(10.0, 10.0));
        line(Point::new(10.0, 10.0), Point::new(0.0, 10.0));
        line(Point::new(0.0, 10.0), Point::new(0.0, 0.0));
        pts
    }

    fn pinch() -> Pinch {
        Pinch {
            width: 0.25,
            separation: 2.0,
            reach: 1.0,
            op: 0,
        }
    }

    #[test]
    fn thin_tail_is_dropped_and_body_kept() {
        let pts = square_with_tail();
        let mut curves = vec![Curve::Line {
            a: Point::ZERO,
            b: Point::ZERO,
            op: 0,
        }];
        let (mut out, mut count) = (Vec::new(), PinchCount::default());
        pinch().apply(ring(&pts), &mut curves, &mut out, &mut count);
        assert!(count.dropped >= 1, "{count:?}");
        // The tail's area 4 px² is what went (the pieces between cuts plus slivers).
        assert!((count.area - 4.0).abs() < 0.5, "{count:?}");
        assert_eq!(out.len(), 1, "one body ring");
        // Inside the body: covered once; in the tail: no longer covered; outside: 0.
        assert_eq!(
            winding(&out, Point::new(5.0, 5.0)),
            winding(&[ring(&pts)], Point::new(5.0, 5.0))
        );
        assert_eq!(winding(&out, Point::new(30.25, 5.05)), 0);
        assert_eq!(winding(&out, Point::new(30.0, 8.0)), 0);
    }

    #[test]
    fn splitting_preserves_winding_numbers() {
        let pts = square_with_tail();
        let r = ring(&pts);
        let p = pinch();
        let cuts = p.find_cuts(&r);
        assert!(!cuts.is_empty());
        let mut curves = Vec::new();
        let pieces = split(&r, &cuts, &mut curves, 0);
        assert_eq!(pieces.len(), cuts.len() + 1);
        let total: usize = pieces.iter().map(Vec::len).sum();
        assert!(total >= r.len(), "every vertex kept");
        for q in [
            Point::new(5.0, 5.0),
            Point::new(30.25, 5.05),
            Point::new(49.9, 5.03),
            Point::new(30.0, 4.0),
            Point::new(-1.0, 3.0),
        ] {
            assert_eq!(
                winding(&pieces, q),
                winding(std::slice::from_ref(&r), q),
                "at {q:?}"
            );
        }
    }

    #[test]
    fn wide_shapes_are_not_cut() {
        let pts: Vec<Point> = (0..400)
            .map(|i| {
                let t = std::f64::consts::TAU * f64::from(i) / 400.0;
                Point::new(50.0 + 20.0 * t.cos(), 50.0 + 20.0 * t.sin())
            })
            .collect();
        assert!(pinch().find_cuts(&ring(&pts)).is_empty());
    }
}
