//! The 3D view window: the design on a sphere, vase, cylinder, book or plane, turned
//! with an orbit camera (drag; wheel or pinch to zoom, double-click to reset), every
//! sample evaluated exactly by the GPU (`marbling_gpu::View3dRenderer`). "As a 2048²
//! texture" shows, side by side, what texture mapping the same design would look like:
//! sharp edges on the left at any zoom, blur on the right in close-up (Lu et al. 2012,
//! figures 6–7). Frames are drawn only when the design, camera or size change; while
//! the camera moves they take one sample per pixel, then antialiased once it stops.
//! *Turn* spins the camera about the object at a chosen speed, *dolly* moves it in or
//! out, and *Record* films one whole turn of the pane (antialiased frames, read back and
//! handed to the recorder as they are drawn) to `marbling-3d-turn.webm`. *Displace*
//! moves the surface by Perlin noise ([`super::view3d_displace`]); *Style* draws the
//! object with marks or fibres, blended into the panes by their shader
//! ([`super::view3d_style`]).

use crate::media::step_clock::StepClock;
use crate::media::view3d_displace::DisplaceControls;
use crate::media::view3d_panes::{Drawn, Panes};
use crate::media::view3d_recording::{TURN_VIDEO, TurnRecording};
use crate::media::view3d_style::StyleControls;
use eframe::egui_wgpu;
use marbling_core::view3d::{Camera, MAX_DOLLY, MAX_ZOOM, MIN_DOLLY, Shape, View3d};
use marbling_core::{Antialias, Design};

/// Side of the baked texture of the comparison, pixels (the paper's figure 6).
pub const COMPARE_TEXTURE: u32 = 2048;
/// Degrees the camera turns per point dragged.
const TURN_PER_POINT: f64 = 0.4;
/// Largest zoom the window offers (close enough to see a texel of an 8000² texture).
const WINDOW_MAX_ZOOM: f64 = 2000.0;
/// Fastest turn offered, degrees per second either way.
pub const MAX_TURN_SPEED: f64 = 180.0;
/// Turn speed at the start, degrees per second.
const DEFAULT_TURN_SPEED: f64 = 30.0;

/// The 3D view window's state.
pub struct View3dWindow {
    /// Whether the window is open.
    pub open: bool,
    /// The object.
    pub shape: Shape,
    /// Camera turn and elevation, degrees.
    pub yaw: f64,
    /// See `yaw`.
    pub pitch: f64,
    /// Magnification (1: the object fills the pane).
    pub zoom: f64,
    /// Show the baked-texture comparison beside the exact view.
    pub compare: bool,
    /// The design point the camera centres on (set by a click), or the object's centre.
    pub look_at: Option<marbling_core::Point>,
    /// Camera distance as a share of the framing distance ([`Camera::dolly`]).
    pub dolly: f64,
    /// Whether the camera turns about the object by itself.
    pub turning: bool,
    /// Turn speed, degrees per second (negative: the other way).
    pub turn_speed: f64,
    /// The turn's clock.
    turn_clock: StepClock,
    /// The surface's displacement and its flow.
    pub displace: DisplaceControls,
    /// The marks or fibres laid over the panes.
    pub style: StyleControls,
    recording: Option<TurnRecording>,
    /// What the last recording left (shown under the panes).
    note: Option<String>,
    panes: Option<Panes>,
    /// Frames drawn since the window opened (read by automation).
    pub frames: u64,
    /// The last GPU problem, shown in the window.
    error: Option<String>,
}

impl Default for View3dWindow {
    fn default() -> Self {
        Self {
            open: false,
            shape: Shape::Vase,
            yaw: 20.0,
            pitch: 12.0,
            zoom: 1.0,
            compare: false,
            look_at: None,
            dolly: 1.0,
            turning: false,
            turn_speed: DEFAULT_TURN_SPEED,
            turn_clock: StepClock::default(),
            displace: DisplaceControls::default(),
            style: StyleControls::default(),
            recording: None,
            note: None,
            panes: None,
            frames: 0,
            error: None,
        }
    }
}

impl View3dWindow {
    /// Puts the camera back where it starts.
    pub fn reset_camera(&mut self) {
        let d = Self::default();
        (self.yaw, self.pitch, self.zoom, self.look_at, self.dolly) =
            (d.yaw, d.pitch, d.zoom, d.look_at, d.dolly);
    }

    /// The `data-view3d` hook: the camera and the turn, as JSON.
    pub fn hook(&self) -> Option<String> {
        self.open.then(|| {
            serde_json::json!({
                "shape": self.shape.name(),
                "yaw": self.yaw,
                "pitch": self.pitch,
                "zoom": self.zoom,
                "dolly": self.dolly,
                "turning": self.turning,
                "speed": self.turn_speed,
                "displace": self.displace.hook(),
                "style": self.style.hook(),
                "recording": self.recording.as_ref().map(|r| {
                    serde_json::json!({"turned": r.turned, "frames": r.frames})
                }),
            })
            .to_string()
        })
    }

    /// Turns the camera by the time passed since the last frame ([`StepClock`]); true
    /// while it turns.
    fn step_turn(&mut self, ctx: &egui::Context) -> bool {
        if !self.turning {
            self.turn_clock.stop();
            return false;
        }
        let step = self.turn_speed * self.turn_clock.step();
        self.yaw = (self.yaw + step).rem_euclid(360.0);
        if let Some(r) = &mut self.recording {
            r.turned += step.abs();
        }
        ctx.request_repaint();
        true
    }

    /// Starts filming one turn of the pane of `size` pixels (turning it if it stands).
    fn start_recording(&mut self, size: [u32; 2]) {
        match TurnRecording::start(size) {
            Ok(recording) => {
                if self.turn_speed == 0.0 {
                    self.turn_speed = DEFAULT_TURN_SPEED;
                }
                self.turning = true;
                self.note = None;
                self.recording = Some(recording);
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// Ends the recording (`whole`: after one whole turn), leaving its note.
    fn finish_recording(&mut self, whole: bool) {
        if let Some(r) = self.recording.take() {
            self.note = Some(r.finish(whole));
        }
    }

    /// Hands the recording a frame that came back from the GPU, and ends it after one
    /// whole turn.
    fn feed_recording(&mut self, device: &wgpu::Device) {
        let Some(r) = &mut self.recording else {
            return;
        };
        if let Err(e) = r.feed(device) {
            self.error = Some(format!("recording the turn failed: {e}"));
            self.finish_recording(false);
        } else if r.turned >= 360.0 {
            self.finish_recording(true);
        }
    }

    /// The 3D view of a pane of `size` pixels.
    fn view(&self, size: [u32; 2], antialias: Antialias, texture: Option<u32>) -> View3d {
        View3d {
            shape: self.shape,
            camera: Camera {
                yaw: Some(self.yaw),
                pitch: Some(self.pitch),
                zoom: self.zoom,
                look_at: self.look_at,
                dolly: self.dolly,
            },
            width: size[0],
            height: size[1],
            antialias,
            texture,
            displace: self.displace.displace,
        }
    }

    /// Shows the window (when open) for `design`, whose content changes with
    /// `design_key`; `controls` records named controls for automation.
    pub fn show(
        &mut self,
        ctx: &egui::Context,
        frame: &eframe::Frame,
        design: &Design,
        design_key: u64,
        controls: &mut Vec<(std::borrow::Cow<'static, str>, egui::Rect)>,
    ) {
        if !self.open {
            return;
        }
        let mut open = self.open;
        // It opens at the window's top right, over the canvas: the panel's controls
        // (Save, Export, the history) stay in reach.
        let screen = ctx.content_rect();
        let corner = screen.right_top() + egui::vec2(-8.0, 8.0);
        // On a phone it fits the screen's width.
        let widest = (screen.width() - 16.0).max(200.0);
        let mut window = egui::Window::new("3D view")
            .open(&mut open)
            .pivot(egui::Align2::RIGHT_TOP)
            .default_pos(corner)
            .default_width(560.0_f32.min(widest))
            .max_width(widest)
            .resizable(true)
            .constrain(true);
        if screen.width() < 600.0 {
            // A phone: pinned across the top of the screen, as wide as it.
            window = window
                .anchor(egui::Align2::RIGHT_TOP, egui::vec2(-8.0, 8.0))
                .resizable(false)
                .min_width(widest);
        }
        window.show(ctx, |ui| {
            self.contents(ui, frame, design, design_key, controls)
        });
        self.open = open;
        if !self.open {
            // Frees the GPU memory of the panes.
            self.finish_recording(false);
            self.turning = false;
            self.displace.flowing = false;
            self.style.release();
            self.panes = None;
        }
    }

    fn contents(
        &mut self,
        ui: &mut egui::Ui,
        frame: &eframe::Frame,
        design: &Design,
        design_key: u64,
        controls: &mut Vec<(std::borrow::Cow<'static, str>, egui::Rect)>,
    ) {
        ui.horizontal_wrapped(|ui| {
            for shape in Shape::ALL {
                let r = ui.selectable_value(&mut self.shape, shape, shape.name());
                controls.push((format!("view3d-{}", shape.name()).into(), r.rect));
            }
        });
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .checkbox(&mut self.compare, "as a 2048² texture")
                .on_hover_text(
                    "Beside the exact view, the same design baked into a 2048-pixel texture, \
                     as texture mapping would draw it: zoom in to see the difference",
                );
            controls.push(("view3d-compare".into(), r.rect));
            let r = ui.add(
                egui::Slider::new(&mut self.zoom, 1.0..=WINDOW_MAX_ZOOM)
                    .logarithmic(true)
                    .text("zoom"),
            );
            controls.push(("view3d-zoom".into(), r.rect));
            if ui.button("Reset view").clicked() {
                self.reset_camera();
            }
        });
        let mut record = false;
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .toggle_value(&mut self.turning, "Turn")
                .on_hover_text("Spin the camera about the object at the speed beside it");
            controls.push(("view3d-turn".into(), r.rect));
            let r = ui
                .add(
                    egui::Slider::new(&mut self.turn_speed, -MAX_TURN_SPEED..=MAX_TURN_SPEED)
                        .suffix("°/s")
                        .text("speed"),
                )
                .on_hover_text("Degrees a second; below 0 it turns the other way");
            controls.push(("view3d-turn-speed".into(), r.rect));
            let label = if self.recording.is_some() {
                "■ Stop recording"
            } else {
                "Record a turn"
            };
            let r = ui
                .add_enabled(
                    cfg!(target_arch = "wasm32") || self.recording.is_some(),
                    egui::Button::new(label),
                )
                .on_hover_text(format!(
                    "Films one whole turn of the object to {TURN_VIDEO}"
                ))
                .on_disabled_hover_text(
                    "Recording needs the web app; `marbling render-3d --turn 360` writes a loop",
                );
            controls.push(("view3d-record".into(), r.rect));
            record = r.clicked();
        });
        // Its own row: a phone's width holds one slider beside a button, not two.
        ui.horizontal_wrapped(|ui| {
            let r = ui
                .add(
                    egui::Slider::new(&mut self.dolly, MIN_DOLLY..=MAX_DOLLY)
                        .logarithmic(true)
                        .text("dolly"),
                )
                .on_hover_text(
                    "Moves the camera in (below 1) or out: the object grows or shrinks and \
                     its perspective changes, unlike zoom",
                );
            controls.push(("view3d-dolly".into(), r.rect));
        });
        // Folded by default: the pane keeps its height on a small screen.
        let r = egui::CollapsingHeader::new("Displace")
            .id_salt("view3d-displace-section")
            .show(ui, |ui| self.displace.ui(ui, controls));
        controls.push(("view3d-displace-section".into(), r.header_response.rect));
        let r = egui::CollapsingHeader::new(format!("Style: {}", self.style.name()))
            .id_salt("view3d-style-section")
            .show(ui, |ui| self.style.ui(ui, controls));
        controls.push(("view3d-style-section".into(), r.header_response.rect));
        let hint = if crate::platform::touch_screen() {
            "Drag to turn · tap to centre a spot · pinch to zoom · double-tap to reset"
        } else {
            "Drag to turn · click to centre a spot · wheel or pinch to zoom · double-click to \
             reset"
        };
        ui.add(egui::Label::new(hint).wrap());
        let Some(rs) = frame.wgpu_render_state() else {
            ui.label("The 3D view needs the GPU renderer.");
            return;
        };
        let ppp = ui.ctx().pixels_per_point();
        let avail = ui.available_size();
        let panes = if self.compare { 2.0 } else { 1.0 };
        let gap = 6.0;
        // Never wider than the screen (a window sized by its content would keep growing).
        let room = avail.x.min(ui.ctx().content_rect().width() - 40.0);
        let width = ((room - gap * (panes - 1.0)) / panes).clamp(120.0, 1400.0);
        // Down to the screen's bottom less a line for notes, not the window's remembered
        // height (which only grows): the pane's size follows the rows above it alone.
        let below = ui.ctx().content_rect().bottom() - ui.cursor().top() - 40.0;
        let height = (width * 0.75).min(below.max(160.0)).max(100.0);
        let size_pt = egui::vec2(width, height);
        let size_px = [
            (size_pt.x * ppp).round().max(16.0) as u32,
            (size_pt.y * ppp).round().max(16.0) as u32,
        ];
        if record {
            if self.recording.is_some() {
                self.finish_recording(false);
            } else {
                self.start_recording(size_px);
            }
        }
        if self.recording.as_ref().is_some_and(|r| r.size != size_px) {
            self.error = Some("the pane changed size: the recording stopped".to_owned());
            self.finish_recording(false);
        }
        let mut interacting = self.step_turn(ui.ctx());
        interacting |= self.displace.step(ui.ctx());
        let textures = Panes::ensure(&mut self.panes, rs, size_px);
        ui.horizontal(|ui| {
            for (i, tex) in textures.iter().take(panes as usize).enumerate() {
                let image = egui::Image::new((*tex, size_pt)).sense(egui::Sense::click_and_drag());
                let r = ui.add(image);
                controls.push((format!("view3d-pane-{i}").into(), r.rect));
                interacting |= self.orbit(ui, &r, design, size_px);
            }
        });
        if let Some(e) = &self.error {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), e);
        }
        if let Some(note) = &self.note {
            ui.label(note);
        }
        // A recording takes antialiased frames; a moving camera one sample per pixel.
        let antialias = if interacting && self.recording.is_none() {
            Antialias::None
        } else {
            Antialias::Rgss
        };
        self.feed_recording(&rs.device);
        self.draw(rs, design, design_key, size_px, antialias);
    }

    /// Draws the panes when what they show changed.
    fn draw(
        &mut self,
        rs: &egui_wgpu::RenderState,
        design: &Design,
        design_key: u64,
        size: [u32; 2],
        antialias: Antialias,
    ) {
        self.style
            .update(design, design_key, &self.view(size, Antialias::None, None));
        let now = Drawn {
            design_key,
            view: self.view(size, antialias, None),
            compare: self.compare,
            style: self.style.revision(),
        };
        let count = if self.compare { 2 } else { 1 };
        let views: Vec<View3d> = (0..count)
            .map(|i| self.view(size, antialias, (i == 1).then_some(COMPARE_TEXTURE)))
            .collect();
        let Some(panes) = &mut self.panes else { return };
        match panes.draw(
            rs,
            design,
            now,
            &views,
            self.style.frame(),
            self.recording.as_mut(),
        ) {
            Ok(false) => {}
            Ok(true) => {
                self.error = None;
                self.frames += 1;
            }
            Err(e) => self.error = Some(e),
        }
    }

    /// Turns and zooms the camera from the pointer over pane `r` (of `size` pixels,
    /// showing `design`); true while it moves.
    fn orbit(
        &mut self,
        ui: &egui::Ui,
        r: &egui::Response,
        design: &Design,
        size: [u32; 2],
    ) -> bool {
        let mut moved = false;
        if r.double_clicked() {
            self.reset_camera();
            moved = true;
        } else if r.clicked()
            && let Some(pos) = r.interact_pointer_pos()
        {
            // The design point under the pointer becomes the centre (the object's
            // surface there faces the camera as it does now).
            let view = self.view(size, Antialias::None, None);
            let k = size[0] as f32 / r.rect.width();
            let (px, py) = ((pos - r.rect.min) * k).into();
            let rig = view.rig(design);
            let ray = rig.ray(
                f64::from(px),
                f64::from(py),
                f64::from(size[0]),
                f64::from(size[1]),
            );
            if let Some(hit) = view.object(design).hit(rig.origin, ray)
                && let marbling_core::view3d::Material::Design(u, v) = hit.material
            {
                self.look_at = Some(marbling_core::Point::new(
                    u * f64::from(design.width),
                    v * f64::from(design.height),
                ));
                moved = true;
            }
        }
        if r.dragged() {
            let d = r.drag_delta();
            // Slower when close, so a close-up can still be aimed.
            let k = TURN_PER_POINT / self.zoom.sqrt();
            self.yaw -= f64::from(d.x) * k;
            self.pitch = (self.pitch + f64::from(d.y) * k).clamp(-85.0, 85.0);
            moved = true;
        }
        if r.hovered() {
            let (scroll, pinch) = ui.input(|i| (i.smooth_scroll_delta.y, i.zoom_delta()));
            let factor = f64::from(pinch) * (f64::from(scroll) * 0.002).exp();
            if factor != 1.0 {
                self.zoom = (self.zoom * factor).clamp(1.0, WINDOW_MAX_ZOOM.min(MAX_ZOOM));
                moved = true;
            }
        }
        moved
    }
}
