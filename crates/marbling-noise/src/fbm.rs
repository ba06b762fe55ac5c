//! Fractional Brownian motion (fBm): a sum of octaves of Perlin or value noise with
//! growing frequency (lacunarity) and shrinking amplitude (persistence), normalised to
//! zero mean and unit variance. Keep in sync with `fbm` in `shaders/fbm.wgsl`.

use crate::perlin::{PERLIN_VARIANCE, perlin2, perlin2_periodic, perlin2_with_gradient};
use crate::value::{VALUE_VARIANCE, value2_periodic};

/// Most octaves an fBm may have.
pub const MAX_OCTAVES: u32 = 12;

/// Added to the seed for each further octave (wrapping), so octaves are independent.
pub const OCTAVE_SEED_STEP: u32 = 0x9E37_79B9;

/// The lattice noise summed by an [`Fbm`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Basis {
    /// Perlin gradient noise ([`crate::perlin2`]).
    Perlin,
    /// Value noise ([`crate::value2`]).
    Value,
}

/// Parameters of an fBm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FbmParams {
    /// The summed noise.
    pub basis: Basis,
    /// Frequency of the first octave, cycles (lattice cells) per output pixel.
    pub frequency: f32,
    /// Number of octaves, 1..=[`MAX_OCTAVES`].
    pub octaves: u32,
    /// Frequency ratio between successive octaves (usually 2).
    pub lacunarity: f32,
    /// Amplitude ratio between successive octaves (usually 0.5).
    pub persistence: f32,
    /// Seed; octave i uses `seed + i·OCTAVE_SEED_STEP`.
    pub seed: u32,
    /// Tile period in output pixels: when set, each octave's frequency is rounded so that
    /// a whole number of lattice cells (at least one) fits the period, and the lattice
    /// wraps, so the noise repeats every `period` pixels in x and y.
    pub period: Option<u32>,
}

impl Default for FbmParams {
    fn default() -> Self {
        Self {
            basis: Basis::Perlin,
            frequency: 1.0 / 32.0,
            octaves: 1,
            lacunarity: 2.0,
            persistence: 0.5,
            seed: 0,
            period: None,
        }
    }
}

#[derive(Clone, Copy, Debug, Default)]
struct Octave {
    frequency: f32,
    amplitude: f32,
    seed: u32,
    period: i32,
}

/// A ready-to-evaluate fBm (octave tables precomputed).
#[derive(Clone, Debug)]
pub struct Fbm {
    params: FbmParams,
    octaves: [Octave; MAX_OCTAVES as usize],
    count: usize,
    amplitude_sum: f32,
    inv_std: f32,
}

impl Fbm {
    /// Precomputes the octaves; `octaves` is clamped to 1..=[`MAX_OCTAVES`].
    #[must_use]
    pub fn new(params: FbmParams) -> Self {
        let count = params.octaves.clamp(1, MAX_OCTAVES) as usize;
        let mut octaves = [Octave::default(); MAX_OCTAVES as usize];
        let (mut f, mut a) = (params.frequency, 1.0_f32);
        let (mut amplitude_sum, mut square_sum) = (0.0_f32, 0.0_f32);
        for (i, o) in octaves.iter_mut().take(count).enumerate() {
            let (frequency, period) = match params.period {
                Some(p) if p > 0 => {
                    let cells = (f * p as f32 + 0.5).floor().max(1.0);
                    (cells / p as f32, cells as i32)
                }
                _ => (f, 0),
            };
            *o = Octave {
                frequency,
                amplitude: a,
                seed: params
                    .seed
                    .wrapping_add((i as u32).wrapping_mul(OCTAVE_SEED_STEP)),
                period,
            };
            amplitude_sum += a;
            square_sum += a * a;
            f *= params.lacunarity;
            a *= params.persistence;
        }
        let variance = match params.basis {
            Basis::Perlin => PERLIN_VARIANCE,
            Basis::Value => VALUE_VARIANCE,
        };
        Self {
            params,
            octaves,
            count,
            amplitude_sum,
            inv_std: 1.0 / (variance * square_sum).sqrt(),
        }
    }

    /// Its octaves as (frequency in cycles per output pixel, amplitude, seed), first
    /// octave first: the numbers [`Fbm::eval`] sums (the f64 twin [`crate::Fbm64`] reads
    /// them here, so both sum the same octaves).
    pub fn octaves(&self) -> impl Iterator<Item = (f32, f32, u32)> + '_ {
        self.octaves[..self.count]
            .iter()
            .map(|o| (o.frequency, o.amplitude, o.seed))
    }

    /// 1/σ: the factor that brings the sum of octaves to unit variance.
    #[must_use]
    pub fn inv_std(&self) -> f32 {
        self.inv_std
    }

    /// The parameters this fBm was built from.
    #[must_use]
    pub fn params(&self) -> &FbmParams {
        &self.params
    }

    /// Σ aᵢ·noise(fᵢ·p): the un-normalised sum (the common non-tiled Perlin case has
    /// its own loop without wrapping).
    #[inline]
    fn sum(&self, x: f32, y: f32) -> f32 {
        let octaves = &self.octaves[..self.count];
        let mut s = 0.0;
        match (self.params.basis, self.params.period) {
            (Basis::Perlin, None) => {
                for o in octaves {
                    s += o.amplitude * perlin2(x * o.frequency, y * o.frequency, o.seed);
                }
            }
            (Basis::Perlin, Some(_)) => {
                for o in octaves {
                    let p = [o.period, o.period];
                    s +=
                        o.amplitude * perlin2_periodic(x * o.frequency, y * o.frequency, o.seed, p);
                }
            }
            (Basis::Value, _) => {
                for o in octaves {
                    let p = [o.period, o.period];
                    s += o.amplitude * value2_periodic(x * o.frequency, y * o.frequency, o.seed, p);
                }
            }
        }
        s
    }

    /// [`Fbm::sum`] along a row (`out[i]` at (xs[i], y)), bit for bit: Perlin octaves
    /// through the row kernel ([`crate::rows::perlin2_row`]).
    fn sum_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        let out = &mut out[..xs.len()];
        out.fill(0.0);
        let mut scaled = vec![0.0; xs.len()];
        let mut n = vec![0.0; xs.len()];
        for o in &self.octaves[..self.count] {
            let p = match self.params.period {
                None => [0, 0],
                Some(_) => [o.period, o.period],
            };
            for (s, &x) in scaled.iter_mut().zip(xs) {
                *s = x * o.frequency;
            }
            match self.params.basis {
                Basis::Perlin => {
                    crate::rows::perlin2_row(&scaled, y * o.frequency, o.seed, p, &mut n)
                }
                Basis::Value => {
                    let p = [o.period, o.period];
                    for (v, &u) in n.iter_mut().zip(&scaled) {
                        *v = value2_periodic(u, y * o.frequency, o.seed, p);
                    }
                }
            }
            for (s, &v) in out.iter_mut().zip(&n) {
                *s += o.amplitude * v;
            }
        }
    }

    /// [`Fbm::eval`] along a row: `out[i]` = `eval(xs[i], y)`, bit for bit, several
    /// times faster.
    pub fn eval_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        self.sum_row(xs, y, out);
        for v in &mut out[..xs.len()] {
            *v *= self.inv_std;
        }
    }

    /// The fBm at (x, y) in output pixels divided by the sum of amplitudes, so it lies
    /// in [−1, 1] whatever the parameters.
    #[inline]
    #[must_use]
    pub fn eval_bounded(&self, x: f32, y: f32) -> f32 {
        self.sum(x, y) / self.amplitude_sum
    }

    /// The fBm at (x, y) in output pixels at zero mean and unit variance (octaves are
    /// independent, so the variance is the basis variance times Σ aᵢ²).
    #[inline]
    #[must_use]
    pub fn eval(&self, x: f32, y: f32) -> f32 {
        self.sum(x, y) * self.inv_std
    }

    /// `[n, ∂n/∂x, ∂n/∂y]` of [`Fbm::eval`], derivatives per output pixel (analytic for
    /// Perlin; central differences of 1/64 cell for value noise).
    #[must_use]
    pub fn eval_with_gradient(&self, x: f32, y: f32) -> [f32; 3] {
        let mut out = [0.0_f32; 3];
        for o in &self.octaves[..self.count] {
            let p = [o.period, o.period];
            let (u, v) = (x * o.frequency, y * o.frequency);
            let [n, dx, dy] = match self.params.basis {
                Basis::Perlin => perlin2_with_gradient(u, v, o.seed, p),
                Basis::Value => {
                    let h = 1.0 / 64.0;
                    let f = |a: f32, b: f32| value2_periodic(a, b, o.seed, p);
                    [
                        f(u, v),
                        (f(u + h, v) - f(u - h, v)) / (2.0 * h),
                        (f(u, v + h) - f(u, v - h)) / (2.0 * h),
                    ]
                }
            };
            out[0] += o.amplitude * n;
            out[1] += o.amplitude * o.frequency * dx;
            out[2] += o.amplitude * o.frequency * dy;
        }
        out.map(|v| v * self.inv_std)
    }

    /// Σ aᵢ²·fᵢ² times the basis derivative variance, over the basis variance times
    /// Σ aᵢ²: the variance of each partial derivative of [`Fbm::eval`] (Perlin basis).
    #[must_use]
    pub fn derivative_variance(&self) -> f32 {
        let s: f32 = self.octaves[..self.count]
            .iter()
            .map(|o| (o.amplitude * o.frequency).powi(2))
            .sum();
        s * crate::perlin::PERLIN_DERIVATIVE_VARIANCE * self.inv_std * self.inv_std
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounded_range_and_unit_variance() {
        let fbm = Fbm::new(FbmParams {
            octaves: 5,
            frequency: 1.0 / 40.0,
            seed: 9,
            ..FbmParams::default()
        });
        let (mut s, mut s2, mut lo, mut hi) = (0.0_f64, 0.0_f64, 0.0_f32, 0.0_f32);
        let n = 512;
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (i as f32 * 1.7 + 0.5, j as f32 * 1.7 + 0.5);
                let b = fbm.eval_bounded(x, y);
                lo = lo.min(b);
                hi = hi.max(b);
                let v = f64::from(fbm.eval(x, y));
                s += v;
                s2 += v * v;
            }
        }
        assert!(lo >= -1.0 && hi <= 1.0, "{lo} {hi}");
        assert!(lo < -0.3 && hi > 0.3, "{lo} {hi}");
        let c = f64::from(n * n);
        let var = s2 / c - (s / c).powi(2);
        assert!((s / c).abs() < 0.1, "mean {}", s / c);
        assert!((var - 1.0).abs() < 0.15, "variance {var}");
    }
}
