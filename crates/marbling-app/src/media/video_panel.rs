//! The *Live video* controls: start the camera or a video file as the background,
//! stop it, keep the current frame as the design's picture, record the marbled canvas;
//! and taking each new frame from the playing video (src/media/video.rs). Web only.

use crate::action::Action;
use crate::frame::Frame;
use crate::media::video::LiveFrame;
#[cfg(target_arch = "wasm32")]
use crate::media::video::VideoSource;
use egui::RichText;
use marbling_core::ImageFit;

/// The live video background: the playing video, its latest frame (shown as the
/// design's picture), how frames are laid on the sheet, and where a picked file arrives.
pub(crate) struct LiveVideoBackground {
    #[cfg(target_arch = "wasm32")]
    video: Option<crate::media::video::LiveVideo>,
    live_frame: Option<LiveFrame>,
    fit: ImageFit,
    pick: crate::platform::PickSlot,
    /// Frames taken since the video started (for `data-video-frames`).
    frames: u64,
}

impl Default for LiveVideoBackground {
    fn default() -> Self {
        Self {
            #[cfg(target_arch = "wasm32")]
            video: None,
            live_frame: None,
            fit: ImageFit::Cover,
            pick: Default::default(),
            frames: 0,
        }
    }
}

impl LiveVideoBackground {
    /// The video's latest frame, shown as the design's picture.
    pub fn live_frame(&self) -> Option<&LiveFrame> {
        self.live_frame.as_ref()
    }

    /// Frames taken since the video started.
    pub fn frames_taken(&self) -> u64 {
        self.frames
    }

    /// Takes the playing video's new frame, if any, once the canvas shows the last one
    /// whole (`drawn`: the number of the live frame the canvas drew last), and reports
    /// a video that could not start (the design is left as it is).
    pub fn tick(&mut self, ctx: &egui::Context, drawn: Option<u64>, frame: &mut Frame<'_>) {
        #[cfg(target_arch = "wasm32")]
        {
            if let Some(Ok((name, bytes))) = self.pick.lock().ok().and_then(|mut s| s.take()) {
                let mime = mime_of(&name);
                let source = VideoSource::File(name, mime.to_owned(), std::sync::Arc::new(bytes));
                self.start(&source, ctx, frame);
            }
            let Some(video) = &mut self.video else {
                return;
            };
            if let Some(e) = video.take_failure() {
                let what = match video.label.as_str() {
                    "camera" => "Camera not available".to_owned(),
                    name => format!("{name}: cannot play the video"),
                };
                self.stop();
                frame.error(format!("{what}: {e}; the design is unchanged"));
                return;
            }
            // The next frame is taken once the canvas shows the last one whole: each
            // shown frame is marbled completely, as fast as the renderer goes.
            let current = self.live_frame.as_ref().map(|f| f.number);
            if current.is_some() && drawn != current {
                ctx.request_repaint();
                return;
            }
            let Some(video) = &mut self.video else {
                return;
            };
            if let Some(live) = video.frame(self.fit) {
                let size = (live.pixels.width, live.pixels.height);
                self.live_frame = Some(live);
                self.frames += 1;
                if self.frames == 1 {
                    let label = video.label.clone();
                    frame.info(format!("live video: {label}, {}×{}", size.0, size.1));
                }
            }
            // Frames arrive between egui's events: keep polling while it plays.
            ctx.request_repaint();
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (ctx, drawn, frame);
    }

    /// Starts `source` as the live background (replacing a video already playing).
    #[cfg(target_arch = "wasm32")]
    fn start(&mut self, source: &VideoSource, ctx: &egui::Context, frame: &mut Frame<'_>) {
        self.stop();
        match crate::media::video::LiveVideo::start(source, ctx.clone()) {
            Ok(v) => {
                frame.info(format!("live video: {} starting…", v.label));
                self.video = Some(v);
                self.frames = 0;
            }
            Err(e) => frame.error(format!("cannot start the video: {e}")),
        }
    }

    /// Stops the live video (and its recording); the design's own background returns.
    fn stop(&mut self) {
        #[cfg(target_arch = "wasm32")]
        {
            self.video = None;
        }
        self.live_frame = None;
    }

    /// The *Live video* controls (web only: a desktop window has *Open image…*).
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        if !cfg!(target_arch = "wasm32") {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            ui.label(RichText::new("Live video").strong());
            let camera = ui
                .button("Camera")
                .on_hover_text("Marble your webcam's picture, live");
            frame.control("video-camera", &camera);
            let file = ui
                .button("Video file…")
                .on_hover_text("Marble a video file (WebM, MP4), looping");
            frame.control("video-file", &file);
            #[cfg(target_arch = "wasm32")]
            if camera.clicked() {
                self.start(&VideoSource::Camera, ui.ctx(), frame);
            }
            if file.clicked() {
                crate::platform::pick_file(
                    self.pick.clone(),
                    crate::media::video::VIDEO_FILE,
                    ui.ctx().clone(),
                );
            }
        });
        if self.live_frame.is_none() {
            return;
        }
        ui.horizontal_wrapped(|ui| {
            for name in marbling_core::image_background::IMAGE_FITS {
                let fit = ImageFit::from_name(name).unwrap_or_default();
                let r = ui.selectable_label(self.fit == fit, *name);
                if r.clicked() {
                    self.fit = fit;
                }
            }
            let stop = ui.button("Stop");
            frame.control("video-stop", &stop);
            if stop.clicked() {
                self.stop();
                frame.info("live video stopped");
            }
            let keep = ui
                .button("Use this frame")
                .on_hover_text("Make the current frame the design's picture");
            frame.control("video-keep", &keep);
            if keep.clicked()
                && let Some(live) = self.live_frame.clone()
            {
                match live.to_background() {
                    Ok(image) => {
                        self.stop();
                        frame.act(Action::SetBackgroundImage {
                            image: Some(image),
                            what: "picture: a video frame".to_owned(),
                        });
                    }
                    Err(e) => frame.error(format!("cannot keep the frame: {e}")),
                }
            }
            self.record_button(ui, frame);
        });
    }

    /// *Record* / *Stop recording* of the marbled canvas while the video plays.
    fn record_button(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        #[cfg(target_arch = "wasm32")]
        {
            let Some(video) = &mut self.video else {
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
            frame.control("video-record", &r);
            if !r.clicked() {
                return;
            }
            match video.recording.take() {
                Some(rec) => {
                    rec.finish("marbled-video.webm");
                    frame.info("recording saved as marbled-video.webm");
                }
                None => {
                    match crate::media::recorder::Recorder::start(crate::media::video::RECORD_FPS) {
                        Ok(rec) => {
                            video.recording = Some(rec);
                            frame.info("recording the marbled video…");
                        }
                        Err(e) => frame.error(e),
                    }
                }
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = (ui, frame);
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
