//! Shared by the GPU integration tests: a renderer on any adapter, or a loud failure.

#![allow(dead_code)]

use marbling_gpu::{GpuContext, GpuError, GpuRenderer};

/// True when the environment explicitly asks to skip GPU tests.
pub fn skip_requested() -> bool {
    std::env::var("MARBLING_SKIP_GPU").is_ok_and(|v| v == "1")
}

/// Handles a failure to open a device: `None` (skip) only with MARBLING_SKIP_GPU=1,
/// otherwise the test fails with the fix in the message.
pub fn or_skip<T>(r: Result<T, GpuError>) -> Option<T> {
    match r {
        Ok(v) => Some(v),
        Err(e) if skip_requested() => {
            eprintln!("MARBLING_SKIP_GPU=1: skipping GPU test ({e})");
            None
        }
        Err(e) => panic!("GPU test cannot run: {e}"),
    }
}

/// A headless renderer on the best adapter (lavapipe here).
pub fn renderer() -> Option<GpuRenderer> {
    let ctx = or_skip(GpuContext::new_headless())?;
    eprintln!("adapter: {}", ctx.describe());
    Some(GpuRenderer::new(ctx))
}
