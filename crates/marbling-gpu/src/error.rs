//! Why a GPU render cannot be made.

/// Errors of the GPU renderer.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No wgpu adapter at all (no GPU driver and no software Vulkan).
    #[error(
        "no GPU adapter found ({0}); install a GPU driver or Mesa's software Vulkan \
         (`apt-get install mesa-vulkan-drivers libvulkan1`, or `make setup-gpu`), \
         or set MARBLING_SKIP_GPU=1 to skip GPU tests"
    )]
    NoAdapter(String),
    /// The adapter refused to open a device with the requested limits.
    #[error("cannot open a GPU device: {0}")]
    Device(#[from] wgpu::RequestDeviceError),
    /// The requested output is invalid (bad scale, too large).
    #[error(transparent)]
    Render(#[from] marbling_core::RenderError),
    /// The design has more op records than the op texture can hold on this device.
    #[error(
        "{ops} op records (one per op, per drop of a pattern, per stylus segment) do not fit in an op texture of at most {max_side}×{max_side} texels"
    )]
    TooManyOps {
        /// Op records of the design.
        ops: usize,
        /// The device's largest 2D texture side.
        max_side: u32,
    },
    /// wgpu reported a validation or out-of-memory error.
    #[error("GPU error: {0}")]
    Wgpu(String),
    /// Reading the rendered pixels back failed.
    #[error("GPU readback failed: {0}")]
    Readback(String),
}
