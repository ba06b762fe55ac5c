//! The step player's bar under the canvas: step back, play/pause, step forward, a
//! timeline with a tick per step (click or drag to scrub), speed, the step's caption,
//! and the explain view (the step's formulas with their numbers, the deformation grid,
//! arrows and the area probe, drawn by src/marbling/player_drawing.rs).

use crate::action::Action;
use crate::app::MarblingApp;
use crate::marbling::player_drawing;
use egui::{Color32, RichText, Sense, Slider, Stroke, vec2};
use marbling_core::{Design, Point};

/// The explain view's settings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Explain {
    /// Formulas, grid, arrows and probe shown.
    pub on: bool,
    /// The grid pushed through every step up to the current one (else that step alone).
    pub cumulative: bool,
    /// The probe circle (centre, radius), design px; `None`: centred on the sheet.
    pub probe: Option<(Point, f64)>,
}

impl Explain {
    /// The probe circle on `design`.
    pub fn probe_circle(&self, design: &Design) -> (Point, f64) {
        self.probe.unwrap_or_else(|| {
            let (w, h) = (f64::from(design.width), f64::from(design.height));
            (Point::new(w / 2.0, h / 2.0), w.min(h) / 10.0)
        })
    }
}

/// The explain view's geometry for what the player shows now.
pub struct ExplainGeometry {
    /// Grid lines pushed forward.
    pub grid: Vec<Vec<Point>>,
    /// Coarse grid nodes and where the step moves them.
    pub arrows: Vec<(Point, Point)>,
    /// The probe before and after.
    pub probe: (Vec<Point>, Vec<Point>),
}

/// Most point-op evaluations the explain geometry may cost in a frame; denser work
/// thins the grid.
const EXPLAIN_WORK: f64 = 4.0e6;

impl MarblingApp {
    /// The player's bar (shown while the player is open).
    pub(crate) fn player_bar(&mut self, ui: &mut egui::Ui) {
        let Some(p) = self.editor.playback else {
            return;
        };
        let design = self.editor.history.design_shared().clone();
        let steps = design.gesture_sizes().len();
        let captions = design.step_captions();
        let mut seek = None;
        ui.add_space(2.0);
        if self.panels.layout.touch() {
            crate::shell::layout::touch_spacing(ui);
        }
        // Wrapped: on a phone the bar's controls take two rows.
        ui.horizontal_wrapped(|ui| {
            let back = ui.button("◀ Step").on_hover_text("Step back");
            self.control("player-back", &back);
            if back.clicked() {
                let to = if p.t > 0.0 {
                    p.step
                } else {
                    p.step.saturating_sub(1)
                };
                seek = Some((to as f64, false));
            }
            let playing = p.playing;
            let play = ui
                .add_sized(
                    [52.0, 20.0],
                    egui::Button::new(if playing { "Pause" } else { "Play" }),
                )
                .on_hover_text("Play from here, or pause");
            self.control("player-play", &play);
            if play.clicked() {
                let from = if p.step >= steps { 0.0 } else { p.position() };
                seek = Some((from, !playing));
            }
            let fwd = ui.button("Step ▶").on_hover_text("Step forward");
            self.control("player-forward", &fwd);
            if fwd.clicked() {
                seek = Some(((p.step + 1).min(steps) as f64, false));
            }
            let width = (ui.available_width() - 8.0).max(60.0);
            let (rect, r) = ui.allocate_exact_size(vec2(width, 22.0), Sense::click_and_drag());
            self.control("player-timeline", &r);
            let x_of = |pos: f64| rect.left() + (pos / steps.max(1) as f64) as f32 * rect.width();
            let painter = ui.painter();
            let y = rect.center().y;
            painter.line_segment(
                [egui::pos2(rect.left(), y), egui::pos2(rect.right(), y)],
                Stroke::new(2.0, Color32::from_gray(110)),
            );
            for k in 0..=steps {
                let x = x_of(k as f64);
                painter.line_segment(
                    [egui::pos2(x, y - 6.0), egui::pos2(x, y + 6.0)],
                    Stroke::new(1.0, Color32::from_gray(170)),
                );
            }
            painter.circle_filled(egui::pos2(x_of(p.position()), y), 6.0, Color32::WHITE);
            if let Some(at) = r
                .interact_pointer_pos()
                .filter(|_| r.clicked() || r.dragged())
            {
                let raw = f64::from((at.x - rect.left()) / rect.width()) * steps as f64;
                // Within 6 points of a tick means that step exactly.
                let near = raw.round();
                let snapped = if (x_of(near) - at.x).abs() <= 6.0 {
                    near
                } else {
                    raw
                };
                seek = Some((snapped, false));
            }
        });
        ui.horizontal(|ui| {
            let speed = ui.add(
                Slider::new(&mut self.editor.play_speed, 0.1..=4.0)
                    .logarithmic(true)
                    .text("steps/s"),
            );
            self.control("player-speed", &speed);
            let explain = ui.selectable_label(self.editor.explain.on, "Explain");
            self.control("player-explain", &explain);
            if explain.clicked() {
                self.editor.explain.on = !self.editor.explain.on;
            }
            let recording = self.panels.recorder.is_some();
            let record = ui
                .selectable_label(
                    recording,
                    if recording {
                        "Stop recording"
                    } else {
                        "Record"
                    },
                )
                .on_hover_text("Film the making from the first step to a WebM video");
            self.control("player-record", &record);
            if record.clicked() {
                if recording {
                    self.finish_recording();
                } else {
                    match crate::media::recorder::Recorder::start(30.0) {
                        Ok(r) => {
                            self.panels.recorder = Some(r);
                            seek = Some((0.0, true));
                            self.info("recording the making: the video downloads at the end");
                        }
                        Err(e) => self.error(e),
                    }
                }
            }
            let close = ui.button("Close").on_hover_text("Close the player");
            self.control("player-close", &close);
            if close.clicked() {
                seek = None;
                self.apply(Action::Play(false));
            }
        });
        let Some(p) = self.editor.playback else {
            return;
        };
        let current = p.current_step();
        let caption = match current {
            None => "Before the first step: the bare tank.".to_owned(),
            Some(k) => format!(
                "Step {} of {steps} · {}",
                k + 1,
                captions.get(k).map_or("", String::as_str)
            ),
        };
        ui.label(RichText::new(caption).strong());
        if self.editor.explain.on {
            self.explain_text(ui, &design, current);
        }
        if let Some((position, playing)) = seek {
            self.apply(Action::Seek { position, playing });
        }
    }

    /// Ends a recording (its video downloads) once the player stops at the end or is
    /// closed, or when asked.
    pub(crate) fn finish_recording(&mut self) {
        if let Some(r) = self.panels.recorder.take() {
            let design = self.editor.history.design();
            let name = crate::store::export::export_file_name(
                design,
                (design.width, design.height),
                "webm",
            );
            r.finish(&name);
            self.info(format!("recorded {name}"));
        }
    }

    /// Called every frame: a recording ends with the player.
    pub(crate) fn follow_recording(&mut self) {
        if self.panels.recorder.is_some() && self.editor.playback.is_none_or(|p| !p.playing) {
            self.finish_recording();
        }
    }

    /// The formulas of the current step's op (the one easing in, else the step's
    /// last), and the probe's areas.
    fn explain_text(&mut self, ui: &mut egui::Ui, design: &Design, current: Option<usize>) {
        let Some(k) = current else {
            ui.label("The tank is empty; every step that follows moves it by a formula.");
            return;
        };
        let bounds = design.step_bounds();
        let p = self
            .editor
            .playback
            .unwrap_or_else(crate::marbling::playback::Playback::start);
        let op = p
            .easing_op(design, &bounds)
            .map(|(op, _)| op)
            .unwrap_or(&design.ops[bounds[k + 1] - 1]);
        let f = marbling_core::explain::formula(op);
        ui.label(format!("forward: {}", f.forward));
        ui.label(format!("inverse: {}", f.inverse));
        ui.label(format!("with {}", f.values));
        ui.horizontal(|ui| {
            let c = ui.checkbox(
                &mut self.editor.explain.cumulative,
                "grid through every step so far",
            );
            self.control("player-cumulative", &c);
            if let Some(g) = self.explain_geometry() {
                let a0 = player_drawing::polygon_area(&g.probe.0);
                let a1 = player_drawing::polygon_area(&g.probe.1);
                ui.label(format!(
                    "probe area: {a0:.0} px² before, {a1:.0} px² after (×{:.3}){}",
                    a1 / a0,
                    if f.area_preserving {
                        " — the marbling maps keep every area"
                    } else {
                        " — this jiggle compresses and stretches"
                    }
                ));
            }
        });
        ui.label(
            RichText::new("Click the sheet to move the probe circle.")
                .small()
                .color(Color32::from_gray(160)),
        );
    }

    /// The ops the explain geometry pushes through (the current step's, or every
    /// step's so far, as shown now).
    fn explain_ops(&self) -> Option<Vec<marbling_core::Op>> {
        let p = self.editor.playback?;
        let current = p.current_step()?;
        let design = self.editor.history.design();
        let bounds = design.step_bounds();
        let from = if self.editor.explain.cumulative {
            0
        } else {
            bounds[current]
        };
        let shown = &self.editor.shown;
        let mut ops: Vec<_> = design.ops[from.min(shown.ops)..shown.ops].to_vec();
        ops.extend(shown.tail.iter().cloned());
        Some(ops)
    }

    /// Grid, arrows and probe for the current moment of the player, computed once per
    /// shown design and explain setting (the bar's readout and the canvas share it).
    pub(crate) fn explain_geometry(&mut self) -> Option<std::sync::Arc<ExplainGeometry>> {
        let key = (self.editor.key, self.editor.explain.clone());
        if let Some((k, g)) = &self.panels.explain_cache
            && *k == key
        {
            return Some(g.clone());
        }
        let g = std::sync::Arc::new(self.compute_explain_geometry()?);
        self.panels.explain_cache = Some((key, g.clone()));
        Some(g)
    }

    fn compute_explain_geometry(&self) -> Option<ExplainGeometry> {
        if !self.editor.explain.on {
            return None;
        }
        let ops = self.explain_ops()?;
        let design = self.editor.history.design();
        let size = (design.width, design.height);
        let counted: usize = ops.iter().map(marbling_core::Op::counted_ops).sum();
        let long = f64::from(size.0.max(size.1));
        // 16 lines along the longer side, fewer when the ops are many.
        let mut step = long / 16.0;
        let work = |step: f64| {
            let nodes = (f64::from(size.0) + f64::from(size.1)) * (long / step) * 8.0 / step;
            nodes * counted.max(1) as f64
        };
        while work(step) > EXPLAIN_WORK && step < long {
            step *= 1.5;
        }
        let grid = player_drawing::grid_lines(&ops, size, step);
        let mut arrows = Vec::new();
        let coarse = step * 2.0;
        let mut y = coarse / 2.0;
        while y < f64::from(size.1) {
            let mut x = coarse / 2.0;
            while x < f64::from(size.0) {
                let a = Point::new(x, y);
                arrows.push((a, player_drawing::push(&ops, a)));
                x += coarse;
            }
            y += coarse;
        }
        let (c, r) = self.editor.explain.probe_circle(design);
        let probe = player_drawing::probe(&ops, c, r);
        Some(ExplainGeometry {
            grid,
            arrows,
            probe,
        })
    }
}
