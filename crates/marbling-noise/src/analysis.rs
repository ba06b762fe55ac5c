//! What the noise playground shows about a field: value statistics, a histogram and the
//! radially averaged power spectrum (how much of the pattern lies at each frequency,
//! whatever the direction; a Gabor ring or an fBm slope is read off it directly).

use rustfft::FftPlanner;
use rustfft::num_complex::Complex;

/// Summary of sampled values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stats {
    /// Smallest value.
    pub min: f32,
    /// Largest value.
    pub max: f32,
    /// Mean.
    pub mean: f64,
    /// Standard deviation (population).
    pub std_dev: f64,
}

/// Statistics of `values`; `None` when empty. Non-finite values are ignored.
pub fn stats(values: &[f32]) -> Option<Stats> {
    let finite: Vec<f64> = values
        .iter()
        .filter(|v| v.is_finite())
        .map(|&v| f64::from(v))
        .collect();
    if finite.is_empty() {
        return None;
    }
    let n = finite.len() as f64;
    let mean = finite.iter().sum::<f64>() / n;
    let var = finite.iter().map(|v| (v - mean) * (v - mean)).sum::<f64>() / n;
    let min = values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(f32::INFINITY, f32::min);
    let max = values
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(f32::NEG_INFINITY, f32::max);
    Some(Stats {
        min,
        max,
        mean,
        std_dev: var.sqrt(),
    })
}

/// Counts of `values` in `bins` equal bins over `[lo, hi]` (values outside are clamped
/// into the end bins; non-finite ones are skipped).
pub fn histogram(values: &[f32], bins: usize, lo: f32, hi: f32) -> Vec<u32> {
    let mut counts = vec![0u32; bins.max(1)];
    let last = counts.len() - 1;
    let width = (hi - lo) / counts.len() as f32;
    for &v in values.iter().filter(|v| v.is_finite()) {
        let k = if width > 0.0 {
            ((v - lo) / width).floor()
        } else {
            0.0
        };
        counts[(k.max(0.0) as usize).min(last)] += 1;
    }
    counts
}

/// Power spectrum |F|² of an `n`×`n` row-major image with its mean removed, indexed
/// `[ky * n + kx]` (unshifted: bin k is frequency k/n, or (k − n)/n for k ≥ n/2,
/// cycles per pixel).
pub fn power_spectrum(img: &[f32], n: usize) -> Vec<f64> {
    assert_eq!(img.len(), n * n, "power_spectrum: image is not n × n");
    let mean = img.iter().map(|&v| f64::from(v)).sum::<f64>() / img.len().max(1) as f64;
    let mut data: Vec<Complex<f64>> = img
        .iter()
        .map(|&v| Complex::new(f64::from(v) - mean, 0.0))
        .collect();
    let fft = FftPlanner::new().plan_fft_forward(n);
    for row in data.chunks_mut(n) {
        fft.process(row);
    }
    let mut column = vec![Complex::new(0.0, 0.0); n];
    for c in 0..n {
        for r in 0..n {
            column[r] = data[r * n + c];
        }
        fft.process(&mut column);
        for r in 0..n {
            data[r * n + c] = column[r];
        }
    }
    data.iter().map(|z| z.norm_sqr()).collect()
}

/// Signed frequency (cycles per pixel) of FFT bin `k` of `n`.
pub fn bin_frequency(k: usize, n: usize) -> f64 {
    let k = if k >= n / 2 {
        k as f64 - n as f64
    } else {
        k as f64
    };
    k / n as f64
}

/// The radially averaged power spectrum of an `n`×`n` image: for each ring of radius
/// r = 1‥n/2 bins, `(r / n cycles per pixel, mean power on the ring)`, the power
/// normalised so the rings sum to 1.
pub fn radial_spectrum(img: &[f32], n: usize) -> Vec<(f64, f64)> {
    let power = power_spectrum(img, n);
    let rings = n / 2;
    let mut sum = vec![0.0; rings + 1];
    let mut count = vec![0u32; rings + 1];
    for ky in 0..n {
        for kx in 0..n {
            let f = bin_frequency(kx, n).hypot(bin_frequency(ky, n)) * n as f64;
            let r = f.round() as usize;
            if (1..=rings).contains(&r) {
                sum[r] += power[ky * n + kx];
                count[r] += 1;
            }
        }
    }
    let means: Vec<f64> = (1..=rings)
        .map(|r| sum[r] / f64::from(count[r].max(1)))
        .collect();
    let total: f64 = means.iter().sum();
    (1..=rings)
        .zip(means)
        .map(|(r, m)| {
            (
                r as f64 / n as f64,
                if total > 0.0 { m / total } else { 0.0 },
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    #[test]
    fn stats_and_histogram_of_known_values() {
        let v = [1.0, 2.0, 3.0, 4.0, f32::NAN];
        let s = stats(&v).expect("stats");
        assert_eq!((s.min, s.max), (1.0, 4.0));
        assert!((s.mean - 2.5).abs() < 1e-12);
        assert!((s.std_dev - 1.25f64.sqrt()).abs() < 1e-12);
        assert_eq!(histogram(&v, 2, 0.0, 4.0), vec![1, 3]);
        assert_eq!(histogram(&[-9.0, 9.0], 4, -1.0, 1.0), vec![1, 0, 0, 1]);
        assert!(stats(&[]).is_none());
    }

    #[test]
    fn a_plane_wave_peaks_on_its_ring() {
        let n = 64;
        // 6 cycles along x and 8 along y: radius 10 bins.
        let img: Vec<f32> = (0..n * n)
            .map(|i| {
                let (x, y) = ((i % n) as f64, (i / n) as f64);
                (TAU * (6.0 * x + 8.0 * y) / n as f64).cos() as f32
            })
            .collect();
        let p = power_spectrum(&img, n);
        let peak = (0..n * n)
            .max_by(|&a, &b| p[a].total_cmp(&p[b]))
            .expect("bins");
        let (kx, ky) = (bin_frequency(peak % n, n), bin_frequency(peak / n, n));
        assert!(
            (kx.abs() - 6.0 / 64.0).abs() < 1e-9 && (ky.abs() - 8.0 / 64.0).abs() < 1e-9,
            "peak at {kx}, {ky}"
        );
        let rings = radial_spectrum(&img, n);
        let best = rings
            .iter()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .expect("rings");
        assert!((best.0 - 10.0 / 64.0).abs() < 1e-12, "ring at {}", best.0);
        assert!(best.1 > 0.9, "the ring holds {} of the power", best.1);
        let total: f64 = rings.iter().map(|r| r.1).sum();
        assert!((total - 1.0).abs() < 1e-9);
    }
}
