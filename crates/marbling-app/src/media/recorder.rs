//! *Record*: a WebM made by the browser's MediaRecorder, downloaded when the recording
//! stops. The step player films the page's canvas (what the window shows: the sheet, the
//! tool moving and the captions); the 3D view's turn films frames handed to it one by
//! one ([`Recorder::start_frames`], [`Recorder::push_frame`]) on a canvas of its own.
//! Outside the browser, `marbling animate` and `marbling render-3d --turn` write loops
//! instead.

/// Why there is no recording outside the browser.
#[cfg(not(target_arch = "wasm32"))]
const NEEDS_THE_WEB: &str = "recording a video needs the web app; `marbling animate` and \
     `marbling render-3d --turn` write loops as animated PNG or GIF";

/// A recording in progress.
pub struct Recorder {
    #[cfg(target_arch = "wasm32")]
    imp: web::Recording,
}

impl Recorder {
    /// Starts filming the page's canvas at `fps` frames per second.
    pub fn start(fps: f64) -> Result<Self, String> {
        #[cfg(target_arch = "wasm32")]
        {
            web::Recording::start(None, fps).map(|imp| Self { imp })
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = fps;
            Err(NEEDS_THE_WEB.into())
        }
    }

    /// Starts filming frames of `width` × `height` pixels handed to
    /// [`Recorder::push_frame`]: each is one frame of the video, shown until the next
    /// arrives (the video runs at the pace they come).
    pub fn start_frames(width: u32, height: u32) -> Result<Self, String> {
        #[cfg(target_arch = "wasm32")]
        {
            web::Recording::start(Some((width, height)), 0.0).map(|imp| Self { imp })
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = (width, height);
            Err(NEEDS_THE_WEB.into())
        }
    }

    /// Shows the next frame (`width` × `height` RGBA8, sRGB) of a recording of frames.
    pub fn push_frame(&self, width: u32, height: u32, rgba: &[u8]) -> Result<(), String> {
        #[cfg(target_arch = "wasm32")]
        {
            self.imp.push_frame(width, height, rgba)
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = (width, height, rgba);
            Err(NEEDS_THE_WEB.into())
        }
    }

    /// Stops; the video downloads as `name` once the browser has it.
    pub fn finish(self, name: &str) {
        #[cfg(target_arch = "wasm32")]
        self.imp.finish(Some(name));
        #[cfg(not(target_arch = "wasm32"))]
        let _ = name;
    }

    /// Stops without saving anything.
    pub fn discard(self) {
        #[cfg(target_arch = "wasm32")]
        self.imp.finish(None);
    }
}

#[cfg(target_arch = "wasm32")]
mod web {
    use std::cell::RefCell;
    use std::rc::Rc;
    use wasm_bindgen::JsCast;
    use wasm_bindgen::closure::Closure;

    pub struct Recording {
        /// The canvas frames are drawn on and its captured track (each frame is asked
        /// for by hand), for a recording of frames.
        painter: Option<(
            web_sys::CanvasRenderingContext2d,
            web_sys::CanvasCaptureMediaStreamTrack,
        )>,
        recorder: web_sys::MediaRecorder,
        chunks: Rc<RefCell<Vec<web_sys::Blob>>>,
        _on_data: Closure<dyn FnMut(web_sys::BlobEvent)>,
    }

    impl Recording {
        /// Films the page's canvas `fps` times a second, or with `frames` a new canvas
        /// of that size, a frame each time one is pushed (`fps` 0).
        pub fn start(frames: Option<(u32, u32)>, fps: f64) -> Result<Self, String> {
            let fail = |what: &str| format!("cannot record a video: {what}");
            let document = web_sys::window()
                .and_then(|w| w.document())
                .ok_or_else(|| fail("no document"))?;
            let element = match frames {
                None => document.get_element_by_id(crate::platform::CANVAS_ID),
                Some(_) => {
                    // In the page (the browser captures only a canvas it renders), unseen.
                    let canvas = document.create_element("canvas").ok();
                    if let (Some(c), Some(body)) = (&canvas, document.body()) {
                        let _ = c.set_attribute(
                            "style",
                            "position:fixed;left:0;top:0;width:1px;height:1px;opacity:0;\
                             pointer-events:none;z-index:-1",
                        );
                        let _ = body.append_child(c);
                    }
                    canvas
                }
            };
            let canvas: web_sys::HtmlCanvasElement = element
                .and_then(|e| e.dyn_into().ok())
                .ok_or_else(|| fail("no canvas"))?;
            // The page's canvas is sampled `fps` times a second; a canvas of frames
            // gives a video frame exactly when one is drawn (rate 0: by hand).
            let stream = canvas
                .capture_stream_with_frame_request_rate(fps)
                .map_err(|_| fail("the canvas cannot be captured"))?;
            let painter = match frames {
                None => None,
                Some((w, h)) => {
                    canvas.set_width(w);
                    canvas.set_height(h);
                    let context = canvas
                        .get_context("2d")
                        .ok()
                        .flatten()
                        .and_then(|c| c.dyn_into().ok())
                        .ok_or_else(|| fail("no 2D canvas"))?;
                    let track = stream
                        .get_video_tracks()
                        .get(0)
                        .dyn_into()
                        .map_err(|_| fail("the canvas gave no video track"))?;
                    Some((context, track))
                }
            };
            let options = web_sys::MediaRecorderOptions::new();
            options.set_mime_type("video/webm");
            let recorder =
                web_sys::MediaRecorder::new_with_media_stream_and_media_recorder_options(
                    &stream, &options,
                )
                .map_err(|_| fail("this browser cannot record WebM"))?;
            let chunks: Rc<RefCell<Vec<web_sys::Blob>>> = Rc::default();
            let sink = chunks.clone();
            let on_data =
                Closure::<dyn FnMut(web_sys::BlobEvent)>::new(move |e: web_sys::BlobEvent| {
                    if let Some(b) = e.data() {
                        sink.borrow_mut().push(b);
                    }
                });
            recorder.set_ondataavailable(Some(on_data.as_ref().unchecked_ref()));
            recorder
                .start_with_time_slice(500)
                .map_err(|_| fail("the recorder did not start"))?;
            Ok(Self {
                painter,
                recorder,
                chunks,
                _on_data: on_data,
            })
        }

        pub fn push_frame(&self, width: u32, height: u32, rgba: &[u8]) -> Result<(), String> {
            let (painter, track) = self
                .painter
                .as_ref()
                .ok_or("this recording films the page, not frames")?;
            let image = web_sys::ImageData::new_with_u8_clamped_array_and_sh(
                wasm_bindgen::Clamped(rgba),
                width,
                height,
            )
            .map_err(|e| format!("a recorded frame: {}", crate::platform::js_error(&e)))?;
            painter
                .put_image_data(&image, 0.0, 0.0)
                .map_err(|e| format!("a recorded frame: {}", crate::platform::js_error(&e)))?;
            track.request_frame();
            Ok(())
        }

        /// Stops; with `name` the video downloads as it.
        pub fn finish(self, name: Option<&str>) {
            let Self {
                painter,
                recorder,
                chunks,
                _on_data,
            } = self;
            // The canvas of frames leaves the page once the recorder has stopped.
            let canvas = painter.and_then(|(context, _)| context.canvas());
            let Some(name) = name.map(str::to_owned) else {
                // Nothing calls the handler once it is gone.
                recorder.set_ondataavailable(None);
                let _ = recorder.stop();
                if let Some(c) = canvas {
                    c.remove();
                }
                return;
            };
            let on_stop = Closure::once_into_js(move |_: web_sys::Event| {
                // The last chunk arrived before `stop`.
                drop(_on_data);
                if let Some(c) = canvas {
                    c.remove();
                }
                let parts = js_sys::Array::new();
                for b in chunks.borrow().iter() {
                    parts.push(b);
                }
                let props = web_sys::BlobPropertyBag::new();
                props.set_type("video/webm");
                if let Ok(blob) = web_sys::Blob::new_with_blob_sequence_and_options(&parts, &props)
                    && let Err(e) = crate::platform::download_blob(&name, &blob)
                {
                    log::warn!("{e}");
                }
            });
            recorder.set_onstop(Some(on_stop.unchecked_ref()));
            let _ = recorder.stop();
        }
    }
}

/// How a recording of the making ends so that the video loops: the finished design held
/// for `hold` seconds, then with `reverse` the making played backwards to the bare tank.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoopEnding {
    /// Seconds on the finished design (0 to [`MAX_HOLD_S`]).
    pub hold: f64,
    /// Whether the making plays backwards after the hold.
    pub reverse: bool,
}

/// The longest hold offered, seconds.
pub const MAX_HOLD_S: f64 = 10.0;

impl Default for LoopEnding {
    fn default() -> Self {
        Self {
            hold: 1.0,
            reverse: false,
        }
    }
}

/// Where a recording is in the making.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Phase {
    /// The making plays forward.
    Forward,
    /// The finished design is held until `until` (seconds of the UI clock).
    Holding {
        /// When the hold ends.
        until: f64,
    },
    /// The making plays backwards.
    Backward,
}

/// What a recording does after [`Phase::next`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Next {
    /// Goes on in this phase (the same or a new one).
    Go(Phase),
    /// Starts playing the making backwards from the end.
    PlayBackward,
    /// Stops; the video downloads.
    Finish,
}

impl Phase {
    /// The next step of a recording in this phase, `ending` as chosen: `playing` and
    /// `at_end` describe the player (`None`: closed), `now` the UI clock (s). A player
    /// paused or closed before the end finishes the recording where it is.
    pub fn next(self, ending: LoopEnding, player: Option<(bool, bool)>, now: f64) -> Next {
        let after_hold = if ending.reverse {
            Next::PlayBackward
        } else {
            Next::Finish
        };
        match (self, player) {
            (_, None) => Next::Finish,
            (Phase::Forward | Phase::Backward, Some((true, _))) => Next::Go(self),
            (Phase::Forward, Some((false, true))) if ending.hold > 0.0 => {
                Next::Go(Phase::Holding {
                    until: now + ending.hold,
                })
            }
            (Phase::Forward, Some((false, true))) => after_hold,
            (Phase::Holding { until }, Some(_)) if now < until => Next::Go(self),
            (Phase::Holding { .. }, Some(_)) => after_hold,
            (Phase::Forward | Phase::Backward, Some((false, _))) => Next::Finish,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_looping_recording_plays_holds_reverses_and_stops() {
        let looping = LoopEnding {
            hold: 1.5,
            reverse: true,
        };
        let playing = Some((true, false));
        let at_end = Some((false, true));
        assert_eq!(
            Phase::Forward.next(looping, playing, 0.0),
            Next::Go(Phase::Forward)
        );
        let hold = Phase::Holding { until: 11.5 };
        assert_eq!(Phase::Forward.next(looping, at_end, 10.0), Next::Go(hold));
        assert_eq!(hold.next(looping, at_end, 11.0), Next::Go(hold));
        assert_eq!(hold.next(looping, at_end, 11.5), Next::PlayBackward);
        assert_eq!(
            Phase::Backward.next(looping, playing, 12.0),
            Next::Go(Phase::Backward)
        );
        assert_eq!(
            Phase::Backward.next(looping, Some((false, false)), 13.0),
            Next::Finish
        );
        // Without reverse the hold ends it; without a hold the end does.
        let held = LoopEnding {
            hold: 1.0,
            reverse: false,
        };
        assert_eq!(
            Phase::Holding { until: 1.0 }.next(held, at_end, 2.0),
            Next::Finish
        );
        let plain = LoopEnding {
            hold: 0.0,
            reverse: false,
        };
        assert_eq!(Phase::Forward.next(plain, at_end, 0.0), Next::Finish);
        assert_eq!(
            Phase::Forward.next(
                LoopEnding {
                    hold: 0.0,
                    reverse: true
                },
                at_end,
                0.0
            ),
            Next::PlayBackward
        );
        // Paused early or closed: it stops where it is.
        assert_eq!(
            Phase::Forward.next(looping, Some((false, false)), 0.0),
            Next::Finish
        );
        assert_eq!(hold.next(looping, None, 0.0), Next::Finish);
    }
}
