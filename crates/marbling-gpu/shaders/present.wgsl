// Shows a rendered texture 1:1 in part of a render pass (the app's canvas): each target
// pixel inside the sheet copies one texel (textureLoad: no filtering), pixels outside it
// get a flat background colour, and nothing is blended. On a software GPU this costs a
// fraction of a general textured, blended quad. `common.wgsl` is prepended.
//
// `vs_frame` + `fs_background` draw only the background around the sheet, in one draw
// of flat colour (while the live preview draws the sheet itself). A software GPU runs
// every branch of `fs_main` for every pixel, texture load and sRGB decode included, so
// the background is cheaper from a shader that has none.

// Keep in sync with `PresentParams` in src/params.rs (checked by tests/layout.rs).
struct PresentParams {
    // Target pixel (x, y) of the texture's texel (0, 0), whole pixels.
    origin: vec2<f32>,
    // 1: the target is …UnormSrgb, so the sRGB-encoded texels are decoded to linear
    // light first (the hardware encodes them again); 0: texels are written as they are.
    linear_target: u32,
    _pad: u32,
    // The sheet in target pixels: (min x, min y, max x, max y). A pixel is inside when
    // its centre is.
    sheet: vec4<f32>,
    // The colour outside the sheet, as written to the target.
    background: vec4<f32>,
    // The target's size in pixels, for `vs_frame` (whose pass viewport is all of it).
    target_size: vec2<f32>,
    _pad2: vec2<u32>,
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

// The target outside the sheet's pixels (those whose centres lie inside `sheet`): four
// quads, above, below, left and right of them, 24 vertices. The viewport must be the
// whole target (`target_size`); quads of margins the sheet leaves none of are empty.
@vertex
fn vs_frame(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    let size = params.target_size;
    // The sheet's pixel edges (a pixel is inside when its centre is), within the target.
    let lo = clamp(ceil(params.sheet.xy - 0.5), vec2<f32>(0.0), size);
    let hi = clamp(ceil(params.sheet.zw - 0.5), lo, size);
    var near = vec2<f32>(0.0);
    var far = size;
    switch vertex / 6u {
        case 0u: {
            far.y = lo.y;
        }
        case 1u: {
            near.y = hi.y;
        }
        case 2u: {
            near.y = lo.y;
            far = vec2<f32>(lo.x, hi.y);
        }
        default: {
            near = vec2<f32>(hi.x, lo.y);
            far.y = hi.y;
        }
    }
    // Two triangles per quad, corners (0, 0) (1, 0) (0, 1) and (0, 1) (1, 0) (1, 1).
    let c = vertex % 6u;
    let t = vec2<f32>(f32(c == 1u || c == 4u || c == 5u), f32(c == 2u || c == 3u || c == 5u));
    let ndc = mix(near, far, t) / size * 2.0 - 1.0;
    return vec4<f32>(ndc.x, -ndc.y, 0.0, 1.0);
}

@fragment
fn fs_background() -> @location(0) vec4<f32> {
    return params.background;
}
