// The exact renderer: every sample of every output pixel walks back through ALL ops of
// the design, newest → oldest, in one fragment-shader pass (common.wgsl, records.wgsl,
// marbling-noise's noise module and surface.wgsl are prepended; see src/shaders.rs).
// Vertex + fragment only, uniforms + a float texture: runs on WebGPU and WebGL2 alike.
// render_compute.wgsl adds a compute entry point drawing the same `shade`.

// Keep in sync with `RenderParams` in src/params.rs (checked by tests/layout.rs).
struct RenderParams {
    // Background: linear r, g, b and the packed sRGB bytes.
    background: vec4<f32>,
    // Output pixel (column, row) of the render target's top-left pixel (tiles, views).
    offset: vec2<f32>,
    // Design pixels per output pixel (1 / scale).
    inv_scale: f32,
    // Number of records in the op texture.
    op_count: u32,
    // log2 of the records per row of the op texture (a power of two; 2 texels each).
    ops_row_shift: u32,
    // Samples of the first pass, at samples[0 .. first_count].
    first_count: u32,
    // Samples of the refinement pass (0: none), at samples[first_count ..].
    refine_count: u32,
    // 1: write sRGB-encoded values (…Unorm targets); 0: write linear light (…UnormSrgb).
    encode_srgb: u32,
    // A looping turbulence's two layers (marbling-core's turbulence.rs), each
    // (Δt, N, weight, record index of the flow's header; 0: no turbulence): a sample
    // walks back N sub-steps of Δt through that flow, then through records
    // [0, op_count), the layers blended in linear light.
    layers: array<vec4<f32>, 2>,
    // (dx, dy, weight, 0): offsets from the pixel's top-left corner in output pixels.
    samples: array<vec4<f32>, 20>,
    // Deep zoom (deep.wgsl; variants with DEEP_ENABLED only): tile side (output
    // pixels), tiles per row, log2 of the reference records per texture row, records
    // per tile (op_count + 1). `offset` is then 0: samples are placed from the target.
    deep: vec4<u32>,
}

@group(0) @binding(0) var<uniform> params: RenderParams;
// Rgba32Float, 2 texels per record, record k at (2·(k mod R), k div R), R = 2^ops_row_shift.
@group(0) @binding(1) var ops: texture_2d<f32>;
// Schema v2 noise background and grain overlays (surface.flags == 0: none).
@group(0) @binding(2) var<uniform> surface: SurfaceParams;
// Image background (surface.flags has SURFACE_IMAGE), Rgba8UnormSrgb; 1×1 otherwise.
@group(0) @binding(3) var surface_image: texture_2d<f32>;

@vertex
fn vs_main(@builtin(vertex_index) vertex: u32) -> @builtin(position) vec4<f32> {
    return fullscreen_position(vertex);
}

// Where a walk ended: the colour (linear r, g, b, packed sRGB) of the ink that covered it
// or of the plain background, whether it reached the background, and the end point.
struct Hit {
    color: vec4<f32>,
    background: bool,
    end: vec2<f32>,
}

// Walks design point `p0` back through every op: the colour it shows as
// (linear r, g, b, packed sRGB; for a v2 surface, packed is the ink's or the plain
// background's, used only to decide refinement). With a turbulence, the two layers'
// colours blended in linear light (packed is −1 where they differ). Only variants with
// a flow have a turbulence (its flow is the design's last op): elsewhere
// `FLOW_ENABLED` is a false constant and the per-sample walk is the plain one.
fn trace(p0: vec2<f32>) -> vec4<f32> {
    let flowing = FLOW_ENABLED && params.layers[0].w != 0.0;
    var acc = vec3<f32>(0.0);
    var packed = -2.0;
    // One call site of `trace_from` for both cases (a software GPU's compiler inlines
    // each call, the whole walk with it): without a turbulence one round at weight 1.
    for (var k = 0u; k < 2u; k++) {
        var p = p0;
        var weight = 1.0;
        if flowing {
            let layer = params.layers[k];
            if layer.z <= 0.0 {
                continue;
            }
            let at = u32(layer.w);
            var h = op_record(at);
            h.a.z = layer.x;
            h.a.w = layer.y;
            p = flow_back(at, h, p0);
            weight = layer.z;
        }
        let c = trace_from(p0, p);
        acc += weight * c.rgb;
        if packed == -2.0 || packed == c.w {
            packed = c.w;
        } else {
            packed = -1.0;
        }
        if !flowing {
            break;
        }
    }
    return vec4<f32>(acc, packed);
}

// The colour design point `p0` shows when its walk through the ops starts at `p`
// (p0 itself, or where a turbulence's flow took it; the paper's grain stays at p0).
fn trace_from(p0: vec2<f32>, p: vec2<f32>) -> vec4<f32> {
    return hit_colour(p0, walk(p));
}

// The colour of output design point `p0` whose walk ended with `h`.
fn hit_colour(p0: vec2<f32>, h: Hit) -> vec4<f32> {
    if surface.flags == 0u {
        return h.color;
    }
    return vec4<f32>(surface_shade(h.color.rgb, h.background, p0, h.end), h.color.w);
}

fn walk(p0: vec2<f32>) -> Hit {
    let e = walk_records(0u, params.op_count, p0);
    if e.covered {
        return Hit(e.ink, false, e.p);
    }
    return Hit(params.background, true, e.p);
}

// Record i of the op texture (records.wgsl walks them).
// (Records per row are a power of two: a mask and a shift, no division; the shift comes
// from the host because WebGL2's GLSL ES 3.00 has no findLSB for countTrailingZeros.)
fn op_record(i: u32) -> OpRecord {
    let col = i32((i & ((1u << params.ops_row_shift) - 1u)) * 2u);
    let row = i32(i >> params.ops_row_shift);
    return OpRecord(textureLoad(ops, vec2<i32>(col, row), 0), textureLoad(ops, vec2<i32>(col + 1, row), 0));
}

// Weighted average in linear light of samples[start .. start + count] of output pixel
// `pixel` (its top-left corner): (r, g, b, packed sRGB shared by every sample, or −1).
fn average(pixel: vec2<f32>, start: u32, count: u32) -> vec4<f32> {
    var acc = vec3<f32>(0.0);
    var packed = -1.0;
    for (var i = 0u; i < count; i++) {
        let s = params.samples[start + i];
        var c: vec4<f32>;
        if DEEP_ENABLED {
            c = deep_trace(pixel + s.xy);
        } else {
            c = trace((pixel + s.xy) * params.inv_scale);
        }
        acc += s.z * c.rgb;
        if i == 0u {
            packed = c.w;
        } else if c.w != packed {
            packed = -1.0;
        }
    }
    return vec4<f32>(acc, packed);
}

@fragment
fn fs_main(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return shade(floor(position.xy));
}

// The colour of the target's pixel (column, row) = `target_pixel` (whole numbers), as
// written to the target (sRGB-encoded or linear, see `encode_srgb`). The fragment entry
// above and the compute entry of render_compute.wgsl both draw with it.
fn shade(target_pixel: vec2<f32>) -> vec4<f32> {
    let pixel = target_pixel + params.offset;
    // The first samples, then the refinement's where they disagree, through one call
    // site of `average`: a software GPU's compiler inlines each call, walk and noise
    // included (two sites compiled all of it twice).
    var r = vec4<f32>(0.0, 0.0, 0.0, -1.0);
    var start = 0u;
    var count = params.first_count;
    for (var k = 0u; k < 2u; k++) {
        r = average(pixel, start, count);
        if r.w >= 0.0 || params.refine_count == 0u {
            break;
        }
        start = params.first_count;
        count = params.refine_count;
    }
    if params.encode_srgb == 0u {
        return vec4<f32>(r.rgb, 1.0);
    }
    if r.w >= 0.0 && surface.flags == 0u {
        // Every sample shows one colour: keep its exact sRGB bytes, as the CPU does.
        return vec4<f32>(unpack_srgb(r.w), 1.0);
    }
    return vec4<f32>(linear_to_srgb(r.rgb), 1.0);
}
