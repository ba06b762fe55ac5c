//! Shared by the GPU integration tests: a renderer on any adapter, or a loud failure.

#![allow(dead_code)]

use marbling_gpu::{GpuContext, GpuRenderer};
use marbling_testkit::gpu_or_skip;

/// A headless renderer on the best adapter (lavapipe here); `None` only where
/// `MARBLING_SKIP_GPU=1` lets a missing adapter skip (`marbling_testkit`).
pub fn renderer() -> Option<GpuRenderer> {
    let ctx = gpu_or_skip(GpuContext::new_headless())?;
    eprintln!("adapter: {}", ctx.describe());
    Some(GpuRenderer::new(ctx))
}
