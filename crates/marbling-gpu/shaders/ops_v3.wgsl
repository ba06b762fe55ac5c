// The ops schema v3 added, in the exact walk (see records.wgsl): shift and turn
// (KIND_RIGID) and the jiggle, one record each (their inverses are in common.wgsl, where
// the live preview takes them too), and the finite comb and the stylus, which span
// several records. Designs without v3 ops are drawn by a variant with ops_v3_off.wgsl
// instead, which compiles none of this: on lavapipe two more cases in the plain walk's
// `op_back` switch made 1,000-op v1 designs 3.5× slower (docs/BENCHMARKS.md).
//
// Several-record encodings (the host's `compiled_records` in src/encode.rs); the header
// is the newest record, its data records come before it:
//   KIND_TINES: ⌈T/8⌉ records of tine offsets (8 per record, padded with the first),
//     then the header a = (kind, ax, ay, mx), b = (my, αλ, λ, T).
//   KIND_STYLUS: for T > 1 tips, ⌈T/8⌉ records of tip offsets; then per segment two
//     records, H2 = a (T, smallest offset, largest offset, H1 index − tips' index),
//     b (records to step back over: 2, plus the tips' for the first segment, ℓ, 0, 0)
//     and the header H1 = a (kind, start x, start y, n.x), b (n.y, δ, N, L).
//   KIND_FLOW: see flow.wgsl (or its stand-in flow_off.wgsl, in variants without a flow).

const V3_ENABLED: bool = true;

// A stylus tip reaches R = 8L.
const STYLUS_REACH: f32 = 8.0;
// Newton steps per stylus sub-step (the error this leaves is measured by
// tests/compute.rs).
const STYLUS_NEWTON: u32 = 4u;

// Walks `p` back through the v3 op whose (header) record is `at`: (x, y, records it
// spans).
fn v3_back(at: u32, r: OpRecord, p: vec2<f32>) -> vec3<f32> {
    let kind = u32(r.a.x);
    if kind == KIND_RIGID {
        return vec3<f32>(rigid_back(r.a, r.b, p).xy, 1.0);
    }
    if kind == KIND_JIGGLE {
        return vec3<f32>(jiggle_back(r.a, r.b, p).xy, 1.0);
    }
    if kind == KIND_TINES {
        return vec3<f32>(tines_back(at, r, p), f32(1u + data_records(u32(r.b.w))));
    }
    if kind == KIND_FLOW {
        return vec3<f32>(flow_back(at, r, p), f32(1u + data_records(2u * u32(r.b.x))));
    }
    let h2 = op_record(at - 1u);
    return vec3<f32>(stylus_back(at, r, h2, p), h2.b.x);
}

// Records holding `count` offsets.
fn data_records(count: u32) -> u32 {
    return (count + 7u) / 8u;
}

// Offset k of the data records starting at record `first`.
fn offset_at(first: u32, k: u32) -> f32 {
    let r = op_record(first + k / 8u);
    let j = k % 8u;
    if j < 4u {
        return r.a[j];
    }
    return r.b[j - 4u];
}

// KIND_TINES (header record i): shift back by αλ/(d + λ) along m, d = minᵢ |s − oᵢ|.
fn tines_back(i: u32, h: OpRecord, p: vec2<f32>) -> vec2<f32> {
    let m = vec2<f32>(h.a.w, h.b.x);
    let s = vec4<f32>(dot(p - h.a.yz, vec2<f32>(-m.y, m.x)));
    var d = 1.0e30;
    for (var r = i - data_records(u32(h.b.w)); r < i; r++) {
        let rec = op_record(r);
        let near = min(abs(s - rec.a), abs(s - rec.b));
        d = min(d, min(min(near.x, near.y), min(near.z, near.w)));
    }
    return p - (h.b.y / (d + h.b.z)) * m;
}

// The tips' summed velocity at local point q (x along n, y along n⊥, from the
// sub-step's midpoint) and its Jacobian (∂uₓ/∂x, ∂uₓ/∂y, ∂u_y/∂x, ∂u_y/∂y).
struct TipField {
    u: vec2<f32>,
    j: vec4<f32>,
}

// Tips: `count` offsets from record `tips`, or the one offset `only` when count is 1.
fn tip_field(q: vec2<f32>, tips: u32, count: u32, only: f32, wake: f32) -> TipField {
    let reach = STYLUS_REACH * wake;
    var u = vec2<f32>(0.0);
    var j = vec4<f32>(0.0);
    for (var t = 0u; t < count; t++) {
        var o = only;
        if count > 1u {
            o = offset_at(tips, t);
        }
        let y = q.y - o;
        let rho = sqrt(q.x * q.x + y * y);
        if rho >= reach {
            continue;
        }
        // g(ρ) = e^{−ρ/L}·c(ρ/R), c(t) = (1 − t²)³, and its first two derivatives.
        let tt = rho / reach;
        let w = 1.0 - tt * tt;
        let c = w * w * w;
        let c1 = -6.0 * tt * w * w;
        let c2 = w * (30.0 * tt * tt - 6.0);
        let e = exp(-rho / wake);
        let g = e * c;
        let g1 = e * (-c / wake + c1 / reach);
        let g2 = e * (c / (wake * wake) - 2.0 * c1 / (wake * reach) + c2 / (reach * reach));
        var ex = 0.0;
        var ey = 0.0;
        if rho > 0.0 {
            ex = q.x / rho;
            ey = y / rho;
        }
        let psi_x = rho * ex * ey * g1;
        let psi_y = g + rho * ey * ey * g1;
        let psi_xx = ey * (g1 * ey * ey + ex * ex * rho * g2);
        let psi_xy = ex * (g1 * ex * ex + ey * ey * rho * g2);
        let psi_yy = ey * (g1 * (3.0 - ey * ey) + ey * ey * rho * g2);
        u += vec2<f32>(psi_y, -psi_x);
        j += vec4<f32>(psi_xy, psi_yy, -psi_xx, -psi_xy);
    }
    return TipField(u, j);
}

// One implicit-midpoint sub-step in its midpoint's frame: M = q + h·u(M) by Newton's
// method from M = q, then 2M − q (h = −δ/2 walks back). Keep one `tip_field` call:
// with a second one (an explicit first guess) lavapipe (Mesa, LLVM 15) drew wrong
// pixels in designs of 700 plain ops that hold no stylus at all (tests/gpu_vs_cpu.rs).
fn stylus_sub_step(q: vec2<f32>, h: f32, tips: u32, count: u32, only: f32, wake: f32) -> vec2<f32> {
    var m = q;
    for (var k = 0u; k < STYLUS_NEWTON; k++) {
        let f = tip_field(m, tips, count, only, wake);
        let r = m - q - h * f.u;
        let a = 1.0 - h * f.j.x;
        let b = -h * f.j.y;
        let c = -h * f.j.z;
        let d = 1.0 - h * f.j.w;
        let det = a * d - b * c;
        m -= vec2<f32>(d * r.x - b * r.y, a * r.y - c * r.x) / det;
    }
    return 2.0 * m - q;
}

// KIND_STYLUS, one segment (header H1 at record i, H2 before it): its sub-steps in
// reverse order, each inverted; only those whose midpoint lies within R of the point.
fn stylus_back(i: u32, h1: OpRecord, h2: OpRecord, p: vec2<f32>) -> vec2<f32> {
    let n = vec2<f32>(h1.a.w, h1.b.x);
    let nt = vec2<f32>(-n.y, n.x);
    let wake = h1.b.w;
    let reach = STYLUS_REACH * wake;
    let delta = h1.b.y;
    let q0 = p - h1.a.yz;
    var x = dot(q0, n);
    var y = dot(q0, nt);
    if x <= -reach || x >= h2.b.y + reach || y <= h2.a.y - reach || y >= h2.a.z + reach {
        return p;
    }
    let count = u32(h2.a.x);
    let tips = i - u32(h2.a.w);
    var j = i32(min(h1.b.z - 1.0, ceil((x + reach) / delta - 0.5)));
    var moved = false;
    loop {
        if j < 0 {
            break;
        }
        let xj = (f32(j) + 0.5) * delta;
        if xj <= x - reach {
            break;
        }
        if abs(x - xj) < reach {
            let q = vec2<f32>(x - xj, y);
            let r = stylus_sub_step(q, -0.5 * delta, tips, count, h2.a.y, wake);
            if any(r != q) {
                x = xj + r.x;
                y = r.y;
                moved = true;
            }
        }
        j -= 1;
    }
    if !moved {
        return p;
    }
    return h1.a.yz + n * x + nt * y;
}
