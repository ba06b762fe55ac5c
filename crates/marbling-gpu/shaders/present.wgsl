// Shows a rendered texture 1:1 in part of a render pass (the app's canvas, its cached
// panels): target pixel p shows texel p − origin, nothing is blended. The texel is
// sampled at its centre with a nearest-texel sampler clamped to the texture's edge:
// exactly the texel, and cheaper than textureLoad on SwiftShader (docs/BENCHMARKS.md).
// The pass's scissor rectangle says which pixels are drawn. Both entry points are
// straight-line code: a software GPU runs every branch of a shader for every pixel, so
// the choice between copying and decoding is made by picking the pipeline, not by a
// uniform. `common.wgsl` is prepended.

// Keep in sync with `PresentParams` in src/params.rs (checked by tests/layout.rs).
struct PresentParams {
    // Target pixel (x, y) of the texture's texel (0, 0), whole pixels.
    origin: vec2<f32>,
    _pad: vec2<f32>,
}

@group(0) @binding(0) var<uniform> params: PresentParams;
@group(0) @binding(1) var image: texture_2d<f32>;
@group(0) @binding(2) var nearest: sampler;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

// The texel under target pixel `position` (a pixel centre; `origin` is whole pixels, so
// the sample point is the texel's centre).
fn texel_at(position: vec2<f32>) -> vec4<f32> {
    let size = vec2<f32>(textureDimensions(image));
    return textureSampleLevel(image, nearest, (position - params.origin) / size, 0.0);
}

// Texels that need no conversion, written as they are (a …Unorm target showing
// sRGB-encoded values, or a texture of the target's own format).
@fragment
fn fs_copy(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return texel_at(position.xy);
}

// sRGB-encoded texels for a …UnormSrgb target: decoded to linear light here, encoded
// again by the hardware on store.
@fragment
fn fs_decode(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let c = texel_at(position.xy);
    return vec4<f32>(srgb_to_linear(c.rgb), c.a);
}
