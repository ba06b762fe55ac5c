//! Sound from the browser for the Sound section (`sound.rs`): the microphone
//! (`getUserMedia`, with echo cancellation, noise suppression and gain control off, so a
//! steady tone is heard as it is) or an audio file (decoded by the `AudioContext`,
//! looping, heard through the speakers), into a Web Audio `AnalyserNode` of
//! [`FFT_SIZE`](crate::media::sound::FFT_SIZE) samples whose spectrum each frame reads.
//! The desktop app has no sound input.

/// Where the sound comes from.
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub enum SoundSource {
    /// The microphone (or Chromium's fake capture device).
    Microphone,
    /// An audio file: its name and bytes.
    File(String, Vec<u8>),
}

pub use imp::SoundInput;

#[cfg(target_arch = "wasm32")]
mod imp {
    use super::SoundSource;
    use crate::media::sound::{FFT_SIZE, SMOOTHING};
    use crate::platform::js_error;
    use std::cell::{Cell, RefCell};
    use std::rc::Rc;
    use wasm_bindgen::JsCast;

    /// Sound playing into the analyser.
    pub struct SoundInput {
        context: web_sys::AudioContext,
        analyser: web_sys::AnalyserNode,
        label: String,
        /// Why the source could not start (taken once).
        failed: Rc<RefCell<Option<String>>>,
        /// A source is connected to the analyser.
        running: Rc<Cell<bool>>,
        /// The microphone's stream (its tracks are stopped with the input).
        stream: Rc<RefCell<Option<web_sys::MediaStream>>>,
        /// The file's player.
        player: Rc<RefCell<Option<web_sys::AudioBufferSourceNode>>>,
    }

    impl SoundInput {
        /// Whether this build can listen (the web app can).
        pub fn available() -> bool {
            true
        }

        /// Starts listening to `source`; `ctx` is woken when it starts or fails.
        pub fn start(source: SoundSource, ctx: egui::Context) -> Result<Self, String> {
            let context = web_sys::AudioContext::new().map_err(|e| js_error(&e))?;
            let analyser = context.create_analyser().map_err(|e| js_error(&e))?;
            analyser.set_fft_size(FFT_SIZE);
            analyser.set_smoothing_time_constant(SMOOTHING);
            // Started from a click: the page may play sound now.
            let _ = context.resume();
            let input = Self {
                context,
                analyser,
                label: String::new(),
                failed: Rc::default(),
                running: Rc::default(),
                stream: Rc::default(),
                player: Rc::default(),
            };
            match source {
                SoundSource::Microphone => input.listen_to_microphone(ctx),
                SoundSource::File(name, bytes) => input.play_file(name, &bytes, ctx),
            }
        }

        fn listen_to_microphone(mut self, ctx: egui::Context) -> Result<Self, String> {
            self.label = "microphone".to_owned();
            let devices = web_sys::window()
                .ok_or("no window")?
                .navigator()
                .media_devices()
                .map_err(|_| "this browser gives no microphone (a secure https page is needed)")?;
            let audio = js_sys::Object::new();
            for key in ["echoCancellation", "noiseSuppression", "autoGainControl"] {
                let _ = js_sys::Reflect::set(&audio, &key.into(), &false.into());
            }
            let constraints = js_sys::Object::new();
            let _ = js_sys::Reflect::set(&constraints, &"audio".into(), &audio);
            let promise = devices
                .get_user_media_with_constraints(constraints.unchecked_ref())
                .map_err(|e| js_error(&e))?;
            let (context, analyser) = (self.context.clone(), self.analyser.clone());
            let (failed, running, stream) = (
                self.failed.clone(),
                self.running.clone(),
                self.stream.clone(),
            );
            wasm_bindgen_futures::spawn_local(async move {
                match wasm_bindgen_futures::JsFuture::from(promise).await {
                    Ok(s) => {
                        let s: web_sys::MediaStream = s.unchecked_into();
                        match context.create_media_stream_source(&s) {
                            Ok(source) => {
                                let _ = source.connect_with_audio_node(&analyser);
                                running.set(true);
                            }
                            Err(e) => *failed.borrow_mut() = Some(js_error(&e)),
                        }
                        *stream.borrow_mut() = Some(s);
                    }
                    Err(e) => {
                        *failed.borrow_mut() = Some(format!("no microphone: {}", js_error(&e)));
                    }
                }
                ctx.request_repaint();
            });
            Ok(self)
        }

        fn play_file(
            mut self,
            name: String,
            bytes: &[u8],
            ctx: egui::Context,
        ) -> Result<Self, String> {
            self.label = name;
            let array = js_sys::Uint8Array::from(bytes);
            let promise = self
                .context
                .decode_audio_data(&array.buffer())
                .map_err(|e| js_error(&e))?;
            let (context, analyser) = (self.context.clone(), self.analyser.clone());
            let (failed, running, player) = (
                self.failed.clone(),
                self.running.clone(),
                self.player.clone(),
            );
            wasm_bindgen_futures::spawn_local(async move {
                let started = async {
                    let buffer: web_sys::AudioBuffer =
                        wasm_bindgen_futures::JsFuture::from(promise)
                            .await
                            .map_err(|e| format!("cannot decode the audio: {}", js_error(&e)))?
                            .unchecked_into();
                    let source = context.create_buffer_source().map_err(|e| js_error(&e))?;
                    source.set_buffer(Some(&buffer));
                    source.set_loop(true);
                    source
                        .connect_with_audio_node(&analyser)
                        .and_then(|_| analyser.connect_with_audio_node(&context.destination()))
                        .map_err(|e| js_error(&e))?;
                    let node: &web_sys::AudioScheduledSourceNode = &source;
                    node.start().map_err(|e| js_error(&e))?;
                    *player.borrow_mut() = Some(source);
                    Ok::<(), String>(())
                };
                match started.await {
                    Ok(()) => running.set(true),
                    Err(e) => *failed.borrow_mut() = Some(e),
                }
                ctx.request_repaint();
            });
            Ok(self)
        }

        /// The microphone, or the file's name.
        pub fn label(&self) -> &str {
            &self.label
        }

        /// Why the source could not start, once (then `None`).
        pub fn take_failure(&self) -> Option<String> {
            self.failed.borrow_mut().take()
        }

        /// The spectrum now, dB per bin, into `out`, and the sample rate (Hz); `None`
        /// until the source plays.
        pub fn spectrum(&mut self, out: &mut Vec<f32>) -> Option<f32> {
            if !self.running.get() {
                return None;
            }
            out.resize(
                self.analyser.frequency_bin_count() as usize,
                f32::NEG_INFINITY,
            );
            self.analyser.get_float_frequency_data(out);
            Some(self.context.sample_rate())
        }
    }

    impl Drop for SoundInput {
        fn drop(&mut self) {
            if let Some(s) = self.stream.borrow_mut().take() {
                for track in s.get_tracks().iter() {
                    if let Ok(t) = track.dyn_into::<web_sys::MediaStreamTrack>() {
                        t.stop();
                    }
                }
            }
            if let Some(p) = self.player.borrow_mut().take() {
                let node: &web_sys::AudioScheduledSourceNode = &p;
                let _ = node.stop();
            }
            let _ = self.context.close();
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod imp {
    use super::SoundSource;

    /// The desktop app hears nothing (no value of this type is ever made).
    pub enum SoundInput {}

    impl SoundInput {
        /// The desktop app has no sound input.
        pub fn available() -> bool {
            false
        }

        /// Refuses: sound input is in the web app.
        pub fn start(_source: SoundSource, _ctx: egui::Context) -> Result<Self, String> {
            Err("sound input is in the web app".to_owned())
        }

        /// Never called.
        pub fn label(&self) -> &str {
            match *self {}
        }

        /// Never called.
        pub fn take_failure(&self) -> Option<String> {
            match *self {}
        }

        /// Never called.
        pub fn spectrum(&mut self, _out: &mut Vec<f32>) -> Option<f32> {
            match *self {}
        }
    }
}
