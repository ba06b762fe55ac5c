//! What the page holds, for `data-memory` (the soak benchmark reads it each minute):
//! the wasm module's linear memory, and the GPU buffers and textures alive where wgpu
//! runs its own core (WebGL2 and native; a browser's WebGPU keeps its own counts).

/// How often the figures are taken, seconds (wgpu's report walks every registry).
pub const EVERY_S: f64 = 2.0;

/// `wasm=<bytes>,buffers=<n>,textures=<n>`: `-` for what this build cannot tell.
pub fn report(frame: &eframe::Frame) -> String {
    let wasm = wasm_bytes().map_or_else(|| "-".to_owned(), |b| b.to_string());
    let gpu = frame
        .wgpu_render_state()
        .and_then(|rs| rs.instance.generate_report());
    let (buffers, textures) = gpu.map_or_else(
        || ("-".to_owned(), "-".to_owned()),
        |r| {
            (
                r.hub.buffers.num_allocated.to_string(),
                r.hub.textures.num_allocated.to_string(),
            )
        },
    );
    format!("wasm={wasm},buffers={buffers},textures={textures}")
}

/// The wasm module's linear memory, bytes (it only grows).
fn wasm_bytes() -> Option<usize> {
    #[cfg(target_arch = "wasm32")]
    {
        Some(core::arch::wasm32::memory_size(0) * 65_536)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        None
    }
}
