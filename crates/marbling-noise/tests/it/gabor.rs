//! Gabor noise statistics: mean ≈ 0 and variance within 5 % of the analytical formula,
//! the anisotropic spectrum peak at F₀ (5 %) and ω₀ (3°), the isotropic spectrum a ring.

use crate::common::{freq, power_spectrum};
use marbling_noise::{Gabor, GaborKind, GaborParams};
use std::f64::consts::PI;

pub(crate) fn params(
    kind: GaborKind,
    frequency: f32,
    orientation: f32,
    bandwidth: f32,
) -> GaborParams {
    GaborParams {
        kind,
        frequency,
        orientation,
        bandwidth,
        impulses: 64.0,
        seed: 17,
        period: None,
        orientation_drive: None,
        frequency_drive: None,
        profile: None,
    }
}

/// Mean and variance of the raw (un-normalised) sum over 512² samples spaced 3 px.
fn raw_moments(g: &Gabor) -> (f64, f64) {
    let (mut s, mut s2) = (0.0_f64, 0.0_f64);
    let n = 512;
    for j in 0..n {
        for i in 0..n {
            let v = f64::from(g.eval_raw(i as f32 * 3.0 + 0.5, j as f32 * 3.0 + 0.5));
            s += v;
            s2 += v * v;
        }
    }
    let c = f64::from(n * n);
    let mean = s / c;
    (mean, s2 / c - mean * mean)
}

#[test]
fn mean_zero_and_variance_matches_formula() {
    let cases = [
        (GaborKind::Anisotropic, 0.1, 0.08),
        // F₀ small against a: the oscillating term e^(−2πF₀²/a²) ≈ 0.67 matters.
        (GaborKind::Anisotropic, 0.02, 0.08),
        (GaborKind::Isotropic, 0.1, 0.08),
        (GaborKind::Isotropic, 0.02, 0.08),
        (GaborKind::RandomPhase, 0.02, 0.08),
        (GaborKind::RandomPhase, 0.1, 0.08),
    ];
    let mut report = String::new();
    let mut ok = true;
    for (kind, f, a) in cases {
        let p = params(kind, f, 0.6, a);
        let formula = f64::from(p.variance());
        let g = Gabor::new(p);
        let (mean, var) = raw_moments(&g);
        let std = formula.sqrt();
        let rel = var / formula - 1.0;
        report.push_str(&format!(
            "{kind:?} F0={f} a={a}: mean {:.4}σ, variance/formula − 1 = {rel:+.4}\n",
            mean / std
        ));
        ok &= (mean / std).abs() < 0.05 && rel.abs() < 0.05;
    }
    println!("{report}");
    assert!(ok, "{report}");
}

pub(crate) fn tiled_image(p: GaborParams, n: usize) -> Vec<f32> {
    let g = Gabor::new(GaborParams {
        period: Some(n as u32),
        ..p
    });
    let mut img = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            img.push(g.eval(i as f32 + 0.5, j as f32 + 0.5));
        }
    }
    img
}

/// Power-weighted mean frequency vector over the half plane containing the strongest
/// bin (the spectrum of a real image is symmetric).
pub(crate) fn spectral_peak(power: &[f64], n: usize) -> (f64, f64) {
    let (mut best, mut arg) = (0.0, 0);
    for (k, &p) in power.iter().enumerate() {
        if p > best {
            best = p;
            arg = k;
        }
    }
    let (dx, dy) = (freq(arg % n, n), freq(arg / n, n));
    let (mut sx, mut sy, mut sw) = (0.0, 0.0, 0.0);
    for (k, &p) in power.iter().enumerate() {
        let (fx, fy) = (freq(k % n, n), freq(k / n, n));
        let s = if fx * dx + fy * dy >= 0.0 { 1.0 } else { -1.0 };
        sx += s * fx * p;
        sy += s * fy * p;
        sw += p;
    }
    (sx / sw, sy / sw)
}

#[test]
fn anisotropic_spectrum_peak_at_f0_and_orientation() {
    let n = 512;
    for (kind, f0, w0) in [
        (GaborKind::Anisotropic, 0.0625_f32, 0.5_f32),
        (GaborKind::Anisotropic, 0.1, 2.0),
        (GaborKind::RandomPhase, 0.08, -0.9),
    ] {
        let img = tiled_image(params(kind, f0, w0, 0.02), n);
        let (fx, fy) = spectral_peak(&power_spectrum(&img, n), n);
        let radius = fx.hypot(fy);
        // Orientation of a frequency vector is defined modulo π.
        let mut dw = (fy.atan2(fx) - f64::from(w0)).rem_euclid(PI);
        if dw > PI / 2.0 {
            dw -= PI;
        }
        println!(
            "{kind:?} F0={f0} ω0={w0}: peak |f| = {radius:.5} ({:+.2} %), angle error {:.3}°",
            100.0 * (radius / f64::from(f0) - 1.0),
            dw.to_degrees()
        );
        assert!((radius / f64::from(f0) - 1.0).abs() < 0.05, "{radius}");
        assert!(dw.to_degrees().abs() < 3.0, "{}", dw.to_degrees());
    }
}

#[test]
fn isotropic_spectrum_is_a_ring() {
    let n = 512;
    let f0 = 0.08;
    let img = tiled_image(params(GaborKind::Isotropic, f0, 0.0, 0.02), n);
    let power = power_spectrum(&img, n);
    // Radial profile peak.
    let bins = n / 2;
    let mut radial = vec![0.0; bins];
    let mut sectors = [0.0_f64; 6];
    for (k, &p) in power.iter().enumerate() {
        let (fx, fy) = (freq(k % n, n), freq(k / n, n));
        let r = fx.hypot(fy);
        let b = (r * n as f64).round() as usize;
        if b < bins {
            radial[b] += p;
        }
        if (r / f64::from(f0) - 1.0).abs() < 0.3 {
            let a = fy.atan2(fx).rem_euclid(PI);
            sectors[((a / PI * 6.0) as usize).min(5)] += p;
        }
    }
    // Mean power per ring, weighting out the 2πr growth of the bins.
    let ring: Vec<f64> = radial
        .iter()
        .enumerate()
        .map(|(b, &p)| p / (b.max(1) as f64))
        .collect();
    let peak = ring
        .iter()
        .enumerate()
        .skip(1)
        .fold(
            (0, 0.0),
            |acc, (b, &p)| if p > acc.1 { (b, p) } else { acc },
        )
        .0;
    let peak_f = peak as f64 / n as f64;
    let mean = sectors.iter().sum::<f64>() / 6.0;
    let spread = sectors
        .iter()
        .map(|s| (s / mean - 1.0).abs())
        .fold(0.0, f64::max);
    println!("isotropic: ring peak {peak_f:.4} (F0 {f0}), max sector deviation {spread:.3}");
    assert!((peak_f / f64::from(f0) - 1.0).abs() < 0.06, "{peak_f}");
    assert!(spread < 0.25, "sectors {sectors:?}");
    // Little power at the centre and far outside the ring.
    assert!(ring[2] < 0.05 * ring[peak] && ring[2 * peak] < 0.05 * ring[peak]);
}
