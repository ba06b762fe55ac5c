//! Phasor noise (Tricard, Efremov, Zanni, Neyret, Martínez & Lefebvre 2019, "Procedural
//! Phasor Noise"): the same sparse Gabor kernels summed as complex numbers,
//! G(x) = Σᵢ wᵢ·e^(−πa²|x − xᵢ|²)·e^(i(2πFᵢ dᵢ·(x − xᵢ) + φᵢ)), whose phase
//! φ(x) = arg G(x) is passed through a periodic profile. Unlike Gabor noise, whose
//! contrast comes and goes with the local sum, every point of a phasor noise oscillates
//! at full amplitude: stripes, dots and bricks of constant contrast.
//!
//! Profiles of φ ∈ (−π, π], scaled to unit variance for a uniformly distributed phase
//! (the field's convention, see [`crate::Field`]): sine √2·sin φ; square sign(sin φ)
//! (φ ∈ [0, π) → +1); saw √3·φ/π; triangle √3·(1 − 2|φ|/π). Keep in sync with
//! `shaders/gabor.wgsl` (`phasor_profile`).

use std::f32::consts::{FRAC_1_PI, SQRT_2};

/// √3, the saw's and triangle's unit-variance scale.
const SQRT_3: f32 = 1.732_050_8;

/// The periodic profile a phasor noise's phase passes through.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PhasorProfile {
    /// √2·sin φ: smooth stripes.
    Sine,
    /// sign(sin φ): hard-edged stripes, half ink, half paper.
    Square,
    /// √3·φ/π: a ramp across each stripe.
    Saw,
    /// √3·(1 − 2|φ|/π): ridges.
    Triangle,
}

impl PhasorProfile {
    /// Every profile, in the order the WGSL numbers them from 1 ([`PhasorProfile::index`]).
    pub const ALL: [PhasorProfile; 4] = [
        PhasorProfile::Sine,
        PhasorProfile::Square,
        PhasorProfile::Saw,
        PhasorProfile::Triangle,
    ];

    /// The WGSL's code: 1 sine, 2 square, 3 saw, 4 triangle (0 is plain Gabor noise).
    #[must_use]
    pub fn index(self) -> u32 {
        self as u32 + 1
    }

    /// The profile at phase `phi` (radians in (−π, π], as `atan2` gives), at zero mean and
    /// unit variance over a uniform phase.
    #[inline]
    #[must_use]
    pub fn apply(self, phi: f32) -> f32 {
        match self {
            PhasorProfile::Sine => SQRT_2 * phi.sin(),
            PhasorProfile::Square => {
                if phi >= 0.0 {
                    1.0
                } else {
                    -1.0
                }
            }
            PhasorProfile::Saw => SQRT_3 * phi * FRAC_1_PI,
            PhasorProfile::Triangle => SQRT_3 * (1.0 - 2.0 * phi.abs() * FRAC_1_PI),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f32::consts::PI;

    /// Mean and variance of each profile over a fine uniform grid of phases.
    #[test]
    fn profiles_have_zero_mean_and_unit_variance() {
        let n = 100_000;
        for p in PhasorProfile::ALL {
            let values: Vec<f64> = (0..n)
                .map(|i| {
                    let phi = -PI + (i as f32 + 0.5) * (2.0 * PI / n as f32);
                    f64::from(p.apply(phi))
                })
                .collect();
            let mean = values.iter().sum::<f64>() / n as f64;
            let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n as f64;
            assert!(mean.abs() < 1e-3, "{p:?} mean {mean}");
            assert!((var - 1.0).abs() < 1e-3, "{p:?} variance {var}");
        }
    }

    #[test]
    fn profiles_shapes() {
        assert_eq!(PhasorProfile::Square.apply(0.3), 1.0);
        assert_eq!(PhasorProfile::Square.apply(-0.3), -1.0);
        assert!((PhasorProfile::Triangle.apply(0.0) - SQRT_3).abs() < 1e-6);
        assert!((PhasorProfile::Triangle.apply(PI) + SQRT_3).abs() < 1e-5);
        assert!((PhasorProfile::Saw.apply(PI) - SQRT_3).abs() < 1e-5);
        assert!((PhasorProfile::Sine.apply(PI / 2.0) - SQRT_2).abs() < 1e-6);
        let codes: Vec<u32> = PhasorProfile::ALL.iter().map(|p| p.index()).collect();
        assert_eq!(codes, [1, 2, 3, 4]);
    }
}
