// Untextured coloured triangles (UI strokes and fills: the app's tool overlay), blended
// with premultiplied alpha as egui blends. Vertices are laid out as egui's
// `epaint::Vertex`: position in points, a texture coordinate (unused), and colour as
// premultiplied sRGB-encoded bytes. The colour is written as it is (`fs_main`, …Unorm
// targets) or decoded to linear light (`fs_linear`, …UnormSrgb targets). Straight-line
// code: on a software GPU egui's general shader, whose every branch runs for every
// pixel, costs far more per pixel (docs/BENCHMARKS.md). marbling-gpu's `common.wgsl` is
// prepended.

// Keep in sync with `FlatMeshParams` in flat_mesh.rs (checked by its test).
struct FlatMeshParams {
    // The target's size in points (egui's screen).
    screen_size_points: vec2<f32>,
    _pad: vec2<f32>,
}

@group(0) @binding(0) var<uniform> params: FlatMeshParams;

struct VertexOutput {
    @builtin(position) position: vec4<f32>,
    // Premultiplied, sRGB-encoded.
    @location(0) color: vec4<f32>,
}

@vertex
fn vs_main(
    @location(0) position: vec2<f32>,
    @location(1) uv: vec2<f32>,
    @location(2) color: vec4<f32>,
) -> VertexOutput {
    let ndc = 2.0 * position / params.screen_size_points - 1.0;
    var out: VertexOutput;
    out.position = vec4<f32>(ndc.x, -ndc.y, 0.0, 1.0);
    out.color = color;
    return out;
}

@fragment
fn fs_main(in: VertexOutput) -> @location(0) vec4<f32> {
    return in.color;
}

@fragment
fn fs_linear(in: VertexOutput) -> @location(0) vec4<f32> {
    return vec4<f32>(srgb_to_linear(in.color.rgb), in.color.a);
}
