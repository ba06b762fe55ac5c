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
