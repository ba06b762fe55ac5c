// white.wgsl — white noise per output pixel, uniform in [-sqrt(3), sqrt(3)] (unit
// variance) (keep in sync with crates/marbling-noise/src/white.rs). Needs hash.wgsl.

const WHITE_HALF_RANGE: f32 = 1.7320508;

fn white2(p: vec2<f32>, seed: u32, period: vec2<i32>) -> f32 {
    let ix = wrap_cell(floor_i32(p.x), period.x);
    let iy = wrap_cell(floor_i32(p.y), period.y);
    return (unit_f32(cell_hash(ix, iy, seed)) * 2.0 - 1.0) * WHITE_HALF_RANGE;
}
