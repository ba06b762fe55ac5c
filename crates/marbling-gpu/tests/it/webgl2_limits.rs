//! The schema's largest design (100,000 ops) renders within WebGL2's limits (2048-texel
//! textures, 16 KiB uniform blocks, no storage buffers) and within WebGPU's default
//! limits, on a device opened with exactly those limits.

use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, MAX_OPS, RenderOptions};
use marbling_gpu::{GpuContext, GpuRenderer};

fn render_max_ops(name: &str, limits: wgpu::Limits) {
    let Some(ctx) =
        marbling_testkit::gpu_or_skip(GpuContext::new_headless_with_limits(limits.clone()))
    else {
        return;
    };
    assert_eq!(ctx.max_texture_side(), limits.max_texture_dimension_2d);
    let gpu = GpuRenderer::new(ctx);
    let design = random_design(2026, 256, 256, MAX_OPS, Mix::Mixed);
    let opts = RenderOptions {
        scale: 0.125,
        antialias: Antialias::Rgss,
    };
    let start = std::time::Instant::now();
    let image = gpu.render(&design, &opts).expect("100,000-op render");
    println!(
        "{MAX_OPS} ops at 32×32 rgss, {name} limits, on {}: {:.2} s",
        gpu.context().describe(),
        start.elapsed().as_secs_f64()
    );
    assert_eq!((image.width, image.height), (32, 32));
    let distinct: std::collections::HashSet<[u8; 4]> = image
        .pixels
        .chunks_exact(4)
        .map(|p| [p[0], p[1], p[2], p[3]])
        .collect();
    assert!(distinct.len() > 3, "a 100,000-op design should not be flat");
    assert!(image.pixels.chunks_exact(4).all(|p| p[3] == 255));
}

#[test]
fn max_ops_on_webgl2_limits() {
    let limits = wgpu::Limits::downlevel_webgl2_defaults();
    assert_eq!(limits.max_texture_dimension_2d, 2048);
    assert_eq!(limits.max_storage_buffers_per_shader_stage, 0);
    render_max_ops("WebGL2", limits);
}

#[test]
fn max_ops_on_webgpu_default_limits() {
    render_max_ops("WebGPU default", wgpu::Limits::default());
}
