//! Transfer functions from noise (zero mean, unit variance) to intensity in [0, 1]:
//! smoothstep thresholds (stipples from isotropic Gabor, hatching from anisotropic Gabor,
//! cross-hatching as the product of two), the C² cubic spline decay of Khlebnikov et al. 2013 whose mean
//! intensity tracks a value v ∈ [0, 1], and Khlebnikov et al. (2013)'s HSV value blend with β.
//! Keep in sync with `shaders/transfer.wgsl`.

use crate::ramp::Rgb;

/// Hermite smoothstep: 0 below `e0`, 1 above `e1`, 3t² − 2t³ between (as WGSL
/// `smoothstep`).
#[inline]
#[must_use]
pub fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// A soft threshold: smoothstep from `threshold − width/2` to `threshold + width/2`
/// (noise units), optionally inverted (1 − …, ink where the noise is high).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Threshold {
    /// Centre of the ramp, noise units (standard deviations).
    pub threshold: f32,
    /// Width of the ramp, noise units (> 0).
    pub width: f32,
    /// Whether high noise maps to 0 instead of 1.
    pub invert: bool,
}

impl Threshold {
    /// Intensity of noise value `n`.
    #[inline]
    #[must_use]
    pub fn apply(&self, n: f32) -> f32 {
        let s = smoothstep(
            self.threshold - 0.5 * self.width,
            self.threshold + 0.5 * self.width,
            n,
        );
        if self.invert { 1.0 - s } else { s }
    }
}

/// Khlebnikov et al. (2013)'s cubic spline decay D(t) = (2q/γ³)|t|³ − (3q/γ²)t² + q for |t| ≤ γ, else 0:
/// peak q at t = 0, support [−γ, γ], max |D′| = 3q/(2γ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SplineDecay {
    /// Half-width of the support γ, noise units.
    pub gamma: f32,
    /// Peak value q ∈ [0, 1].
    pub q: f32,
}

const INV_SQRT_2PI: f64 = 0.398_942_280_401_432_7;

impl SplineDecay {
    /// The decay of support γ with the largest peak whose slope stays ≤ 1:
    /// q = min(1, 2γ/3).
    #[must_use]
    pub fn with_gamma(gamma: f32) -> Self {
        Self {
            gamma,
            q: (2.0 * gamma / 3.0).min(1.0),
        }
    }

    /// D(t).
    #[inline]
    #[must_use]
    pub fn apply(&self, t: f32) -> f32 {
        let a = t.abs();
        if a > self.gamma || self.gamma <= 0.0 {
            return 0.0;
        }
        let g = self.gamma;
        self.q * (2.0 * a * a * a / (g * g * g) - 3.0 * a * a / (g * g) + 1.0)
    }

    /// E[D(N)] for N standard normal, the mean intensity on unit-variance Gaussian noise
    /// (Simpson's rule, 256 intervals).
    #[must_use]
    pub fn mean_on_gaussian(&self) -> f64 {
        let g = f64::from(self.gamma);
        if g <= 0.0 {
            return 0.0;
        }
        let n = 256;
        let h = 2.0 * g / f64::from(n);
        let f = |t: f64| f64::from(self.apply(t as f32)) * (-0.5 * t * t).exp() * INV_SQRT_2PI;
        let mut s = f(-g) + f(g);
        for i in 1..n {
            let t = -g + h * f64::from(i);
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(t);
        }
        s * h / 3.0
    }

    /// The decay whose mean intensity on unit-variance Gaussian noise is `v` (Khlebnikov et al. 2013,
    /// eq. 6), by bisection on γ ∈ [0, 40]; `v` is clamped to [0, 0.998] (v → 1 needs an
    /// infinitely wide support).
    #[must_use]
    pub fn for_value(v: f32) -> Self {
        let target = f64::from(v.clamp(0.0, 0.998));
        let (mut lo, mut hi) = (0.0_f32, 40.0_f32);
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if Self::with_gamma(mid).mean_on_gaussian() < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Self::with_gamma(0.5 * (lo + hi))
    }
}

/// γ(v) tabulated at 257 evenly spaced v ∈ [0, 1] and interpolated linearly, as Khlebnikov et al. 2013
/// does for per-pixel values.
#[derive(Clone, Debug)]
pub struct SplineDecayTable {
    gammas: Vec<f32>,
}

impl Default for SplineDecayTable {
    fn default() -> Self {
        Self::new()
    }
}

impl SplineDecayTable {
    /// Builds the table (≈ 10 ms).
    #[must_use]
    pub fn new() -> Self {
        Self {
            gammas: (0..=256)
                .map(|i| SplineDecay::for_value(i as f32 / 256.0).gamma)
                .collect(),
        }
    }

    /// The decay for value `v` ∈ [0, 1].
    #[must_use]
    pub fn decay(&self, v: f32) -> SplineDecay {
        let x = v.clamp(0.0, 1.0) * 256.0;
        let i = (x.floor() as usize).min(255);
        let f = x - i as f32;
        SplineDecay::with_gamma(self.gammas[i] + f * (self.gammas[i + 1] - self.gammas[i]))
    }
}

/// sRGB → HSV, all components in [0, 1] (hue as a fraction of a turn).
#[must_use]
pub fn rgb_to_hsv(c: Rgb) -> [f32; 3] {
    let [r, g, b] = c;
    let max = r.max(g).max(b);
    let min = r.min(g).min(b);
    let d = max - min;
    let h = if d <= 0.0 {
        0.0
    } else if max == r {
        ((g - b) / d).rem_euclid(6.0) / 6.0
    } else if max == g {
        ((b - r) / d + 2.0) / 6.0
    } else {
        ((r - g) / d + 4.0) / 6.0
    };
    let s = if max <= 0.0 { 0.0 } else { d / max };
    [h, s, max]
}

/// HSV → sRGB, all components in [0, 1].
#[must_use]
pub fn hsv_to_rgb(hsv: [f32; 3]) -> Rgb {
    let [h, s, v] = hsv;
    let h6 = h.rem_euclid(1.0) * 6.0;
    let c = v * s;
    let x = c * (1.0 - (h6.rem_euclid(2.0) - 1.0).abs());
    let (r, g, b) = match h6 as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let m = v - c;
    [r + m, g + m, b + m]
}

/// Khlebnikov et al. 2013 eq. 9: keeps hue and saturation of `color` and sets its value to
/// β·C_v + (1 − β)·`intensity` (β = 0.6 in the paper).
#[must_use]
pub fn hsv_value_blend(color: Rgb, intensity: f32, beta: f32) -> Rgb {
    let [h, s, v] = rgb_to_hsv(color);
    hsv_to_rgb([h, s, beta * v + (1.0 - beta) * intensity.clamp(0.0, 1.0)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spline_decay_tracks_value_and_slope_bound() {
        let table = SplineDecayTable::new();
        for v in [0.05_f32, 0.2, 0.5, 0.8, 0.95] {
            let d = table.decay(v);
            assert!((d.mean_on_gaussian() - f64::from(v)).abs() < 0.01, "{v}");
            assert!(1.5 * d.q / d.gamma <= 1.0 + 1e-5);
            assert!(d.apply(d.gamma * 1.001) == 0.0 && (d.apply(0.0) - d.q).abs() < 1e-6);
        }
    }

    #[test]
    fn hsv_round_trip_and_blend() {
        for c in [
            [0.2, 0.4, 0.9],
            [0.9, 0.1, 0.1],
            [0.5, 0.5, 0.5],
            [0.1, 0.8, 0.3],
        ] {
            let back = hsv_to_rgb(rgb_to_hsv(c));
            for k in 0..3 {
                assert!((back[k] - c[k]).abs() < 1e-5, "{c:?} {back:?}");
            }
        }
        let c = [0.8, 0.2, 0.2];
        let out = hsv_value_blend(c, 0.0, 0.6);
        let [h0, s0, v0] = rgb_to_hsv(c);
        let [h1, s1, v1] = rgb_to_hsv(out);
        assert!((h0 - h1).abs() < 1e-5 && (s0 - s1).abs() < 1e-5);
        assert!((v1 - 0.6 * v0).abs() < 1e-5);
    }

    #[test]
    fn threshold_is_smoothstep() {
        let t = Threshold {
            threshold: 1.0,
            width: 0.5,
            invert: false,
        };
        assert_eq!(t.apply(0.0), 0.0);
        assert_eq!(t.apply(2.0), 1.0);
        assert!((t.apply(1.0) - 0.5).abs() < 1e-6);
    }
}
