//! The step player's bar under the canvas: step back, play/pause, step forward, a
//! timeline with a tick per step (click or drag to scrub), speed, the step's caption,
//! and the explain view (the step's formulas with their numbers, the deformation grid,
//! arrows and the area probe, drawn by src/marbling/player_drawing.rs).

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::editor::Editor;
use crate::marbling::explain_geometry::{ExplainGeometry, Window};
use crate::media::recorder::{LoopEnding, MAX_HOLD_S, Next, Phase, Recorder};
use egui::{Color32, Sense, Slider, Stroke, vec2};
use marbling_core::{Design, Point};
use std::sync::Arc;

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

/// The step player's own state: its speed, the explain view's settings and geometry,
/// and a recording of the making.
pub(crate) struct Player {
    /// Steps per second.
    speed: f64,
    explain: Explain,
    /// A recording of the making and where it is.
    recording: Option<(Recorder, Phase)>,
    /// How a recording ends: the hold on the finished design, the way back.
    ending: LoopEnding,
    /// The explain view's geometry and what it was computed for (shown design's key,
    /// settings, half-octave of zoom).
    explain_cache: Option<((u64, Explain, i32), Arc<ExplainGeometry>)>,
}

impl Default for Player {
    fn default() -> Self {
        Self {
            speed: 0.8,
            explain: Explain::default(),
            recording: None,
            ending: LoopEnding::default(),
            explain_cache: None,
        }
    }
}

impl Player {
    /// Steps per second with a sign: negative while a recording plays the making back.
    pub fn velocity(&self) -> f64 {
        match self.recording {
            Some((_, Phase::Backward)) => -self.speed,
            _ => self.speed,
        }
    }

    /// The explain view's settings.
    pub fn explain(&self) -> &Explain {
        &self.explain
    }

    /// Moves the explain view's probe circle to `center` (design px), keeping its size.
    pub fn move_probe(&mut self, center: Point, design: &Design) {
        let (_, r) = self.explain.probe_circle(design);
        self.explain.probe = Some((center, r));
    }

    /// The player's bar (shown while the player is open), at most `max_height` points
    /// tall: the explain text scrolls in what is left, so the canvas keeps its share.
    pub fn ui(&mut self, ui: &mut egui::Ui, max_height: f32, frame: &mut Frame<'_>) {
        let Some(p) = frame.editor.playback else {
            return;
        };
        let top = ui.cursor().top();
        let design = frame.editor.history.design_shared().clone();
        let steps = design.gesture_sizes().len();
        let captions = design.step_captions();
        let mut seek = None;
        ui.add_space(2.0);
        if frame.layout.touch() {
            crate::shell::layout::touch_spacing(ui);
        }
        // One height for every control of the row; on a phone the row wraps.
        let row = vec2(0.0, ui.spacing().interact_size.y);
        ui.horizontal_wrapped(|ui| {
            let back = ui
                .add(egui::Button::new("◀ Step").min_size(row))
                .on_hover_text("Step back");
            frame.control("player-back", &back);
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
                .add(
                    egui::Button::new(if playing { "Pause" } else { "Play" })
                        .min_size(vec2(52.0, row.y)),
                )
                .on_hover_text("Play from here, or pause");
            frame.control("player-play", &play);
            if play.clicked() {
                let from = if p.step >= steps { 0.0 } else { p.position() };
                seek = Some((from, !playing));
            }
            let fwd = ui
                .add(egui::Button::new("Step ▶").min_size(row))
                .on_hover_text("Step forward");
            frame.control("player-forward", &fwd);
            if fwd.clicked() {
                seek = Some(((p.step + 1).min(steps) as f64, false));
            }
            // A slider keeps its width: on a narrow screen it gets a row of its own.
            let slider = ui.spacing().slider_width + 120.0;
            if ui.available_size_before_wrap().x < slider {
                ui.end_row();
                ui.spacing_mut().slider_width =
                    (ui.available_size_before_wrap().x - 120.0).min(ui.spacing().slider_width);
            }
            let speed = ui.add(
                Slider::new(&mut self.speed, 0.1..=4.0)
                    .logarithmic(true)
                    .text("steps/s"),
            );
            frame.control("player-speed", &speed);
            // Toggles look like buttons, lit while on.
            let explain = ui
                .add(
                    egui::Button::new("Explain")
                        .selected(self.explain.on)
                        .min_size(row),
                )
                .on_hover_text("Formulas, the deformation grid, arrows and the area probe");
            frame.control("player-explain", &explain);
            if explain.clicked() {
                self.explain.on = !self.explain.on;
            }
            self.record_button(ui, row, &mut seek, frame);
            let close = ui
                .add(egui::Button::new("Close").min_size(row))
                .on_hover_text("Close the player");
            frame.control("player-close", &close);
            if close.clicked() {
                seek = None;
                frame.act(Action::Play(false));
            }
        });
        if let Some(to) = Self::timeline(ui, p, steps, frame) {
            seek = Some((to, false));
        }
        let current = p.current_step();
        let caption = match current {
            None => "Before the first step: the bare tank.".to_owned(),
            Some(k) => format!(
                "Step {} of {steps} · {}",
                k + 1,
                captions.get(k).map_or("", String::as_str)
            ),
        };
        // Ink codes ("#3b2a1a") read as a swatch and a colour name.
        let font = egui::TextStyle::Body.resolve(ui.style());
        let color = ui.visuals().strong_text_color();
        ui.label(crate::marbling::colour_words::caption_job(
            &caption, font, color,
        ));
        if self.explain.on {
            // What is left of the bar's share scrolls the explain text; always the same
            // height, so stepping does not move the canvas.
            let used = ui.cursor().top() - top;
            let height = (max_height - used).clamp(48.0, 220.0);
            egui::ScrollArea::vertical()
                .min_scrolled_height(height)
                .max_height(height)
                .auto_shrink([false, false])
                .show(ui, |ui| self.explain_text(ui, &design, current, frame));
        }
        if let Some((position, playing)) = seek {
            frame.act(Action::Seek { position, playing });
        }
    }

    /// Record (a toggle): films the making from the first step; beside it, how the video
    /// ends (a hold on the finished design, the making backwards) so that it loops.
    fn record_button(
        &mut self,
        ui: &mut egui::Ui,
        row: egui::Vec2,
        seek: &mut Option<(f64, bool)>,
        frame: &mut Frame<'_>,
    ) {
        let recording = self.recording.is_some();
        // One width for both labels, so that stopping does not move Close under the
        // pointer.
        let widest = ui
            .painter()
            .layout_no_wrap(
                "Stop recording".to_owned(),
                egui::TextStyle::Button.resolve(ui.style()),
                egui::Color32::WHITE,
            )
            .size()
            .x
            + 2.0 * ui.spacing().button_padding.x;
        let record = ui
            .add(
                egui::Button::new(if recording {
                    "Stop recording"
                } else {
                    "Record"
                })
                .selected(recording)
                .min_size(vec2(widest, row.y)),
            )
            .on_hover_text("Film the making from the first step to a WebM video");
        frame.control("player-record", &record);
        if record.clicked() {
            // The row and the status line change with it: drawn again at once.
            ui.ctx().request_repaint();
            if recording {
                self.finish_recording(frame);
            } else {
                match Recorder::start(30.0) {
                    Ok(r) => {
                        self.recording = Some((r, Phase::Forward));
                        *seek = Some((0.0, true));
                        frame.info("recording the making: the video downloads at the end");
                    }
                    Err(e) => frame.error(e),
                }
            }
        }
        // A landscape phone keeps its player to two rows (the canvas needs the height):
        // it records with the hold and direction set elsewhere. While recording they stay
        // in place, greyed, so the row does not move.
        if frame.layout != crate::shell::layout::Layout::Landscape {
            // As the click above left it: egui hit-tests a click against the last
            // frame's widgets, so a stale state would swallow the next click.
            let recording = self.recording.is_some();
            let hold = ui
                .add_enabled(
                    !recording,
                    egui::DragValue::new(&mut self.ending.hold)
                        .range(0.0..=MAX_HOLD_S)
                        .speed(0.1)
                        .suffix(" s hold"),
                )
                .on_hover_text("Seconds the video stays on the finished design");
            frame.control("player-hold", &hold);
            let reverse = ui
                .add_enabled(
                    !recording,
                    egui::Checkbox::new(&mut self.ending.reverse, "reverse"),
                )
                .on_hover_text("Then the making backwards, so the video loops without a jump");
            frame.control("player-reverse", &reverse);
        }
    }

    /// The timeline across the bar: a tick per step with its number (as many as fit),
    /// the playhead in the accent colour; a click or drag seeks (returned, in steps).
    fn timeline(
        ui: &mut egui::Ui,
        p: crate::marbling::playback::Playback,
        steps: usize,
        frame: &mut Frame<'_>,
    ) -> Option<f64> {
        let width = (ui.available_width() - 8.0).max(60.0);
        let (rect, r) = ui.allocate_exact_size(vec2(width, 36.0), Sense::click_and_drag());
        frame.control("player-timeline", &r);
        let line = egui::Rect::from_min_size(rect.min, vec2(rect.width(), 22.0));
        let x_of = |pos: f64| line.left() + (pos / steps.max(1) as f64) as f32 * line.width();
        let painter = ui.painter();
        let y = line.center().y;
        let ink = ui.visuals().text_color();
        painter.line_segment(
            [egui::pos2(line.left(), y), egui::pos2(line.right(), y)],
            Stroke::new(3.0, Color32::from_gray(120)),
        );
        // Numbers every `every` steps, at least 22 points apart.
        let gap = line.width() / steps.max(1) as f32;
        let every = (22.0 / gap).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let x = x_of(k as f64);
            painter.line_segment(
                [egui::pos2(x, y - 7.0), egui::pos2(x, y + 7.0)],
                Stroke::new(1.5, Color32::from_gray(90)),
            );
            if k % every == 0 || k == steps {
                painter.text(
                    egui::pos2(
                        x.clamp(line.left() + 4.0, line.right() - 4.0),
                        line.bottom() + 1.0,
                    ),
                    egui::Align2::CENTER_TOP,
                    k.to_string(),
                    egui::FontId::proportional(11.0),
                    ink,
                );
            }
        }
        let head = egui::pos2(x_of(p.position()), y);
        painter.circle(
            head,
            8.0,
            ui.visuals().selection.bg_fill,
            Stroke::new(2.0, Color32::WHITE),
        );
        let at = r
            .interact_pointer_pos()
            .filter(|_| r.clicked() || r.dragged())?;
        let raw = f64::from((at.x - line.left()) / line.width()).clamp(0.0, 1.0) * steps as f64;
        // Within 6 points of a tick means that step exactly.
        let near = raw.round();
        Some(if (x_of(near) - at.x).abs() <= 6.0 {
            near
        } else {
            raw
        })
    }

    /// Ends a recording (its video downloads) once the player stops at the end or is
    /// closed, or when asked.
    pub fn finish_recording(&mut self, frame: &mut Frame<'_>) {
        if let Some((r, _)) = self.recording.take() {
            let design = frame.editor.history.design();
            let name = crate::store::export::export_file_name(
                design,
                (design.width, design.height),
                "webm",
            );
            r.finish(&name);
            frame.info(format!("recorded {name}"));
        }
    }

    /// Called every frame: a recording follows the player — at the end the hold, then
    /// the way back if chosen, and it ends with the player.
    pub fn follow_recording(&mut self, ctx: &egui::Context, frame: &mut Frame<'_>) {
        let Some((_, phase)) = &self.recording else {
            return;
        };
        let steps = frame.editor.history.design().gesture_sizes().len();
        let player = frame
            .editor
            .playback
            .map(|p| (p.playing, p.position() >= steps as f64));
        let now = ctx.input(|i| i.time);
        match phase.next(self.ending, player, now) {
            Next::Go(next) => {
                if let Some((_, phase)) = &mut self.recording {
                    *phase = next;
                }
                if let Phase::Holding { until } = next {
                    ctx.request_repaint_after(std::time::Duration::from_secs_f64(
                        (until - now).max(0.0),
                    ));
                }
            }
            Next::PlayBackward => {
                if let Some((_, phase)) = &mut self.recording {
                    *phase = Phase::Backward;
                }
                frame.act(Action::PlayBackward);
            }
            Next::Finish => self.finish_recording(frame),
        }
    }

    /// The formulas of the current step's op (the one easing in, else the step's
    /// last) with every symbol defined, what the drawing shows, and the probe's areas.
    fn explain_text(
        &mut self,
        ui: &mut egui::Ui,
        design: &Design,
        current: Option<usize>,
        frame: &mut Frame<'_>,
    ) {
        let Some(k) = current else {
            ui.label("The tank is empty; every step that follows moves it by a formula.");
            return;
        };
        let bounds = design.step_bounds();
        let p = frame
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
        ui.label(f.symbols);
        let c = ui.checkbox(
            &mut self.explain.cumulative,
            "grid through every step so far",
        );
        frame.control("player-cumulative", &c);
        if let Some(g) = self.explain_geometry(frame.editor) {
            let mut shows = format!(
                "Grid: lines {:.0} px apart pushed through {}. Red arrows: where nodes go, \
                 drawn at most one square long (the longest trip is {:.0} px).",
                g.spacing,
                match (self.explain.cumulative, g.first_of) {
                    (true, _) => "every step so far".to_owned(),
                    (false, Some((n, of))) => format!("the first {n} of this step's {of} drops"),
                    (false, None) => "this step".to_owned(),
                },
                g.longest_trip()
            );
            if !g.complete {
                shows.push_str(" Parts stretched thinner than the view shows are left out.");
            }
            let (grid_share, probe_shown) = g.on_sheet;
            if grid_share < 0.02 {
                shows.push_str(
                    " The ink laid since has pushed nearly all of the grid off the sheet.",
                );
            }
            if !probe_shown {
                shows.push_str(" The probe has been pushed off the sheet.");
            }
            ui.label(shows);
            ui.label(match g.probe_areas {
                Some((a0, a1)) => format!(
                    "Probe (white circle → bold outline): {a0:.0} px² before, {a1:.0} px² after \
                     (×{:.3}){}",
                    a1 / a0,
                    if f.area_preserving {
                        " — the marbling maps keep every area"
                    } else {
                        " — this jiggle compresses and stretches"
                    }
                ),
                None => "Probe (white circle → bold outline): stretched too thin to measure its \
                         area here"
                    .to_owned(),
            });
        }
        let verb = if frame.layout.touch() { "Tap" } else { "Click" };
        ui.label(format!("{verb} the sheet to move the probe circle."));
    }

    /// The explain view's window: the current step's ops (its first drops when it lays
    /// many), or every step's so far, as shown now.
    fn explain_window(&self, editor: &Editor) -> Option<Window> {
        let p = editor.playback?;
        let current = p.current_step()?;
        let design = editor.history.design();
        let bounds = design.step_bounds();
        let from = if self.explain.cumulative {
            0
        } else {
            bounds[current]
        };
        let shown = &editor.shown;
        let mut ops: Vec<_> = design.ops[from.min(shown.ops)..shown.ops].to_vec();
        ops.extend(shown.tail.iter().cloned());
        Some(if self.explain.cumulative {
            Window::all(&ops)
        } else {
            Window::step(&ops)
        })
    }

    /// Grid, arrows and probe for the current moment of the player, computed once per
    /// shown design, explain setting and half-octave of zoom (the bar's readout and the
    /// canvas share it).
    pub fn explain_geometry(&mut self, editor: &Editor) -> Option<Arc<ExplainGeometry>> {
        if !self.explain.on {
            return None;
        }
        let zoom = editor.view.map_or(1.0, |v| v.zoom);
        // Made for the top of the zoom's half-octave: fine enough anywhere in it.
        let half_octaves = (zoom.log2() * 2.0).ceil();
        let key = (editor.key, self.explain.clone(), half_octaves as i32);
        if let Some((k, g)) = &self.explain_cache
            && *k == key
        {
            return Some(g.clone());
        }
        let window = self.explain_window(editor)?;
        let design = editor.history.design();
        let g = Arc::new(ExplainGeometry::new(
            &window,
            (design.width, design.height),
            (half_octaves / 2.0).exp2(),
            self.explain.probe_circle(design),
        ));
        self.explain_cache = Some((key, g.clone()));
        Some(g)
    }
}
