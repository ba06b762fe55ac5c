//! The automation hooks: attributes of the page's `<body>` that tests and tools read
//! (the README lists them). Only changed values are written.

use crate::marbling::editor::Editor;
use crate::noise::Noise;
use crate::state::{Panels, Rendering};
use crate::store::prefs::Prefs;
use crate::{platform, recovery};
use std::borrow::Cow;
use std::collections::VecDeque;

/// The `<body>` automation hooks and what they are computed from.
#[derive(Default)]
pub(crate) struct Hooks {
    /// The attributes as last written.
    written: Vec<(&'static str, Option<String>)>,
    /// Where this frame drew the panel's main controls (for `data-controls`).
    pub(crate) controls: Vec<(Cow<'static, str>, egui::Rect)>,
    /// Recent frame intervals, seconds (for `data-frame-ms`).
    frame_times: VecDeque<f64>,
    /// Frames drawn since start (for `data-frames`).
    frames: u64,
    /// The sheet's top-left corner on the page and CSS pixels per design pixel.
    pub(crate) sheet_on_page: Option<[f64; 3]>,
    /// The noise setup and its spec JSON (for `data-noise`, written when it changes).
    noise_json: Option<(u64, String)>,
    /// The exact frame this frame's canvas asks for (design, size, view, antialiasing,
    /// live picture); `None` when no canvas is shown. `data-ready` is 1 only when it is
    /// the frame drawn.
    pub(crate) requested: Option<crate::gpu::canvas_gpu::FrameRequest>,
    /// `data-memory` (src/automation/memory.rs) and when it was taken (egui's clock, seconds).
    memory: Option<(f64, String)>,
    /// The status line's text as last drawn (for `data-status`).
    pub(crate) status: String,
}

/// What the hooks report on, read only.
pub(crate) struct Seen<'a> {
    /// The document and how it is shown.
    pub editor: &'a Editor,
    /// The tool preferences (antialiasing, the stream's settings).
    pub prefs: &'a Prefs,
    /// The GPU renderer's side.
    pub rendering: &'a Rendering,
    /// The panels.
    pub panels: &'a Panels,
    /// The noise playground.
    pub noise: &'a Noise,
}

impl Hooks {
    /// Counts a frame that came `dt` seconds after the last (`data-frames`,
    /// `data-frame-ms`: the mean of the last 60).
    pub fn count_frame(&mut self, dt: f64) {
        if self.frame_times.len() == 60 {
            self.frame_times.pop_front();
        }
        self.frame_times.push_back(dt);
        self.frames += 1;
    }

    /// Takes `data-memory` again when [`crate::automation::memory::EVERY_S`] passed
    /// since the last time (`now_s`: egui's clock, seconds).
    pub fn sample_memory(&mut self, now_s: f64, frame: &eframe::Frame) {
        let every = crate::automation::memory::EVERY_S;
        if self
            .memory
            .as_ref()
            .is_none_or(|(at, _)| now_s - at >= every)
        {
            self.memory = Some((now_s, crate::automation::memory::report(frame)));
        }
    }

    /// Keeps the `<body>` automation hooks current (only changed values are written).
    pub fn update(&mut self, ctx: &egui::Context, seen: Seen<'_>) {
        let Seen {
            editor,
            prefs,
            rendering,
            panels,
            noise,
        } = seen;
        // Recorded: the exact frame this frame's canvas asks for — this design, view,
        // size, antialiasing and picture — is in the canvas texture's commands. Ready: the
        // GPU has also finished it (the queue's work-done callback). A zoom, pan or resize
        // asks for another frame, so ready falls to 0 until that one is drawn.
        let (recorded, finished, streaming) = {
            let st = rendering.status.lock().ok();
            let drawn = st.as_ref().and_then(|s| s.drawn.clone());
            let finished = st.as_ref().is_some_and(|s| {
                s.exact_done.load(std::sync::atomic::Ordering::SeqCst) == s.work.exact
            });
            (
                rendering.gpu
                    && !editor.landing
                    && editor.active.is_none()
                    && editor.playback.is_none_or(|p| !p.playing)
                    && self.requested.is_some()
                    && drawn == self.requested
                    && drawn
                        .as_ref()
                        .is_some_and(|d| d.design_key == editor.key || d.stream.is_some()),
                finished,
                drawn.is_some_and(|d| d.stream.is_some()),
            )
        };
        let ready = recorded && finished;
        if recorded && !finished {
            // The next frame asks to hear when the GPU is done; backends that report it
            // only when polled (wgpu's GL) hear of it in a later frame.
            ctx.request_repaint_after(std::time::Duration::from_millis(100));
        }
        let progress = rendering
            .progress()
            .filter(|_| rendering.gpu && editor.active.is_none() && !ready)
            // Rounded down: 1 only when done (and then the hook is gone).
            .map(|p| format!("{:.3}", (p * 1000.0).floor() / 1000.0));
        let (preview_ready, work) = rendering
            .status
            .lock()
            .ok()
            .map(|s| {
                let asked = s.cache_ready == Some(editor.key);
                if recorded && !asked && !streaming {
                    // One more frame builds the live-preview cache (none is built while
                    // the stream shows).
                    ctx.request_repaint();
                }
                let done = s.cache_done.load(std::sync::atomic::Ordering::SeqCst) == editor.key;
                if asked && !done {
                    // Backends that report finished work only when polled (wgpu's GL)
                    // hear of it in a later frame: look again soon.
                    ctx.request_repaint_after(std::time::Duration::from_millis(250));
                }
                (asked && done, s.work)
            })
            .unwrap_or_default();
        let preview_samples = rendering
            .fast_paint
            .preview_antialias(prefs.antialias)
            .samples()
            .len()
            .min(marbling_gpu::params::MAX_PREVIEW_SAMPLES);
        let (panel_copies, panel_renders) = rendering.fast_paint.panel_counts();
        let error = panels
            .message
            .as_ref()
            .filter(|m| m.error)
            .map(|m| m.text.clone());
        let view = self
            .sheet_on_page
            .map(|[x, y, s]| format!("{x:.3},{y:.3},{s:.9}"));
        let frame_ms = (!self.frame_times.is_empty()).then(|| {
            format!(
                "{:.2}",
                1000.0 * self.frame_times.iter().sum::<f64>() / self.frame_times.len() as f64
            )
        });
        if self
            .noise_json
            .as_ref()
            .is_none_or(|(r, _)| *r != noise.revision())
        {
            let noise = &noise;
            let json = noise.settings().export_spec().to_value().to_string();
            self.noise_json = Some((noise.revision(), json));
        }
        let controls = self
            .controls
            .iter()
            .map(|(n, r)| {
                format!(
                    "{n}={:.0},{:.0},{:.0},{:.0}",
                    r.min.x,
                    r.min.y,
                    r.width(),
                    r.height()
                )
            })
            .collect::<Vec<_>>()
            .join(";");
        let exporting = panels
            .export
            .png_hook()
            .or_else(|| {
                let side = noise.export_side()?;
                Some(format!("{side}x{side}"))
            })
            .or_else(|| panels.export.svg_hook());
        let wanted: Vec<(&'static str, Option<String>)> = vec![
            ("data-ready", ready.then(|| "1".to_owned())),
            ("data-progress", progress),
            ("data-backend", Some(rendering.backend.clone())),
            ("data-ops", Some(editor.shown.op_count().to_string())),
            ("data-error", error),
            ("data-view", view),
            ("data-frame-ms", frame_ms),
            ("data-frames", Some(self.frames.to_string())),
            (
                "data-video-frames",
                rendering
                    .video
                    .live_frame()
                    .map(|_| rendering.video.frames_taken().to_string()),
            ),
            (
                "data-view3d-frames",
                panels.view3d.open.then(|| panels.view3d.frames.to_string()),
            ),
            ("data-view3d", panels.view3d.hook()),
            ("data-midi-learning", panels.midi.learning_hook()),
            ("data-preview-ready", preview_ready.then(|| "1".to_owned())),
            ("data-qr", panels.qr.hook()),
            (
                "data-gpu-work",
                Some(format!(
                    "exact={},tiles={},frame_units={},ops_written={},preview={},caches={},preview_samples={},panel_copies={},panel_renders={}",
                    work.exact,
                    work.tiles,
                    work.frame_units,
                    work.ops_written,
                    work.preview,
                    work.caches,
                    preview_samples,
                    panel_copies,
                    panel_renders
                )),
            ),
            ("data-fast-paint", Some(rendering.fast_paint.hook())),
            ("data-controls", Some(controls)),
            ("data-exporting", exporting),
            ("data-memory", self.memory.as_ref().map(|(_, m)| m.clone())),
            ("data-mode", Some(editor.mode.name().to_owned())),
            ("data-status", Some(self.status.clone())),
            (
                "data-noise",
                self.noise_json.as_ref().map(|(_, j)| j.clone()),
            ),
            ("data-noise-preview", Some(noise.preview_hook())),
            ("data-audio", panels.sound.hook()),
            ("data-stream", rendering.stream.hook(&prefs.settings)),
            ("data-layout", Some(panels.layout.name().to_owned())),
            (
                "data-focus",
                crate::shell::accessibility::focused_control(
                    ctx,
                    self.controls.iter().map(|(n, r)| (n.as_ref(), *r)),
                )
                .map(str::to_owned),
            ),
            ("data-landing", editor.landing.then(|| "1".to_owned())),
            (
                "data-player",
                editor.playback.map(|p| {
                    let steps = editor.history.design().gesture_sizes().len();
                    format!("{}/{steps}", p.position())
                }),
            ),
            (
                "data-thumbnails",
                panels.gallery.view().map(|g| {
                    let (drawn, total) = g.progress();
                    format!("{drawn}/{total}")
                }),
            ),
            (
                "data-thumbnails-from",
                panels.gallery.view().map(|g| g.source().to_owned()),
            ),
            (
                "data-recovered",
                (recovery::recoveries() > 0).then(|| recovery::recoveries().to_string()),
            ),
        ];
        if ready {
            recovery::note_drawn();
        }
        for (name, value) in &wanted {
            if !self.written.contains(&(*name, value.clone())) {
                platform::set_body_attribute(name, value.as_deref());
            }
        }
        self.written = wanted;
    }
}
