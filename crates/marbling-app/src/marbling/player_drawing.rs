//! What the step player draws over the sheet: the tool of the step easing in, moving
//! (the comb crossing the tank, the stylus tip along its path, a drop growing), and
//! the explain view's geometry (src/marbling/explain_geometry.rs) — the deformation grid,
//! displacement arrows and the area probe.

use crate::marbling::explain_geometry::{ExplainGeometry, arrow_tip};
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
            let Op::Stylus(part) = op.scaled(e) else {
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
        Op::Flow(f) => {
            // Floating markers on a 6×4 grid, each trailing the path it has streamed.
            let field = f.field();
            for j in 0..4 {
                for i in 0..6 {
                    let start = Point::new(
                        w * (f64::from(i) + 0.5) / 6.0,
                        h * (f64::from(j) + 0.5) / 4.0,
                    );
                    let path = field.path(start, e, 24);
                    let head = *path.last().unwrap_or(&start);
                    polyline(painter, path.iter().map(|p| at(*p)).collect());
                    painter.circle_filled(at(head), 3.0, Color32::WHITE);
                }
            }
        }
    }
}

/// Draws the explain view's geometry: the pushed grid, arrows from coarse nodes toward
/// where the ops send them (at most one grid square long, with heads), and the probe
/// before (thin, white) and after (bold).
pub fn draw_explain(painter: &Painter, rect: Rect, view: &ViewState, g: &ExplainGeometry) {
    let at = |p: Point| screen(rect, view, p);
    let grid_stroke = Stroke::new(1.0, Color32::from_rgba_unmultiplied(20, 20, 20, 170));
    for l in &g.grid {
        painter.add(egui::Shape::line(
            l.iter().map(|p| at(*p)).collect(),
            grid_stroke,
        ));
    }
    let arrow_stroke = Stroke::new(1.5, Color32::from_rgb(200, 30, 30));
    for (a, b) in &g.arrows {
        let (pa, pb) = (at(*a), at(arrow_tip(*a, *b, g.spacing)));
        let v = pb - pa;
        let len = v.length();
        if len < 2.0 {
            painter.circle_filled(pa, 1.5, arrow_stroke.color);
            continue;
        }
        // A head of fixed size (at most half the arrow), readable on a projector.
        let head = (len / 2.0).min(7.0);
        let back = -v / len * head;
        let side = egui::vec2(-back.y, back.x) * 0.5;
        painter.line_segment([pa, pb], arrow_stroke);
        painter.add(egui::Shape::convex_polygon(
            vec![pb, pb + back + side, pb + back - side],
            arrow_stroke.color,
            Stroke::NONE,
        ));
    }
    let (before, after) = &g.probe;
    painter.add(egui::Shape::line(
        before.iter().map(|p| at(*p)).collect(),
        Stroke::new(1.0, Color32::WHITE),
    ));
    for piece in after {
        polyline(painter, piece.iter().map(|p| at(*p)).collect());
    }
}
