//! Live video as the background (Lu et al. 2012: "every video frame is a marbling
//! pattern"): the webcam (getUserMedia) or a video file plays in a hidden `<video>`;
//! each new frame is drawn into a 2D canvas of at most [`MAX_FRAME`] pixels, read back
//! and handed to the exact renderer as the design's picture (`ExactRenderer::
//! set_live_image`), so every frame is marbled through the whole design while the
//! tools keep working on top. *Use this frame* makes the current frame the design's
//! picture; *Record* films the canvas to a WebM. Web only: a desktop window has
//! *Open image…*.
// The desktop build keeps the shared parts (tested natively) without their web users.
#![cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]

use marbling_core::image_background::ImagePixels;
use marbling_core::{ImageBackground, ImageFit};
use std::sync::Arc;

/// Largest frame handed to the renderer, pixels (the aspect is kept).
pub const MAX_FRAME: [u32; 2] = [640, 480];
/// A video file the browser plays.
pub const VIDEO_FILE: crate::platform::FileKind = (
    "video (WebM, MP4, Ogg)",
    &["webm", "mp4", "m4v", "ogv", "mov"],
);
/// Frames per second of *Record*.
pub const RECORD_FPS: f64 = 30.0;

/// One frame of the live picture, numbered: a new number asks for a new exact frame.
#[derive(Clone, Debug)]
pub struct LiveFrame {
    /// Increases with every frame taken from the video.
    pub number: u64,
    /// The frame's pixels.
    pub pixels: Arc<ImagePixels>,
    /// How it is laid on the sheet.
    pub fit: ImageFit,
}

impl PartialEq for LiveFrame {
    fn eq(&self, other: &Self) -> bool {
        self.number == other.number && self.fit == other.fit
    }
}

impl LiveFrame {
    /// The frame as a picture background (JPEG-encoded, for *Use this frame*).
    pub fn to_background(&self) -> Result<ImageBackground, String> {
        ImageBackground::from_file_bytes(&self.pixels.to_jpeg(4096, 92), self.fit)
            .map_err(|e| e.to_string())
    }
}

/// The frame size for a `w`×`h` video: at most [`MAX_FRAME`], aspect kept.
pub fn frame_size(w: u32, h: u32) -> [u32; 2] {
    let k = (f64::from(MAX_FRAME[0]) / f64::from(w.max(1)))
        .min(f64::from(MAX_FRAME[1]) / f64::from(h.max(1)))
        .min(1.0);
    [
        ((f64::from(w) * k).round() as u32).max(1),
        ((f64::from(h) * k).round() as u32).max(1),
    ]
}

/// Where a video comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum VideoSource {
    /// The webcam.
    Camera,
    /// A picked file: its name, MIME type and bytes.
    File(String, String, Arc<Vec<u8>>),
}

#[cfg(target_arch = "wasm32")]
pub use web::LiveVideo;

#[cfg(target_arch = "wasm32")]
mod web {
    use super::{LiveFrame, VideoSource, frame_size};
    use marbling_core::ImageFit;
    use marbling_core::image_background::ImagePixels;
    use std::cell::RefCell;
    use std::rc::Rc;
    use std::sync::Arc;
    use wasm_bindgen::JsCast;

    /// A playing video and the canvas its frames are read through.
    pub struct LiveVideo {
        video: web_sys::HtmlVideoElement,
        canvas: web_sys::HtmlCanvasElement,
        context: web_sys::CanvasRenderingContext2d,
        /// The camera stream, once the browser granted it.
        stream: Rc<RefCell<Option<web_sys::MediaStream>>>,
        /// Why the video could not start, once known.
        failed: Rc<RefCell<Option<String>>>,
        object_url: Option<String>,
        last_time: f64,
        number: u64,
        /// What the user sees named in messages.
        pub label: String,
        /// A recording of the canvas in progress.
        pub recording: Option<crate::media::recorder::Recorder>,
    }

    use crate::platform::js_error;

    impl LiveVideo {
        /// Starts playing `source`; `ctx` is woken when it starts or fails.
        pub fn start(source: &VideoSource, ctx: egui::Context) -> Result<Self, String> {
            let document = web_sys::window()
                .and_then(|w| w.document())
                .ok_or("no document")?;
            let video: web_sys::HtmlVideoElement = document
                .create_element("video")
                .map_err(|e| js_error(&e))?
                .dyn_into()
                .map_err(|_| "no <video> element")?;
            video.set_muted(true);
            video.set_autoplay(true);
            let _ = video.set_attribute("playsinline", "");
            let canvas: web_sys::HtmlCanvasElement = document
                .create_element("canvas")
                .map_err(|e| js_error(&e))?
                .dyn_into()
                .map_err(|_| "no <canvas> element")?;
            let options = js_sys::Object::new();
            let _ = js_sys::Reflect::set(&options, &"willReadFrequently".into(), &true.into());
            let context: web_sys::CanvasRenderingContext2d = canvas
                .get_context_with_context_options("2d", &options)
                .map_err(|e| js_error(&e))?
                .ok_or("no 2D canvas")?
                .dyn_into()
                .map_err(|_| "no 2D canvas")?;
            let mut live = Self {
                video,
                canvas,
                context,
                stream: Rc::default(),
                failed: Rc::default(),
                object_url: None,
                last_time: -1.0,
                number: 0,
                label: String::new(),
                recording: None,
            };
            match source {
                VideoSource::Camera => {
                    live.label = "camera".to_owned();
                    live.start_camera(ctx)?;
                }
                VideoSource::File(name, mime, bytes) => {
                    live.label = name.clone();
                    let array = js_sys::Uint8Array::from(bytes.as_slice());
                    let parts = js_sys::Array::of1(&array);
                    let bag = web_sys::BlobPropertyBag::new();
                    bag.set_type(mime);
                    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &bag)
                        .map_err(|e| js_error(&e))?;
                    let url = web_sys::Url::create_object_url_with_blob(&blob)
                        .map_err(|e| js_error(&e))?;
                    live.video.set_loop(true);
                    live.video.set_src(&url);
                    live.object_url = Some(url);
                    live.play(ctx);
                }
            }
            Ok(live)
        }

        fn start_camera(&mut self, ctx: egui::Context) -> Result<(), String> {
            let devices = web_sys::window()
                .ok_or("no window")?
                .navigator()
                .media_devices()
                .map_err(
                    |_| "this browser gives no camera access (a secure https page is needed)",
                )?;
            let constraints = js_sys::Object::new();
            let video = js_sys::Object::new();
            let _ = js_sys::Reflect::set(&video, &"width".into(), &640.into());
            let _ = js_sys::Reflect::set(&video, &"height".into(), &480.into());
            let _ = js_sys::Reflect::set(&constraints, &"video".into(), &video);
            let promise = devices
                .get_user_media_with_constraints(constraints.unchecked_ref())
                .map_err(|e| js_error(&e))?;
            let (stream, failed, element) =
                (self.stream.clone(), self.failed.clone(), self.video.clone());
            wasm_bindgen_futures::spawn_local(async move {
                match wasm_bindgen_futures::JsFuture::from(promise).await {
                    Ok(s) => {
                        let s: web_sys::MediaStream = s.unchecked_into();
                        element.set_src_object(Some(&s));
                        if let Ok(p) = element.play() {
                            let _ = wasm_bindgen_futures::JsFuture::from(p).await;
                        }
                        *stream.borrow_mut() = Some(s);
                    }
                    Err(e) => *failed.borrow_mut() = Some(js_error(&e)),
                }
                ctx.request_repaint();
            });
            Ok(())
        }

        fn play(&self, ctx: egui::Context) {
            let Ok(promise) = self.video.play() else {
                return;
            };
            let failed = self.failed.clone();
            wasm_bindgen_futures::spawn_local(async move {
                if let Err(e) = wasm_bindgen_futures::JsFuture::from(promise).await {
                    *failed.borrow_mut() = Some(js_error(&e));
                }
                ctx.request_repaint();
            });
        }

        /// Why the video could not start, once (then `None`).
        pub fn take_failure(&self) -> Option<String> {
            self.failed.borrow_mut().take()
        }

        /// The next frame, when the video shows a new one.
        pub fn frame(&mut self, fit: ImageFit) -> Option<LiveFrame> {
            let v = &self.video;
            // HAVE_CURRENT_DATA: a frame can be drawn.
            if v.ready_state() < 2 || v.video_width() == 0 {
                return None;
            }
            let t = v.current_time();
            if t == self.last_time {
                return None;
            }
            self.last_time = t;
            let [w, h] = frame_size(v.video_width(), v.video_height());
            if self.canvas.width() != w || self.canvas.height() != h {
                self.canvas.set_width(w);
                self.canvas.set_height(h);
            }
            self.context
                .draw_image_with_html_video_element_and_dw_and_dh(
                    v,
                    0.0,
                    0.0,
                    f64::from(w),
                    f64::from(h),
                )
                .ok()?;
            let data = self
                .context
                .get_image_data(0.0, 0.0, f64::from(w), f64::from(h))
                .ok()?;
            let pixels = ImagePixels::from_rgba(w, h, data.data().0).ok()?;
            self.number += 1;
            Some(LiveFrame {
                number: self.number,
                pixels: Arc::new(pixels),
                fit,
            })
        }
    }

    impl Drop for LiveVideo {
        fn drop(&mut self) {
            let _ = self.video.pause();
            if let Some(s) = self.stream.borrow_mut().take() {
                for track in s.get_tracks().iter() {
                    if let Ok(t) = track.dyn_into::<web_sys::MediaStreamTrack>() {
                        t.stop();
                    }
                }
            }
            self.video.set_src_object(None);
            if let Some(url) = self.object_url.take() {
                let _ = web_sys::Url::revoke_object_url(&url);
            }
            if let Some(r) = self.recording.take() {
                r.finish("marbled-video.webm");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_keep_the_aspect_within_640_by_480() {
        assert_eq!(frame_size(1280, 720), [640, 360]);
        assert_eq!(frame_size(640, 480), [640, 480]);
        assert_eq!(frame_size(320, 240), [320, 240]);
        assert_eq!(frame_size(480, 1920), [120, 480]);
    }
}
