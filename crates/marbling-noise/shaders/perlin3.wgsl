// perlin3.wgsl — 3D Perlin gradient noise (quintic fade, the twelve cube-edge gradients)
// and its fBm (keep in sync with crates/marbling-noise/src/perlin3.rs). Needs hash.wgsl
// and perlin.wgsl (fade).

const PRIME_Z: u32 = 0xC2B2AE3Du;
const PERLIN3_GRADS = array<vec3<f32>, 16>(
    vec3<f32>(1.0, 1.0, 0.0), vec3<f32>(-1.0, 1.0, 0.0), vec3<f32>(1.0, -1.0, 0.0), vec3<f32>(-1.0, -1.0, 0.0),
    vec3<f32>(1.0, 0.0, 1.0), vec3<f32>(-1.0, 0.0, 1.0), vec3<f32>(1.0, 0.0, -1.0), vec3<f32>(-1.0, 0.0, -1.0),
    vec3<f32>(0.0, 1.0, 1.0), vec3<f32>(0.0, -1.0, 1.0), vec3<f32>(0.0, 1.0, -1.0), vec3<f32>(0.0, -1.0, -1.0),
    vec3<f32>(1.0, 1.0, 0.0), vec3<f32>(-1.0, 1.0, 0.0), vec3<f32>(0.0, -1.0, 1.0), vec3<f32>(0.0, -1.0, -1.0),
);

// g·(f − c) of lattice corner c (0 or 1 per axis) of the cell at i.
fn perlin3_corner(i: vec3<i32>, f: vec3<f32>, c: vec3<i32>, seed: u32) -> f32 {
    let xp = bitcast<u32>(i.x + c.x) * PRIME_X;
    let yp = bitcast<u32>(i.y + c.y) * PRIME_Y;
    let zp = bitcast<u32>(i.z + c.z) * PRIME_Z;
    let h = lattice_hash_premul(xp, yp ^ zp, seed);
    var grads = PERLIN3_GRADS;
    return dot(grads[h >> 28u], f - vec3<f32>(c));
}

// The trilinear blend of the eight corners, in one loop (one call site keeps the
// shader small for software GPUs' compilers).
fn perlin3(p: vec3<f32>, seed: u32) -> f32 {
    let i = vec3<i32>(floor_i32(p.x), floor_i32(p.y), floor_i32(p.z));
    let f = p - vec3<f32>(i);
    let u = vec3<f32>(fade(f.x), fade(f.y), fade(f.z));
    var n = 0.0;
    for (var c = 0u; c < 8u; c++) {
        let corner = vec3<u32>(c & 1u, (c >> 1u) & 1u, (c >> 2u) & 1u);
        let w = mix(1.0 - u, u, vec3<f32>(corner));
        n += w.x * w.y * w.z * perlin3_corner(i, f, vec3<i32>(corner), seed);
    }
    return n;
}

// Octave k at frequency lacunarityᵏ, amplitude persistenceᵏ, seed + k; divided by
// the sum of the amplitudes.
fn fbm3(p: vec3<f32>, octaves: u32, lacunarity: f32, persistence: f32, seed: u32) -> f32 {
    var sum = 0.0;
    var norm = 0.0;
    var amp = 1.0;
    var freq = 1.0;
    for (var k = 0u; k < max(octaves, 1u); k++) {
        sum += amp * perlin3(p * freq, seed + k);
        norm += amp;
        amp *= persistence;
        freq *= lacunarity;
    }
    if norm > 0.0 {
        return sum / norm;
    }
    return 0.0;
}
