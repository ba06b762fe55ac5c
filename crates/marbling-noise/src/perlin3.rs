//! 3D Perlin gradient noise (Perlin 2002, "Improving Noise": quintic fade, the twelve
//! cube-edge gradients) and its fBm, the noise Kung 2019 (ch. 3) displaces surfaces
//! with. Input in lattice cells. Keep in sync with `shaders/perlin3.wgsl`.

use crate::hash::{PRIME_X, PRIME_Y, floor_i32, lattice_hash_premul};
use crate::perlin::fade;

/// Multiplier applied to lattice z indices before mixing.
pub const PRIME_Z: u32 = 0xC2B2_AE3D;

/// The twelve cube-edge gradients (length √2) and four of them again, indexed by the top
/// four bits of the corner hash (Perlin 2002). Keep in sync with `PERLIN3_GRADS`.
pub const GRADIENTS3: [[f32; 3]; 16] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [0.0, -1.0, 1.0],
    [0.0, -1.0, -1.0],
];

/// A bound on |[`perlin3`]| (and so on |[`fbm3`]|): the noise is a convex blend of
/// the corners' g·d, |g| = √2 and |d| ≤ √3, so |n| ≤ √6. (Sampled values stay
/// below 1.05; the bound is what a ray march may rely on.)
pub const PERLIN3_BOUND: f32 = 2.449_49;

/// 3D Perlin noise at `p` (lattice units), zero at lattice points.
#[must_use]
pub fn perlin3(p: [f32; 3], seed: u32) -> f32 {
    let i = p.map(floor_i32);
    let f: [f32; 3] = std::array::from_fn(|k| p[k] - i[k] as f32);
    let prime = [PRIME_X, PRIME_Y, PRIME_Z];
    let lattice = |k: usize, corner: i32| ((i[k] + corner) as u32).wrapping_mul(prime[k]);
    let corner = |cx: i32, cy: i32, cz: i32| {
        let h = lattice_hash_premul(lattice(0, cx), lattice(1, cy) ^ lattice(2, cz), seed);
        let g = GRADIENTS3[(h >> 28) as usize];
        g[0] * (f[0] - cx as f32) + g[1] * (f[1] - cy as f32) + g[2] * (f[2] - cz as f32)
    };
    let [u, v, w] = f.map(fade);
    let lerp = |a: f32, b: f32, t: f32| a + t * (b - a);
    let x00 = lerp(corner(0, 0, 0), corner(1, 0, 0), u);
    let x10 = lerp(corner(0, 1, 0), corner(1, 1, 0), u);
    let x01 = lerp(corner(0, 0, 1), corner(1, 0, 1), u);
    let x11 = lerp(corner(0, 1, 1), corner(1, 1, 1), u);
    lerp(lerp(x00, x10, v), lerp(x01, x11, v), w)
}

/// Fractal sum of [`perlin3`]: octave k at frequency lacunarityᵏ with amplitude
/// persistenceᵏ and seed `seed + k`, divided by the sum of the amplitudes (so
/// |fbm3| ≤ [`PERLIN3_BOUND`], and one octave is [`perlin3`] itself).
#[must_use]
pub fn fbm3(p: [f32; 3], octaves: u32, lacunarity: f32, persistence: f32, seed: u32) -> f32 {
    let (mut sum, mut norm, mut amp, mut freq) = (0.0, 0.0, 1.0, 1.0);
    for k in 0..octaves.max(1) {
        sum += amp * perlin3(p.map(|c| c * freq), seed.wrapping_add(k));
        norm += amp;
        amp *= persistence;
        freq *= lacunarity;
    }
    if norm > 0.0 { sum / norm } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(n: usize) -> impl Iterator<Item = [f32; 3]> {
        let mut s = 7_u32;
        let mut next = move || {
            s = crate::hash::pcg_hash(s);
            (s as f32 / u32::MAX as f32) * 40.0 - 20.0
        };
        (0..n).map(move |_| [next(), next(), next()])
    }

    #[test]
    fn perlin3_is_zero_on_the_lattice_bounded_and_continuous() {
        for p in [[0.0, 0.0, 0.0], [3.0, -2.0, 7.0], [-11.0, 5.0, 0.0]] {
            assert_eq!(perlin3(p, 9), 0.0);
        }
        let (mut max, mut sum2, mut n) = (0.0_f32, 0.0_f64, 0);
        for p in points(200_000) {
            let v = perlin3(p, 1);
            max = max.max(v.abs());
            sum2 += f64::from(v * v);
            n += 1;
            // Continuity across a cell face: a step of 1e-4 moves the value by less
            // than the gradient bound times the step.
            let q = [p[0] + 1e-4, p[1], p[2]];
            assert!((perlin3(q, 1) - v).abs() < 1e-3, "jump at {p:?}");
        }
        assert!(max <= PERLIN3_BOUND && max > 0.7, "max |n| = {max}");
        let sd = (sum2 / f64::from(n)).sqrt();
        assert!((0.15..0.4).contains(&sd), "standard deviation {sd}");
    }

    #[test]
    fn fbm3_of_one_octave_is_perlin3_and_more_octaves_add_detail() {
        let p = [1.3, -0.4, 2.9];
        assert_eq!(fbm3(p, 1, 2.0, 0.5, 4), perlin3(p, 4));
        let two = fbm3(p, 2, 2.0, 0.5, 4);
        let expect = (perlin3(p, 4) + 0.5 * perlin3([2.6, -0.8, 5.8], 5)) / 1.5;
        assert!((two - expect).abs() < 1e-6);
        for p in points(10_000) {
            assert!(fbm3(p, 5, 2.0, 0.7, 3).abs() <= PERLIN3_BOUND);
        }
    }
}
