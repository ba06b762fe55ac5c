//! Perlin gradient noise (improved, quintic fade) in 2D, with analytic derivatives and a
//! periodic (tileable) variant. Input coordinates are in lattice cells (multiply output
//! pixels by a frequency in cycles per output pixel first). Keep in sync with
//! `shaders/perlin.wgsl`.

use crate::hash::{PRIME_X, PRIME_Y, floor_i32, lattice_hash_premul, wrap_cell};

const S: f32 = std::f32::consts::SQRT_2;

/// The eight gradients, all of length √2 so that the noise spans [−1, 1]; indexed by the
/// top three bits of the corner hash. Keep in sync with `PERLIN_GRADS` in `perlin.wgsl`.
pub const GRADIENTS: [[f32; 2]; 8] = [
    [1.0, 1.0],
    [-1.0, 1.0],
    [1.0, -1.0],
    [-1.0, -1.0],
    [S, 0.0],
    [-S, 0.0],
    [0.0, S],
    [0.0, -S],
];

/// Variance of [`perlin2`] over the plane (measured over 4·10⁶ points; checked by a test).
/// Dividing by its square root gives unit variance.
pub const PERLIN_VARIANCE: f32 = 0.0932;

/// Variance of each partial derivative of [`perlin2`] (lattice units), measured like
/// [`PERLIN_VARIANCE`]; used to normalise curl noise.
pub const PERLIN_DERIVATIVE_VARIANCE: f32 = 0.7809;

/// Bound on |∇n| of [`perlin2`] in lattice units: over every choice of the four corner
/// gradients and a 1/40-cell grid of positions in the cell the largest length is 2.831;
/// 2.9 leaves 2.4 % for the points between (a test checks random points against it).
pub const PERLIN_GRADIENT_BOUND: f32 = 2.9;

/// Quintic fade 6t⁵ − 15t⁴ + 10t³ (C² continuous).
#[inline(always)]
#[must_use]
pub fn fade(t: f32) -> f32 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// Derivative of [`fade`]: 30t²(t − 1)².
#[inline(always)]
#[must_use]
pub fn fade_derivative(t: f32) -> f32 {
    let s = t * (t - 1.0);
    30.0 * s * s
}

/// The gradient of a lattice corner's hash.
#[inline(always)]
pub(crate) fn gradient(h: u32) -> [f32; 2] {
    GRADIENTS[(h >> 29) as usize]
}

/// The four corner hashes of the cell containing (x, y) and the fractional position.
#[inline(always)]
fn corners(x: f32, y: f32, seed: u32, period: [i32; 2]) -> ([u32; 4], f32, f32) {
    let ix = floor_i32(x);
    let iy = floor_i32(y);
    let fx = x - ix as f32;
    let fy = y - iy as f32;
    let (x0, x1, y0, y1) = if period[0] > 0 || period[1] > 0 {
        (
            wrap_cell(ix, period[0]),
            wrap_cell(ix + 1, period[0]),
            wrap_cell(iy, period[1]),
            wrap_cell(iy + 1, period[1]),
        )
    } else {
        (ix, ix + 1, iy, iy + 1)
    };
    let xp0 = (x0 as u32).wrapping_mul(PRIME_X);
    let xp1 = (x1 as u32).wrapping_mul(PRIME_X);
    let yp0 = (y0 as u32).wrapping_mul(PRIME_Y);
    let yp1 = (y1 as u32).wrapping_mul(PRIME_Y);
    (
        [
            lattice_hash_premul(xp0, yp0, seed),
            lattice_hash_premul(xp1, yp0, seed),
            lattice_hash_premul(xp0, yp1, seed),
            lattice_hash_premul(xp1, yp1, seed),
        ],
        fx,
        fy,
    )
}

#[inline(always)]
fn perlin_from(h: [u32; 4], fx: f32, fy: f32) -> f32 {
    let g = |h: u32, x: f32, y: f32| {
        let g = gradient(h);
        g[0] * x + g[1] * y
    };
    let a = g(h[0], fx, fy);
    let b = g(h[1], fx - 1.0, fy);
    let c = g(h[2], fx, fy - 1.0);
    let d = g(h[3], fx - 1.0, fy - 1.0);
    let u = fade(fx);
    let v = fade(fy);
    let ab = a + u * (b - a);
    let cd = c + u * (d - c);
    ab + v * (cd - ab)
}

/// 2D Perlin gradient noise at (x, y) in lattice units, in [−1, 1], zero at lattice
/// points, variance [`PERLIN_VARIANCE`].
#[inline]
#[must_use]
pub fn perlin2(x: f32, y: f32, seed: u32) -> f32 {
    let (h, fx, fy) = corners(x, y, seed, [0, 0]);
    perlin_from(h, fx, fy)
}

/// [`perlin2`] repeating every `period` lattice cells in x and y (a period ≤ 0 does not
/// wrap that axis).
#[inline]
#[must_use]
pub fn perlin2_periodic(x: f32, y: f32, seed: u32, period: [i32; 2]) -> f32 {
    let (h, fx, fy) = corners(x, y, seed, period);
    perlin_from(h, fx, fy)
}

/// [`perlin2_periodic`] and its analytic gradient: `[n, ∂n/∂x, ∂n/∂y]` in lattice units.
#[must_use]
pub fn perlin2_with_gradient(x: f32, y: f32, seed: u32, period: [i32; 2]) -> [f32; 3] {
    let (h, fx, fy) = corners(x, y, seed, period);
    let g00 = gradient(h[0]);
    let g10 = gradient(h[1]);
    let g01 = gradient(h[2]);
    let g11 = gradient(h[3]);
    let a = g00[0] * fx + g00[1] * fy;
    let b = g10[0] * (fx - 1.0) + g10[1] * fy;
    let c = g01[0] * fx + g01[1] * (fy - 1.0);
    let d = g11[0] * (fx - 1.0) + g11[1] * (fy - 1.0);
    let u = fade(fx);
    let v = fade(fy);
    let du = fade_derivative(fx);
    let dv = fade_derivative(fy);
    let k = a - b - c + d;
    let n = a + u * (b - a) + v * (c - a) + u * v * k;
    let dx = g00[0]
        + u * (g10[0] - g00[0])
        + v * (g01[0] - g00[0])
        + u * v * (g00[0] - g10[0] - g01[0] + g11[0])
        + du * ((b - a) + v * k);
    let dy = g00[1]
        + u * (g10[1] - g00[1])
        + v * (g01[1] - g00[1])
        + u * v * (g00[1] - g10[1] - g01[1] + g11[1])
        + dv * ((c - a) + u * k);
    [n, dx, dy]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_and_lattice_zeros() {
        let mut max = 0.0_f32;
        for j in 0..300 {
            for i in 0..300 {
                let v = perlin2(i as f32 * 0.0731 - 9.0, j as f32 * 0.0617 - 5.0, 4);
                max = max.max(v.abs());
            }
        }
        assert!(max <= 1.0 && max > 0.6, "max {max}");
        assert_eq!(perlin2(3.0, -2.0, 9), 0.0);
    }

    #[test]
    fn gradient_matches_finite_differences() {
        let h = 1e-3;
        for k in 0..50 {
            let x = k as f32 * 0.377 - 3.1;
            let y = k as f32 * 0.211 + 0.4;
            let [n, dx, dy] = perlin2_with_gradient(x, y, 5, [0, 0]);
            assert!((n - perlin2(x, y, 5)).abs() < 1e-6);
            let fdx = (perlin2(x + h, y, 5) - perlin2(x - h, y, 5)) / (2.0 * h);
            let fdy = (perlin2(x, y + h, 5) - perlin2(x, y - h, 5)) / (2.0 * h);
            assert!((dx - fdx).abs() < 2e-2, "{dx} {fdx}");
            assert!((dy - fdy).abs() < 2e-2, "{dy} {fdy}");
        }
    }

    #[test]
    fn variance_constants() {
        let (mut s, mut s2, mut d2) = (0.0_f64, 0.0_f64, 0.0_f64);
        let n = 1000;
        for j in 0..n {
            for i in 0..n {
                let [v, dx, dy] = perlin2_with_gradient(
                    i as f32 * 0.1373 + 0.01,
                    j as f32 * 0.1291 + 0.02,
                    11,
                    [0, 0],
                );
                s += f64::from(v);
                s2 += f64::from(v) * f64::from(v);
                d2 += 0.5 * (f64::from(dx).powi(2) + f64::from(dy).powi(2));
            }
        }
        let count = f64::from(n * n);
        let var = s2 / count - (s / count).powi(2);
        let dvar = d2 / count;
        assert!(
            (var / f64::from(PERLIN_VARIANCE) - 1.0).abs() < 0.03,
            "{var}"
        );
        assert!(
            (dvar / f64::from(PERLIN_DERIVATIVE_VARIANCE) - 1.0).abs() < 0.03,
            "{dvar}"
        );
    }

    #[test]
    fn periodic_wraps() {
        for k in 0..20 {
            let y = k as f32 * 0.37;
            let a = perlin2_periodic(0.25, y, 3, [5, 7]);
            let b = perlin2_periodic(5.25, y + 7.0, 3, [5, 7]);
            assert!((a - b).abs() < 1e-5);
        }
    }
}
