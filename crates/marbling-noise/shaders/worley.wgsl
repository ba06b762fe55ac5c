// worley.wgsl — Worley/cellular noise, one feature point per cell, F1/F2/F2-F1 under
// Euclidean (0), Manhattan (1) or Chebyshev (2) distance (keep in sync with
// crates/marbling-noise/src/worley.rs). Needs hash.wgsl.

// (mean, std) per feature (row) and metric (column).
const WORLEY_MOMENTS = array<vec2<f32>, 9>(
    vec2<f32>(0.4299, 0.1900), vec2<f32>(0.5411, 0.2414), vec2<f32>(0.3819, 0.1695),
    vec2<f32>(0.6991, 0.1765), vec2<f32>(0.8771, 0.2244), vec2<f32>(0.6215, 0.1597),
    vec2<f32>(0.2692, 0.2009), vec2<f32>(0.3359, 0.2513), vec2<f32>(0.2395, 0.1799),
);

fn worley_distance(metric: u32, d: vec2<f32>) -> f32 {
    if metric == 1u {
        return abs(d.x) + abs(d.y);
    }
    if metric == 2u {
        return max(abs(d.x), abs(d.y));
    }
    return sqrt(d.x * d.x + d.y * d.y);
}

// (F1, F2) at p in lattice units.
fn worley2(p: vec2<f32>, seed: u32, metric: u32, period: vec2<i32>) -> vec2<f32> {
    let ix = floor_i32(p.x);
    let iy = floor_i32(p.y);
    let fx = p.x - f32(ix);
    let fy = p.y - f32(iy);
    var f1 = 3.4028234e38;
    var f2 = 3.4028234e38;
    for (var dj = -1; dj <= 1; dj = dj + 1) {
        for (var di = -1; di <= 1; di = di + 1) {
            var rng = cell_hash(wrap_cell(ix + di, period.x), wrap_cell(iy + dj, period.y), seed);
            let px = f32(di) + rng_next_f32(&rng);
            let py = f32(dj) + rng_next_f32(&rng);
            let d = worley_distance(metric, vec2<f32>(px - fx, py - fy));
            if d < f1 {
                f2 = f1;
                f1 = d;
            } else if d < f2 {
                f2 = d;
            }
        }
    }
    return vec2<f32>(f1, f2);
}

// The feature (0 F1, 1 F2, 2 F2-F1) normalised to zero mean and unit variance.
fn worley_normalised(p: vec2<f32>, seed: u32, feature: u32, metric: u32, period: vec2<i32>) -> f32 {
    let f = worley2(p, seed, metric, period);
    var d = f.x;
    if feature == 1u {
        d = f.y;
    } else if feature == 2u {
        d = f.y - f.x;
    }
    var moments = WORLEY_MOMENTS;
    let m = moments[min(feature, 2u) * 3u + min(metric, 2u)];
    return (d - m.x) / m.y;
}
