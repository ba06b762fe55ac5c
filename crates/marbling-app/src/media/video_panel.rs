//! The *Live video* controls: start the camera or a video file as the background,
//! stop it, keep the current frame as the design's picture, record the marbled canvas;
//! and taking each new frame from the playing video (src/media/video.rs). Web only.

use crate::action::Action;
use crate::app::MarblingApp;
#[cfg(target_arch = "wasm32")]
use crate::media::video::VideoSource;
use egui::RichText;

impl MarblingApp {
    /// Takes the playing video's new frame, if any, and reports a video that could not
    /// start (the design is left as it is).
    pub(crate) fn advance_video(&mut self, ctx: &egui::Context) {
        #[cfg(target_arch = "wasm32")]
        {
            if let Some(Ok((name, bytes))) = self
                .rendering
                .video_pick
                .lock()
                .ok()
                .and_then(|mut s| s.take())
            {
                let mime = mime_of(&name);
                self.start_video(
                    &VideoSource::File(name, mime.to_owned(), std::sync::Arc::new(bytes)),
                    ctx,
                );
            }
            let Some(video) = &mut self.rendering.video else {
                return;
            };
            if let Some(e) = video.take_failure() {
                let what = match video.label.as_str() {
                    "camera" => "Camera not available".to_owned(),
                    name => format!("{name}: cannot play the video"),
                };
                self.stop_video();
                self.error(format!("{what}: {e}; the design is unchanged"));
                return;
            }
            // The next frame is taken once the canvas shows the last one whole: each
            // shown frame is marbled completely, as fast as the renderer goes.
            let current = self.rendering.live_frame.as_ref().map(|f| f.number);
            let drawn = self.rendering.status.lock().ok().and_then(|s| {
                s.drawn
                    .as_ref()
                    .and_then(|r| r.live.as_ref())
                    .map(|f| f.number)
            });
            if current.is_some() && drawn != current {
                ctx.request_repaint();
                return;
            }
            let Some(video) = &mut self.rendering.video else {
                return;
            };
            if let Some(frame) = video.frame(self.rendering.video_fit) {
                let size = (frame.pixels.width, frame.pixels.height);
                self.rendering.live_frame = Some(frame);
                self.rendering.video_frames += 1;
                if self.rendering.video_frames == 1 {
                    let label = video.label.clone();
                    self.info(format!("live video: {label}, {}×{}", size.0, size.1));
                }
            }
            // Frames arrive between egui's events: keep polling while it plays.
            ctx.request_repaint();
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = ctx;
    }

    /// Starts `source` as the live background (replacing a video already playing).
    #[cfg(target_arch = "wasm32")]
    fn start_video(&mut self, source: &VideoSource, ctx: &egui::Context) {
        self.stop_video();
        match crate::media::video::LiveVideo::start(source, ctx.clone()) {
            Ok(v) => {
                self.info(format!("live video: {} starting…", v.label));
                self.rendering.video = Some(v);
                self.rendering.video_frames = 0;
            }
            Err(e) => self.error(format!("cannot start the video: {e}")),
        }
    }

    /// Stops the live video (and its recording); the design's own background returns.
    pub(crate) fn stop_video(&mut self) {
        #[cfg(target_arch = "wasm32")]
        {
            self.rendering.video = None;
        }
        self.rendering.live_frame = None;
    }

    /// The *Live video* controls (web only: a desktop window has *Open image…*).
    pub(crate) fn video_section(&mut self, ui: &mut egui::Ui) {
        if !cfg!(target_arch = "wasm32") {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new("Live video").strong());
            let camera = ui
                .button("Camera")
                .on_hover_text("Marble your webcam's picture, live");
            self.control("video-camera", &camera);
            let file = ui
                .button("Video file…")
                .on_hover_text("Marble a video file (WebM, MP4), looping");
            self.control("video-file", &file);
            #[cfg(target_arch = "wasm32")]
            if camera.clicked() {
                self.start_video(&VideoSource::Camera, ui.ctx());
            }
            if file.clicked() {
                crate::platform::pick_file(
                    self.rendering.video_pick.clone(),
                    crate::media::video::VIDEO_FILE,
                    ui.ctx().clone(),
                );
            }
        });
        if self.rendering.live_frame.is_none() {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            for name in marbling_core::image_background::IMAGE_FITS {
                let fit = marbling_core::ImageFit::from_name(name).unwrap_or_default();
                let r = ui.selectable_label(self.rendering.video_fit == fit, *name);
                if r.clicked() {
                    self.rendering.video_fit = fit;
                }
            }
            let stop = ui.button("Stop");
            self.control("video-stop", &stop);
            if stop.clicked() {
                self.stop_video();
                self.info("live video stopped");
            }
            let keep = ui
                .button("Use this frame")
                .on_hover_text("Make the current frame the design's picture");
            self.control("video-keep", &keep);
            if keep.clicked()
                && let Some(frame) = self.rendering.live_frame.clone()
            {
                match frame.to_background() {
                    Ok(image) => {
                        self.stop_video();
                        self.apply(Action::SetBackgroundImage {
                            image: Some(image),
                            what: "picture: a video frame".to_owned(),
                        });
                    }
                    Err(e) => self.error(format!("cannot keep the frame: {e}")),
                }
            }
            self.record_video_button(ui);
        });
    }

    /// *Record* / *Stop recording* of the marbled canvas while the video plays.
    fn record_video_button(&mut self, ui: &mut egui::Ui) {
        #[cfg(target_arch = "wasm32")]
        {
            let Some(video) = &mut self.rendering.video else {
                return;
            };
            let recording = video.recording.is_some();
            let label = if recording {
                "Stop recording"
            } else {
                "Record"
            };
            let r = ui
                .button(label)
                .on_hover_text("Film the marbled canvas to a WebM video");
            self.control("video-record", &r);
            if !r.clicked() {
                return;
            }
            let Some(video) = &mut self.rendering.video else {
                return;
            };
            match video.recording.take() {
                Some(rec) => {
                    rec.finish("marbled-video.webm");
                    self.info("recording saved as marbled-video.webm");
                }
                None => {
                    match crate::media::recorder::Recorder::start(crate::media::video::RECORD_FPS) {
                        Ok(rec) => {
                            video.recording = Some(rec);
                            self.info("recording the marbled video…");
                        }
                        Err(e) => self.error(e),
                    }
                }
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = ui;
    }
}

/// The MIME type of a video file named `name`.
#[cfg(target_arch = "wasm32")]
fn mime_of(name: &str) -> &'static str {
    let lower = name.to_ascii_lowercase();
    if lower.ends_with(".webm") {
        "video/webm"
    } else if lower.ends_with(".ogv") {
        "video/ogg"
    } else if lower.ends_with(".mov") {
        "video/quicktime"
    } else {
        "video/mp4"
    }
}
