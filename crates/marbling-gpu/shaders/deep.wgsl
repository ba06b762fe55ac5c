// Deep zoom by perturbation (the exact renderer's variant for views past f32's reach;
// deep_off.wgsl stands in elsewhere). The host walks one reference point per tile of
// the target back through every op in f64 (marbling-core's deep.rs) and uploads what
// each op needs; a sample walks only its offset δ from the reference, in f32, by exact
// differences δ' = g(R + δ) − g(R) that never subtract two nearly equal large numbers:
//   drop:   e' = e_R + 2D_R·δ + |δ|² (e = |P − C|² − r²; e' < 0: the ink covers it),
//           δ' = δ·f' + D_R·(f' − f_R), f = √(e/ρ²), f' − f_R = q·r²/(ρ'²ρ_R²(f' + f_R)),
//           q = ρ'² − ρ_R² = 2D_R·δ + |δ|²;
//   comb:   Δs = δ·n, Δd = shape·(|kink + Δs| − |kink|) (while |kink + Δs| ≤ reach),
//           δ' = δ + αλ·Δd/((d + λ)(d + Δd + λ))·m;
//   wave:   δ' = δ − A·2cos(θ_R + h/2)·sin(h/2)·m, h = k·(δ·n);
//   swirl:  Δρ = q/(ρ' + ρ_R), Δd = |ring + Δρ| − |ring|,
//           Δθ = −αλ(Δd·ρ' + (d + λ)Δρ)/((d + λ)ρ_R(d + Δd + λ)ρ'),
//           δ' = Rot(−θ')δ + Rot(−θ_R)(Rot(−Δθ) − I)D_R;
//   rigid:  δ' = Rot(−θ)δ;
//   jiggle: Δφ solves Δφ + c(sin(φ_R + Δφ) − sin φ_R) = k(δ·u) by Newton,
//           δ' = δ − A(sin φ' − sin φ_R)u − B(cos φ' − cos φ_R)v (half-angle forms);
//   stylus segment, flow: δ' = J_R·δ while |δ| ≤ reach.
// Past a reach (or at a swirl's centre) the sample goes on in absolute f32 from R + δ.
//
// Reference records (Rgba32Float, 2 texels each), per tile t: records [0, op_count)
// parallel the op records (a step at each op's header record, zeros elsewhere), then
// one record (end.x, end.y, 0, 0), (start.x, start.y, 0, 0): where the reference's walk
// ended and the tile's reference point (design pixels). Tile t's record i is record
// k = t·params.deep.w + i, at texel (2·(k mod M), k div M), M = 2^params.deep.z.
// Step records: a (kind's values, below), b = (R.x, R.y, then per kind):
//   drop, spray: a = (e_R, D_R.x, D_R.y, 0), b.zw = the rebase added to δ first;
//   comb, tines: a = (d_R, kink, shape ±1, reach);
//   wave: a.x = θ_R; swirl: a = (D_R.x, D_R.y, ring, θ_R); jiggle: a.x = φ_R;
//   stylus segment header, flow header: a = J_R (row-major), b.z = reach.

const DEEP_ENABLED: bool = true;

// A step's outcome, in the third component of what the steps return.
const DEEP_MOVED: f32 = 0.0;
const DEEP_COVERED: f32 = 1.0;
const DEEP_FAR: f32 = 2.0;

@group(0) @binding(4) var deep_refs: texture_2d<f32>;

// Record i of tile t's reference walk.
fn deep_record(t: u32, i: u32) -> OpRecord {
    let k = t * params.deep.w + i;
    let col = i32((k & ((1u << params.deep.z) - 1u)) * 2u);
    let row = i32(k >> params.deep.z);
    return OpRecord(textureLoad(deep_refs, vec2<i32>(col, row), 0), textureLoad(deep_refs, vec2<i32>(col + 1, row), 0));
}

// |a + h| − |a|, exact in sign and without cancellation when |h| ≪ |a|.
fn abs_change(a: f32, h: f32) -> f32 {
    let b = a + h;
    if (a >= 0.0) == (b >= 0.0) {
        return select(-h, h, a >= 0.0);
    }
    return abs(b) - abs(a);
}

// δ through a drop or spray (op record r, reference record q).
fn deep_drop(r: OpRecord, q: OpRecord, d0: vec2<f32>) -> vec3<f32> {
    let d = d0 + q.b.zw;
    let dr = q.a.yz;
    let change = 2.0 * dot(dr, d) + dot(d, d);
    let excess = q.a.x + change;
    if excess < 0.0 {
        return vec3<f32>(d, DEEP_COVERED);
    }
    if u32(r.a.x) != KIND_DROP {
        return vec3<f32>(d, DEEP_MOVED);
    }
    let rho2 = dot(dr, dr);
    let rho2_new = rho2 + change;
    let f = sqrt(excess / rho2_new);
    let f_ref = sqrt(q.a.x / rho2);
    var df = 0.0;
    if f + f_ref > 0.0 {
        df = change * r.a.w / (rho2_new * rho2 * (f + f_ref));
    }
    return vec3<f32>(d * f + dr * df, DEEP_MOVED);
}

// δ through a comb of direction m, αλ = al (a tine, rake or finite comb).
fn deep_comb(m: vec2<f32>, al: f32, lambda: f32, q: OpRecord, d: vec2<f32>) -> vec3<f32> {
    let ds = dot(d, vec2<f32>(-m.y, m.x));
    if abs(q.a.y + ds) > q.a.w {
        return vec3<f32>(d, DEEP_FAR);
    }
    let dd = q.a.z * abs_change(q.a.y, ds);
    let base = q.a.x + lambda;
    return vec3<f32>(d + (al * dd / (base * (base + dd))) * m, DEEP_MOVED);
}

// δ through a wavy comb.
fn deep_wave(r: OpRecord, q: OpRecord, d: vec2<f32>) -> vec3<f32> {
    let m = r.a.yz;
    let h = r.b.x * dot(d, vec2<f32>(m.y, -m.x));
    let change = 2.0 * cos(q.a.x + 0.5 * h) * sin(0.5 * h);
    return vec3<f32>(d - r.a.w * change * m, DEEP_MOVED);
}

// v turned by the angle whose sine and cosine are s and c.
fn turned(v: vec2<f32>, s: f32, c: f32) -> vec2<f32> {
    return vec2<f32>(v.x * c - v.y * s, v.x * s + v.y * c);
}

// δ through a circular comb or vortex.
fn deep_swirl(r: OpRecord, q: OpRecord, d: vec2<f32>) -> vec3<f32> {
    let dr = q.a.xy;
    let rho = length(dr);
    let rho_new = length(dr + d);
    if rho == 0.0 || rho_new == 0.0 {
        return vec3<f32>(d, DEEP_FAR);
    }
    let drho = (2.0 * dot(dr, d) + dot(d, d)) / (rho_new + rho);
    let dist = abs(q.a.z);
    let ddist = abs_change(q.a.z, drho);
    let lambda = r.b.y;
    let before = (dist + lambda) * rho;
    let after = (dist + ddist + lambda) * rho_new;
    let dtheta = -r.b.x * (ddist * rho_new + (dist + lambda) * drho) / (before * after);
    let theta = q.a.w + dtheta;
    // (Rot(−Δθ) − I)·D_R, with cos Δθ − 1 = −2 sin²(Δθ/2), then turned by −θ_R.
    let half = sin(0.5 * dtheta);
    let w = turned(dr, -sin(dtheta), 0.0) - 2.0 * half * half * dr;
    let moved = turned(d, -sin(theta), cos(theta)) + turned(w, -sin(q.a.w), cos(q.a.w));
    return vec3<f32>(moved, DEEP_MOVED);
}

// δ through a jiggle (Newton on Δφ from Δφ = Δt/(1 + c·cos φ_R)).
fn deep_jiggle(r: OpRecord, q: OpRecord, d: vec2<f32>) -> vec3<f32> {
    let u = r.a.yz;
    let v = vec2<f32>(-u.y, u.x);
    let c = r.a.w * r.b.x;
    let phi = q.a.x;
    let dt = r.a.w * dot(d, u);
    var x = dt / (1.0 + c * cos(phi));
    for (var i = 0u; i < JIGGLE_NEWTON; i++) {
        let f = x + 2.0 * c * cos(phi + 0.5 * x) * sin(0.5 * x) - dt;
        x -= f / (1.0 + c * cos(phi + x));
    }
    let hs = sin(0.5 * x);
    let dsin = 2.0 * cos(phi + 0.5 * x) * hs;
    let dcos = -2.0 * sin(phi + 0.5 * x) * hs;
    return vec3<f32>(d - r.b.x * dsin * u - r.b.y * dcos * v, DEEP_MOVED);
}

// δ through a stylus segment or flow: the reference's Jacobian, within its reach.
fn deep_linear(q: OpRecord, d: vec2<f32>) -> vec3<f32> {
    if length(d) > q.b.z {
        return vec3<f32>(d, DEEP_FAR);
    }
    return vec3<f32>(q.a.x * d.x + q.a.y * d.y, q.a.z * d.x + q.a.w * d.y, DEEP_MOVED);
}

// The colour (linear r, g, b, packed sRGB, as `trace`) of the sample at target position
// `at` (output pixels from the target's top-left corner): its tile's reference walk,
// followed by the sample's offset.
fn deep_trace(at: vec2<f32>) -> vec4<f32> {
    let side = f32(params.deep.x);
    let tile = floor(at / side);
    let t = u32(tile.y) * params.deep.y + u32(tile.x);
    let start = deep_record(t, params.op_count).b.xy;
    let d0 = (at - (tile + 0.5) * side) * params.inv_scale;
    var d = d0;
    var i = params.op_count;
    while i > 0u {
        let k = i - 1u;
        let r = op_record(k);
        let q = deep_record(t, k);
        let kind = u32(r.a.x);
        var span = 1u;
        var s = vec3<f32>(d, DEEP_MOVED);
        // Schema v3's kinds only in variants with them (V3_ENABLED): fewer branches in
        // every v1 walk on a CPU-emulated GPU.
        if kind == KIND_DROP || kind == KIND_SPRAY {
            s = deep_drop(r, q, d);
        } else if kind == KIND_COMB || (V3_ENABLED && kind == KIND_TINES) {
            s = deep_comb(vec2<f32>(r.a.w, r.b.x), r.b.y, r.b.z, q, d);
            if kind == KIND_TINES {
                span = 1u + (u32(r.b.w) + 7u) / 8u;
            }
        } else if kind == KIND_WAVE {
            s = deep_wave(r, q, d);
        } else if kind == KIND_CIRCULAR || kind == KIND_VORTEX {
            s = deep_swirl(r, q, d);
        } else if V3_ENABLED {
            if kind == KIND_RIGID {
                s = vec3<f32>(turned(d, -r.a.w, r.b.x), DEEP_MOVED);
            } else if kind == KIND_JIGGLE {
                s = deep_jiggle(r, q, d);
            } else {
                s = deep_linear(q, d);
                if kind == KIND_FLOW {
                    span = 1u + (2u * u32(r.b.x) + 7u) / 8u;
                } else {
                    span = u32(op_record(k - 1u).b.x);
                }
            }
        }
        if s.z == DEEP_COVERED {
            return hit_colour(start + d0, Hit(r.b, false, q.b.xy + s.xy));
        }
        if s.z == DEEP_FAR {
            let e = walk_records(0u, i, q.b.xy + d);
            if e.covered {
                return hit_colour(start + d0, Hit(e.ink, false, e.p));
            }
            return hit_colour(start + d0, Hit(params.background, true, e.p));
        }
        d = s.xy;
        i -= span;
    }
    let end = deep_record(t, params.op_count).a.xy;
    return hit_colour(start + d0, Hit(params.background, true, end + d));
}
