//! The automation hooks: attributes of the page's `<body>` that tests and tools read
//! (the README lists them). Only changed values are written.

use crate::app::MarblingApp;
use crate::{platform, recovery};

impl MarblingApp {
    /// Keeps the `<body>` automation hooks current (only changed values are written).
    pub(crate) fn update_hooks(&mut self, ctx: &egui::Context) {
        // Recorded: the exact frame this frame's canvas asks for — this design, view,
        // size, antialiasing and picture — is in the canvas texture's commands. Ready: the
        // GPU has also finished it (the queue's work-done callback). A zoom, pan or resize
        // asks for another frame, so ready falls to 0 until that one is drawn.
        let (recorded, finished, streaming) = {
            let st = self.rendering.status.lock().ok();
            let drawn = st.as_ref().and_then(|s| s.drawn.clone());
            let finished = st.as_ref().is_some_and(|s| {
                s.exact_done.load(std::sync::atomic::Ordering::SeqCst) == s.work.exact
            });
            (
                self.rendering.gpu
                    && !self.editor.landing
                    && self.editor.active.is_none()
                    && self.editor.playback.is_none_or(|p| !p.playing)
                    && self.hooks.requested.is_some()
                    && drawn == self.hooks.requested
                    && drawn
                        .as_ref()
                        .is_some_and(|d| d.design_key == self.editor.key || d.stream.is_some()),
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
        let progress = self
            .rendering
            .progress()
            .filter(|_| self.rendering.gpu && self.editor.active.is_none() && !ready)
            // Rounded down: 1 only when done (and then the hook is gone).
            .map(|p| format!("{:.3}", (p * 1000.0).floor() / 1000.0));
        let (preview_ready, work) = self
            .rendering
            .status
            .lock()
            .ok()
            .map(|s| {
                let asked = s.cache_ready == Some(self.editor.key);
                if recorded && !asked && !streaming {
                    // One more frame builds the live-preview cache (none is built while
                    // the stream shows).
                    ctx.request_repaint();
                }
                let done =
                    s.cache_done.load(std::sync::atomic::Ordering::SeqCst) == self.editor.key;
                if asked && !done {
                    // Backends that report finished work only when polled (wgpu's GL)
                    // hear of it in a later frame: look again soon.
                    ctx.request_repaint_after(std::time::Duration::from_millis(250));
                }
                (asked && done, s.work)
            })
            .unwrap_or_default();
        let preview_samples = self
            .rendering
            .fast_paint
            .preview_antialias(self.prefs.antialias)
            .samples()
            .len()
            .min(marbling_gpu::params::MAX_PREVIEW_SAMPLES);
        let (panel_copies, panel_renders) = self.rendering.fast_paint.panel_counts();
        let error = self
            .panels
            .message
            .as_ref()
            .filter(|m| m.error)
            .map(|m| m.text.clone());
        let view = self
            .hooks
            .sheet_on_page
            .map(|[x, y, s]| format!("{x:.3},{y:.3},{s:.9}"));
        let frame_ms = (!self.hooks.frame_times.is_empty()).then(|| {
            format!(
                "{:.2}",
                1000.0 * self.hooks.frame_times.iter().sum::<f64>()
                    / self.hooks.frame_times.len() as f64
            )
        });
        if self
            .hooks
            .noise_json
            .as_ref()
            .is_none_or(|(r, _)| *r != self.noise.revision())
        {
            let noise = &self.noise;
            let json = noise.settings().export_spec().to_value().to_string();
            self.hooks.noise_json = Some((noise.revision(), json));
        }
        let controls = self
            .hooks
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
        let exporting = self
            .rendering
            .export
            .as_ref()
            .map(|(e, _)| format!("{}x{}", e.size().0, e.size().1))
            .or_else(|| {
                let side = self.noise.export_side()?;
                Some(format!("{side}x{side}"))
            })
            .or_else(|| {
                let done = self.rendering.svg.progress()?;
                Some(format!("svg {:.0}%", 100.0 * done))
            });
        let wanted: Vec<(&'static str, Option<String>)> = vec![
            ("data-ready", ready.then(|| "1".to_owned())),
            ("data-progress", progress),
            ("data-backend", Some(self.rendering.backend.clone())),
            ("data-ops", Some(self.editor.shown.op_count().to_string())),
            ("data-error", error),
            ("data-view", view),
            ("data-frame-ms", frame_ms),
            ("data-frames", Some(self.hooks.frames.to_string())),
            (
                "data-video-frames",
                self.rendering
                    .video
                    .live_frame()
                    .map(|_| self.rendering.video.frames_taken().to_string()),
            ),
            (
                "data-view3d-frames",
                self.panels
                    .view3d
                    .open
                    .then(|| self.panels.view3d.frames.to_string()),
            ),
            ("data-view3d", self.panels.view3d.hook()),
            ("data-midi-learning", self.panels.midi.learning_hook()),
            ("data-preview-ready", preview_ready.then(|| "1".to_owned())),
            ("data-qr", self.panels.qr.hook()),
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
            ("data-fast-paint", Some(self.rendering.fast_paint.hook())),
            ("data-controls", Some(controls)),
            ("data-exporting", exporting),
            (
                "data-memory",
                self.hooks.memory.as_ref().map(|(_, m)| m.clone()),
            ),
            ("data-mode", Some(self.editor.mode.name().to_owned())),
            ("data-status", Some(self.hooks.status.clone())),
            (
                "data-noise",
                self.hooks.noise_json.as_ref().map(|(_, j)| j.clone()),
            ),
            ("data-noise-preview", Some(self.noise.preview_hook())),
            ("data-audio", self.panels.sound.hook()),
            (
                "data-stream",
                self.rendering.stream.hook(&self.prefs.settings),
            ),
            ("data-layout", Some(self.panels.layout.name().to_owned())),
            (
                "data-focus",
                crate::shell::accessibility::focused_control(
                    ctx,
                    self.hooks.controls.iter().map(|(n, r)| (n.as_ref(), *r)),
                )
                .map(str::to_owned),
            ),
            ("data-landing", self.editor.landing.then(|| "1".to_owned())),
            (
                "data-player",
                self.editor.playback.map(|p| {
                    let steps = self.editor.history.design().gesture_sizes().len();
                    format!("{}/{steps}", p.position())
                }),
            ),
            (
                "data-thumbnails",
                self.panels.gallery.view().map(|g| {
                    let (drawn, total) = g.progress();
                    format!("{drawn}/{total}")
                }),
            ),
            (
                "data-thumbnails-from",
                self.panels.gallery.view().map(|g| g.source().to_owned()),
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
            if !self.hooks.written.contains(&(*name, value.clone())) {
                platform::set_body_attribute(name, value.as_deref());
            }
        }
        self.hooks.written = wanted;
    }
}
