// fibers.wgsl — paper (layout 0) and canvas (layout 1) height fields after Kaplan & Cohen
// 2005, fibers generated per cell from the cell stream, optional impurity specks (keep in
// sync with crates/marbling-noise/src/fibers.rs). Needs hash.wgsl.

const IMPURITY_SEED: u32 = 0x5BD1E995u;
const FIBER_PI: f32 = 3.1415927;

// One Poisson process's generation grid.
struct FiberGrid {
    cell: f32,
    reach_cells: i32,
    period_cells: i32,
    exp_neg_part: f32,
    poisson_parts: u32,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
}

// Keep in sync with `FibersGpu` in crates/marbling-noise/src/wgsl.rs (48 bytes). The
// fiber and speck grids are separate arguments (in `NoiseUniform`, next to this struct):
// WebGL2 allows a uniform's structs to nest only 3 deep below the block.
struct FiberParams {
    fiber_layout: u32,
    seed: u32,
    has_impurities: u32,
    _pad0: u32,
    length: f32,
    width: f32,
    horizontal_probability: f32,
    mean: f32,
    inv_std: f32,
    speck_radius: f32,
    speck_strength: f32,
    _pad1: f32,
}

// Antialiased count of fibers covering p.
fn fibers_height(p: vec2<f32>, fp: FiberParams, g: FiberGrid) -> f32 {
    let half_l = 0.5 * fp.length + 0.5;
    let half_w = 0.5 * fp.width + 0.5;
    let ix = floor_i32(p.x / g.cell);
    let iy = floor_i32(p.y / g.cell);
    var h = 0.0;
    for (var cy = iy - g.reach_cells; cy <= iy + g.reach_cells; cy = cy + 1) {
        for (var cx = ix - g.reach_cells; cx <= ix + g.reach_cells; cx = cx + 1) {
            var rng = cell_hash(wrap_cell(cx, g.period_cells), wrap_cell(cy, g.period_cells), fp.seed);
            let count = rng_poisson_parts(&rng, g.exp_neg_part, g.poisson_parts);
            for (var k = 0u; k < count; k = k + 1u) {
                let ox = (f32(cx) + rng_next_f32(&rng)) * g.cell;
                let oy = (f32(cy) + rng_next_f32(&rng)) * g.cell;
                let u = rng_next_f32(&rng);
                var dir = vec2<f32>(0.0, 1.0);
                if fp.fiber_layout == 0u {
                    let a = FIBER_PI * u;
                    dir = vec2<f32>(cos(a), sin(a));
                } else if u < fp.horizontal_probability {
                    dir = vec2<f32>(1.0, 0.0);
                }
                let dx = p.x - ox;
                let dy = p.y - oy;
                let along = abs(dx * dir.x + dy * dir.y);
                let across = abs(dy * dir.x - dx * dir.y);
                h = h + clamp(half_l - along, 0.0, 1.0) * clamp(half_w - across, 0.0, 1.0);
            }
        }
    }
    return h;
}

// Total impurity speck coverage at p.
fn fibers_specks(p: vec2<f32>, fp: FiberParams, g: FiberGrid) -> f32 {
    let ix = floor_i32(p.x / g.cell);
    let iy = floor_i32(p.y / g.cell);
    var cover = 0.0;
    for (var cy = iy - g.reach_cells; cy <= iy + g.reach_cells; cy = cy + 1) {
        for (var cx = ix - g.reach_cells; cx <= ix + g.reach_cells; cx = cx + 1) {
            var rng = cell_hash(wrap_cell(cx, g.period_cells), wrap_cell(cy, g.period_cells), fp.seed ^ IMPURITY_SEED);
            let count = rng_poisson_parts(&rng, g.exp_neg_part, g.poisson_parts);
            for (var k = 0u; k < count; k = k + 1u) {
                let ox = (f32(cx) + rng_next_f32(&rng)) * g.cell;
                let oy = (f32(cy) + rng_next_f32(&rng)) * g.cell;
                let d = sqrt((p.x - ox) * (p.x - ox) + (p.y - oy) * (p.y - oy));
                cover = cover + clamp(fp.speck_radius + 0.5 - d, 0.0, 1.0);
            }
        }
    }
    return cover;
}

// Normalised height (zero mean, unit variance) minus impurities.
fn fibers(p: vec2<f32>, fp: FiberParams, grid: FiberGrid, specks: FiberGrid) -> f32 {
    let n = (fibers_height(p, fp, grid) - fp.mean) * fp.inv_std;
    if fp.has_impurities != 0u {
        return n - fp.speck_strength * fibers_specks(p, fp, specks);
    }
    return n;
}
