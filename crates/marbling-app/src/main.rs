//! Starts the marbling playground: a desktop window natively, or the web app in the
//! page's `<canvas id="marbling_canvas">` on wasm32.

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
    use wasm_bindgen::JsCast;
    eframe::WebLogger::init(log::LevelFilter::Warn).ok();
    wasm_bindgen_futures::spawn_local(async {
        let document = web_sys::window().and_then(|w| w.document());
        let canvas = document
            .as_ref()
            .and_then(|d| d.get_element_by_id("marbling_canvas"))
            .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok());
        let Some(canvas) = canvas else {
            log::error!("no <canvas id=\"marbling_canvas\"> in the page");
            return;
        };
        let options = eframe::WebOptions::default();
        let result = eframe::WebRunner::new()
            .start(
                canvas,
                options,
                Box::new(|cc| Ok(Box::new(marbling_app::MarblingApp::new(cc)))),
            )
            .await;
        if let Err(e) = result {
            let text = format!("the playground could not start: {e:?}");
            marbling_app::platform::set_body_attribute("data-error", Some(&text));
            log::error!("{text}");
        }
    });
}
