// noise.wgsl — one entry point for every noise: `sample_noise(p, u)` at p in output pixels,
// zero mean and unit variance (keep in sync with `NoiseGpu` in
// crates/marbling-noise/src/wgsl.rs and with render.rs). Needs every other noise file.

const NOISE_GABOR: u32 = 0u;
const NOISE_FBM: u32 = 1u;
const NOISE_WORLEY: u32 = 2u;
const NOISE_WHITE: u32 = 3u;
const NOISE_CURL: u32 = 4u;
const NOISE_FIBERS: u32 = 5u;

// Keep in sync with `NoiseGpu` in crates/marbling-noise/src/wgsl.rs (304 bytes). Structs
// nest at most 2 deep here, so that a uniform holding this struct stays within WebGL2's
// limit (ANGLE counts the block too: 4 levels in all).
struct NoiseUniform {
    noise_type: u32,
    seed: u32,            // worley, white
    feature: u32,         // worley feature, curl component
    metric: u32,          // worley metric
    period: vec2<i32>,    // worley cells / white pixels per tile, 0 = none
    frequency: f32,       // worley cells per pixel
    _pad: u32,
    fbm: FbmParams,       // perlin/value fBm, curl potential
    gabor: GaborParams,
    gabor_orientation_drive: FbmParams,
    gabor_frequency_drive: FbmParams,
    fibers: FiberParams,
    fiber_grid: FiberGrid,
    speck_grid: FiberGrid,
}

fn sample_noise(p: vec2<f32>, u: NoiseUniform) -> f32 {
    switch u.noise_type {
        case 0u: {
            return gabor(p, u.gabor, u.gabor_orientation_drive, u.gabor_frequency_drive);
        }
        case 1u: {
            return fbm(p, u.fbm);
        }
        case 2u: {
            return worley_normalised(p * u.frequency, u.seed, u.feature, u.metric, u.period);
        }
        case 3u: {
            return white2(p, u.seed, u.period);
        }
        case 4u: {
            return curl_component(p, u.fbm, u.feature);
        }
        case 5u: {
            return fibers(p, u.fibers, u.fiber_grid, u.speck_grid);
        }
        default: {
            return 0.0;
        }
    }
}
