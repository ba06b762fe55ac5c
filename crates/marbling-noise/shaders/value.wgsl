// value.wgsl — value noise, uniform lattice values in [-1, 1] with quintic interpolation
// (keep in sync with crates/marbling-noise/src/value.rs). Needs hash.wgsl, perlin.wgsl.

const VALUE_VARIANCE: f32 = 0.20465009; // (1/3)(181/231)^2

fn value_corner(ix: i32, iy: i32, seed: u32) -> f32 {
    return unit_f32(lattice_hash(ix, iy, seed)) * 2.0 - 1.0;
}

fn value2_periodic(p: vec2<f32>, seed: u32, period: vec2<i32>) -> f32 {
    let ix = floor_i32(p.x);
    let iy = floor_i32(p.y);
    let u = fade(p.x - f32(ix));
    let v = fade(p.y - f32(iy));
    let x0 = wrap_cell(ix, period.x);
    let x1 = wrap_cell(ix + 1, period.x);
    let y0 = wrap_cell(iy, period.y);
    let y1 = wrap_cell(iy + 1, period.y);
    let a = value_corner(x0, y0, seed);
    let b = value_corner(x1, y0, seed);
    let c = value_corner(x0, y1, seed);
    let d = value_corner(x1, y1, seed);
    let ab = a + u * (b - a);
    let cd = c + u * (d - c);
    return ab + v * (cd - ab);
}

fn value2(p: vec2<f32>, seed: u32) -> f32 {
    return value2_periodic(p, seed, vec2<i32>(0, 0));
}
