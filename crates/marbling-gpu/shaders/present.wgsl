// Shows a rendered texture 1:1 in part of a render pass (the app's canvas): each target
// pixel inside the sheet copies one texel (textureLoad: no filtering), pixels outside it
// get a flat background colour, and nothing is blended. On a software GPU this costs a
// fraction of a general textured, blended quad. `common.wgsl` is prepended.

// Keep in sync with `PresentParams` in src/params.rs (checked by tests/layout.rs).
struct PresentParams {
    // Target pixel (x, y) of the texture's texel (0, 0), whole pixels.
    origin: vec2<f32>,
    // 1: the texels are sRGB-encoded values and the target is …UnormSrgb, so they are
    // decoded to linear light first (the hardware encodes them again); 0: texels are
    // written as they are (also for a texture of the target's own format).
    linear_target: u32,
    _pad: u32,
    // The sheet in target pixels: (min x, min y, max x, max y). A pixel is inside when
    // its centre is.
    sheet: vec4<f32>,
    // The colour outside the sheet, as written to the target.
    background: vec4<f32>,
}

@group(0) @binding(0) var<uniform> params: PresentParams;
@group(0) @binding(1) var image: texture_2d<f32>;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let p = position.xy;
    let s = params.sheet;
    if p.x < s.x || p.y < s.y || p.x >= s.z || p.y >= s.w {
        return params.background;
    }
    let last = vec2<i32>(textureDimensions(image)) - vec2<i32>(1);
    let texel = clamp(vec2<i32>(floor(p - params.origin)), vec2<i32>(0), last);
    let c = textureLoad(image, texel, 0);
    if params.linear_target != 0u {
        return vec4<f32>(srgb_to_linear(c.rgb), c.a);
    }
    return c;
}

// Texels that need no conversion (`linear_target` 0), copied as they are: target pixel
// p shows texel p − origin, with no sheet test and no background. Straight-line code,
// which a software GPU runs for each pixel at a fraction of `fs_main`'s cost. The pass's
// scissor rectangle must lie within the sheet.
@fragment
fn fs_copy(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let last = vec2<i32>(textureDimensions(image)) - vec2<i32>(1);
    let texel = clamp(vec2<i32>(floor(position.xy - params.origin)), vec2<i32>(0), last);
    return textureLoad(image, texel, 0);
}
