//! Bounded-error simplification of closed outlines: off-canvas runs collapse to chords,
//! then Ramer–Douglas–Peucker within a distance ε.

use crate::Canvas;
use crate::guard::Guard;
use crate::reference::distance_to_segment;
use kurbo::Point;

/// Replaces every run of consecutive vertices lying in one common half-plane beyond
/// `canvas` by the run's first and last vertex. The loop between a run and its chord
/// lies in that convex half-plane, so winding numbers, and hence the nonzero fill, are
/// unchanged everywhere inside `canvas`. Returns an empty outline when every vertex lies
/// in one half-plane (the region does not reach the canvas).
pub fn collapse_off_canvas(points: &[Point], canvas: &Canvas) -> Vec<Point> {
    let n = points.len();
    let masks: Vec<u8> = points.iter().map(|&p| canvas.outside_mask(p)).collect();
    if n == 0 || masks.iter().fold(0b1111, |m, &x| m & x) != 0 {
        return Vec::new();
    }
    // Start where a run cannot continue from the previous vertex, so no run wraps.
    let start = (0..n)
        .find(|&i| masks[i] & masks[(i + n - 1) % n] == 0)
        .unwrap_or(0);
    let mut out = Vec::with_capacity(n);
    // The current run: common mask, first and last index.
    let mut run: Option<(u8, usize, usize)> = None;
    let flush = |run: &mut Option<(u8, usize, usize)>, out: &mut Vec<Point>| {
        if let Some((_, first, last)) = run.take() {
            out.push(points[first]);
            if last != first {
                out.push(points[last]);
            }
        }
    };
    for k in 0..n {
        let i = (start + k) % n;
        let m = masks[i];
        match run {
            _ if m == 0 => {
                flush(&mut run, &mut out);
                out.push(points[i]);
            }
            Some((common, first, _)) if common & m != 0 => run = Some((common & m, first, i)),
            _ => {
                flush(&mut run, &mut out);
                run = Some((m, i, i));
            }
        }
    }
    flush(&mut run, &mut out);
    out
}

/// Ramer–Douglas–Peucker on a closed polygon: keeps a subset of the vertices such that
/// every removed vertex, and so every point of the original polyline, lies within
/// `epsilon` of the segment that replaced it. Returns fewer than 3 vertices only when
/// the whole outline lies within `epsilon` of one segment.
///
/// Topology guard: a chain is replaced by its chord only if no other vertex of the
/// outline lies inside the loop they form and no other edge crosses the chord, so thin
/// filaments (narrower than `epsilon`) keep both their sides instead of collapsing into
/// crossing zig-zags whose reversed loops the nonzero rule would fill.
pub fn rdp_closed(points: &[Point], epsilon: f64) -> Vec<Point> {
    rdp_closed_with(points, |_| epsilon, epsilon)
}

/// [`rdp_closed`] where vertex k may move by `slack(k)` (at most `most`): a chain is
/// replaced by its chord when every vertex k of it lies within `slack(k)` of the chord;
/// otherwise it is split at the vertex furthest beyond its slack.
pub fn rdp_closed_with(points: &[Point], slack: impl Fn(usize) -> f64, most: f64) -> Vec<Point> {
    let epsilon = most;
    let n = points.len();
    if n <= 3 {
        return points.to_vec();
    }
    let far = (1..n)
        .max_by(|&i, &j| {
            let (di, dj) = (
                (points[i] - points[0]).hypot2(),
                (points[j] - points[0]).hypot2(),
            );
            di.total_cmp(&dj)
        })
        .unwrap_or(n / 2);
    let guard = Guard::new(points, 2.0 * epsilon);
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[far] = true;
    // Chains (first, last) by index into the polygon, `last` may be n (= vertex 0).
    let mut stack = vec![(0usize, far), (far, n)];
    while let Some((a, b)) = stack.pop() {
        if b <= a + 1 {
            continue;
        }
        let (pa, pb) = (points[a], points[b % n]);
        let mut worst = (0.0, a);
        for (k, &p) in points.iter().enumerate().take(b).skip(a + 1) {
            let beyond = distance_to_segment(p, pa, pb) / slack(k);
            if beyond > worst.0 {
                worst = (beyond, k);
            }
        }
        let split = if worst.0 > 1.0 {
            Some(worst.1)
        } else if !guard.chord_is_clear(a, b) {
            Some(if worst.1 > a { worst.1 } else { (a + b) / 2 })
        } else {
            None
        };
        if let Some(k) = split {
            keep[k] = true;
            stack.push((a, k));
            stack.push((k, b));
        }
    }
    points
        .iter()
        .zip(&keep)
        .filter_map(|(&p, &k)| k.then_some(p))
        .collect()
}

/// Off-canvas collapse then RDP within `epsilon` (design pixels); an empty result means
/// the outline is invisible on the canvas (or thinner than `epsilon` everywhere).
pub fn simplify_outline(points: &[Point], canvas: &Canvas, epsilon: f64) -> Vec<Point> {
    let collapsed = collapse_off_canvas(points, canvas);
    at_least_a_triangle(rdp_closed(&collapsed, epsilon))
}

/// RDP of a closed ring whose vertices may move by `epsilon`, or by `hidden_epsilon`
/// (≥ `epsilon`) where `hidden` says newer paint covers them; empty when less than a
/// triangle is left.
pub fn simplify_ring(
    points: &[Point],
    hidden: &[bool],
    epsilon: f64,
    hidden_epsilon: f64,
) -> Vec<Point> {
    let slack = |k: usize| if hidden[k] { hidden_epsilon } else { epsilon };
    at_least_a_triangle(rdp_closed_with(points, slack, hidden_epsilon.max(epsilon)))
}

fn at_least_a_triangle(ring: Vec<Point>) -> Vec<Point> {
    if ring.len() < 3 { Vec::new() } else { ring }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle(n: usize, r: f64, c: Point) -> Vec<Point> {
        (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / n as f64;
                c + kurbo::Vec2::new(t.cos(), t.sin()) * r
            })
            .collect()
    }

    #[test]
    fn rdp_keeps_every_vertex_within_epsilon() {
        let pts = circle(4000, 100.0, Point::new(0.0, 0.0));
        let eps = 0.5;
        let s = rdp_closed(&pts, eps);
        assert!(s.len() < 100, "{} vertices", s.len());
        let worst = pts
            .iter()
            .map(|&p| {
                (0..s.len())
                    .map(|i| distance_to_segment(p, s[i], s[(i + 1) % s.len()]))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max);
        assert!(worst <= eps, "worst {worst}");
    }

    #[test]
    fn off_canvas_runs_collapse_and_outside_outlines_vanish() {
        let canvas = Canvas::new(100.0, 100.0, 0.0);
        let far = circle(500, 30.0, Point::new(-100.0, 50.0));
        assert!(collapse_off_canvas(&far, &canvas).is_empty());
        let half = circle(1000, 60.0, Point::new(0.0, 50.0));
        let c = collapse_off_canvas(&half, &canvas);
        assert!(c.len() < 400, "{}", c.len());
        assert!(c.len() > 250, "{}", c.len());
    }
}
