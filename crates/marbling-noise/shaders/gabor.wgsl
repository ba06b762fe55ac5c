// gabor.wgsl — sparse Gabor noise (Lagae et al. 2009): anisotropic (0), isotropic (1) and
// random-phase (2) kernels, impulses per cell from the cell stream, orientation and
// frequency optionally driven by an fBm; phasor noise (Tricard et al. 2019) from the same
// kernels summed as complex numbers, the phase through a profile (keep in sync with
// crates/marbling-noise/src/gabor.rs and phasor.rs). Needs hash.wgsl, fbm.wgsl (FbmParams)
// and `gabor_drive`: gabor_drive.wgsl, or gabor_drive_off.wgsl in modules without a
// driven Gabor (the drives' fBm is most of a Gabor module's compile on a software GPU).

const GABOR_TAU: f32 = 6.2831855;
const GABOR_INV_PI: f32 = 0.31830987;
const GABOR_SQRT_2: f32 = 1.4142135;
const GABOR_SQRT_3: f32 = 1.7320508;

// Keep in sync with `GaborGpu` in crates/marbling-noise/src/wgsl.rs (64 bytes). The
// driving fBms are separate arguments (in `NoiseUniform`, next to this struct): WebGL2
// allows a uniform's structs to nest only 3 deep below the block.
struct GaborParams {
    kind: u32,
    seed: u32,
    period_cells: i32,        // 0 = not tileable
    drives: u32,              // bit 0: orientation driven, bit 1: frequency driven
    frequency: f32,           // F0, cycles per pixel
    orientation: f32,         // omega0, radians, x right / y down
    cell: f32,                // impulse cell side, pixels
    radius2: f32,             // truncation radius squared, pixels^2
    pi_a2: f32,               // pi * a^2
    exp_neg_part: f32,        // e^-(mean impulses per cell / poisson_parts)
    inv_std: f32,             // 1 / analytical standard deviation
    orientation_amount: f32,  // radians per unit of the driving fBm
    frequency_amount: f32,    // octaves per unit of the driving fBm
    poisson_parts: u32,       // the Poisson draw is split into this many parts
    reach_cells: i32,         // cells searched each way, ceil(R / cell)
    profile: u32,             // 0 Gabor; phasor profile 1 sine, 2 square, 3 saw, 4 triangle
}

// The un-normalised sum at p (output pixels): (real part, imaginary part), the imaginary
// part summed only for a phasor noise (g.profile != 0).
fn gabor_raw(p: vec2<f32>, g: GaborParams, orientation_drive: FbmParams, frequency_drive: FbmParams) -> vec2<f32> {
    let u = p.x / g.cell;
    let v = p.y / g.cell;
    let ix = floor_i32(u);
    let iy = floor_i32(v);
    let fx = (u - f32(ix)) * g.cell;
    let fy = (v - f32(iy)) * g.cell;
    let base = vec2<f32>(cos(g.orientation), sin(g.orientation));
    var sum = vec2<f32>(0.0, 0.0);
    let reach = g.reach_cells;
    for (var dj = -reach; dj <= reach; dj = dj + 1) {
        for (var di = -reach; di <= reach; di = di + 1) {
            let ex = max(max(f32(di) * g.cell - fx, fx - f32(di + 1) * g.cell), 0.0);
            let ey = max(max(f32(dj) * g.cell - fy, fy - f32(dj + 1) * g.cell), 0.0);
            if ex * ex + ey * ey >= g.radius2 {
                continue;
            }
            let cx = ix + di;
            let cy = iy + dj;
            var rng = cell_hash(wrap_cell(cx, g.period_cells), wrap_cell(cy, g.period_cells), g.seed);
            let count = rng_poisson_parts(&rng, g.exp_neg_part, g.poisson_parts);
            for (var k = 0u; k < count; k = k + 1u) {
                let ox = rng_next_f32(&rng);
                let oy = rng_next_f32(&rng);
                let w = rng_next_f32(&rng) * 2.0 - 1.0;
                let extra = rng_next_f32(&rng);
                let dx = fx - (f32(di) + ox) * g.cell;
                let dy = fy - (f32(dj) + oy) * g.cell;
                let r2 = dx * dx + dy * dy;
                if r2 >= g.radius2 {
                    continue;
                }
                let ip = vec2<f32>((f32(cx) + ox) * g.cell, (f32(cy) + oy) * g.cell);
                let drive = gabor_drive(ip, g, orientation_drive, frequency_drive);
                var dir = base;
                var phase = 0.0;
                if g.kind == 1u {
                    let a = GABOR_TAU * extra;
                    dir = vec2<f32>(cos(a), sin(a));
                } else {
                    if g.kind == 2u {
                        phase = GABOR_TAU * extra;
                    }
                    if (g.drives & 1u) != 0u {
                        let a = g.orientation + g.orientation_amount * drive.x;
                        dir = vec2<f32>(cos(a), sin(a));
                    }
                }
                var f = g.frequency;
                if (g.drives & 2u) != 0u {
                    f = g.frequency * exp2(g.frequency_amount * drive.y);
                }
                let e = w * exp(-g.pi_a2 * r2);
                let arg = GABOR_TAU * f * (dx * dir.x + dy * dir.y) + phase;
                if g.profile == 0u {
                    sum.x = sum.x + e * cos(arg);
                } else {
                    sum = sum + e * vec2<f32>(cos(arg), sin(arg));
                }
            }
        }
    }
    return sum;
}

// A phasor profile (1 sine, 2 square, 3 saw, 4 triangle) of phase phi in (-pi, pi], at
// unit variance over a uniform phase.
fn phasor_profile(profile: u32, phi: f32) -> f32 {
    switch profile {
        case 1u: { return GABOR_SQRT_2 * sin(phi); }
        case 2u: { return select(-1.0, 1.0, phi >= 0.0); }
        case 3u: { return GABOR_SQRT_3 * phi * GABOR_INV_PI; }
        default: { return GABOR_SQRT_3 * (1.0 - 2.0 * abs(phi) * GABOR_INV_PI); }
    }
}

// Gabor or phasor noise at p, zero mean and unit variance; the drives are read only when
// `g.drives` says so. atan2(0, 0) is 0 where no kernel reaches, as on the CPU.
fn gabor(p: vec2<f32>, g: GaborParams, orientation_drive: FbmParams, frequency_drive: FbmParams) -> f32 {
    let sum = gabor_raw(p, g, orientation_drive, frequency_drive);
    if g.profile == 0u {
        return sum.x * g.inv_std;
    }
    var phi = 0.0;
    if sum.x != 0.0 || sum.y != 0.0 {
        phi = atan2(sum.y, sum.x);
    }
    return phasor_profile(g.profile, phi);
}
