//! Phasor noise (Tricard et al. 2019): the spectrum of an anisotropic phasor noise peaks at
//! F₀ (5 %) and ω₀ (3°) like the Gabor noise of the same kernels; its amplitude is constant
//! (a sine profile spends half its points beyond 1/√2 of the peak, where the Gaussian Gabor
//! noise spends 32 %); a square profile takes only ±1, half each, with the square wave's
//! third harmonic at 3F₀ (ideal 1/9 of the fundamental's power); every profile has zero
//! mean and unit variance over an image (10 %).

use crate::common::{freq, power_spectrum};
use crate::gabor::{params, spectral_peak, tiled_image};
use marbling_noise::{Gabor, GaborKind, GaborParams, PhasorProfile};
use std::f64::consts::PI;

const N: usize = 256;

fn phasor(kind: GaborKind, f0: f32, w0: f32, profile: PhasorProfile) -> GaborParams {
    GaborParams {
        profile: Some(profile),
        ..params(kind, f0, w0, 0.02)
    }
}

/// Share of the power within 15 % of frequency `f` (cycles per pixel), over all angles.
fn ring_power(power: &[f64], f: f64) -> f64 {
    let mut ring = 0.0;
    for (k, &p) in power.iter().enumerate() {
        let r = freq(k % N, N).hypot(freq(k / N, N));
        if (r / f - 1.0).abs() < 0.15 {
            ring += p;
        }
    }
    ring / power.iter().sum::<f64>()
}

#[test]
fn anisotropic_phasor_spectrum_peaks_at_f0_and_orientation() {
    for (profile, f0, w0) in [
        (PhasorProfile::Sine, 0.0625_f32, 0.5_f32),
        (PhasorProfile::Triangle, 0.08, -0.9),
    ] {
        let img = tiled_image(phasor(GaborKind::Anisotropic, f0, w0, profile), N);
        let (fx, fy) = spectral_peak(&power_spectrum(&img, N), N);
        let radius = fx.hypot(fy);
        let mut dw = (fy.atan2(fx) - f64::from(w0)).rem_euclid(PI);
        if dw > PI / 2.0 {
            dw -= PI;
        }
        println!(
            "{profile:?} F0={f0}: peak |f| {radius:.5} ({:+.2} %), angle error {:.2}°",
            100.0 * (radius / f64::from(f0) - 1.0),
            dw.to_degrees()
        );
        assert!((radius / f64::from(f0) - 1.0).abs() < 0.05, "{radius}");
        assert!(dw.to_degrees().abs() < 3.0, "{}", dw.to_degrees());
    }
}

#[test]
fn phasor_amplitude_is_constant_where_gabor_fades() {
    let share_beyond = |img: &[f32], level: f32| {
        img.iter().filter(|v| v.abs() > level).count() as f64 / img.len() as f64
    };
    let base = params(GaborKind::Anisotropic, 0.0625, 0.5, 0.02);
    let gabor = tiled_image(base.clone(), N);
    let sine = tiled_image(
        phasor(GaborKind::Anisotropic, 0.0625, 0.5, PhasorProfile::Sine),
        N,
    );
    let (g, s) = (share_beyond(&gabor, 1.0), share_beyond(&sine, 1.0));
    println!("share of |n| > 1: Gabor {g:.3}, phasor sine {s:.3}");
    assert!((0.45..0.55).contains(&s), "phasor {s}");
    assert!((0.25..0.38).contains(&g), "gabor {g}");
    assert!(
        sine.iter()
            .all(|v| v.abs() <= std::f32::consts::SQRT_2 + 1e-5)
    );
}

#[test]
fn square_profile_is_two_levels_with_a_third_harmonic() {
    let f0 = 0.04;
    let img = tiled_image(
        phasor(GaborKind::Anisotropic, f0, 0.3, PhasorProfile::Square),
        N,
    );
    assert!(img.iter().all(|v| *v == 1.0 || *v == -1.0));
    let up = img.iter().filter(|v| **v > 0.0).count() as f64 / img.len() as f64;
    let power = power_spectrum(&img, N);
    let (first, third) = (
        ring_power(&power, f0.into()),
        ring_power(&power, 3.0 * f64::from(f0)),
    );
    println!(
        "square: {up:.3} at +1; third/first harmonic power {:.3}",
        third / first
    );
    assert!((0.45..0.55).contains(&up), "{up}");
    assert!((0.04..0.2).contains(&(third / first)), "{}", third / first);
    // A sine profile has (almost) no third harmonic: the test can tell them apart.
    let sine = tiled_image(
        phasor(GaborKind::Anisotropic, f0, 0.3, PhasorProfile::Sine),
        N,
    );
    let power = power_spectrum(&sine, N);
    let ratio = ring_power(&power, 3.0 * f64::from(f0)) / ring_power(&power, f0.into());
    assert!(ratio < 0.02, "sine third/first {ratio}");
}

#[test]
fn every_profile_has_zero_mean_and_unit_variance() {
    for profile in PhasorProfile::ALL {
        let g = Gabor::new(phasor(GaborKind::Isotropic, 0.05, 0.0, profile));
        let values: Vec<f64> = (0..N * N)
            .map(|k| f64::from(g.eval((k % N) as f32 * 1.7, (k / N) as f32 * 1.7)))
            .collect();
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / values.len() as f64;
        println!("{profile:?}: mean {mean:+.3}, variance {var:.3}");
        assert!(
            mean.abs() < 0.1 && (var - 1.0).abs() < 0.1,
            "{profile:?} {mean} {var}"
        );
    }
}
