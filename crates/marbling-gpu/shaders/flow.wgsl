// KIND_FLOW (schema v4): the tank streaming along a curl noise, the exact walk of
// marbling-core's ops/flow.rs in f32. Needs marbling-noise's hash.wgsl, perlin.wgsl and
// value.wgsl (the same lattice, hashes and corner gradients as the CPU's f64 noise,
// marbling-noise's fbm64.rs). Records (src/encode.rs): ⌈octaves/4⌉ records of
// (frequency, amplitude/σ) pairs, then the header a = (kind, U/(2πf), Δt, N),
// b = (octaves, basis: 0 Perlin, 1 value, seed's high 16 bits, low 16 bits).

// This variant walks flows (flow_off.wgsl: false), so render.wgsl keeps its turbulence.
const FLOW_ENABLED: bool = true;

// Newton steps per sub-step, from the explicit guess (the error this leaves is measured
// by tests/it/gpu_vs_cpu_v4.rs).
const FLOW_NEWTON: u32 = 2u;

// (∂n/∂x, ∂n/∂y) and (∂²n/∂x², ∂²n/∂x∂y, ∂²n/∂y²) of one octave, lattice units.
struct NoiseJet {
    g: vec2<f32>,
    h: vec3<f32>,
}

fn fade2(t: f32) -> f32 {
    return 60.0 * t * (t - 1.0) * (2.0 * t - 1.0);
}

// Perlin noise's derivatives (fbm64.rs `perlin_jet`).
fn perlin_jet(p: vec2<f32>, seed: u32) -> NoiseJet {
    let hs = perlin_corners(p, seed, vec2<i32>(0, 0));
    let fx = p.x - f32(floor_i32(p.x));
    let fy = p.y - f32(floor_i32(p.y));
    let g00 = perlin_gradient(hs.x);
    let g10 = perlin_gradient(hs.y);
    let g01 = perlin_gradient(hs.z);
    let g11 = perlin_gradient(hs.w);
    let a = dot(g00, vec2<f32>(fx, fy));
    let b = dot(g10, vec2<f32>(fx - 1.0, fy));
    let c = dot(g01, vec2<f32>(fx, fy - 1.0));
    let d = dot(g11, vec2<f32>(fx - 1.0, fy - 1.0));
    let u = fade(fx);
    let v = fade(fy);
    let u1 = fade_derivative(fx);
    let v1 = fade_derivative(fy);
    let k = a - b - c + d;
    let gk = g00 - g10 - g01 + g11;
    let ba = g10 - g00;
    let ca = g01 - g00;
    let ex = (b - a) + v * k;
    let ey = (c - a) + u * k;
    let g = vec2<f32>(
        g00.x + u * ba.x + v * ca.x + u * v * gk.x + u1 * ex,
        g00.y + u * ba.y + v * ca.y + u * v * gk.y + v1 * ey,
    );
    let h = vec3<f32>(
        2.0 * u1 * (ba.x + v * gk.x) + fade2(fx) * ex,
        v1 * (ca.x + u * gk.x) + u1 * (ba.y + v * gk.y + v1 * k),
        2.0 * v1 * (ca.y + u * gk.y) + fade2(fy) * ey,
    );
    return NoiseJet(g, h);
}

// Value noise's derivatives (fbm64.rs `value_jet`).
fn value_jet(p: vec2<f32>, seed: u32) -> NoiseJet {
    let ix = floor_i32(p.x);
    let iy = floor_i32(p.y);
    let fx = p.x - f32(ix);
    let fy = p.y - f32(iy);
    let a = value_corner(ix, iy, seed);
    let b = value_corner(ix + 1, iy, seed);
    let c = value_corner(ix, iy + 1, seed);
    let d = value_corner(ix + 1, iy + 1, seed);
    let u = fade(fx);
    let v = fade(fy);
    let u1 = fade_derivative(fx);
    let v1 = fade_derivative(fy);
    let k = a - b - c + d;
    let ex = (b - a) + v * k;
    let ey = (c - a) + u * k;
    return NoiseJet(vec2<f32>(u1 * ex, v1 * ey), vec3<f32>(fade2(fx) * ex, u1 * v1 * k, fade2(fy) * ey));
}

// The flow's velocity u = U/(2πf)·(∂n/∂y, −∂n/∂x) at p and its Jacobian
// (∂uₓ/∂x, ∂uₓ/∂y, ∂u_y/∂x, ∂u_y/∂y), the octaves read from records [first, first + ⌈n/4⌉).
fn flow_field(first: u32, h: OpRecord, p: vec2<f32>) -> TipField {
    let octaves = u32(h.b.x);
    let value = h.b.y > 0.5;
    let seed0 = (u32(h.b.z) << 16u) | u32(h.b.w);
    var g = vec2<f32>(0.0);
    var s = vec3<f32>(0.0);
    for (var o = 0u; o < octaves; o++) {
        let f = offset_at(first, 2u * o);
        let amp = offset_at(first, 2u * o + 1u);
        let seed = seed0 + o * 0x9E3779B9u;
        var j: NoiseJet;
        if value {
            j = value_jet(p * f, seed);
        } else {
            j = perlin_jet(p * f, seed);
        }
        g += (amp * f) * j.g;
        s += (amp * f * f) * j.h;
    }
    let c = h.a.y;
    return TipField(c * vec2<f32>(g.y, -g.x), c * vec4<f32>(s.y, s.z, -s.x, -s.y));
}

// KIND_FLOW (header record i): N implicit-midpoint sub-steps of −Δt, each
// M = q − (Δt/2)·u(M) by Newton's method, then 2M − q. The first guess takes u(q)
// extrapolated from the previous sub-step's last field (where it was taken, its u and
// Jacobian), as the CPU does; the first sub-step evaluates it.
fn flow_back(i: u32, h: OpRecord, p: vec2<f32>) -> vec2<f32> {
    let first = i - data_records(2u * u32(h.b.x));
    let hh = -0.5 * h.a.z;
    let steps = u32(h.a.w);
    var q = p;
    var last = flow_field(first, h, q);
    var at = q;
    for (var n = 0u; n < steps; n++) {
        let dq = q - at;
        let u0 = last.u + vec2<f32>(dot(last.j.xy, dq), dot(last.j.zw, dq));
        var m = q + hh * u0;
        for (var k = 0u; k < FLOW_NEWTON; k++) {
            last = flow_field(first, h, m);
            at = m;
            let r = m - q - hh * last.u;
            let a = 1.0 - hh * last.j.x;
            let b = -hh * last.j.y;
            let c = -hh * last.j.z;
            let d = 1.0 - hh * last.j.w;
            let det = a * d - b * c;
            m -= vec2<f32>(d * r.x - b * r.y, a * r.y - c * r.x) / det;
        }
        q = 2.0 * m - q;
    }
    return q;
}
