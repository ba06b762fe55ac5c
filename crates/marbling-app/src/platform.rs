//! What differs between the browser and a desktop window: the address bar (share
//! links), storage for autosave, downloads and file dialogs, and the automation hooks on
//! `<body>`.

/// A file the user picked: its name and bytes, or why it could not be read.
pub type PickedFile = Result<(String, Vec<u8>), String>;

/// Where an asynchronous file pick delivers its result.
pub type PickSlot = std::sync::Arc<std::sync::Mutex<Option<PickedFile>>>;

/// What a file dialog offers: a filter name and its extensions.
pub type FileKind = (&'static str, &'static [&'static str]);
/// A design JSON.
pub const DESIGN_FILE: FileKind = ("design", &["json"]);
/// A data grid for the noise playground.
pub const DATA_FILE: FileKind = ("data (PNG or CSV)", &["png", "csv", "txt"]);
/// A picture for an image background.
pub const IMAGE_FILE: FileKind = (
    "picture (PNG, JPEG or WebP)",
    &["png", "jpg", "jpeg", "webp"],
);

/// The id of the page's `<canvas>` the app draws into.
pub const CANVAS_ID: &str = "marbling_canvas";

#[cfg(target_arch = "wasm32")]
mod imp {
    use super::{FileKind, PickSlot, PickedFile};
    use wasm_bindgen::JsCast;

    fn window() -> Option<web_sys::Window> {
        web_sys::window()
    }

    /// What a JavaScript error says: its `message`, or the value as text.
    pub fn js_error(e: &wasm_bindgen::JsValue) -> String {
        js_sys::Reflect::get(e, &"message".into())
            .ok()
            .and_then(|m| m.as_string())
            .or_else(|| e.as_string())
            .unwrap_or_else(|| "unknown error".to_owned())
    }

    /// The page's URL fragment without `#` (e.g. `d=…`).
    pub fn fragment() -> Option<String> {
        let hash = window()?.location().hash().ok()?;
        let f = hash.strip_prefix('#').unwrap_or(&hash).to_owned();
        (!f.is_empty()).then_some(f)
    }

    /// True on the first call and whenever the fragment changed since the last call
    /// (a `hashchange` event). The fragment of a big design is megabytes: reading it
    /// every frame would cost milliseconds a frame.
    pub fn fragment_changed() -> bool {
        use std::sync::atomic::{AtomicBool, Ordering};
        use wasm_bindgen::closure::Closure;
        static CHANGED: AtomicBool = AtomicBool::new(true);
        static WATCHING: std::sync::Once = std::sync::Once::new();
        WATCHING.call_once(|| {
            let Some(w) = window() else { return };
            let changed = Closure::<dyn Fn(web_sys::Event)>::new(|_: web_sys::Event| {
                CHANGED.store(true, Ordering::SeqCst);
            });
            let _ =
                w.add_event_listener_with_callback("hashchange", changed.as_ref().unchecked_ref());
            changed.forget();
        });
        CHANGED.swap(false, std::sync::atomic::Ordering::SeqCst)
    }

    /// The pressure of the pen or finger on the screen, 0..=1, from the latest
    /// `pointerdown` or `pointermove` (read before egui's own handlers, in the capture
    /// phase); `None` for a mouse, which has none.
    pub fn pointer_pressure() -> Option<f64> {
        use std::sync::atomic::{AtomicU64, Ordering};
        use wasm_bindgen::closure::Closure;
        /// The latest pressure's f64 bits; NaN: a mouse, or nothing yet.
        static PRESSURE: AtomicU64 = AtomicU64::new(0x7ff8_0000_0000_0000);
        static WATCHING: std::sync::Once = std::sync::Once::new();
        WATCHING.call_once(|| {
            let Some(w) = window() else { return };
            let felt = Closure::<dyn Fn(web_sys::PointerEvent)>::new(|e: web_sys::PointerEvent| {
                let p = if e.pointer_type() == "mouse" {
                    f64::NAN
                } else {
                    f64::from(e.pressure())
                };
                PRESSURE.store(p.to_bits(), Ordering::SeqCst);
            });
            let options = web_sys::AddEventListenerOptions::new();
            options.set_capture(true);
            for kind in ["pointerdown", "pointermove"] {
                let _ = w.add_event_listener_with_callback_and_add_event_listener_options(
                    kind,
                    felt.as_ref().unchecked_ref(),
                    &options,
                );
            }
            felt.forget();
        });
        let p = f64::from_bits(PRESSURE.load(std::sync::atomic::Ordering::SeqCst));
        p.is_finite().then_some(p)
    }

    /// The address that share links start with (the page without its fragment).
    pub fn base_url() -> String {
        window()
            .and_then(|w| {
                let l = w.location();
                Some(format!("{}{}", l.origin().ok()?, l.pathname().ok()?))
            })
            .unwrap_or_default()
    }

    /// Shows `fragment` in the address bar without reloading.
    pub fn set_fragment(fragment: &str) {
        if let Some(w) = window() {
            let _ = w.location().set_hash(fragment);
        }
    }

    /// The value of `name` in the page's query string (`?landing=0` → `Some("0")`).
    pub fn query(name: &str) -> Option<String> {
        let search = window()?.location().search().ok()?;
        search
            .trim_start_matches('?')
            .split('&')
            .find_map(|kv| kv.strip_prefix(name)?.strip_prefix('=').map(str::to_owned))
    }

    /// Removes a `#d=…` link from the address bar without reloading or adding a history
    /// entry (after an edit, so a reload shows the edited design, not the link's).
    pub fn clear_fragment() {
        let Some(w) = window() else { return };
        let l = w.location();
        let url = format!(
            "{}{}",
            l.pathname().unwrap_or_default(),
            l.search().unwrap_or_default()
        );
        if let Ok(h) = w.history() {
            let _ = h.replace_state_with_url(&wasm_bindgen::JsValue::NULL, "", Some(&url));
        }
    }

    /// The value stored under `key` (browser local storage), if any.
    pub fn load_string(_storage: Option<&dyn eframe::Storage>, key: &str) -> Option<String> {
        window()?.local_storage().ok()??.get_item(key).ok()?
    }

    /// Stores `value` under `key` now (browser local storage).
    pub fn store_string(_frame: &mut eframe::Frame, key: &str, value: &str) -> Result<(), String> {
        store_now(key, value)
    }

    /// Stores `value` under `key` without an eframe frame (page-hide handlers).
    pub fn store_now(key: &str, value: &str) -> Result<(), String> {
        let storage = window()
            .and_then(|w| w.local_storage().ok().flatten())
            .ok_or("browser storage is not available")?;
        storage
            .set_item(key, value)
            .map_err(|_| "browser storage is full".to_owned())
    }

    /// Milliseconds since 1970 (the page's clock).
    pub fn now_ms() -> f64 {
        js_sys::Date::now()
    }

    /// Calls `f` when the page is hidden or unloaded (tab switch, close, reload): the
    /// last moment to save.
    pub fn on_page_hide(f: impl Fn() + 'static) {
        use wasm_bindgen::closure::Closure;
        let Some(w) = window() else { return };
        let f = std::rc::Rc::new(f);
        let hide = {
            let f = f.clone();
            Closure::<dyn Fn(web_sys::Event)>::new(move |_: web_sys::Event| f())
        };
        let _ = w.add_event_listener_with_callback("pagehide", hide.as_ref().unchecked_ref());
        hide.forget();
        let Some(document) = w.document() else { return };
        let doc = document.clone();
        let visibility = Closure::<dyn Fn(web_sys::Event)>::new(move |_: web_sys::Event| {
            if doc.visibility_state() == web_sys::VisibilityState::Hidden {
                f();
            }
        });
        let _ = document.add_event_listener_with_callback(
            "visibilitychange",
            visibility.as_ref().unchecked_ref(),
        );
        visibility.forget();
    }

    /// Offers `bytes` as a download named `name`.
    pub fn save_file(name: &str, mime: &str, bytes: &[u8]) -> Result<(), String> {
        let fail = |what: &str| format!("cannot download {name}: {what}");
        let array = js_sys::Uint8Array::from(bytes);
        let parts = js_sys::Array::of1(&array);
        let props = web_sys::BlobPropertyBag::new();
        props.set_type(mime);
        let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &props)
            .map_err(|_| fail("blob"))?;
        download_blob(name, &blob)
    }

    /// Offers `blob` as a download named `name`.
    pub fn download_blob(name: &str, blob: &web_sys::Blob) -> Result<(), String> {
        let fail = |what: &str| format!("cannot download {name}: {what}");
        let url =
            web_sys::Url::create_object_url_with_blob(blob).map_err(|_| fail("object URL"))?;
        let document = window()
            .and_then(|w| w.document())
            .ok_or_else(|| fail("no document"))?;
        let a: web_sys::HtmlAnchorElement = document
            .create_element("a")
            .map_err(|_| fail("anchor"))?
            .dyn_into()
            .map_err(|_| fail("anchor"))?;
        a.set_href(&url);
        a.set_download(name);
        a.click();
        let _ = web_sys::Url::revoke_object_url(&url);
        Ok(())
    }

    /// Asks the user for a file of `kind` (a filter name and its extensions); the result
    /// arrives in `slot` later.
    pub fn pick_file(slot: PickSlot, kind: FileKind, ctx: egui::Context) {
        wasm_bindgen_futures::spawn_local(async move {
            let picked = rfd::AsyncFileDialog::new()
                .add_filter(kind.0, kind.1)
                .pick_file()
                .await;
            if let Some(file) = picked {
                let result: PickedFile = Ok((file.file_name(), file.read().await));
                if let Ok(mut s) = slot.lock() {
                    *s = Some(result);
                }
                ctx.request_repaint();
            }
        });
    }

    /// Reads the dropped `file` (called `name`) into `slot`, asynchronously.
    pub fn read_dropped(
        file: egui::DroppedFileHandle,
        name: String,
        slot: PickSlot,
        ctx: egui::Context,
    ) {
        wasm_bindgen_futures::spawn_local(async move {
            let result = file
                .bytes_async()
                .await
                .map(|b| (name.clone(), b))
                .map_err(|e| format!("cannot read '{name}': {e}"));
            if let Ok(mut s) = slot.lock() {
                *s = Some(result);
            }
            ctx.request_repaint();
        });
    }

    /// Delivers every picture pasted into the page (Ctrl+V of a copied image or image
    /// file) to `slot`, named after the file or "pasted image".
    pub fn on_paste_image(slot: PickSlot, ctx: egui::Context) {
        use wasm_bindgen::closure::Closure;
        let Some(w) = window() else { return };
        let listener =
            Closure::<dyn Fn(web_sys::ClipboardEvent)>::new(move |e: web_sys::ClipboardEvent| {
                let Some(files) = e.clipboard_data().and_then(|d| d.files()) else {
                    return;
                };
                let Some(file) = (0..files.length())
                    .filter_map(|i| files.get(i))
                    .find(|f| f.type_().starts_with("image/"))
                else {
                    return;
                };
                e.prevent_default();
                let (slot, ctx) = (slot.clone(), ctx.clone());
                wasm_bindgen_futures::spawn_local(async move {
                    let name = match file.name() {
                        n if n.is_empty() || n == "image.png" => "pasted image".to_owned(),
                        n => n,
                    };
                    let bytes = wasm_bindgen_futures::JsFuture::from(file.array_buffer())
                        .await
                        .map(|b| js_sys::Uint8Array::new(&b).to_vec())
                        .map_err(|_| format!("{name}: cannot read the pasted picture"));
                    if let Ok(mut s) = slot.lock() {
                        *s = Some(bytes.map(|b| (name, b)));
                    }
                    ctx.request_repaint();
                });
            });
        let _ = w.add_event_listener_with_callback("paste", listener.as_ref().unchecked_ref());
        // One listener for the page's life.
        listener.forget();
    }

    /// Calls `f` when the page's canvas loses its WebGL context.
    pub fn on_context_lost(f: impl Fn() + 'static) {
        use wasm_bindgen::closure::Closure;
        let Some(canvas) = window()
            .and_then(|w| w.document())
            .and_then(|d| d.get_element_by_id(super::CANVAS_ID))
        else {
            return;
        };
        let listener = Closure::<dyn Fn(web_sys::Event)>::new(move |e: web_sys::Event| {
            e.prevent_default();
            f();
        });
        let _ = canvas.add_event_listener_with_callback(
            "webglcontextlost",
            listener.as_ref().unchecked_ref(),
        );
        // The canvas is replaced on restart; the listener lives as long as the page.
        listener.forget();
    }

    /// Defines `window.marblingLoseDevice()`, which destroys the GPU device as a driver
    /// reset would: how the browser tests check that the app survives it.
    pub fn expose_device_loss(device: &wgpu::Device) {
        use wasm_bindgen::closure::Closure;
        let Some(w) = window() else { return };
        let device = device.clone();
        let f = Closure::<dyn Fn()>::new(move || device.destroy());
        let _ = js_sys::Reflect::set(&w, &"marblingLoseDevice".into(), f.as_ref());
        f.forget();
    }

    /// Defines `window.marblingPanic()`, which makes the next frame panic: how the
    /// browser tests check that a panic keeps the design (src/automation/panic_guard.rs).
    pub fn expose_panic() {
        use wasm_bindgen::closure::Closure;
        let Some(w) = window() else { return };
        let f = Closure::<dyn Fn()>::new(crate::automation::panic_guard::request_panic);
        let _ = js_sys::Reflect::set(&w, &"marblingPanic".into(), f.as_ref());
        f.forget();
    }

    /// Shows `text` in a red bar at the bottom of the page, in plain HTML (for when the
    /// canvas can no longer draw).
    pub fn show_alert(text: &str) {
        let Some(document) = window().and_then(|w| w.document()) else {
            return;
        };
        let Some(body) = document.body() else { return };
        let Ok(bar) = document.create_element("div") else {
            return;
        };
        let _ = bar.set_attribute("role", "alert");
        let _ = bar.set_attribute("id", "marbling-alert");
        let _ = bar.set_attribute(
            "style",
            "position:fixed;left:0;right:0;bottom:0;padding:14px 16px;background:#9b1c1c;\
             color:#fff;font:16px/1.4 system-ui,sans-serif;z-index:10",
        );
        bar.set_text_content(Some(text));
        let _ = body.append_child(&bar);
    }

    /// True when the screen takes touches (`navigator.maxTouchPoints` > 0), read once.
    pub fn touch_screen() -> bool {
        static TOUCH: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        *TOUCH.get_or_init(|| {
            let points = window()
                .and_then(|w| js_sys::Reflect::get(&w, &"navigator".into()).ok())
                .and_then(|n| js_sys::Reflect::get(&n, &"maxTouchPoints".into()).ok())
                .and_then(|p| p.as_f64());
            points.is_some_and(|p| p > 0.0)
        })
    }

    /// Sets (or with `None` removes) a `data-…` attribute on `<body>`.
    pub fn set_body_attribute(name: &str, value: Option<&str>) {
        let Some(body) = window().and_then(|w| w.document()).and_then(|d| d.body()) else {
            return;
        };
        let _ = match value {
            Some(v) => body.set_attribute(name, v),
            None => body.remove_attribute(name),
        };
    }
}

#[cfg(not(target_arch = "wasm32"))]
mod imp {
    use super::{FileKind, PickSlot};

    /// A share link given on the command line (`marbling-app 'http://…#d=…'`).
    pub fn fragment() -> Option<String> {
        std::env::args()
            .nth(1)
            .and_then(|a| a.split_once('#').map(|(_, f)| f.to_owned()))
    }

    /// True on the first call only: the command line does not change.
    pub fn fragment_changed() -> bool {
        static READ: std::sync::Once = std::sync::Once::new();
        let mut first = false;
        READ.call_once(|| first = true);
        first
    }

    /// The address that share links start with: the web app served by `make run`.
    pub fn base_url() -> String {
        "http://127.0.0.1:8080/".to_owned()
    }

    /// Desktop windows have no address bar.
    pub fn set_fragment(_fragment: &str) {}

    /// No query string outside the browser.
    pub fn query(_name: &str) -> Option<String> {
        None
    }

    /// Desktop windows have no address bar.
    pub fn clear_fragment() {}

    /// The value stored under `key` (eframe's app storage), if any.
    pub fn load_string(storage: Option<&dyn eframe::Storage>, key: &str) -> Option<String> {
        storage?.get_string(key)
    }

    /// Stores `value` under `key` now (eframe's app storage, flushed to disk).
    pub fn store_string(frame: &mut eframe::Frame, key: &str, value: &str) -> Result<(), String> {
        let storage = frame.storage_mut().ok_or("no app storage")?;
        storage.set_string(key, value.to_owned());
        storage.flush();
        Ok(())
    }

    /// A pen's pressure: the desktop app reads none (egui gives no pen pressure).
    pub fn pointer_pressure() -> Option<f64> {
        None
    }

    /// Milliseconds since 1970.
    pub fn now_ms() -> f64 {
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0.0, |d| d.as_secs_f64() * 1000.0)
    }

    /// Desktop windows save on exit instead (`eframe::App::save`).
    pub fn on_page_hide(_f: impl Fn() + 'static) {}

    /// Desktop windows store through eframe's storage ([`store_string`]).
    pub fn store_now(_key: &str, _value: &str) -> Result<(), String> {
        Err("no page storage".to_owned())
    }

    /// Asks where to save `bytes` and writes them there.
    pub fn save_file(name: &str, _mime: &str, bytes: &[u8]) -> Result<(), String> {
        let Some(path) = rfd::FileDialog::new().set_file_name(name).save_file() else {
            return Ok(());
        };
        std::fs::write(&path, bytes).map_err(|e| format!("cannot write '{}': {e}", path.display()))
    }

    /// Asks the user for a file of `kind` (a filter name and its extensions); the result
    /// arrives in `slot` at once.
    pub fn pick_file(slot: PickSlot, kind: FileKind, _ctx: egui::Context) {
        let Some(path) = rfd::FileDialog::new()
            .add_filter(kind.0, kind.1)
            .pick_file()
        else {
            return;
        };
        let result = std::fs::read(&path)
            .map(|b| (path.display().to_string(), b))
            .map_err(|e| format!("cannot read '{}': {e}", path.display()));
        if let Ok(mut s) = slot.lock() {
            *s = Some(result);
        }
    }

    /// Reads the dropped `file` (called `name`) into `slot`.
    pub fn read_dropped(
        file: egui::DroppedFileHandle,
        name: String,
        slot: PickSlot,
        _ctx: egui::Context,
    ) {
        let result = file
            .bytes()
            .map(|b| (name.clone(), b))
            .map_err(|e| format!("cannot read '{name}': {e}"));
        if let Ok(mut s) = slot.lock() {
            *s = Some(result);
        }
    }

    /// Desktop windows take pictures by *Open image…* and drag-and-drop.
    pub fn on_paste_image(_slot: PickSlot, _ctx: egui::Context) {}

    /// Desktop windows have no page to expose a test hook on.
    pub fn expose_device_loss(_device: &wgpu::Device) {}

    /// Desktop windows are used with a mouse (a touch screen's touches arrive as one).
    pub fn touch_screen() -> bool {
        false
    }

    /// Desktop windows have no `<body>`.
    pub fn set_body_attribute(_name: &str, _value: Option<&str>) {}
}

pub use imp::*;
