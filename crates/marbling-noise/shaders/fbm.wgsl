// fbm.wgsl — fractional Brownian motion of Perlin or value noise, normalised to unit
// variance (keep in sync with crates/marbling-noise/src/fbm.rs). Needs hash.wgsl,
// perlin.wgsl, value.wgsl.

const OCTAVE_SEED_STEP: u32 = 0x9E3779B9u;
const MAX_OCTAVES: u32 = 12u;

// Keep in sync with `FbmGpu` in crates/marbling-noise/src/wgsl.rs (8 × 4 bytes).
struct FbmParams {
    frequency: f32,   // first octave, cycles per output pixel
    lacunarity: f32,
    persistence: f32,
    octaves: u32,     // 1..=12
    seed: u32,
    basis: u32,       // 0 Perlin, 1 value
    period: u32,      // tile period in pixels, 0 = none
    _pad: u32,
}

// Frequency (cycles/px) and lattice period (cells, 0 = none) of an octave's nominal frequency.
fn fbm_octave_lattice(f: f32, period: u32) -> vec2<f32> {
    if period > 0u {
        let cells = max(floor(f * f32(period) + 0.5), 1.0);
        return vec2<f32>(cells / f32(period), cells);
    }
    return vec2<f32>(f, 0.0);
}

fn fbm_basis(basis: u32, p: vec2<f32>, seed: u32, period: vec2<i32>) -> f32 {
    if basis == 1u {
        return value2_periodic(p, seed, period);
    }
    return perlin2_periodic(p, seed, period);
}

// 1 / sqrt(basis variance × Σ a_i²).
fn fbm_inv_std(params: FbmParams) -> f32 {
    var a = 1.0;
    var sq = 0.0;
    for (var i = 0u; i < clamp(params.octaves, 1u, MAX_OCTAVES); i = i + 1u) {
        sq = sq + a * a;
        a = a * params.persistence;
    }
    var variance = PERLIN_VARIANCE;
    if params.basis == 1u {
        variance = VALUE_VARIANCE;
    }
    return 1.0 / sqrt(variance * sq);
}

// fBm at p (output pixels), zero mean and unit variance.
fn fbm(p: vec2<f32>, params: FbmParams) -> f32 {
    var f = params.frequency;
    var a = 1.0;
    var s = 0.0;
    for (var i = 0u; i < clamp(params.octaves, 1u, MAX_OCTAVES); i = i + 1u) {
        let lat = fbm_octave_lattice(f, params.period);
        let per = vec2<i32>(i32(lat.y), i32(lat.y));
        let seed = params.seed + i * OCTAVE_SEED_STEP;
        s = s + a * fbm_basis(params.basis, p * lat.x, seed, per);
        f = f * params.lacunarity;
        a = a * params.persistence;
    }
    return s * fbm_inv_std(params);
}

// (n, dn/dx, dn/dy) of a Perlin-basis fbm (curl's potential, the only caller, always is),
// derivatives per output pixel, analytic. (A value-basis branch here, by central
// differences, made SwiftShader take 9 s to compile the curl shader.)
fn fbm_with_gradient(p: vec2<f32>, params: FbmParams) -> vec3<f32> {
    var f = params.frequency;
    var a = 1.0;
    var out = vec3<f32>(0.0);
    for (var i = 0u; i < clamp(params.octaves, 1u, MAX_OCTAVES); i = i + 1u) {
        let lat = fbm_octave_lattice(f, params.period);
        let per = vec2<i32>(i32(lat.y), i32(lat.y));
        let seed = params.seed + i * OCTAVE_SEED_STEP;
        let g = perlin2_with_gradient(p * lat.x, seed, per);
        out = out + vec3<f32>(a * g.x, a * lat.x * g.y, a * lat.x * g.z);
        f = f * params.lacunarity;
        a = a * params.persistence;
    }
    return out * fbm_inv_std(params);
}

// Variance of each partial derivative of fbm (Perlin basis), per pixel².
fn fbm_derivative_variance(params: FbmParams) -> f32 {
    var f = params.frequency;
    var a = 1.0;
    var s = 0.0;
    for (var i = 0u; i < clamp(params.octaves, 1u, MAX_OCTAVES); i = i + 1u) {
        let lat = fbm_octave_lattice(f, params.period);
        s = s + (a * lat.x) * (a * lat.x);
        f = f * params.lacunarity;
        a = a * params.persistence;
    }
    let inv = fbm_inv_std(params);
    return s * PERLIN_DERIVATIVE_VARIANCE * inv * inv;
}
