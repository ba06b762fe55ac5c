//! The GPU side: the canvas's renderer and its progressive refinement, the gallery's
//! thumbnails, the page canvas's backing store, lost devices and uncaught wgpu errors.

pub mod canvas_gpu;
pub(crate) mod device_pixels;
pub mod gallery_atlas;
pub(crate) mod gallery_gpu;
pub(crate) mod gpu_errors;
pub mod recovery;
pub(crate) mod refine;
#[cfg(test)]
pub(crate) mod test_window;

/// The name automation and users see for a wgpu backend.
pub(crate) fn backend_name(b: wgpu::Backend) -> String {
    match b {
        wgpu::Backend::BrowserWebGpu => "webgpu".to_owned(),
        wgpu::Backend::Gl if cfg!(target_arch = "wasm32") => "webgl2".to_owned(),
        other => other.to_str().to_owned(),
    }
}
