// noise.wgsl — the uniform of every noise (keep in sync with `NoiseGpu` in
// crates/marbling-noise/src/wgsl.rs, whose `NoiseKind` numbers `noise_type`); the one entry
// point `sample_noise(p, u)`, at p in output pixels with zero mean and unit variance, is
// appended by wgsl.rs. Needs every other noise file.

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

// `sample_noise(p: vec2<f32>, u: NoiseUniform) -> f32` follows, written by `wgsl.rs`
// (`sample_noise_wgsl`) with a case for each noise type the module is made for: SwiftShader
// compiles and runs every case of the switch, whichever the uniform picks.
