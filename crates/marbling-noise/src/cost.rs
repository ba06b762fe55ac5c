//! What one GPU sample of a noise costs, in the unit renderers size their tiles by: one
//! simple op walked (a drop's, `marbling_core::Op::walk_cost`).
//!
//! Measured with `marbling render --backend gpu --scale 1.5` (960×600 px, RGSS: 2.3·10⁶
//! samples) on lavapipe, 2026-12-05, each noise as the background of an empty 640×400
//! sheet, against a 100-drop design (0.86 s over the empty sheet: 8.6 ms a drop): value
//! fBm of 1 octave 2.7 s and of 6 octaves 3.0 s, Worley 2.4 s, curl of 5 octaves 3.2 s,
//! paper fibres 5.0 s, Gabor of 16 impulses 11.4 s and of 64 about 32 s. Most of a
//! noise's cost is the noise shader itself (its one `sample_noise` call and every branch
//! around it), whatever the noise; Gabor then adds its kernels. A tile sized by these
//! keeps its frame within about a factor of two of the aim on other GPUs too: the frame
//! budget steers the rest from the measured frame times.

use crate::spec::{DriveSource, NoiseSpec, Source};

/// Any noise: the noise shader's fixed part, in simple ops.
pub const NOISE_BASE: u64 = 300;
/// Each fBm octave (Perlin or value).
pub const OCTAVE: u64 = 8;
/// Each octave of a curl potential (its gradient).
pub const CURL_OCTAVE: u64 = 15;
/// Each mean Gabor impulse per kernel area.
pub const GABOR_IMPULSE: u64 = 60;
/// Paper or canvas fibres beyond the fixed part.
pub const FIBERS: u64 = 280;

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
            Source::Gabor {
                impulses,
                orientation_field,
                frequency_field,
                ..
            } => {
                let drive = |d: &Option<crate::spec::DriveSpec>| match d.as_ref().map(|d| &d.by) {
                    Some(DriveSource::Noise(n)) => n.source_cost(),
                    _ => 0,
                };
                GABOR_IMPULSE * impulses.max(1.0).ceil() as u64
                    + drive(orientation_field)
                    + drive(frequency_field)
            }
            Source::Fbm(p) => OCTAVE * u64::from(p.octaves),
            Source::Curl { potential, .. } => CURL_OCTAVE * u64::from(potential.octaves),
            Source::Fibers(_) => FIBERS,
            Source::Worley { .. } | Source::White { .. } => 0,
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
        let value6 = cost(r#"{"type":"value","frequency":0.01,"octaves":6,"seed":1}"#);
        let worley = cost(r#"{"type":"worley","frequency":0.02,"seed":1}"#);
        let gabor16 = cost(
            r#"{"type":"gabor","kind":"anisotropic","frequency":0.02,"orientation":0.6,"bandwidth":0.04,"impulses":16,"seed":1}"#,
        );
        let gabor64 = cost(
            r#"{"type":"gabor","kind":"anisotropic","frequency":0.02,"orientation":0.6,"bandwidth":0.04,"impulses":64,"seed":1}"#,
        );
        // Measured (module doc), in drops: value 1 octave ≈ 310, 6 ≈ 350, Worley ≈ 280,
        // Gabor 16 ≈ 1300, 64 ≈ 3700; each within a factor of 1.5.
        for (c, measured) in [
            (value1, 310.0),
            (value6, 350.0),
            (worley, 280.0),
            (gabor16, 1300.0),
            (gabor64, 3700.0),
        ] {
            let r = c as f64 / measured;
            assert!((1.0 / 1.5..1.5).contains(&r), "{c} vs {measured}");
        }
        assert!(value1 < value6 && gabor16 < gabor64);
    }
}
