// curl.wgsl — curl noise v = (dpsi/dy, -dpsi/dx) of an fBm potential (keep in sync with
// crates/marbling-noise/src/curl.rs). Needs hash.wgsl, perlin.wgsl, value.wgsl, fbm.wgsl.

const RAYLEIGH_MEAN: f32 = 1.2533141;
const RAYLEIGH_STD: f32 = 0.6551364;

// Velocity at p (output pixels), units of psi per pixel.
fn curl_velocity(p: vec2<f32>, potential: FbmParams) -> vec2<f32> {
    let g = fbm_with_gradient(p, potential);
    return vec2<f32>(g.z, -g.y);
}

// Component 0 = vx, 1 = vy (unit variance), 2 = |v| normalised as a Rayleigh variable.
fn curl_component(p: vec2<f32>, potential: FbmParams, component: u32) -> f32 {
    let v = curl_velocity(p, potential);
    let inv = 1.0 / sqrt(fbm_derivative_variance(potential));
    if component == 0u {
        return v.x * inv;
    }
    if component == 1u {
        return v.y * inv;
    }
    return (sqrt(v.x * v.x + v.y * v.y) * inv - RAYLEIGH_MEAN) / RAYLEIGH_STD;
}
