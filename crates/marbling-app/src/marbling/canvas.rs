//! The canvas: the exactly rendered design, pan and zoom, the tools' gestures and
//! their footprints.

use crate::action::Action;
use crate::fast_paint::FastPaint;
use crate::frame::Asked;
use crate::gpu::canvas_gpu::{CanvasCallback, CanvasPlacement, FrameRequest, StandIn};
use crate::marbling::editor::Editor;
use crate::marbling::footprint;
use crate::marbling::player::Player;
use crate::marbling::tools::{Gesture, ToolKind, ops_for};
use crate::marbling::view::ViewState;
use crate::media::midi::MidiPanel;
use crate::media::sound::SoundPanel;
use crate::noise::Noise;
use crate::shell::message::Message;
use crate::state::Rendering;
use crate::store::prefs::Prefs;
use eframe::egui_wgpu;
use egui::{Color32, PointerButton, Pos2, Rect, Vec2};
use marbling_core::{Op, Point};

/// How much the canvas may change in width or height, points, before a fitted view is
/// fitted again.
const REFIT_PT: f64 = 24.0;

/// A tool being dragged on the canvas.
#[derive(Clone, Debug)]
pub struct ActiveGesture {
    /// The tool in use.
    pub tool: ToolKind,
    /// The pointer's path so far.
    pub gesture: Gesture,
    /// Seed of this gesture's random choices (spray droplets).
    pub seed: u64,
}

/// What the canvas reads and changes in a frame: the document's view and gesture (the
/// canvas is the marbling editor's own), the tool preferences, and the features it
/// draws for or feels through (the noise preview, the player's explain view, MIDI's
/// line, sound's pressure, the renderer).
pub(crate) struct Canvas<'a> {
    /// The document, its view and the gesture under way.
    pub editor: &'a mut Editor,
    /// The tool, its settings and the ink (cycled by drops).
    pub prefs: &'a mut Prefs,
    /// The noise playground (its preview over the sheet).
    pub noise: &'a mut Noise,
    /// The step player (its explain view and probe).
    pub player: &'a mut Player,
    /// MIDI (the line its notes fall on, drawn on the canvas).
    pub midi: &'a mut MidiPanel,
    /// Sound (it may press like a pen).
    pub sound: &'a SoundPanel,
    /// The GPU renderer's side.
    pub rendering: &'a mut Rendering,
}

/// What the canvas drew and asks for in a frame.
#[derive(Default)]
pub(crate) struct Drawn {
    /// Its control, and a message.
    pub asked: Asked,
    /// The exact frame it asked the GPU for (`data-ready`), if it painted one.
    pub requested: Option<FrameRequest>,
    /// The sheet's top-left on the page and the CSS pixels per design pixel
    /// (`data-view`).
    pub sheet_on_page: Option<[f64; 3]>,
}

impl Canvas<'_> {
    /// The canvas's input: fits or moves the view, pans and zooms, and drives the tool.
    /// A released gesture is asked for as an [`Action::Commit`], applied before
    /// [`Canvas::paint`] so the frame shows the design with it.
    pub fn input(&mut self, ui: &egui::Ui, response: &egui::Response) -> Asked {
        let mut asked = Asked::default();
        asked.control("canvas", response);
        let rect = response.rect;
        let size = [f64::from(rect.width()), f64::from(rect.height())];
        let ppp = f64::from(ui.ctx().pixels_per_point());
        // Refit, unless the user zoomed or panned, on a new window size or pixel ratio (a
        // rotated phone, a hi-DPI page's first frames), when the canvas grows or shrinks
        // by more than a line of text (the player, Explain or the bottom sheet opened or
        // closed), and when it shrinks so that the sheet no longer fits; not when it grows
        // by a line, and not during a gesture.
        let window = ui.ctx().content_rect().size();
        let canvas_key = [
            f64::from(window.x),
            f64::from(window.y),
            ppp,
            size[0],
            size[1],
        ];
        let refit = match (self.editor.view, self.editor.fit) {
            (None, _) => true,
            (Some(v), Some((fitted, key))) => {
                let (w, h) = self.editor.shown.size();
                let (tl, br) = (
                    v.to_screen(Point::ZERO),
                    v.to_screen(Point::new(f64::from(w), f64::from(h))),
                );
                let cut =
                    tl[0] < -0.5 || tl[1] < -0.5 || br[0] > size[0] + 0.5 || br[1] > size[1] + 0.5;
                // Never under a finger: a gesture keeps the view it started with.
                v == fitted
                    && self.editor.active.is_none()
                    && !self.editor.pinching
                    && (key[..3] != canvas_key[..3]
                        || (key[3] - size[0]).abs() > REFIT_PT
                        || (key[4] - size[1]).abs() > REFIT_PT
                        || cut)
            }
            (Some(_), None) => false,
        };
        if refit {
            let v = ViewState::fit(&self.editor.shown.design, size).snapped(ppp);
            self.editor.view = Some(v);
            self.editor.fit = Some((v, canvas_key));
        }
        self.editor.canvas_size = size;
        if let Some(spec) = self.editor.view_request.take() {
            self.editor.view = Some(ViewState::centred(spec, size));
        }
        let view = self.editor.view.unwrap_or_default();
        self.navigate(ui, response, rect, ppp);
        let view = self.editor.view.unwrap_or(view);
        if self.editor.mode == crate::shell::mode::Mode::Marbling {
            self.drive_tool(ui, response, rect, &view, &mut asked);
        }
        asked
    }

    /// Draws the canvas: the exact frame (or live preview), the noise preview, the
    /// sheet's outline and the tool's footprint or the player's drawing.
    pub fn paint(
        &mut self,
        ui: &egui::Ui,
        frame: &mut eframe::Frame,
        response: &egui::Response,
    ) -> Drawn {
        let mut drawn = Drawn::default();
        let rect = response.rect;
        let painter = ui.painter_at(rect);
        let ppp = f64::from(ui.ctx().pixels_per_point());
        let view = self.editor.view.unwrap_or_default();
        let pointer = response.hover_pos();
        let local = |p: Pos2| [f64::from(p.x - rect.min.x), f64::from(p.y - rect.min.y)];
        // The design's rectangle on screen, clipped to the canvas.
        let tl = view.to_screen(Point::ZERO);
        let (w, h) = self.editor.shown.size();
        let br = view.to_screen(Point::new(f64::from(w), f64::from(h)));
        let sheet = Rect::from_min_max(
            rect.min + Vec2::new(tl[0] as f32, tl[1] as f32),
            rect.min + Vec2::new(br[0] as f32, br[1] as f32),
        );
        let (left, top) = (f64::from(rect.min.x), f64::from(rect.min.y));
        let sheet_f64 = [left + tl[0], top + tl[1], left + br[0], top + br[1]];
        let placement = CanvasPlacement::new(rect, sheet_f64, ppp);
        if self.rendering.gpu {
            drawn.requested = self.paint_design(ui, frame, rect, placement, &view);
        } else {
            let [r, g, b] = crate::gpu::canvas_gpu::SURROUND;
            painter.rect_filled(rect, 0.0, Color32::from_rgb(r, g, b));
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                "No GPU renderer available",
                egui::FontId::proportional(18.0),
                Color32::WHITE,
            );
        }
        if self.editor.mode == crate::shell::mode::Mode::Noise {
            let d = self.editor.history.design();
            let (size, factor) = ([d.width, d.height], self.noise.factor_at(self.editor.view));
            if let Err(e) = self.noise.paint_preview(ui, &painter, sheet, size, factor) {
                drawn.asked.message = Some(Message::error(e));
            }
        }
        // The sheet's outline and the tool overlay: untextured shapes, drawn by the
        // flat-mesh pipeline (src/fast_paint/flat_overlay.rs) when fast paint is on.
        let overlay_start = FastPaint::mark(ui.ctx(), painter.layer_id());
        painter.rect_stroke(
            sheet,
            0.0,
            egui::Stroke::new(1.0, Color32::from_gray(20)),
            egui::StrokeKind::Outside,
        );
        let design_pointer = pointer.map(|p| view.to_design(local(p)));
        // For automation: the sheet's top-left on the page and the CSS pixels per design
        // pixel (egui points are CSS pixels; the hooks use no other unit).
        // (In f64: at 10⁶× the sheet's corner lies 10⁸ points off, where an egui (f32)
        // coordinate is 8 points coarse.)
        drawn.sheet_on_page = Some([
            placement.sheet_px[0] / ppp,
            placement.sheet_px[1] / ppp,
            view.zoom,
        ]);
        if let Some(p) = self.editor.playback {
            // The player draws the step's tool moving, and the explain view.
            if let Some(g) = self.player.explain_geometry(self.editor) {
                crate::marbling::player_drawing::draw_explain(
                    &painter.with_clip_rect(sheet),
                    rect,
                    &view,
                    &g,
                );
            }
            let design = self.editor.history.design();
            if let Some((op, e)) = p.easing_op(design, &design.step_bounds()) {
                crate::marbling::player_drawing::draw_tool(&painter, rect, &view, op, e, (w, h));
            }
        } else if self.editor.mode == crate::shell::mode::Mode::Marbling {
            footprint::draw(
                &painter,
                rect,
                &view,
                self.editor,
                self.prefs,
                design_pointer,
            );
            if let Some(line) = self.midi.shown_line() {
                // The line MIDI notes fall on: low notes at its start (the dot).
                let at = |p: Point| {
                    let [x, y] = view.to_screen(p);
                    rect.min + egui::vec2(x as f32, y as f32)
                };
                let stroke =
                    egui::Stroke::new(1.5, Color32::from_rgba_unmultiplied(30, 30, 30, 160));
                painter.line_segment([at(line[0]), at(line[1])], stroke);
                painter.circle_filled(at(line[0]), 3.0, stroke.color);
            }
        }
        let overlay_end = FastPaint::mark(ui.ctx(), painter.layer_id());
        self.rendering.fast_paint.overlay(
            ui.ctx(),
            frame.wgpu_render_state().map(|rs| rs.target_format),
            painter.layer_id(),
            overlay_start..overlay_end,
        );
        drawn
    }

    /// Pan (middle drag, space + drag, two fingers) and zoom (wheel, pinch).
    /// After each zoom the view is snapped to physical pixels (`ppp` per point), so every
    /// zoom level samples exactly the points of a CPU render at that scale (whole-pixel
    /// pans keep it snapped).
    fn navigate(&mut self, ui: &egui::Ui, response: &egui::Response, rect: Rect, ppp: f64) {
        let (steps, any_touches) =
            ui.input(|i| (self.editor.fingers.feed(&i.events), i.any_touches()));
        if !any_touches {
            // No finger is down (also after a lift the canvas did not see).
            self.editor.fingers = Default::default();
        }
        let Some(view) = self.editor.view.as_mut() else {
            return;
        };
        let before = *view;
        let space = ui.input(|i| i.key_down(egui::Key::Space));
        if response.dragged_by(PointerButton::Middle)
            || (space && response.dragged_by(PointerButton::Primary))
        {
            let d = response.drag_delta();
            view.pan([f64::from(d.x), f64::from(d.y)]);
        }
        // Two fingers: the design point under their midpoint follows the midpoint (pan),
        // and the pinch zooms about it, move by move (src/marbling/fingers.rs).
        for step in &steps {
            view.pan([f64::from(step.pan.x), f64::from(step.pan.y)]);
            let c = step.about - rect.min;
            view.zoom_about(step.zoom, [f64::from(c.x), f64::from(c.y)]);
        }
        let two_fingers = self.editor.fingers.count() >= 2 || !steps.is_empty();
        if two_fingers || ui.input(|i| i.multi_touch().is_some()) {
            // egui's own pinch summary (zoom_delta) is the same motion: not twice.
        } else if let Some(p) = response.hover_pos() {
            let (scroll, zoom) = ui.input(|i| (wheel_points(i), i.zoom_delta()));
            let factor = f64::from(zoom) * (scroll * 0.002).exp();
            if (factor - 1.0).abs() > 1e-6 {
                view.zoom_about(
                    factor,
                    [f64::from(p.x - rect.min.x), f64::from(p.y - rect.min.y)],
                );
            }
        }
        let pinching = two_fingers;
        let pinch_ended = std::mem::replace(&mut self.editor.pinching, pinching) && !pinching;
        if (view.zoom != before.zoom && !pinching) || pinch_ended {
            *view = view.snapped(ppp);
        }
    }

    /// Press starts a gesture, drags extend it, release commits its ops.
    fn drive_tool(
        &mut self,
        ui: &egui::Ui,
        response: &egui::Response,
        rect: Rect,
        view: &ViewState,
        asked: &mut Asked,
    ) {
        let (pressed, down, released, pos, dt, space, touches) = ui.input(|i| {
            (
                i.pointer.primary_pressed(),
                i.pointer.primary_down(),
                i.pointer.primary_released(),
                i.pointer.interact_pos(),
                f64::from(i.stable_dt).min(0.1),
                i.key_down(egui::Key::Space),
                i.multi_touch().is_some() || self.editor.fingers.count() >= 2,
            )
        });
        let to_design =
            |p: Pos2| view.to_design([f64::from(p.x - rect.min.x), f64::from(p.y - rect.min.y)]);
        if touches || space {
            self.editor.active = None;
            return;
        }
        if self.midi.drawing_line() {
            // *Draw line* of the MIDI section: this drag is the notes' line, no tool's.
            self.editor.active = None;
            let at = pos
                .filter(|_| !pressed || response.hovered())
                .map(to_design);
            self.midi.draw_line(at, pressed, down);
            if down {
                ui.ctx().request_repaint();
            }
            return;
        }
        if self.editor.playback.is_some() && self.player.explain().on {
            // While explaining, a click on the sheet moves the area probe.
            if pressed
                && response.hovered()
                && let Some(p) = pos
            {
                self.player
                    .move_probe(to_design(p), self.editor.history.design());
            }
            return;
        }
        if pressed
            && response.hovered()
            && let Some(p) = pos
        {
            self.editor.playback = None;
            let mut gesture = Gesture::new(to_design(p));
            gesture.pixel = 1.0 / view.zoom.max(1e-9);
            self.editor.active = Some(ActiveGesture {
                tool: self.prefs.tool,
                gesture,
                seed: self.editor.next_seed,
            });
            self.editor.next_seed += 1;
        }
        if let Some(active) = &mut self.editor.active {
            if down {
                let pen = if self.prefs.settings.pressure {
                    crate::marbling::tools::pressure_scale(crate::platform::pointer_pressure())
                } else {
                    1.0
                };
                // Sound may press too (src/media/sound.rs).
                let sound = self.sound.factor(crate::media::sound::Target::Pressure);
                let scale = pen * sound.unwrap_or(1.0);
                if let Some(p) = pos.map(to_design)
                    && active.gesture.end() != p
                {
                    active.gesture.path.push(p);
                    active.gesture.scales.push(scale);
                }
                active.gesture.feel(scale);
                active.gesture.held_seconds += dt;
                ui.ctx().request_repaint();
            }
            if released || !down {
                let done = self.editor.active.take();
                if let Some(a) = done {
                    let inks = self.prefs.cycled_inks();
                    let ops = ops_for(a.tool, &self.prefs.settings, &a.gesture, &inks, a.seed);
                    // Cycling colours: the next click starts with the colour after the
                    // last drop's.
                    if a.tool == ToolKind::Drop && self.prefs.settings.cycle_colors {
                        let laid = ops.first().map_or(0, Op::counted_ops);
                        self.prefs.ink = inks[laid % inks.len()];
                    }
                    asked.actions.push(Action::Commit(ops));
                }
            }
        }
    }

    /// The ops the current gesture would add if released now.
    fn pending_ops(&self) -> Vec<Op> {
        match &self.editor.active {
            Some(a) => ops_for(
                a.tool,
                &self.prefs.settings,
                &a.gesture,
                &self.prefs.cycled_inks(),
                a.seed,
            ),
            None => Vec::new(),
        }
    }

    /// Asks the GPU for the frame (exact, or live preview while dragging) and shows it,
    /// with the grey around the sheet, in one paint callback covering the canvas.
    fn paint_design(
        &mut self,
        ui: &egui::Ui,
        frame: &mut eframe::Frame,
        rect: Rect,
        placement: CanvasPlacement,
        view: &ViewState,
    ) -> Option<FrameRequest> {
        frame.wgpu_render_state()?;
        let ppp = f64::from(ui.ctx().pixels_per_point());
        let size = [
            ((f64::from(rect.width()) * ppp).round() as u32).max(1),
            ((f64::from(rect.height()) * ppp).round() as u32).max(1),
        ];
        let pending = self.pending_ops();
        let stand_in = self
            .editor
            .stand_in
            .clone()
            .filter(|(key, _)| *key == self.editor.key)
            .map(|(_, s)| s);
        // The stream shows while no gesture or Play is under way.
        let stream = self
            .rendering
            .stream
            .frame(&self.prefs.settings)
            .filter(|_| {
                pending.is_empty() && self.editor.active.is_none() && self.editor.playback.is_none()
            });
        let (shown, design_key, single) = match pending.as_slice() {
            [] => match &stream {
                // The design then its flow (the renderer walks it for each layer's
                // time), keyed by the flow so the GPU writes the ops once.
                Some(s) => {
                    let flow = [Op::Flow(s.flow.clone())];
                    (
                        self.editor.shown.then(&flow),
                        (self.editor.key.wrapping_mul(1_000_003) ^ fingerprint(&flow)) | (1 << 63),
                        None,
                    )
                }
                None => (self.editor.shown.clone(), self.editor.key, None),
            },
            [op] if previewable(op) => {
                (self.editor.shown.clone(), self.editor.key, Some(op.clone()))
            }
            many => {
                // Several ops at once (spray, a rake of separate tines): exact render of
                // the design with them after it, keyed by what they are, so the preview
                // follows every change of the stroke (the GPU writes only new ops).
                (
                    self.editor.shown.then(many),
                    (self.editor.key.wrapping_mul(1_000_003) ^ fingerprint(many)) | (1 << 63),
                    None,
                )
            }
        };
        let antialias = if single.is_some() {
            let dt = f64::from(ui.input(|i| i.unstable_dt));
            let samples = self.prefs.antialias.samples().len();
            self.rendering.fast_paint.preview_frame(dt, samples);
            self.rendering
                .fast_paint
                .preview_antialias(self.prefs.antialias)
        } else if stream.is_some() && self.rendering.stream.is_playing() {
            // A playing stream: one sample per pixel, so frames keep coming; paused, the
            // frame takes the antialiasing setting.
            marbling_core::Antialias::None
        } else if self.rendering.video.live_frame().is_some() {
            // Live video: one sample per pixel, so frames keep coming (the 640×480
            // video is coarser than the canvas anyway); *Use this frame* keeps the
            // antialiasing setting.
            marbling_core::Antialias::None
        } else {
            self.rendering.fast_paint.end_drag();
            self.prefs.antialias
        };
        let request = FrameRequest {
            design_key,
            size,
            scale: view.zoom * ppp,
            origin: [view.origin.x, view.origin.y],
            antialias,
            pending: single,
            // A gesture's several ops drawn exactly: the design's cache stands in. A stream
            // frame is drawn over the last one (no cache holds a stream).
            stand_in: if design_key == self.editor.key {
                stand_in
            } else if stream.is_some() {
                None
            } else {
                Some(StandIn {
                    key: Some(self.editor.key),
                    op: None,
                    paper: false,
                })
            },
            transient: design_key != self.editor.key,
            live: self.rendering.video.live_frame().cloned(),
            stream,
        };
        let requested = request.exact_frame();
        let acting =
            ui.input(|i| !i.events.is_empty() || i.pointer.any_down() || i.pointer.is_moving());
        if acting {
            self.rendering.last_input_s = ui.input(|i| i.time);
        }
        let idle = ui.input(|i| i.time) - self.rendering.last_input_s > IDLE_AFTER_S;
        let callback = CanvasCallback {
            shown,
            request,
            placement,
            status: self.rendering.status.clone(),
            ctx: ui.ctx().clone(),
            active: !idle,
        };
        ui.painter()
            .add(egui_wgpu::Callback::new_paint_callback(rect, callback));
        Some(requested)
    }
}

/// Seconds without input after which the canvas refines at its idle pace.
const IDLE_AFTER_S: f64 = 0.3;

/// A hash of `ops`' exact values (two lists differ in it unless they are equal, with
/// the odds of a 64-bit hash collision).
fn fingerprint(ops: &[Op]) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for op in ops {
        // Debug prints every f64 exactly (shortest round-trip form).
        format!("{op:?}").hash(&mut h);
    }
    h.finish()
}

/// Vertical wheel movement this frame, points (up is positive), taken from the raw
/// events rather than egui's smoothed scroll so one notch is one exact re-render, not a
/// dozen animated ones. Ctrl/Cmd+wheel is left to egui's zoom (`zoom_delta`).
fn wheel_points(i: &egui::InputState) -> f64 {
    if i.modifiers.command || i.modifiers.ctrl {
        return 0.0;
    }
    i.events
        .iter()
        .map(|e| match e {
            egui::Event::MouseWheel { unit, delta, .. } => {
                let per_unit = match unit {
                    egui::MouseWheelUnit::Point => 1.0,
                    egui::MouseWheelUnit::Line => 40.0,
                    egui::MouseWheelUnit::Page => f64::from(i.content_rect().height()),
                };
                f64::from(delta.y) * per_unit
            }
            _ => 0.0,
        })
        .sum()
}

/// Whether the live preview can walk `op` alone over the cached design: one GPU record
/// (not a drop pattern, a finite comb or a stylus) and not a spray droplet (sprays come
/// many to a gesture, drawn exactly).
pub(crate) fn previewable(op: &Op) -> bool {
    !matches!(op, Op::Spray(_)) && marbling_gpu::encode::encode_op(op).is_some()
}
