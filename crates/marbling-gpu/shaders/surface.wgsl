// Schema v2 surfaces (keep in sync with marbling-core's surface.rs and with
// `SurfaceParams` in src/surface.rs): a noise background mapped to a palette and sampled at
// the back-traced point, pigment grain sampled where the walk ended, paper grain sampled
// at the output design point. Needs marbling-noise's `noise` module (sample_noise,
// noise_to_grey, threshold_transfer) and a `surface: SurfaceParams` uniform declared by
// the shader that includes this file.

// `flags` bits and layer indices: bit i set ⇔ layers[i] is used.
const SURFACE_BACKGROUND: u32 = 1u;
const SURFACE_PIGMENT: u32 = 2u;
const SURFACE_PAPER: u32 = 4u;

// How layer i's noise (`SurfaceParams::noises[i]`) becomes an intensity in [0, 1]
// (keep in sync with `LayerParams`). The noise is not a member: WebGL2 (GLSL ES, as
// ANGLE enforces it) allows structs nested at most 4 deep, and NoiseUniform is 3 deep.
struct SurfaceLayer {
    // Threshold transfer: centre and width (noise units).
    threshold: f32,
    width: f32,
    // 0: 0.5 + n/6 clamped; 1: threshold; 2: inverted threshold.
    transfer: u32,
    // Overlays: darkening at intensity 1 (factor 1 − strength·g on linear colour).
    strength: f32,
}

// Keep in sync with `SurfaceParams` in src/surface.rs (checked by tests/layout.rs).
struct SurfaceParams {
    // SURFACE_* bits; 0 for a plain background without overlays.
    flags: u32,
    // Palette stops in use (2..=8).
    stop_count: u32,
    // Always 3: the loop bound over `layers`, read from the uniform so that the
    // compiler keeps ONE call of sample_noise (unrolling would triple a large shader).
    layer_count: u32,
    _pad: u32,
    // Palette stops, sRGB in [0, 1] (rgb; w unused), evenly spaced over intensity 0..1.
    stops: array<vec4<f32>, 8>,
    // 0: background noise (at the back-traced point), 1: pigment grain (where the walk
    // ended), 2: paper grain (at the output design point).
    noises: array<NoiseUniform, 3>,
    // The transfer and strength of each of `noises`.
    layers: array<SurfaceLayer, 3>,
    // Image background: image pixel u = (x − [0])·[2], v = (y − [1])·[3].
    image_map: vec4<f32>,
    // Image width, height (pixels), 1 when letterboxed (contain) else 0, unused.
    image_size: vec4<f32>,
    // The paper around a letterboxed image, linear rgb.
    paper: vec4<f32>,
}

fn surface_intensity(p: vec2<f32>, i: u32) -> f32 {
    let n = sample_noise(p, i);
    let transfer = surface.layers[i].transfer;
    if transfer == 0u {
        return noise_to_grey(n);
    }
    return threshold_transfer(n, surface.layers[i].threshold, surface.layers[i].width, transfer == 2u);
}

// Linear colour of the palette at intensity t.
fn surface_palette(t: f32) -> vec3<f32> {
    let n = surface.stop_count - 1u;
    let x = clamp(t, 0.0, 1.0) * f32(n);
    let i = min(u32(floor(x)), n - 1u);
    let f = x - f32(i);
    let a = surface.stops[i].rgb;
    let b = surface.stops[i + 1u].rgb;
    return srgb_to_linear(a + f * (b - a));
}

// Linear colour `c` of a sample that left design point `start` and whose walk ended at
// `end` (background: the back-traced point), with `background` true when no ink covered
// it: the noise background, then pigment grain at `end`, then paper grain at `start`.
fn surface_shade(c: vec3<f32>, background: bool, start: vec2<f32>, end: vec2<f32>) -> vec3<f32> {
    var rgb = c;
    for (var i = 0u; i < surface.layer_count; i++) {
        if (surface.flags & (1u << i)) == 0u || (i == 0u && !background) {
            continue;
        }
        var p = end;
        if i == 2u {
            p = start;
        }
        if i == 0u && (surface.flags & SURFACE_IMAGE) != 0u {
            rgb = surface_image_color(p);
            continue;
        }
        let g = surface_intensity(p, i);
        if i == 0u {
            rgb = surface_palette(g);
        } else {
            rgb *= 1.0 - surface.layers[i].strength * g;
        }
    }
    return rgb;
}
