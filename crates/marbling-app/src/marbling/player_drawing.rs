//! What the step player draws over the sheet: the tool of the step easing in, moving
//! (the comb crossing the tank, the stylus tip along its path, a drop growing), and
//! the explain view's geometry — a deformation grid pushed forward through the step (or
//! through every step up to it), displacement arrows, and the area probe.

use crate::marbling::footprint::{circle, line, polyline, screen};
use crate::marbling::view::ViewState;
use egui::{Color32, Painter, Pos2, Rect, Stroke};
use marbling_core::{Op, Point, Vec2};

/// Draws `op`'s tool `e` (0..=1) of the way through its motion on a `size` sheet.
pub fn draw_tool(
    painter: &Painter,
    rect: Rect,
    view: &ViewState,
    op: &Op,
    e: f64,
    size: (u32, u32),
) {
    let at = |p: Point| screen(rect, view, p);
    let (w, h) = (f64::from(size.0), f64::from(size.1));
    let mid = Point::new(w / 2.0, h / 2.0);
    let reach = w.hypot(h) / 2.0;
    let z = view.zoom as f32;
    // A comb whose teeth sit at `offsets` along N from `origin`, crossing the tank
    // along M: the teeth, the back joining them, each tooth's trail.
    let comb = |origin: Point, m: Vec2, offsets: &[f64]| {
        let m = m.normalize();
        let n = Vec2::new(-m.y, m.x);
        // Where the comb's back is along M: from before the tank to past it.
        let along = (mid - origin).dot(m) - reach + 2.0 * reach * e;
        let teeth: Vec<Point> = offsets
            .iter()
            .map(|o| origin + n * *o + m * along)
            .collect();
        for t in &teeth {
            line(painter, at(*t - m * (2.0 * reach * e)), at(*t));
            painter.circle_filled(at(*t), 3.0, Color32::WHITE);
        }
        if let (Some(a), Some(b)) = (teeth.first(), teeth.last()) {
            line(painter, at(*a - m * 12.0), at(*b - m * 12.0));
        }
    };
    match op {
        Op::Drop(d) => circle(painter, at(d.center), (d.radius * e) as f32 * z),
        Op::Spray(d) => circle(painter, at(d.center), (d.radius * e) as f32 * z),
        Op::Drops(s) | Op::Sprays(s) => {
            for (i, c) in s.centers.iter().enumerate().take(2_000) {
                circle(painter, at(*c), (s.radius(i) * e) as f32 * z);
            }
        }
        Op::Tine(t) => comb(t.origin, t.direction * t.alpha.signum(), &[0.0]),
        Op::Comb(c) => comb(c.origin, c.direction * c.alpha.signum(), &c.tines),
        Op::Rake(r) => {
            // The tine lines that cross the sheet.
            let m = r.direction.normalize();
            let n = Vec2::new(-m.y, m.x);
            let base = (mid - r.origin).dot(n);
            let k0 = ((base - reach) / r.spacing).floor() as i64;
            let k1 = ((base + reach) / r.spacing).ceil() as i64;
            let offsets: Vec<f64> = (k0..=k1).take(400).map(|k| k as f64 * r.spacing).collect();
            comb(r.origin, m * r.alpha.signum(), &offsets);
        }
        Op::Wavy(wv) => {
            // Teeth across the sheet, each carried along M by its sine.
            let m = Vec2::new(wv.angle.cos(), wv.angle.sin());
            let n = Vec2::new(-m.y, m.x);
            let pts: Vec<Pos2> = (0..=80)
                .map(|i| {
                    let s = -reach + 2.0 * reach * f64::from(i) / 80.0;
                    let p = mid + n * s;
                    let phase =
                        std::f64::consts::TAU * p.to_vec2().dot(n) / wv.wavelength + wv.phase;
                    at(p + m * (wv.amplitude * e * phase.sin()))
                })
                .collect();
            polyline(painter, pts);
        }
        Op::Circular(c) => {
            let a = c.alpha / c.radius * e;
            let tip = c.center + Vec2::new(a.cos(), a.sin()) * c.radius;
            circle(painter, at(c.center), c.radius as f32 * z);
            painter.circle_filled(at(tip), 4.0, Color32::WHITE);
        }
        Op::Vortex(v) => {
            let r = 2.0 * v.lambda;
            let a = std::f64::consts::TAU * e;
            painter.circle_filled(
                at(v.center + Vec2::new(a.cos(), a.sin()) * r),
                4.0,
                Color32::WHITE,
            );
            painter.circle_filled(at(v.center), 2.0, Color32::WHITE);
        }
        Op::Stylus(s) => {
            let Op::Stylus(part) = marbling_core::making::scaled(op, e) else {
                return;
            };
            polyline(painter, part.path.iter().map(|p| at(*p)).collect());
            let tip = *part.path.last().unwrap_or(&s.path[0]);
            let dir = part
                .path
                .windows(2)
                .last()
                .map_or(Vec2::new(1.0, 0.0), |w| (w[1] - w[0]).normalize());
            let n = Vec2::new(-dir.y, dir.x);
            for o in s.tips.as_deref().unwrap_or(&[0.0]) {
                painter.circle_filled(at(tip + n * *o), 4.0, Color32::WHITE);
            }
        }
        Op::Shift(sh) => line(painter, at(mid), at(mid + sh.offset * e)),
        Op::Turn(t) => {
            let a = t.angle * e;
            line(
                painter,
                at(t.center),
                at(t.center + Vec2::new(a.cos(), a.sin()) * 60.0),
            );
        }
        Op::Jiggle(j) => {
            let u = Vec2::new(j.angle.cos(), j.angle.sin());
            line(
                painter,
                at(mid - u * j.wavelength * e),
                at(mid + u * j.wavelength * e),
            );
        }
    }
}

/// Pushes `p` forward through `ops` in order.
pub fn push(ops: &[Op], p: Point) -> Point {
    ops.iter().fold(p, |p, op| op.forward(p))
}

/// A regular grid over a `size` sheet (lines `step` apart, sampled every `step/8`),
/// each line pushed forward through `ops`.
pub fn grid_lines(ops: &[Op], size: (u32, u32), step: f64) -> Vec<Vec<Point>> {
    let (w, h) = (f64::from(size.0), f64::from(size.1));
    let sample = step / 8.0;
    let mut lines = Vec::new();
    let line_along = |from: Point, to: Point| -> Vec<Point> {
        let n = ((to - from).hypot() / sample).ceil().max(1.0) as usize;
        (0..=n)
            .map(|i| push(ops, from.lerp(to, i as f64 / n as f64)))
            .collect()
    };
    let mut x = 0.0;
    while x <= w + 1e-9 {
        lines.push(line_along(Point::new(x, 0.0), Point::new(x, h)));
        x += step;
    }
    let mut y = 0.0;
    while y <= h + 1e-9 {
        lines.push(line_along(Point::new(0.0, y), Point::new(w, y)));
        y += step;
    }
    lines
}

/// The area enclosed by a closed polygon (shoelace formula), design px².
pub fn polygon_area(pts: &[Point]) -> f64 {
    let n = pts.len();
    (0..n)
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % n]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

/// A circle of `radius` around `c` as a 256-gon, and the same pushed through `ops`.
pub fn probe(ops: &[Op], c: Point, radius: f64) -> (Vec<Point>, Vec<Point>) {
    let before: Vec<Point> = (0..256)
        .map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 256.0;
            c + Vec2::new(a.cos(), a.sin()) * radius
        })
        .collect();
    let after = before.iter().map(|p| push(ops, *p)).collect();
    (before, after)
}

/// Draws the explain view's geometry: the pushed grid, arrows from a coarse grid to
/// where the step moves them, and the probe before (thin) and after (bold).
pub fn draw_explain(
    painter: &Painter,
    rect: Rect,
    view: &ViewState,
    grid: &[Vec<Point>],
    arrows: &[(Point, Point)],
    probe: &(Vec<Point>, Vec<Point>),
) {
    let at = |p: Point| screen(rect, view, p);
    let grid_stroke = Stroke::new(1.0, Color32::from_rgba_unmultiplied(20, 20, 20, 170));
    for l in grid {
        painter.add(egui::Shape::line(
            l.iter().map(|p| at(*p)).collect(),
            grid_stroke,
        ));
    }
    let arrow_stroke = Stroke::new(1.5, Color32::from_rgb(200, 30, 30));
    for (a, b) in arrows {
        let (pa, pb) = (at(*a), at(*b));
        if (pb - pa).length() < 2.0 {
            painter.circle_filled(pa, 1.5, arrow_stroke.color);
            continue;
        }
        painter.arrow(pa, pb - pa, arrow_stroke);
    }
    let (before, after) = probe;
    let closed = |pts: &[Point]| {
        let mut v: Vec<Pos2> = pts.iter().map(|p| at(*p)).collect();
        v.extend(v.first().copied());
        v
    };
    painter.add(egui::Shape::line(
        closed(before),
        Stroke::new(1.0, Color32::WHITE),
    ));
    polyline(painter, closed(after));
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{Drop, Jiggle, Rgb8, Tine};

    fn tine() -> Op {
        Op::Tine(Tine {
            origin: Point::new(0.0, 50.0),
            direction: Vec2::new(1.0, 0.0),
            alpha: 30.0,
            lambda: 6.0,
        })
    }

    /// The grid of a tine step: every node is where the tine's forward map sends the
    /// regular node (checked against the formula αλ/(d+λ), not the op's own code).
    #[test]
    fn a_tine_steps_grid_nodes_follow_the_forward_map() {
        let lines = grid_lines(&[tine()], (200, 100), 25.0);
        assert_eq!(lines.len(), 9 + 5);
        // Vertical line x = 50 (index 2), sampled every 25/8 px from y = 0.
        for (i, p) in lines[2].iter().enumerate() {
            let y = i as f64 * 25.0 / 8.0;
            let d = (y - 50.0).abs();
            let shift = 30.0 * 6.0 / (d + 6.0);
            assert!(
                (p.x - (50.0 + shift)).abs() < 1e-9 && (p.y - y).abs() < 1e-9,
                "{p:?}"
            );
        }
        // A horizontal line slides along itself: its nodes stay on it.
        assert!(lines[9 + 2].iter().all(|p| (p.y - 50.0).abs() < 1e-9));
    }

    #[test]
    fn the_probe_keeps_its_area_through_a_drop_and_a_jiggle_compresses_it() {
        let drop = Op::Drop(Drop {
            center: Point::new(40.0, 50.0),
            radius: 20.0,
            color: Rgb8::new(0, 0, 0),
        });
        let (before, after) = probe(&[drop, tine()], Point::new(70.0, 50.0), 10.0);
        let (a0, a1) = (polygon_area(&before), polygon_area(&after));
        assert!((a0 - std::f64::consts::PI * 100.0).abs() < 0.1, "{a0}");
        assert!((a1 / a0 - 1.0).abs() < 2e-3, "area changed: {a0} → {a1}");
        let jiggle = Op::Jiggle(Jiggle {
            angle: 0.0,
            wavelength: 100.0,
            along: 12.0,
            across: 0.0,
            phase: 0.0,
        });
        // At φ = 0 the Jacobian is 1 + kA = 1.754: a small probe there grows by it.
        let (b0, b1) = probe(&[jiggle], Point::new(0.0, 50.0), 1.0);
        let ratio = polygon_area(&b1) / polygon_area(&b0);
        let k = std::f64::consts::TAU / 100.0;
        assert!((ratio - (1.0 + k * 12.0)).abs() < 0.01, "{ratio}");
    }
}
