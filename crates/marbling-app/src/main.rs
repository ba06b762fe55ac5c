//! Starts the marbling playground: a desktop window natively, or the web app in the
//! page's `<canvas id="marbling_canvas">` on wasm32. On the web, a lost GPU device
//! restarts the renderer on a fresh canvas, keeping the editing state (see
//! `marbling_app::recovery`).

#[cfg(not(target_arch = "wasm32"))]
fn main() -> eframe::Result {
    let options = eframe::NativeOptions {
        renderer: eframe::Renderer::Wgpu,
        viewport: egui::ViewportBuilder::default()
            .with_inner_size([1280.0, 860.0])
            .with_title("Marbling"),
        ..Default::default()
    };
    eframe::run_native(
        "marbling",
        options,
        Box::new(|cc| Ok(Box::new(marbling_app::MarblingApp::new(cc)))),
    )
}

#[cfg(target_arch = "wasm32")]
fn main() {
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    marbling_app::panic_guard::install();
    wasm_bindgen_futures::spawn_local(web::run());
}

#[cfg(target_arch = "wasm32")]
mod web {
    use marbling_app::platform::{CANVAS_ID, set_body_attribute};
    use marbling_app::recovery;
    use wasm_bindgen::JsCast;

    /// Runs the app, and restarts it on a new canvas whenever it parks its state after
    /// losing the GPU device.
    pub async fn run() {
        let mut canvas = existing_canvas();
        loop {
            let Some(c) = canvas.take() else {
                fail("no <canvas id=\"marbling_canvas\"> in the page");
                return;
            };
            let runner = eframe::WebRunner::new();
            let started = runner
                .start(
                    c.clone(),
                    eframe::WebOptions::default(),
                    Box::new(|cc| Ok(Box::new(marbling_app::MarblingApp::new(cc)))),
                )
                .await;
            if let Err(e) = started {
                fail(&format!("the playground could not start: {e:?}"));
                return;
            }
            while !recovery::take_restart_request() {
                sleep_ms(100).await;
            }
            if recovery::give_up() {
                fail(&format!(
                    "the GPU device was lost {} times in a row without drawing a frame: the \
                     playground stopped trying. Your design is autosaved; reload the page \
                     to go on (a smaller view or fewer ops may help)",
                    recovery::MAX_RESTARTS_IN_A_ROW + 1
                ));
                return;
            }
            log::warn!("restarting the renderer after a lost GPU device");
            runner.destroy();
            canvas = fresh_canvas(&c);
        }
    }

    fn existing_canvas() -> Option<web_sys::HtmlCanvasElement> {
        web_sys::window()?
            .document()?
            .get_element_by_id(CANVAS_ID)?
            .dyn_into()
            .ok()
    }

    /// Replaces `old` (whose context is gone) with a new canvas of the same id.
    fn fresh_canvas(old: &web_sys::HtmlCanvasElement) -> Option<web_sys::HtmlCanvasElement> {
        let document = web_sys::window()?.document()?;
        let new: web_sys::HtmlCanvasElement =
            document.create_element("canvas").ok()?.dyn_into().ok()?;
        new.set_id(CANVAS_ID);
        if let Some(label) = old.get_attribute("aria-label") {
            let _ = new.set_attribute("aria-label", &label);
        }
        old.replace_with_with_node_1(&new).ok()?;
        Some(new)
    }

    async fn sleep_ms(ms: i32) {
        let promise = js_sys::Promise::new(&mut |resolve, _| {
            if let Some(w) = web_sys::window() {
                let _ = w.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, ms);
            }
        });
        let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
    }

    fn fail(text: &str) {
        set_body_attribute("data-error", Some(text));
        log::error!("{text}");
    }
}
