// layers.wgsl — a spec's layer stack on the GPU: each noise's intensity (default grey map
// or threshold), combined bottom to top (keep in sync with crates/marbling-noise/src/
// layer.rs and `NoiseStackGpu` in src/stack_gpu.rs). Needs the `noise` module.

const COMBINE_ADD: u32 = 0u;
const COMBINE_MULTIPLY: u32 = 1u;
const COMBINE_MAX: u32 = 2u;
const COMBINE_MIN: u32 = 3u;
const COMBINE_MASK: u32 = 4u;

// Most layers on the base noise (MAX_LAYERS), and so 1 + 2 * 4 noise slots.
const STACK_SLOTS: u32 = 9u;

// c combined with the layer's b (and the mask's m, read by COMBINE_MASK), faded in by
// `weight`, clamped to [0, 1].
fn combine_layer(c: f32, b: f32, m: f32, mode: u32, weight: f32) -> f32 {
    var mixed = c + b - 0.5;
    switch mode {
        case 1u: { mixed = c * b; }
        case 2u: { mixed = max(c, b); }
        case 3u: { mixed = min(c, b); }
        case 4u: { mixed = c + (b - c) * m; }
        default: {}
    }
    return clamp(c + (mixed - c) * weight, 0.0, 1.0);
}

// How one slot's noise becomes an intensity: 0 the default grey map, 1 threshold,
// 2 inverted threshold.
struct StackTransfer {
    threshold: f32,
    width: f32,
    transfer: u32,
    _pad: u32,
}

// Layer i's combine mode (COMBINE_*) and weight.
struct StackLayer {
    combine: u32,
    weight: f32,
    _pad0: u32,
    _pad1: u32,
}

struct NoiseStack {
    layer_count: u32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
    // Slot 0: the base noise; 1 + 2i: layer i; 2 + 2i: layer i's mask (a cheap white
    // noise when it has none).
    noises: array<NoiseUniform, 9>,
    transfers: array<StackTransfer, 9>,
    layers: array<StackLayer, 4>,
}

fn stack_transfer(n: f32, t: StackTransfer) -> f32 {
    if t.transfer == 0u {
        return noise_to_grey(n);
    }
    return threshold_transfer(n, t.threshold, t.width, t.transfer == 2u);
}

// The stack's intensity at p (output pixels): one call of sample_noise in a loop over
// the slots in use.
fn stack_intensity(p: vec2<f32>, s: NoiseStack) -> f32 {
    var c = 0.0;
    var b = 0.0;
    let slots = min(1u + 2u * s.layer_count, STACK_SLOTS);
    for (var k = 0u; k < slots; k++) {
        let t = stack_transfer(sample_noise(p, s.noises[k]), s.transfers[k]);
        if k == 0u {
            c = t;
        } else if k % 2u == 1u {
            b = t;
        } else {
            let l = s.layers[(k - 2u) / 2u];
            c = combine_layer(c, b, t, l.combine, l.weight);
        }
    }
    return c;
}
