//! White noise: an independent uniform value per output pixel, scaled to zero mean and
//! unit variance (range ±√3). Keep in sync with `shaders/white.wgsl`.

use crate::hash::{cell_hash, floor_i32, unit_f32, wrap_cell};

/// √3: the half-range of a unit-variance uniform distribution.
pub const WHITE_HALF_RANGE: f32 = 1.732_050_8;

/// White noise at the pixel containing (x, y) (output pixels); uniform in [−√3, √3].
/// `period` > 0 repeats the pattern every `period` pixels on that axis.
#[inline]
#[must_use]
pub fn white2(x: f32, y: f32, seed: u32, period: [i32; 2]) -> f32 {
    let ix = wrap_cell(floor_i32(x), period[0]);
    let iy = wrap_cell(floor_i32(y), period[1]);
    (unit_f32(cell_hash(ix, iy, seed)) * 2.0 - 1.0) * WHITE_HALF_RANGE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_variance_and_constant_within_pixel() {
        let (mut s, mut s2) = (0.0_f64, 0.0_f64);
        for j in 0..300 {
            for i in 0..300 {
                let v = f64::from(white2(i as f32 + 0.5, j as f32 + 0.5, 4, [0, 0]));
                s += v;
                s2 += v * v;
            }
        }
        let c = 90_000.0;
        assert!((s / c).abs() < 0.02);
        assert!((s2 / c - 1.0).abs() < 0.03);
        assert_eq!(white2(3.1, 4.2, 1, [0, 0]), white2(3.9, 4.8, 1, [0, 0]));
    }
}
