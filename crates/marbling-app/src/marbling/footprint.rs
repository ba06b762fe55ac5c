//! Tool footprints drawn over the canvas: where a click or drag will act, before and
//! while it happens.

use crate::marbling::drop_patterns::DropPattern;
use crate::marbling::editor::Editor;
use crate::marbling::tools::ToolKind;
use crate::marbling::view::ViewState;
use crate::store::prefs::Prefs;
use egui::{Color32, Painter, Pos2, Rect, Shape, Stroke};
use marbling_core::{Point, Vec2};

const LIGHT: Color32 = Color32::from_rgba_premultiplied(255, 255, 255, 220);
const DARK: Color32 = Color32::from_rgba_premultiplied(0, 0, 0, 160);

pub(crate) fn screen(rect: Rect, view: &ViewState, p: Point) -> Pos2 {
    let s = view.to_screen(p);
    rect.min + egui::vec2(s[0] as f32, s[1] as f32)
}

/// A line visible on light and dark inks alike.
pub(crate) fn line(painter: &Painter, a: Pos2, b: Pos2) {
    painter.line_segment([a, b], Stroke::new(3.0, DARK));
    painter.line_segment([a, b], Stroke::new(1.2, LIGHT));
}

pub(crate) fn circle(painter: &Painter, c: Pos2, r: f32) {
    painter.circle_stroke(c, r, Stroke::new(3.0, DARK));
    painter.circle_stroke(c, r, Stroke::new(1.2, LIGHT));
}

pub(crate) fn polyline(painter: &Painter, pts: Vec<Pos2>) {
    painter.add(Shape::line(pts.clone(), Stroke::new(3.0, DARK)));
    painter.add(Shape::line(pts, Stroke::new(1.2, LIGHT)));
}

/// Draws the current tool's footprint: the active gesture's, or at the pointer.
pub fn draw(
    painter: &Painter,
    rect: Rect,
    view: &ViewState,
    editor: &Editor,
    prefs: &Prefs,
    pointer: Option<Point>,
) {
    let s = &prefs.settings;
    let (tool, a, b, held) = match &editor.active {
        Some(g) => (
            g.tool,
            g.gesture.start,
            g.gesture.end(),
            g.gesture.held_seconds,
        ),
        None => match pointer {
            Some(p) => (prefs.tool, p, p, 0.0),
            None => return,
        },
    };
    let z = view.zoom as f32;
    let at = |p: Point| screen(rect, view, p);
    let dragging = editor.active.is_some();
    let drag = b - a;
    // Direction of motion: the drag, or (hovering) to the right.
    let m = if drag.hypot() >= 1.0 {
        drag.normalize()
    } else {
        Vec2::new(1.0, 0.0)
    };
    let n = Vec2::new(-m.y, m.x);
    let reach = f64::from(rect.width().hypot(rect.height())) / view.zoom;
    match tool {
        ToolKind::Drop => {
            let r = crate::marbling::tools::drop_radius(s, held) as f32 * z;
            if s.drop_pattern == DropPattern::Single {
                circle(painter, at(a), r);
            } else {
                // Ghost drops: exactly where the click lays them (same seed).
                let seed = editor.active.as_ref().map_or(editor.next_seed, |g| g.seed);
                for c in crate::marbling::tools::drop_centers(s, a, b, seed) {
                    circle(painter, at(c), r.max(1.5));
                }
            }
        }
        ToolKind::Stylus => {
            let reach = (marbling_core::WAKE_REACH * s.stylus_wake) as f32 * z;
            let tips = crate::marbling::tools::stylus_tips(s);
            let offsets: Vec<f64> = tips.as_deref().map_or(vec![0.0], <[f64]>::to_vec);
            // The tips sit across the direction of travel (the last stretch of the path).
            let dir = editor
                .active
                .as_ref()
                .and_then(|g| {
                    let p = &g.gesture.path;
                    p.iter()
                        .rev()
                        .find(|q| (b - **q).hypot() >= 2.0 / view.zoom)
                        .map(|q| (b - *q).normalize())
                })
                .unwrap_or(Vec2::new(1.0, 0.0));
            let across = Vec2::new(-dir.y, dir.x);
            for o in offsets {
                circle(painter, at(b + across * o), reach.max(3.0));
            }
            if let Some(g) = &editor.active {
                polyline(painter, g.gesture.path.iter().map(|p| at(*p)).collect());
            }
        }
        ToolKind::Jiggle => {
            // The wave of motion across the drag: A along it, B across.
            let steps = 400;
            let k = std::f64::consts::TAU / s.jiggle_wavelength.max(1.0);
            let pts =
                (0..=steps)
                    .map(|i| {
                        let t = (f64::from(i) / f64::from(steps) * 2.0 - 1.0) * reach;
                        let phi = k * t;
                        at(a + m * (t + s.jiggle_along * phi.sin())
                            + n * (s.jiggle_across * phi.cos()))
                    })
                    .collect();
            polyline(painter, pts);
            if dragging {
                arrow(painter, at(a), at(b));
            }
        }
        ToolKind::Shift => {
            if dragging {
                arrow(painter, at(a), at(b));
            } else {
                for d in [
                    Vec2::new(1.0, 0.0),
                    Vec2::new(-1.0, 0.0),
                    Vec2::new(0.0, 1.0),
                    Vec2::new(0.0, -1.0),
                ] {
                    arrow(painter, at(a), at(a + d * (18.0 / view.zoom)));
                }
            }
        }
        ToolKind::Spray => circle(painter, at(b), s.spray_spread as f32 * z),
        ToolKind::Tine => {
            line(painter, at(a - m * reach), at(a + m * reach));
            if dragging {
                arrow(painter, at(a), at(b));
            }
        }
        ToolKind::Comb => {
            let offsets: Vec<f64> = if s.comb_tines == 0 {
                // Whole-sheet rake: while dragging, every tine in view; hovering, a few.
                let k = if dragging {
                    ((reach / s.comb_spacing).ceil() as i64).min(300)
                } else {
                    4
                };
                (-k..=k).map(|i| i as f64 * s.comb_spacing).collect()
            } else {
                let half = f64::from(s.comb_tines - 1) / 2.0;
                (0..s.comb_tines)
                    .map(|i| (f64::from(i) - half) * s.comb_spacing)
                    .collect()
            };
            let len = if dragging { reach } else { 20.0 / view.zoom };
            for o in offsets {
                let base = a + n * o;
                line(painter, at(base - m * len), at(base + m * len));
            }
            if dragging {
                arrow(painter, at(a), at(b));
            }
        }
        ToolKind::Wavy => {
            let steps = 400;
            let pts = (0..=steps)
                .map(|i| {
                    let t = (f64::from(i) / f64::from(steps) * 2.0 - 1.0) * reach;
                    let phase = std::f64::consts::TAU * t / s.wavy_wavelength + s.wavy_phase;
                    at(a + n * t + m * (s.wavy_amplitude * phase.sin()))
                })
                .collect();
            polyline(painter, pts);
        }
        ToolKind::Flow => {
            if dragging {
                // Markers streaming as far as the flow released now would take them.
                let design = editor.history.design();
                let flow = marbling_core::Op::Flow(crate::marbling::tools::flow(s, drag.hypot()));
                let size = (design.width, design.height);
                crate::marbling::player_drawing::draw_tool(painter, rect, view, &flow, 1.0, size);
                arrow(painter, at(a), at(b));
            } else {
                // The noise's feature size.
                circle(painter, at(a), (0.5 * s.flow_size) as f32 * z);
            }
        }
        ToolKind::Turn => {
            circle(painter, at(a), 4.0);
            if dragging {
                let r = (b - a).hypot() as f32 * z;
                circle(painter, at(a), r.max(4.0));
                line(painter, at(a), at(b));
            } else {
                circle(painter, at(a), 40.0);
            }
        }
        ToolKind::Circular | ToolKind::Vortex => {
            let r = if dragging {
                editor.active.as_ref().map_or(0.0, |g| {
                    g.gesture
                        .path
                        .iter()
                        .map(|p| (*p - a).hypot())
                        .fold(0.0, f64::max)
                })
            } else {
                80.0
            };
            circle(painter, at(a), (r as f32 * z).max(4.0));
            if tool == ToolKind::Vortex {
                circle(painter, at(a), (r as f32 * z * 0.5).max(2.0));
            }
            if dragging {
                line(painter, at(a), at(b));
            }
        }
    }
}

fn arrow(painter: &Painter, from: Pos2, to: Pos2) {
    let d = to - from;
    if d.length() < 2.0 {
        return;
    }
    line(painter, from, to);
    let dir = d.normalized();
    let side = egui::vec2(-dir.y, dir.x);
    line(painter, to, to - dir * 10.0 + side * 5.0);
    line(painter, to, to - dir * 10.0 - side * 5.0);
}
