//! The accepted ranges and names of the noise spec's parameters: one source for the
//! spec parser's checks and for the sliders and menus that set them (the playground's
//! Noise panel). Frequencies are cycles per output pixel, lengths output pixels.

use crate::{CurlComponent, GaborKind, MAX_OCTAVES, Metric, PhasorProfile, WorleyFeature};
use std::ops::RangeInclusive;

/// A parameter's accepted values: `lo < x ≤ hi` when `open_below`, else `lo ≤ x ≤ hi`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// Lower bound (excluded when `open_below`).
    pub lo: f64,
    /// Upper bound (included).
    pub hi: f64,
    /// True when `lo` itself is refused.
    pub open_below: bool,
}

impl Range {
    /// `lo < x ≤ hi`.
    pub const fn above(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_below: true,
        }
    }

    /// `lo ≤ x ≤ hi`.
    pub const fn within(lo: f64, hi: f64) -> Self {
        Self {
            lo,
            hi,
            open_below: false,
        }
    }

    /// True when `x` is accepted.
    pub fn contains(self, x: f64) -> bool {
        (if self.open_below {
            x > self.lo
        } else {
            x >= self.lo
        }) && x <= self.hi
    }

    /// The range for a slider: a range open below starts at `floor` (a small accepted
    /// value) instead of at its excluded bound.
    pub fn slider(self, floor: f64) -> RangeInclusive<f64> {
        let lo = if self.open_below {
            floor.max(self.lo)
        } else {
            self.lo
        };
        lo..=self.hi
    }

    /// `x` brought into the range (an open bound is replaced by `floor`).
    pub fn clamp(self, x: f64, floor: f64) -> f64 {
        let r = self.slider(floor);
        x.clamp(*r.start(), *r.end())
    }
}

/// fBm (Perlin, value, curl potential) and Worley frequency.
pub const FREQUENCY: Range = Range::above(0.0, 1.0);
/// Gabor frequency F0 (at most the Nyquist rate).
pub const GABOR_FREQUENCY: Range = Range::above(0.0, 0.5);
/// fBm octaves (whole numbers).
pub const OCTAVES: Range = Range::within(1.0, MAX_OCTAVES as f64);
/// fBm frequency factor between octaves.
pub const LACUNARITY: Range = Range::within(1.0, 8.0);
/// fBm amplitude factor between octaves.
pub const PERSISTENCE: Range = Range::within(0.0, 1.0);
/// Gabor kernel bandwidth a (its radius √(−ln 0.05/π)/a stays ≤ 512 px).
pub const BANDWIDTH: Range = Range::within(0.002, 1.0);
/// Gabor mean impulses per kernel area.
pub const IMPULSES: Range = Range::within(1.0, 256.0);
/// Paper and canvas fiber length.
pub const FIBER_LENGTH: Range = Range::within(1.0, 256.0);
/// Paper and canvas fiber width.
pub const FIBER_WIDTH: Range = Range::within(1.0, 32.0);
/// Fibers per 100 px².
pub const FIBER_DENSITY: Range = Range::above(0.0, 4.0);
/// Width of a threshold transfer's smoothstep, in noise standard deviations.
pub const THRESHOLD_WIDTH: Range = Range::above(0.0, 100.0);

/// Gabor `kind` names.
pub const GABOR_KINDS: [(&str, GaborKind); 3] = [
    ("anisotropic", GaborKind::Anisotropic),
    ("isotropic", GaborKind::Isotropic),
    ("random-phase", GaborKind::RandomPhase),
];
/// Relief of a normal map: the height of intensity 1 above 0, output pixels.
pub const RELIEF: Range = Range::above(0.0, 1024.0);
/// The relief an editor starts from, output pixels.
pub const DEFAULT_RELIEF: f64 = 24.0;

/// Phasor `profile` names.
pub const PHASOR_PROFILES: [(&str, PhasorProfile); 4] = [
    ("sine", PhasorProfile::Sine),
    ("square", PhasorProfile::Square),
    ("saw", PhasorProfile::Saw),
    ("triangle", PhasorProfile::Triangle),
];
/// Worley `feature` names.
pub const WORLEY_FEATURES: [(&str, WorleyFeature); 3] = [
    ("f1", WorleyFeature::F1),
    ("f2", WorleyFeature::F2),
    ("f2-f1", WorleyFeature::F2MinusF1),
];
/// Worley `metric` names.
pub const WORLEY_METRICS: [(&str, Metric); 3] = [
    ("euclidean", Metric::Euclidean),
    ("manhattan", Metric::Manhattan),
    ("chebyshev", Metric::Chebyshev),
];
/// Curl `component` names.
pub const CURL_COMPONENTS: [(&str, CurlComponent); 3] = [
    ("magnitude", CurlComponent::Magnitude),
    ("x", CurlComponent::X),
    ("y", CurlComponent::Y),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn open_and_closed_bounds() {
        assert!(!FREQUENCY.contains(0.0) && FREQUENCY.contains(1e-9) && FREQUENCY.contains(1.0));
        assert!(!FREQUENCY.contains(1.0001));
        assert!(PERSISTENCE.contains(0.0) && PERSISTENCE.contains(1.0));
        assert_eq!(FREQUENCY.slider(0.001), 0.001..=1.0);
        assert_eq!(LACUNARITY.slider(0.001), 1.0..=8.0);
        assert_eq!(FIBER_DENSITY.clamp(0.0, 1e-4), 1e-4);
        assert_eq!(BANDWIDTH.clamp(5.0, 0.0), 1.0);
    }
}
