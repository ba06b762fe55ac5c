// Live preview while a tool is dragged: the committed design comes from a cache
// texture (rendered exactly by render.wgsl at ≥ 2× the view resolution, stored as
// Rgba8Unorm holding sRGB-encoded bytes, filtered bilinearly as they are); only the
// pending op is walked here (common.wgsl is prepended). An approximation, used only
// while dragging.
//
// `pending_back(a, b, p)` is appended by the host (src/preview_kind.rs): one pipeline per
// op kind, each calling only that kind's inverse from common.wgsl. So is
// `encoded_to_target(c)` (src/shaders.rs): sRGB-encoded colour → what the target takes
// (the colour itself for …Unorm targets, linear light for …UnormSrgb). A software GPU runs
// every case of a switch for every pixel, even when all pixels take the same case.
//
// Two fragment entry points: `fs_main` takes `sample_count` samples per pixel (the
// user's antialiasing); `fs_one_sample` takes one at the pixel's centre, with no loop and
// no branch, which is what slow devices get (crates/marbling-app/src/fast_paint/preview_quality.rs).
// SwiftShader runs loops and branches in a general, masked form for every pixel: the
// straight-line entry point draws a tine-drag frame about 8 ms faster there.

// Keep in sync with `PreviewParams` in src/params.rs (checked by tests/layout.rs).
struct PreviewParams {
    // The pending op, encoded as in common.wgsl.
    pending_a: vec4<f32>,
    pending_b: vec4<f32>,
    // Design point (x, y) at the view target's top-left corner.
    view_origin: vec2<f32>,
    // Design pixels per view pixel.
    view_inv_scale: f32,
    // 1 when pending_a/pending_b hold an op, 0 to show the cache alone.
    has_pending: u32,
    // Design width and height, design pixels (the cache covers exactly this rectangle).
    design_size: vec2<f32>,
    // Samples per view pixel, at samples[0 .. sample_count].
    sample_count: u32,
    // 1: write sRGB-encoded values (…Unorm targets); 0: write linear light (…UnormSrgb).
    encode_srgb: u32,
    // (dx, dy, weight, 0): offsets from the pixel's top-left corner in view pixels.
    samples: array<vec4<f32>, 4>,
}

@group(0) @binding(0) var<uniform> params: PreviewParams;
@group(0) @binding(1) var cache: texture_2d<f32>;
@group(0) @binding(2) var cache_sampler: sampler;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

// sRGB-encoded colour at design point `p0`: the pending op's ink, or the cache
// (bilinear, clamped to the canvas edge) at the point the pending op moved here.
fn shade(p0: vec2<f32>) -> vec3<f32> {
    var p = p0;
    if params.has_pending != 0u {
        let r = pending_back(params.pending_a, params.pending_b, p);
        if r.z > 0.0 {
            return unpack_srgb(params.pending_b.w);
        }
        p = r.xy;
    }
    return textureSampleLevel(cache, cache_sampler, p / params.design_size, 0.0).rgb;
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let pixel = floor(position.xy);
    var acc = vec3<f32>(0.0);
    for (var i = 0u; i < params.sample_count; i++) {
        let s = params.samples[i];
        let p = params.view_origin + (pixel + s.xy) * params.view_inv_scale;
        acc += s.z * srgb_to_linear(shade(p));
    }
    if params.encode_srgb == 0u {
        return vec4<f32>(acc, 1.0);
    }
    return vec4<f32>(linear_to_srgb(acc), 1.0);
}

// One sample at the pixel's centre (the same point `fs_main` takes with the one-sample
// pattern): straight-line code, the pending op's ink chosen with `select`, and for
// …Unorm targets no sRGB conversion at all (the cache holds encoded bytes).
@fragment
fn fs_one_sample(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let p = params.view_origin + position.xy * params.view_inv_scale;
    let r = pending_back(params.pending_a, params.pending_b, p);
    let cached = textureSampleLevel(cache, cache_sampler, r.xy / params.design_size, 0.0).rgb;
    let c = select(cached, unpack_srgb(params.pending_b.w), r.z > 0.0);
    return vec4<f32>(encoded_to_target(c), 1.0);
}
