//! *Record*: the step player filmed to a WebM by the browser's MediaRecorder on the
//! page's canvas (what the window shows: the sheet, the tool moving and the captions),
//! downloaded when the player reaches the end or the recording is stopped. Outside the
//! browser, `marbling animate` writes the making instead.

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
            web::Recording::start(fps).map(|imp| Self { imp })
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = fps;
            Err(
                "recording a video needs the web app; `marbling animate` writes the making \
                 as an animated PNG or GIF"
                    .into(),
            )
        }
    }

    /// Stops; the video downloads as `name` once the browser has it.
    pub fn finish(self, name: &str) {
        #[cfg(target_arch = "wasm32")]
        self.imp.finish(name);
        #[cfg(not(target_arch = "wasm32"))]
        let _ = name;
    }
}

#[cfg(target_arch = "wasm32")]
mod web {
    use std::cell::RefCell;
    use std::rc::Rc;
    use wasm_bindgen::JsCast;
    use wasm_bindgen::closure::Closure;

    pub struct Recording {
        recorder: web_sys::MediaRecorder,
        chunks: Rc<RefCell<Vec<web_sys::Blob>>>,
        _on_data: Closure<dyn FnMut(web_sys::BlobEvent)>,
    }

    impl Recording {
        pub fn start(fps: f64) -> Result<Self, String> {
            let fail = |what: &str| format!("cannot record a video: {what}");
            let canvas: web_sys::HtmlCanvasElement = web_sys::window()
                .and_then(|w| w.document())
                .and_then(|d| d.get_element_by_id(crate::platform::CANVAS_ID))
                .and_then(|e| e.dyn_into().ok())
                .ok_or_else(|| fail("no canvas"))?;
            let stream = canvas
                .capture_stream_with_frame_request_rate(fps)
                .map_err(|_| fail("the canvas cannot be captured"))?;
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
                recorder,
                chunks,
                _on_data: on_data,
            })
        }

        pub fn finish(self, name: &str) {
            let Self {
                recorder,
                chunks,
                _on_data,
            } = self;
            let name = name.to_owned();
            let on_stop = Closure::once_into_js(move |_: web_sys::Event| {
                // The last chunk arrived before `stop`.
                drop(_on_data);
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
