//! Value noise: uniform random values in [−1, 1] at lattice points, interpolated with the
//! quintic fade; periodic variant. Coordinates in lattice cells. Keep in sync with
//! `shaders/value.wgsl`.

use crate::hash::{floor_i32, lattice_hash, unit_f32, wrap_cell};
use crate::perlin::fade;

/// Variance of [`value2`] over the plane: (1/3)·(E[(1−s)² + s²])² with s the quintic
/// fade of a uniform t, = (1/3)·(181/231)² (exact; checked by a test).
pub const VALUE_VARIANCE: f32 = (1.0 / 3.0) * (181.0 / 231.0) * (181.0 / 231.0);

/// The value at lattice corner (ix, iy), in [−1, 1].
#[inline(always)]
pub(crate) fn corner(ix: i32, iy: i32, seed: u32) -> f32 {
    unit_f32(lattice_hash(ix, iy, seed)) * 2.0 - 1.0
}

/// Value noise at (x, y) in lattice units, in [−1, 1]; repeats every `period` cells
/// when a period component is > 0.
#[inline]
#[must_use]
pub fn value2_periodic(x: f32, y: f32, seed: u32, period: [i32; 2]) -> f32 {
    let ix = floor_i32(x);
    let iy = floor_i32(y);
    let u = fade(x - ix as f32);
    let v = fade(y - iy as f32);
    let x0 = wrap_cell(ix, period[0]);
    let x1 = wrap_cell(ix + 1, period[0]);
    let y0 = wrap_cell(iy, period[1]);
    let y1 = wrap_cell(iy + 1, period[1]);
    let a = corner(x0, y0, seed);
    let b = corner(x1, y0, seed);
    let c = corner(x0, y1, seed);
    let d = corner(x1, y1, seed);
    let ab = a + u * (b - a);
    let cd = c + u * (d - c);
    ab + v * (cd - ab)
}

/// Value noise at (x, y) in lattice units, in [−1, 1], variance [`VALUE_VARIANCE`].
#[inline]
#[must_use]
pub fn value2(x: f32, y: f32, seed: u32) -> f32 {
    value2_periodic(x, y, seed, [0, 0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variance_formula() {
        let (mut s, mut s2) = (0.0_f64, 0.0_f64);
        let n = 1000;
        for j in 0..n {
            for i in 0..n {
                let v = f64::from(value2(i as f32 * 0.1373, j as f32 * 0.1291, 2));
                s += v;
                s2 += v * v;
            }
        }
        let c = f64::from(n * n);
        let var = s2 / c - (s / c).powi(2);
        assert!(
            (var / f64::from(VALUE_VARIANCE) - 1.0).abs() < 0.03,
            "{var}"
        );
    }
}
