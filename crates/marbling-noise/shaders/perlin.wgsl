// perlin.wgsl — 2D Perlin gradient noise with quintic fade, periodic variant and analytic
// gradient (keep in sync with crates/marbling-noise/src/perlin.rs). Needs hash.wgsl.

const PERLIN_S: f32 = 1.4142135;
const PERLIN_GRADS = array<vec2<f32>, 8>(
    vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0), vec2<f32>(1.0, -1.0), vec2<f32>(-1.0, -1.0),
    vec2<f32>(PERLIN_S, 0.0), vec2<f32>(-PERLIN_S, 0.0), vec2<f32>(0.0, PERLIN_S), vec2<f32>(0.0, -PERLIN_S),
);
const PERLIN_VARIANCE: f32 = 0.0932;
const PERLIN_DERIVATIVE_VARIANCE: f32 = 0.7809;

fn fade(t: f32) -> f32 {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

fn fade_derivative(t: f32) -> f32 {
    let s = t * (t - 1.0);
    return 30.0 * s * s;
}

fn perlin_gradient(h: u32) -> vec2<f32> {
    var grads = PERLIN_GRADS;
    return grads[h >> 29u];
}

// Corner hashes (x: 00, y: 10, z: 01, w: 11) of the cell containing p.
fn perlin_corners(p: vec2<f32>, seed: u32, period: vec2<i32>) -> vec4<u32> {
    let ix = floor_i32(p.x);
    let iy = floor_i32(p.y);
    let x0 = wrap_cell(ix, period.x);
    let x1 = wrap_cell(ix + 1, period.x);
    let y0 = wrap_cell(iy, period.y);
    let y1 = wrap_cell(iy + 1, period.y);
    let xp0 = bitcast<u32>(x0) * PRIME_X;
    let xp1 = bitcast<u32>(x1) * PRIME_X;
    let yp0 = bitcast<u32>(y0) * PRIME_Y;
    let yp1 = bitcast<u32>(y1) * PRIME_Y;
    return vec4<u32>(
        lattice_hash_premul(xp0, yp0, seed),
        lattice_hash_premul(xp1, yp0, seed),
        lattice_hash_premul(xp0, yp1, seed),
        lattice_hash_premul(xp1, yp1, seed),
    );
}

fn perlin2_periodic(p: vec2<f32>, seed: u32, period: vec2<i32>) -> f32 {
    let h = perlin_corners(p, seed, period);
    let fx = p.x - f32(floor_i32(p.x));
    let fy = p.y - f32(floor_i32(p.y));
    let a = dot(perlin_gradient(h.x), vec2<f32>(fx, fy));
    let b = dot(perlin_gradient(h.y), vec2<f32>(fx - 1.0, fy));
    let c = dot(perlin_gradient(h.z), vec2<f32>(fx, fy - 1.0));
    let d = dot(perlin_gradient(h.w), vec2<f32>(fx - 1.0, fy - 1.0));
    let u = fade(fx);
    let v = fade(fy);
    let ab = a + u * (b - a);
    let cd = c + u * (d - c);
    return ab + v * (cd - ab);
}

fn perlin2(p: vec2<f32>, seed: u32) -> f32 {
    return perlin2_periodic(p, seed, vec2<i32>(0, 0));
}

// (n, dn/dx, dn/dy) in lattice units.
fn perlin2_with_gradient(p: vec2<f32>, seed: u32, period: vec2<i32>) -> vec3<f32> {
    let h = perlin_corners(p, seed, period);
    let fx = p.x - f32(floor_i32(p.x));
    let fy = p.y - f32(floor_i32(p.y));
    let g00 = perlin_gradient(h.x);
    let g10 = perlin_gradient(h.y);
    let g01 = perlin_gradient(h.z);
    let g11 = perlin_gradient(h.w);
    let a = g00.x * fx + g00.y * fy;
    let b = g10.x * (fx - 1.0) + g10.y * fy;
    let c = g01.x * fx + g01.y * (fy - 1.0);
    let d = g11.x * (fx - 1.0) + g11.y * (fy - 1.0);
    let u = fade(fx);
    let v = fade(fy);
    let du = fade_derivative(fx);
    let dv = fade_derivative(fy);
    let k = a - b - c + d;
    let n = a + u * (b - a) + v * (c - a) + u * v * k;
    let dx = g00.x + u * (g10.x - g00.x) + v * (g01.x - g00.x)
        + u * v * (g00.x - g10.x - g01.x + g11.x) + du * ((b - a) + v * k);
    let dy = g00.y + u * (g10.y - g00.y) + v * (g01.y - g00.y)
        + u * v * (g00.y - g10.y - g01.y + g11.y) + dv * ((c - a) + u * k);
    return vec3<f32>(n, dx, dy);
}
