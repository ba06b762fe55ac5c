// Stand-ins for surface.wgsl in the variants without noise (designs with a plain or
// image background and no overlays): the same `SurfaceParams` with the noise members
// skipped, and a `surface_shade` that draws only the image background (image.wgsl), so
// no noise code is compiled.

// Keep in sync with `SurfaceParams` in src/surface.rs (tests/layout.rs checks that the
// image fields sit at the host's offsets).
struct SurfaceParams {
    // 0 for a plain background; SURFACE_BACKGROUND | SURFACE_IMAGE for an image.
    flags: u32,
    stop_count: u32,
    layer_count: u32,
    _pad: u32,
    // The palette, noises and layers of surface.wgsl, unread here.
    _noise: array<vec4<f32>, 68>,
    image_map: vec4<f32>,
    image_size: vec4<f32>,
    paper: vec4<f32>,
}

fn surface_shade(c: vec3<f32>, background: bool, start: vec2<f32>, end: vec2<f32>) -> vec3<f32> {
    if background && (surface.flags & SURFACE_IMAGE) != 0u {
        return surface_image_color(end);
    }
    return c;
}
