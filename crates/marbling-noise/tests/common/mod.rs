//! Helpers shared by the integration tests: a small radix-2 FFT and power spectra.

#![allow(dead_code)]

use std::f64::consts::TAU;

/// In-place iterative radix-2 FFT of `re`/`im` (length a power of two).
pub fn fft(re: &mut [f64], im: &mut [f64]) {
    let n = re.len();
    assert!(n.is_power_of_two() && im.len() == n);
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let ang = -TAU / len as f64;
        let (wr, wi) = (ang.cos(), ang.sin());
        for start in (0..n).step_by(len) {
            let (mut cr, mut ci) = (1.0, 0.0);
            for k in 0..len / 2 {
                let (a, b) = (start + k, start + k + len / 2);
                let tr = re[b] * cr - im[b] * ci;
                let ti = re[b] * ci + im[b] * cr;
                re[b] = re[a] - tr;
                im[b] = im[a] - ti;
                re[a] += tr;
                im[a] += ti;
                let t = cr * wr - ci * wi;
                ci = cr * wi + ci * wr;
                cr = t;
            }
        }
        len <<= 1;
    }
}

/// Power spectrum |F|² of an n×n row-major image (mean removed), indexed [ky][kx].
pub fn power_spectrum(img: &[f32], n: usize) -> Vec<f64> {
    let mean = img.iter().map(|&v| f64::from(v)).sum::<f64>() / img.len() as f64;
    let mut re: Vec<f64> = img.iter().map(|&v| f64::from(v) - mean).collect();
    let mut im = vec![0.0; n * n];
    for r in 0..n {
        fft(&mut re[r * n..(r + 1) * n], &mut im[r * n..(r + 1) * n]);
    }
    let (mut cr, mut ci) = (vec![0.0; n], vec![0.0; n]);
    for c in 0..n {
        for r in 0..n {
            cr[r] = re[r * n + c];
            ci[r] = im[r * n + c];
        }
        fft(&mut cr, &mut ci);
        for r in 0..n {
            re[r * n + c] = cr[r];
            im[r * n + c] = ci[r];
        }
    }
    re.iter().zip(&im).map(|(a, b)| a * a + b * b).collect()
}

/// Signed frequency (cycles per pixel) of FFT bin k of n.
pub fn freq(k: usize, n: usize) -> f64 {
    let k = if k >= n / 2 {
        k as f64 - n as f64
    } else {
        k as f64
    };
    k / n as f64
}
