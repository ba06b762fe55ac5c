//! A free-hand stroke: the pointer path simplified (Ramer–Douglas–Peucker, every
//! dropped point within a tolerance of the kept polyline) and cut into stylus ops that
//! each stay within the op's limits.

use marbling_core::{MAX_STYLUS_POINTS, MAX_STYLUS_WORK, Point, Stylus, sub_steps_of};
use std::sync::Arc;

/// The indices of the points of `path` kept while every dropped point stays within
/// `tolerance` of the polyline kept (first and last points always kept), in order.
pub fn simplify_indices(path: &[Point], tolerance: f64) -> Vec<usize> {
    if path.len() <= 2 {
        return (0..path.len()).collect();
    }
    let mut keep = vec![false; path.len()];
    keep[0] = true;
    keep[path.len() - 1] = true;
    let mut stack = vec![(0, path.len() - 1)];
    while let Some((a, b)) = stack.pop() {
        let (pa, pb) = (path[a], path[b]);
        let d = pb - pa;
        let len = d.hypot();
        let mut worst = (0.0, a);
        for (i, &p) in path.iter().enumerate().take(b).skip(a + 1) {
            let dist = if len > 0.0 {
                (p - pa).cross(d).abs() / len
            } else {
                (p - pa).hypot()
            };
            if dist > worst.0 {
                worst = (dist, i);
            }
        }
        if worst.0 > tolerance {
            keep[worst.1] = true;
            stack.push((a, worst.1));
            stack.push((worst.1, b));
        }
    }
    keep.iter()
        .enumerate()
        .filter_map(|(i, &k)| k.then_some(i))
        .collect()
}

/// Relative change of the pressure scale that starts a new stylus piece.
const PRESSURE_STEP: f64 = 0.15;

/// Stylus ops along `path` (simplified) whose wake follows the pen: `scales[i]` is the
/// pressure scale at point `i` (see `tools::pressure_scale`); the path is cut where the
/// scale has moved by more than 15 % from the piece's first new point, and each piece's ops get
/// `wake` × the mean scale of its points (pieces share their end points).
pub fn pressed_stylus_ops(
    path: &[Point],
    scales: &[f64],
    wake: f64,
    tips: Option<Arc<[f64]>>,
) -> Vec<Stylus> {
    let mut out = Vec::new();
    let mut begin = 0;
    while begin + 1 < path.len() {
        // The piece's first new point sets the scale its others stay near.
        let scale = |i: usize| scales.get(i).copied().unwrap_or(1.0);
        let first = scale(begin + 1);
        let mut end = begin + 1;
        while end + 1 < path.len() && (scale(end + 1) - first).abs() <= PRESSURE_STEP * first {
            end += 1;
        }
        let piece = &scales[begin.min(scales.len())..(end + 1).min(scales.len())];
        let mean = if piece.is_empty() {
            1.0
        } else {
            piece.iter().sum::<f64>() / piece.len() as f64
        };
        out.extend(stylus_ops(&path[begin..=end], wake * mean, tips.clone()));
        begin = end;
    }
    out
}

/// Stylus ops along `path` (already simplified): one op while it fits the limits
/// ([`MAX_STYLUS_POINTS`] points, [`MAX_STYLUS_WORK`] sub-steps × tips), otherwise
/// consecutive pieces sharing their end points. Empty when the path does not move.
pub fn stylus_ops(path: &[Point], wake: f64, tips: Option<Arc<[f64]>>) -> Vec<Stylus> {
    let tip_count = tips.as_ref().map_or(1, |t| t.len()).max(1);
    let budget = MAX_STYLUS_WORK / tip_count;
    let mut out = Vec::new();
    let mut piece = vec![path[0]];
    let mut work = 0;
    for w in path.windows(2) {
        let steps = sub_steps_of((w[1] - w[0]).hypot(), wake);
        if steps == 0 {
            continue;
        }
        if steps > budget {
            // One segment too long for an op: cut it in equal parts that fit.
            let parts = steps.div_ceil(budget.max(1));
            for k in 1..=parts {
                let p = w[0].lerp(w[1], k as f64 / parts as f64);
                push_piece(&mut out, &mut piece, &mut work, wake, &tips);
                piece.push(p);
                work = sub_steps_of((p - piece[0]).hypot(), wake);
            }
            continue;
        }
        if work + steps > budget || piece.len() >= MAX_STYLUS_POINTS {
            push_piece(&mut out, &mut piece, &mut work, wake, &tips);
        }
        piece.push(w[1]);
        work += steps;
    }
    push_piece(&mut out, &mut piece, &mut work, wake, &tips);
    out
}

/// Ends the current piece (if it moves) and starts the next at its last point.
fn push_piece(
    out: &mut Vec<Stylus>,
    piece: &mut Vec<Point>,
    work: &mut usize,
    wake: f64,
    tips: &Option<Arc<[f64]>>,
) {
    let last = *piece.last().unwrap_or(&Point::ZERO);
    if piece.len() >= 2 {
        out.push(Stylus {
            path: std::mem::take(piece).into(),
            wake,
            tips: tips.clone(),
        });
    }
    *piece = vec![last];
    *work = 0;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn simplification_keeps_every_point_within_the_tolerance() {
        let path: Vec<Point> = (0..=200)
            .map(|i| {
                let t = f64::from(i) / 200.0;
                Point::new(300.0 * t, 40.0 * (6.0 * t).sin())
            })
            .collect();
        let kept: Vec<Point> = simplify_indices(&path, 0.5)
            .into_iter()
            .map(|i| path[i])
            .collect();
        assert!(kept.len() < 60, "{}", kept.len());
        assert_eq!((kept.first(), kept.last()), (path.first(), path.last()));
        for p in &path {
            let d = kept
                .windows(2)
                .map(|w| {
                    let (a, b) = (w[0], w[1]);
                    let t = ((*p - a).dot(b - a) / (b - a).hypot2()).clamp(0.0, 1.0);
                    (*p - a.lerp(b, t)).hypot()
                })
                .fold(f64::INFINITY, f64::min);
            assert!(d <= 0.5 + 1e-9, "{p:?} is {d} from the simplified path");
        }
    }

    #[test]
    fn pen_pressure_sets_each_pieces_wake() {
        // Light for the first half, hard for the second: two pieces meeting at x = 100,
        // their wakes the set wake times the mean scale of their points.
        let path: Vec<Point> = (0..=20)
            .map(|i| Point::new(10.0 * f64::from(i), 0.0))
            .collect();
        let scales: Vec<f64> = (0..=20).map(|i| if i <= 10 { 0.5 } else { 2.0 }).collect();
        let ops = pressed_stylus_ops(&path, &scales, 6.0, None);
        assert_eq!(ops.len(), 2, "{ops:?}");
        assert_eq!(
            (ops[0].wake, ops[0].path.last()),
            (3.0, Some(&Point::new(100.0, 0.0)))
        );
        assert_eq!(
            (ops[1].path[0], ops[1].path.last()),
            (Point::new(100.0, 0.0), Some(&Point::new(200.0, 0.0)))
        );
        // 10 points at 2.0 and the shared one at 0.5.
        assert!((ops[1].wake - 6.0 * (10.0 * 2.0 + 0.5) / 11.0).abs() < 1e-12);
        // No pen: one piece at the set wake, as before.
        let plain = pressed_stylus_ops(&path, &[1.0; 21], 6.0, None);
        assert_eq!(plain, stylus_ops(&path, 6.0, None));
    }

    #[test]
    fn a_long_stroke_is_cut_into_ops_within_the_limits() {
        let path = [
            Point::new(0.0, 0.0),
            Point::new(3000.0, 0.0),
            Point::new(3000.0, 900.0),
        ];
        let ops = stylus_ops(&path, 1.0, Some(Arc::from([-5.0, 5.0])));
        assert!(ops.len() > 2);
        for s in &ops {
            assert!(s.sub_steps() * s.tip_count() <= MAX_STYLUS_WORK);
        }
        // The pieces join end to end and cover the path.
        for w in ops.windows(2) {
            assert_eq!(w[0].path.last(), w[1].path.first());
        }
        assert_eq!(ops[0].path[0], path[0]);
        assert_eq!(ops.last().and_then(|s| s.path.last()), Some(&path[2]));
        // A click without travel makes nothing.
        assert!(stylus_ops(&[Point::new(1.0, 1.0)], 4.0, None).is_empty());
    }
}
