//! Shared by the GPU integration tests: a renderer on any adapter, or a loud failure.

#![allow(dead_code)]

use marbling_core::{Design, Op};
use marbling_gpu::{GpuContext, GpuRenderer};
use marbling_testkit::gpu_or_skip;

/// A headless renderer on the best adapter (lavapipe here); `None` only where
/// `MARBLING_SKIP_GPU=1` lets a missing adapter skip (`marbling_testkit`).
pub fn renderer() -> Option<GpuRenderer> {
    let ctx = gpu_or_skip(GpuContext::new_headless())?;
    eprintln!("adapter: {}", ctx.describe());
    Some(GpuRenderer::new(ctx))
}

/// `design` with every comb and swirl `k` times as strong.
pub fn scaled(mut design: Design, k: f64) -> Design {
    for op in &mut design.ops {
        match op {
            Op::Tine(t) => t.alpha *= k,
            Op::Rake(r) => r.alpha *= k,
            Op::Wavy(w) => w.amplitude *= k,
            Op::Circular(c) => c.alpha *= k,
            Op::Vortex(v) => v.alpha *= k,
            Op::Comb(c) => c.alpha *= k,
            Op::Jiggle(j) => {
                j.along *= k;
                j.across *= k;
            }
            Op::Turn(t) => t.angle *= k,
            Op::Shift(t) => t.offset *= k,
            Op::Flow(f) => f.strength *= k,
            Op::Drop(_) | Op::Spray(_) | Op::Drops(_) | Op::Sprays(_) | Op::Stylus(_) => {}
        }
    }
    design
}
