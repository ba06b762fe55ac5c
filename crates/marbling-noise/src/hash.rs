//! Integer hashing and the per-cell random stream shared by every noise, bit for bit
//! identical to `shaders/hash.wgsl` (u32 arithmetic only, wrapping multiplication).

/// PCG-style output hash of one 32-bit word (Jarzynski & Olano 2020, "Hash Functions for
/// GPU Rendering"). Keep in sync with `pcg_hash` in `shaders/hash.wgsl`.
#[inline(always)]
#[must_use]
pub fn pcg_hash(v: u32) -> u32 {
    let state = v.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let word = ((state >> ((state >> 28) + 4)) ^ state).wrapping_mul(277_803_737);
    (word >> 22) ^ word
}

/// Multiplier applied to lattice x indices before mixing.
pub const PRIME_X: u32 = 0x9E37_79B1;
/// Multiplier applied to lattice y indices before mixing.
pub const PRIME_Y: u32 = 0x85EB_CA77;

/// Cheap hash of a lattice corner for gradient/value noise: one multiply per axis (the
/// caller may pre-multiply), one mixing multiply and an xor-shift; callers use the well
/// mixed high bits. Keep in sync with `lattice_hash` in `shaders/hash.wgsl`.
#[inline(always)]
#[must_use]
pub fn lattice_hash_premul(xp: u32, yp: u32, seed: u32) -> u32 {
    let h = (xp ^ yp ^ seed).wrapping_mul(0x27D4_EB2D);
    h ^ (h >> 15)
}

/// [`lattice_hash_premul`] of integer lattice coordinates.
#[inline(always)]
#[must_use]
pub fn lattice_hash(ix: i32, iy: i32, seed: u32) -> u32 {
    lattice_hash_premul(
        (ix as u32).wrapping_mul(PRIME_X),
        (iy as u32).wrapping_mul(PRIME_Y),
        seed,
    )
}

/// Strong hash of a grid cell and a seed, used to seed per-cell random streams.
/// Keep in sync with `cell_hash` in `shaders/hash.wgsl`.
#[inline(always)]
#[must_use]
pub fn cell_hash(ix: i32, iy: i32, seed: u32) -> u32 {
    pcg_hash(pcg_hash(pcg_hash(seed) ^ ix as u32).wrapping_add(iy as u32))
}

/// A u32 mapped to a float in the open interval (0, 1): the top 23 bits plus one half,
/// times 2⁻²³, exact in f32 on every platform.
#[inline(always)]
#[must_use]
pub fn unit_f32(h: u32) -> f32 {
    ((h >> 9) as f32 + 0.5) * (1.0 / 8_388_608.0)
}

/// The deterministic random stream of one grid cell: each draw re-hashes the state.
/// Keep in sync with `CellRng`/`rng_next` in `shaders/hash.wgsl`.
#[derive(Clone, Copy, Debug)]
pub struct CellRng {
    state: u32,
}

impl CellRng {
    /// The stream of cell (`ix`, `iy`) for `seed`.
    #[inline(always)]
    #[must_use]
    pub fn new(ix: i32, iy: i32, seed: u32) -> Self {
        Self {
            state: cell_hash(ix, iy, seed),
        }
    }

    /// The next 32 random bits.
    #[inline(always)]
    pub fn next_u32(&mut self) -> u32 {
        self.state = pcg_hash(self.state);
        self.state
    }

    /// The next uniform float in (0, 1).
    #[inline(always)]
    pub fn next_f32(&mut self) -> f32 {
        unit_f32(self.next_u32())
    }

    /// A Poisson-distributed count by Knuth's product-of-uniforms method, given
    /// `exp_neg_mean` = e^(−mean) computed once by the caller (on the host for the GPU,
    /// so CPU and WGSL compare against the same f32). Capped at `cap` draws; with
    /// the means used here (≤ 90) the cap is never reached in practice.
    #[inline(always)]
    pub fn poisson(&mut self, exp_neg_mean: f32, cap: u32) -> u32 {
        let mut k = 0;
        let mut p = self.next_f32();
        while p > exp_neg_mean && k < cap {
            k += 1;
            p *= self.next_f32();
        }
        k
    }

    /// A Poisson count of mean `parts`·(−ln `exp_neg_part`): the sum of `parts` draws
    /// of [`CellRng::poisson`] (see [`poisson_split`]).
    #[inline(always)]
    pub fn poisson_parts(&mut self, exp_neg_part: f32, parts: u32) -> u32 {
        let mut k = 0;
        for _ in 0..parts {
            k += self.poisson(exp_neg_part, POISSON_CAP);
        }
        k
    }
}

/// Largest mean drawn with one Knuth loop; larger means are split into equal parts and
/// the part counts summed (Poisson variables add), so e^(−part) stays a normal f32.
pub const POISSON_PART_MEAN: f32 = 64.0;

/// `(e^(−mean/parts), parts)` for a Poisson mean, parts = ⌈mean / POISSON_PART_MEAN⌉ ≥ 1.
#[must_use]
pub fn poisson_split(mean: f32) -> (f32, u32) {
    let parts = (mean / POISSON_PART_MEAN).ceil().max(1.0) as u32;
    ((-mean / parts as f32).exp(), parts)
}

/// Cap on Poisson draws per cell (the WGSL uses the same constant).
pub const POISSON_CAP: u32 = 256;

/// Wraps a cell index into `[0, period)` when `period > 0` (tileable variants); returns it
/// unchanged otherwise.
#[inline(always)]
#[must_use]
pub fn wrap_cell(i: i32, period: i32) -> i32 {
    if period > 0 { i.rem_euclid(period) } else { i }
}

/// ⌊x⌋ as an integer, exact for every finite f32 in the i32 range (matches WGSL
/// `i32(floor(x))`).
#[inline(always)]
#[must_use]
pub fn floor_i32(x: f32) -> i32 {
    let i = x as i32;
    if (i as f32) > x { i - 1 } else { i }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pcg_reference_values() {
        // Values of the published reference implementation.
        assert_eq!(pcg_hash(0), 129_708_002);
        assert_ne!(pcg_hash(1), pcg_hash(2));
    }

    #[test]
    fn unit_is_open_interval() {
        assert!(unit_f32(0) > 0.0);
        assert!(unit_f32(u32::MAX) < 1.0);
    }

    #[test]
    fn poisson_mean_and_variance() {
        let mean = 12.5_f32;
        let l = (-mean).exp();
        let n = 20_000;
        let (mut s, mut s2) = (0.0_f64, 0.0_f64);
        for i in 0..n {
            let k = f64::from(CellRng::new(i, 7, 3).poisson(l, POISSON_CAP));
            s += k;
            s2 += k * k;
        }
        let m = s / f64::from(n);
        let v = s2 / f64::from(n) - m * m;
        assert!((m - 12.5).abs() < 0.15, "mean {m}");
        assert!((v / 12.5 - 1.0).abs() < 0.05, "variance {v}");
    }

    #[test]
    fn split_poisson_keeps_large_means() {
        for mean in [10.0_f32, 200.0, 330.0] {
            let (l, parts) = poisson_split(mean);
            assert!(l > 0.0 && parts == (mean / 64.0).ceil() as u32);
            let n = 4000;
            let total: u64 = (0..n)
                .map(|i| u64::from(CellRng::new(i, -3, 1).poisson_parts(l, parts)))
                .sum();
            let m = total as f64 / f64::from(n);
            assert!((m / f64::from(mean) - 1.0).abs() < 0.02, "{mean}: {m}");
        }
    }

    #[test]
    fn floor_matches_std() {
        for x in [-2.0_f32, -1.5, -0.0, 0.0, 0.3, 1.0, 7.9, -7.9, -1e-7] {
            assert_eq!(floor_i32(x), x.floor() as i32, "{x}");
        }
    }
}
