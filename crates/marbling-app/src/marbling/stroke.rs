//! A free-hand stroke: the pointer path simplified (Ramer–Douglas–Peucker, every
//! dropped point within a tolerance of the kept polyline) and cut into stylus ops that
//! each stay within the op's limits.

use marbling_core::{MAX_STYLUS_POINTS, MAX_STYLUS_WORK, Point, Stylus, sub_steps_of};
use std::sync::Arc;

/// `path` with points dropped while every dropped point stays within `tolerance` of
/// the polyline kept (first and last points always kept).
pub fn simplify(path: &[Point], tolerance: f64) -> Vec<Point> {
    if path.len() <= 2 {
        return path.to_vec();
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
    path.iter()
        .zip(keep)
        .filter_map(|(p, k)| k.then_some(*p))
        .collect()
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
        let kept = simplify(&path, 0.5);
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
