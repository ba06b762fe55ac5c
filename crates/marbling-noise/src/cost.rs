//! What one GPU sample of a noise costs, in the unit renderers size their tiles by: one
//! simple op walked (a drop's, `marbling_core::Op::walk_cost`).
//!
//! Measured where a noise's cost hurts most, in the browser on SwiftShader (WebGL2,
//! headless Chromium, `nproc` = 2; 2026-12-05): the app's exact frame and preview cache
//! of a 640×400 sheet at 948×593 px (4.5·10⁶ samples together) drawn in one tile each,
//! against designs of 100 and 400 drops (6.5 s and 13.3 s: 22.5 ms a drop, 4.3 s for the
//! samples themselves). Noise backgrounds on the same sheet, each shader holding only
//! its own noise type (`wgsl::NoiseKinds`; a first one of a type includes its compile):
//! value fBm of 1 octave 5.0 s and of 5 octaves 5.9 s, Worley 5.0 s, curl of 5 octaves
//! 9.6 s (after a 9.2 s compile, since cut), paper fibres 31.8 s, Gabor of 16 impulses
//! 46.0 s and of 64 impulses 133.8 s.
//! On other GPUs the frame budget steers from the measured frame times.

use crate::spec::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use crate::spec::{DriveSource, NoiseSpec, Source};

/// Any noise: the noise shader's fixed part (the uniform read, the transfer and
/// palette), in simple ops.
pub const NOISE_BASE: u64 = 30;
/// Each fBm octave (Perlin or value).
pub const OCTAVE: u64 = 8;
/// Each octave of a curl potential (its gradient).
pub const CURL_OCTAVE: u64 = 40;
/// Gabor's kernel loop beyond the fixed part, before its impulses.
pub const GABOR: u64 = 530;
/// Each mean Gabor impulse per kernel area.
pub const GABOR_IMPULSE: u64 = 80;
/// Paper or canvas fibres beyond the fixed part.
pub const FIBERS: u64 = 1200;

impl NoiseSpec {
    /// What one GPU sample of this noise (its source, drives, layers and masks) costs,
    /// in simple ops walked (see the module's measurements).
    pub fn sample_cost(&self) -> u64 {
        let layers: u64 = self
            .layers
            .iter()
            .map(|l| l.noise.source_cost() + l.mask.as_ref().map_or(0, NoiseSpec::source_cost))
            .sum();
        NOISE_BASE + self.source_cost() + layers
    }

    /// The cost of the source beyond [`NOISE_BASE`].
    fn source_cost(&self) -> u64 {
        self.source.cost()
    }
}

impl Source {
    fn cost(&self) -> u64 {
        match self {
            Source::Gabor(GaborSpec {
                impulses,
                orientation_field,
                frequency_field,
                ..
            }) => {
                let drive = |d: &Option<crate::spec::DriveSpec>| match d.as_ref().map(|d| &d.by) {
                    Some(DriveSource::Noise(n)) => n.source_cost(),
                    _ => 0,
                };
                GABOR
                    + GABOR_IMPULSE * impulses.max(1.0).ceil() as u64
                    + drive(orientation_field)
                    + drive(frequency_field)
            }
            Source::Fbm(p) => OCTAVE * u64::from(p.octaves),
            Source::Curl(CurlSpec { potential, .. }) => CURL_OCTAVE * u64::from(potential.octaves),
            Source::Fibers(_) => FIBERS,
            Source::Worley(WorleySpec { .. }) | Source::White(WhiteSpec { .. }) => 0,
            Source::Product(inputs) => inputs.iter().map(NoiseSpec::source_cost).sum(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cost(json: &str) -> u64 {
        NoiseSpec::from_json(json).expect("spec").sample_cost()
    }

    #[test]
    fn costs_follow_the_measured_shape() {
        let value1 = cost(r#"{"type":"value","frequency":0.01,"octaves":1,"seed":1}"#);
        let value5 = cost(r#"{"type":"value","frequency":0.01,"octaves":5,"seed":1}"#);
        let worley = cost(r#"{"type":"worley","frequency":0.02,"seed":1}"#);
        let curl = cost(
            r#"{"type":"curl","frequency":0.02,"octaves":5,"seed":1,"component":"magnitude"}"#,
        );
        let gabor16 = cost(
            r#"{"type":"gabor","kind":"anisotropic","frequency":0.02,"orientation":0.6,"bandwidth":0.04,"impulses":16,"seed":1}"#,
        );
        let gabor64 = cost(
            r#"{"type":"gabor","kind":"anisotropic","frequency":0.02,"orientation":0.6,"bandwidth":0.04,"impulses":64,"seed":1}"#,
        );
        // Measured (module doc), in drops: value 1 octave ≈ 35, 5 ≈ 75, Worley ≈ 35,
        // curl ≈ 240, Gabor 16 ≈ 1860, 64 ≈ 5760; each within a factor of 1.5.
        for (c, measured) in [
            (value1, 35.0),
            (value5, 75.0),
            (worley, 35.0),
            (curl, 240.0),
            (gabor16, 1860.0),
            (gabor64, 5760.0),
        ] {
            let r = c as f64 / measured;
            assert!((1.0 / 1.5..1.5).contains(&r), "{c} vs {measured}");
        }
        assert!(value1 < value5 && gabor16 < gabor64);
    }
}
