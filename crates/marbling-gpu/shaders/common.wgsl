// Shared by render.wgsl and preview.wgsl (the host prepends this file to each; see
// src/shaders.rs): the inverse of one marbling op in f32, and the sRGB transfer function.
//
// Op encoding: two vec4<f32> per op, `a` and `b`, the host's `GpuOp` (src/encode.rs,
// made from marbling-core's `CompiledOp`). a.x is the kind, the code of marbling-core's
// `OpKind` (tests/shaders_validate.rs checks the KIND_ constants against it):
//   KIND_DROP, KIND_SPRAY: a = (kind, cx, cy, r²),          b = (ink linear r, g, b, packed sRGB)
//   KIND_COMB (tine/rake): a = (kind, ax, ay, mx),          b = (my, αλ, λ, spacing; 0 = tine)
//   KIND_WAVE:             a = (kind, mx, my, amplitude),   b = (2π/wavelength, phase, 0, 0)
//   KIND_CIRCULAR, KIND_VORTEX: a = (kind, cx, cy, r),      b = (αλ, λ, 0, 0)
//   KIND_RIGID (shift, turn):   a = (kind, cx, cy, sin θ),  b = (cos θ, ox, oy, 0)
//   KIND_JIGGLE:           a = (kind, ux, uy, 2π/λ),        b = (A, B, φ₀ mod 2π, 0)
// KIND_TINES, KIND_STYLUS and KIND_FLOW span several records; ops_v3.wgsl walks them
// (a flow with flow.wgsl) and, in the
// exact walk, KIND_RIGID and KIND_JIGGLE (the live preview calls rigid_back and
// jiggle_back directly).
// Packed sRGB is r·65536 + g·256 + b, exact in an f32 (24 bits).

const KIND_DROP: u32 = 0u;
const KIND_SPRAY: u32 = 1u;
const KIND_COMB: u32 = 2u;
const KIND_WAVE: u32 = 3u;
const KIND_CIRCULAR: u32 = 4u;
const KIND_VORTEX: u32 = 5u;
const KIND_RIGID: u32 = 6u;
const KIND_TINES: u32 = 7u;
const KIND_JIGGLE: u32 = 8u;
const KIND_STYLUS: u32 = 9u;
const KIND_FLOW: u32 = 10u;

// Walks design point `p` back through the op (a, b): returns (x, y, covered), where
// covered = 1.0 when `p` lies in the op's ink (the walk stops there with colour `b`),
// else (x, y) is where `p` was before the op. Same formulas as marbling-core's walk.rs.
fn op_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    switch u32(a.x) {
        case KIND_DROP, KIND_SPRAY: {
            return drop_back(a, b, p);
        }
        case KIND_COMB: {
            return comb_back(a, b, p);
        }
        case KIND_WAVE: {
            return wave_back(a, b, p);
        }
        case KIND_CIRCULAR, KIND_VORTEX: {
            return swirl_back(a, b, p);
        }
        default: {
            // Schema v3's kinds are walked by ops_v3.wgsl (`v3_back`), never here: two
            // more cases slow every v1 walk on a CPU-emulated GPU.
            return vec3<f32>(p, 0.0);
        }
    }
}

// op_back for KIND_RIGID: P = C + R(−θ)(P′ − o − C).
fn rigid_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let q = p - b.yz - a.yz;
    let s = a.w;
    let c = b.x;
    return vec3<f32>(a.yz + vec2<f32>(q.x * c + q.y * s, -q.x * s + q.y * c), 0.0);
}

// Newton steps of the jiggle's inverse (safeguarded in the bracket; the error this
// leaves is measured by tests/compute.rs).
const JIGGLE_NEWTON: u32 = 6u;

// op_back for KIND_JIGGLE: solves φ + kA·sin φ = k(P′·u) + φ₀ (t reduced to [0, 2π)),
// then P = P′ − A·sin φ·u − B·cos φ·v with v = (−u.y, u.x).
fn jiggle_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let u = a.yz;
    let v = vec2<f32>(-u.y, u.x);
    let tau = 6.2831855;
    var t = a.w * dot(p, u) + b.z;
    t = t - floor(t / tau) * tau;
    let c = a.w * b.x;
    let lo = t - abs(c);
    let hi = t + abs(c);
    var phi = clamp(t - c * sin(t), lo, hi);
    for (var i = 0u; i < JIGGLE_NEWTON; i++) {
        let f = phi + c * sin(phi) - t;
        phi = clamp(phi - f / (1.0 + c * cos(phi)), lo, hi);
    }
    return vec3<f32>(p - b.x * sin(phi) * u - b.y * cos(phi) * v, 0.0);
}

// op_back for KIND_DROP and KIND_SPRAY (a spray droplet leaves the rest in place).
fn drop_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let d = p - a.yz;
    let d2 = dot(d, d);
    if d2 < a.w {
        return vec3<f32>(p, 1.0);
    }
    if u32(a.x) == KIND_DROP {
        return vec3<f32>(a.yz + d * sqrt(1.0 - a.w / d2), 0.0);
    }
    return vec3<f32>(p, 0.0);
}

// op_back for KIND_COMB (tine, or rake when b.w, the spacing, is > 0).
fn comb_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let m = vec2<f32>(a.w, b.x);
    let n = vec2<f32>(-m.y, m.x);
    var d = abs(dot(p - a.yz, n));
    if b.w > 0.0 {
        let fr = fract(d / b.w);
        d = b.w * (0.5 - abs(fr - 0.5));
    }
    return vec3<f32>(p - (b.y / (d + b.z)) * m, 0.0);
}

// op_back for KIND_WAVE.
fn wave_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let m = a.yz;
    let n = vec2<f32>(m.y, -m.x);
    let f = a.w * sin(b.x * dot(p, n) + b.y);
    return vec3<f32>(p - f * m, 0.0);
}

// op_back for KIND_CIRCULAR and KIND_VORTEX (a rotation about the centre).
fn swirl_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {
    let d = p - a.yz;
    let rho = sqrt(dot(d, d));
    if rho == 0.0 {
        return vec3<f32>(p, 0.0);
    }
    var dist = rho;
    if u32(a.x) == KIND_CIRCULAR {
        dist = abs(rho - a.w);
    }
    let theta = b.x / (dist + b.y) / rho;
    let s = sin(-theta);
    let c = cos(theta);
    return vec3<f32>(a.yz + vec2<f32>(d.x * c - d.y * s, d.x * s + d.y * c), 0.0);
}

// The sRGB bytes packed as r·65536 + g·256 + b, as floats in 0..=1 (exact byte/255).
fn unpack_srgb(packed: f32) -> vec3<f32> {
    let v = u32(packed);
    return vec3<f32>(f32((v >> 16u) & 255u), f32((v >> 8u) & 255u), f32(v & 255u)) / 255.0;
}

// sRGB-encoded value (0..=1) → linear light (IEC 61966-2-1), per channel.
fn srgb_to_linear(s: vec3<f32>) -> vec3<f32> {
    let lo = s / 12.92;
    let hi = pow((s + 0.055) / 1.055, vec3<f32>(2.4));
    return select(hi, lo, s <= vec3<f32>(0.04045));
}

// Linear light (0..=1) → sRGB-encoded value in 0..=1 (IEC 61966-2-1), per channel.
fn linear_to_srgb(l: vec3<f32>) -> vec3<f32> {
    let c = clamp(l, vec3<f32>(0.0), vec3<f32>(1.0));
    let lo = c * 12.92;
    let hi = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(hi, lo, c <= vec3<f32>(0.0031308));
}

// A full-screen triangle: vertices 0, 1, 2 cover the whole target.
fn fullscreen_position(vertex: u32) -> vec4<f32> {
    let x = f32(i32(vertex & 1u) * 4 - 1);
    let y = f32(i32(vertex >> 1u) * 4 - 1);
    return vec4<f32>(x, y, 0.0, 1.0);
}
