// hash.wgsl — integer hashing and the per-cell random stream, bit for bit the CPU's
// crate::hash (keep in sync with crates/marbling-noise/src/hash.rs).

const PRIME_X: u32 = 0x9E3779B1u;
const PRIME_Y: u32 = 0x85EBCA77u;
const POISSON_CAP: u32 = 256u;

// PCG-style output hash (Jarzynski & Olano 2020).
fn pcg_hash(v: u32) -> u32 {
    let state = v * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Lattice corner hash from pre-multiplied coordinates.
fn lattice_hash_premul(xp: u32, yp: u32, seed: u32) -> u32 {
    let h = (xp ^ yp ^ seed) * 0x27D4EB2Du;
    return h ^ (h >> 15u);
}

fn lattice_hash(ix: i32, iy: i32, seed: u32) -> u32 {
    return lattice_hash_premul(bitcast<u32>(ix) * PRIME_X, bitcast<u32>(iy) * PRIME_Y, seed);
}

// Strong hash of a grid cell and a seed: seeds the cell's random stream.
fn cell_hash(ix: i32, iy: i32, seed: u32) -> u32 {
    return pcg_hash(pcg_hash(pcg_hash(seed) ^ bitcast<u32>(ix)) + bitcast<u32>(iy));
}

// A u32 to a float in (0, 1): top 23 bits plus one half, times 2^-23 (exact).
fn unit_f32(h: u32) -> f32 {
    return (f32(h >> 9u) + 0.5) * (1.0 / 8388608.0);
}

// Next 32 random bits of a cell stream (CellRng::next_u32).
fn rng_next(state: ptr<function, u32>) -> u32 {
    *state = pcg_hash(*state);
    return *state;
}

// Next uniform in (0, 1) of a cell stream (CellRng::next_f32).
fn rng_next_f32(state: ptr<function, u32>) -> f32 {
    return unit_f32(rng_next(state));
}

// Poisson count by Knuth's method against e^-mean computed on the host.
fn rng_poisson(state: ptr<function, u32>, exp_neg_mean: f32, cap: u32) -> u32 {
    var k = 0u;
    var p = rng_next_f32(state);
    loop {
        if !(p > exp_neg_mean && k < cap) {
            break;
        }
        k = k + 1u;
        p = p * rng_next_f32(state);
    }
    return k;
}

// Sum of `parts` Poisson draws (CellRng::poisson_parts): means above 64 are split so
// e^-part stays a normal f32.
fn rng_poisson_parts(state: ptr<function, u32>, exp_neg_part: f32, parts: u32) -> u32 {
    var k = 0u;
    for (var i = 0u; i < parts; i = i + 1u) {
        k = k + rng_poisson(state, exp_neg_part, POISSON_CAP);
    }
    return k;
}

// Wraps a cell index into [0, period) when period > 0.
fn wrap_cell(i: i32, period: i32) -> i32 {
    if period > 0 {
        return ((i % period) + period) % period;
    }
    return i;
}

fn floor_i32(x: f32) -> i32 {
    return i32(floor(x));
}
