// Stand-ins for surface.wgsl in the exact renderer's plain variant (designs with a plain
// background and no overlays): the same `SurfaceParams` head, and a `surface_shade` that
// is never called there (flags are 0), so no noise code is compiled.

const SURFACE_ENABLED: bool = false;

struct SurfaceParams {
    // Always 0 for the designs drawn with this variant.
    flags: u32,
    stop_count: u32,
    layer_count: u32,
    _pad: u32,
}

fn surface_shade(c: vec3<f32>, background: bool, start: vec2<f32>, end: vec2<f32>) -> vec3<f32> {
    return c;
}
