// Image backgrounds (keep in sync with marbling-core's image_background.rs), shared by
// every exact-renderer variant: surface.wgsl (with noise and grain) and its stand-in
// surface_off.wgsl both read `surface.image_map`, `surface.image_size` and
// `surface.paper`, and the `surface_image` texture the render module declares.

// With SURFACE_BACKGROUND (1): the background is `surface_image`, not noise.
const SURFACE_IMAGE: u32 = 8u;

// Linear colour of texel (i, j) of the image, clamped to its edge (an …UnormSrgb
// texture: loads decode to linear light).
fn image_texel(i: i32, j: i32) -> vec3<f32> {
    let size = vec2<i32>(surface.image_size.xy);
    return textureLoad(surface_image, clamp(vec2<i32>(i, j), vec2<i32>(0), size - 1), 0).rgb;
}

// The image background at back-traced design point p: bilinear in linear light
// between texel centres (whole + ½), clamped to the edge; the paper outside a
// letterboxed image (keep in sync with marbling-core's image_background.rs).
fn surface_image_color(p: vec2<f32>) -> vec3<f32> {
    let uv = (p - surface.image_map.xy) * surface.image_map.zw;
    let size = surface.image_size.xy;
    if surface.image_size.z > 0.5 && (any(uv < vec2<f32>(0.0)) || any(uv > size)) {
        return surface.paper.rgb;
    }
    let f = uv - 0.5;
    let base = floor(f);
    let t = f - base;
    let i = i32(base.x);
    let j = i32(base.y);
    let top = mix(image_texel(i, j), image_texel(i + 1, j), t.x);
    let bottom = mix(image_texel(i, j + 1), image_texel(i + 1, j + 1), t.x);
    return mix(top, bottom, t.y);
}

