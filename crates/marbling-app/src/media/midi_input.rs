//! MIDI messages from the browser: Web MIDI (`navigator.requestMIDIAccess`, asked for
//! when the user presses *Connect MIDI*) and the test hook `window.marblingMidi([status,
//! data1, data2])`, both queued here until the next frame takes them ([`take`]). Each
//! message wakes the app. The desktop app has no MIDI input.

/// Where MIDI input stands (the desktop app is always `Unavailable`).
#[derive(Clone, Debug, PartialEq, Eq)]
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub enum MidiStatus {
    /// Not asked for yet (the browser has Web MIDI).
    Ready,
    /// Waiting for the browser's answer.
    Asking,
    /// Listening to this many inputs.
    Listening(u32),
    /// The browser or the user refused, or there is no Web MIDI: why.
    Unavailable(String),
}

#[cfg(target_arch = "wasm32")]
mod imp {
    use super::MidiStatus;
    use std::cell::RefCell;
    use wasm_bindgen::JsCast;
    use wasm_bindgen::closure::Closure;
    use wasm_bindgen::prelude::JsValue;

    /// A JavaScript callback of one argument.
    type Callback = Closure<dyn Fn(JsValue)>;

    thread_local! {
        static QUEUE: RefCell<Vec<[u8; 3]>> = const { RefCell::new(Vec::new()) };
        static WAKE: RefCell<Option<egui::Context>> = const { RefCell::new(None) };
        static STATUS: RefCell<Option<MidiStatus>> = const { RefCell::new(None) };
        static HANDLER: RefCell<Option<Callback>> = const { RefCell::new(None) };
    }

    fn push(bytes: &[u8]) {
        if let Some(&status) = bytes.first() {
            let at = |i: usize| bytes.get(i).copied().unwrap_or(0);
            QUEUE.with(|q| q.borrow_mut().push([status, at(1), at(2)]));
            WAKE.with(|w| {
                if let Some(ctx) = &*w.borrow() {
                    ctx.request_repaint();
                }
            });
        }
    }

    fn has_web_midi() -> bool {
        web_sys::window().is_some_and(|w| {
            js_sys::Reflect::get(&w.navigator(), &"requestMIDIAccess".into())
                .is_ok_and(|f| f.is_function())
        })
    }

    /// Installs the test hook and remembers `ctx` to wake (once).
    fn install(ctx: &egui::Context) {
        WAKE.with(|w| {
            if w.borrow().is_some() {
                return;
            }
            *w.borrow_mut() = Some(ctx.clone());
            let Some(window) = web_sys::window() else {
                return;
            };
            let hook = Closure::<dyn Fn(JsValue)>::new(|v: JsValue| {
                let bytes: Vec<u8> = js_sys::Array::from(&v)
                    .iter()
                    .filter_map(|x| x.as_f64())
                    .map(|x| x.clamp(0.0, 255.0) as u8)
                    .collect();
                push(&bytes);
            });
            let _ = js_sys::Reflect::set(&window, &"marblingMidi".into(), hook.as_ref());
            hook.forget();
        });
    }

    /// The messages since the last call, oldest first.
    pub fn take(ctx: &egui::Context) -> Vec<[u8; 3]> {
        install(ctx);
        QUEUE.with(|q| std::mem::take(&mut *q.borrow_mut()))
    }

    /// Where MIDI input stands.
    pub fn status() -> MidiStatus {
        STATUS.with(|s| s.borrow().clone()).unwrap_or_else(|| {
            if has_web_midi() {
                MidiStatus::Ready
            } else {
                MidiStatus::Unavailable("this browser has no Web MIDI".to_owned())
            }
        })
    }

    fn set_status(s: MidiStatus) {
        STATUS.with(|x| *x.borrow_mut() = Some(s));
        WAKE.with(|w| {
            if let Some(ctx) = &*w.borrow() {
                ctx.request_repaint();
            }
        });
    }

    /// Points every input of `access` at the message handler; how many there are.
    fn listen_to_inputs(access: &JsValue) -> u32 {
        let Ok(inputs) = js_sys::Reflect::get(access, &"inputs".into()) else {
            return 0;
        };
        let handler: JsValue = HANDLER.with(|h| {
            h.borrow_mut()
                .get_or_insert_with(|| {
                    Closure::<dyn Fn(JsValue)>::new(|event: JsValue| {
                        if let Ok(data) = js_sys::Reflect::get(&event, &"data".into()) {
                            push(&js_sys::Uint8Array::new(&data).to_vec());
                        }
                    })
                })
                .as_ref()
                .clone()
        });
        let count = std::rc::Rc::new(std::cell::Cell::new(0));
        let counted = count.clone();
        let each = Closure::<dyn FnMut(JsValue)>::new(move |input: JsValue| {
            let _ = js_sys::Reflect::set(&input, &"onmidimessage".into(), &handler);
            counted.set(counted.get() + 1);
        });
        if let Ok(for_each) = js_sys::Reflect::get(&inputs, &"forEach".into())
            && let Some(f) = for_each.dyn_ref::<js_sys::Function>()
        {
            let _ = f.call1(&inputs, each.as_ref());
        }
        count.get()
    }

    /// Asks the browser for MIDI input (a permission prompt where it has one).
    pub fn connect() {
        let Some(window) = web_sys::window() else {
            return;
        };
        let navigator = window.navigator();
        let asked = js_sys::Reflect::get(&navigator, &"requestMIDIAccess".into())
            .ok()
            .and_then(|f| f.dyn_into::<js_sys::Function>().ok())
            .and_then(|f| f.call0(&navigator).ok())
            .and_then(|p| p.dyn_into::<js_sys::Promise>().ok());
        let Some(promise) = asked else {
            set_status(MidiStatus::Unavailable(
                "this browser has no Web MIDI".to_owned(),
            ));
            return;
        };
        set_status(MidiStatus::Asking);
        wasm_bindgen_futures::spawn_local(async move {
            match wasm_bindgen_futures::JsFuture::from(promise).await {
                Ok(access) => {
                    let n = listen_to_inputs(&access);
                    // A device plugged in later is listened to as well.
                    let again = access.clone();
                    let changed = Closure::<dyn Fn(JsValue)>::new(move |_: JsValue| {
                        set_status(MidiStatus::Listening(listen_to_inputs(&again)));
                    });
                    let _ =
                        js_sys::Reflect::set(&access, &"onstatechange".into(), changed.as_ref());
                    changed.forget();
                    set_status(MidiStatus::Listening(n));
                }
                Err(e) => {
                    let why = js_sys::Reflect::get(&e, &"message".into())
                        .ok()
                        .and_then(|m| m.as_string())
                        .unwrap_or_else(|| "refused".to_owned());
                    set_status(MidiStatus::Unavailable(format!("MIDI refused: {why}")));
                }
            }
        });
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod imp {
    use super::MidiStatus;

    /// The desktop app receives no MIDI.
    pub fn take(_ctx: &egui::Context) -> Vec<[u8; 3]> {
        Vec::new()
    }

    /// The desktop app has no MIDI input.
    pub fn status() -> MidiStatus {
        MidiStatus::Unavailable("MIDI input is in the web app".to_owned())
    }

    /// Nothing to connect to on the desktop.
    pub fn connect() {}
}

pub use imp::{connect, status, take};
