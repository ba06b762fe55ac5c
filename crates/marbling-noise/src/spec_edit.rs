//! Changing a spec in code, as an editor does: the starting values of each noise type,
//! the type's name, the seed, and the spec rescaled for a zoom (Khlebnikov et al. (2013)'s
//! zoom-independent rule: every frequency × a power of two, or for a data-driven Gabor
//! the paper's continuous frequency control), and Khlebnikov et al. (2013)'s weather example.

use crate::data::DataRef;
use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams};
use crate::gabor::GaborKind;
use crate::phasor::PhasorProfile;
use crate::ramp::ColorRamp;
use crate::ranges::{self, Range};
use crate::spec::{
    Blend, BlendBase, DecayValue, DriveSource, DriveSpec, NoiseSpec, Source, Transfer,
};
use crate::spec::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use crate::{CurlComponent, Metric, WorleyFeature};

/// The smallest value an editor gives a parameter whose range is open below.
pub const EDIT_FLOOR: f64 = 0.001;

impl Source {
    /// The spec's `type` of this source.
    #[must_use]
    pub fn type_name(&self) -> &'static str {
        match self {
            Source::Gabor(GaborSpec {
                profile: Some(_), ..
            }) => "phasor",
            Source::Gabor(GaborSpec { .. }) => "gabor",
            Source::Fbm(p) if p.basis == Basis::Value => "value",
            Source::Fbm(_) => "perlin",
            Source::Worley(WorleySpec { .. }) => "worley",
            Source::White(WhiteSpec { .. }) => "white",
            Source::Curl(CurlSpec { .. }) => "curl",
            Source::Fibers(p) if matches!(p.layout, FiberLayout::Canvas { .. }) => "canvas",
            Source::Fibers(_) => "paper",
            Source::Product(_) => "product",
        }
    }

    /// A noise of type `type_name` (one of [`crate::NOISE_TYPES`] but `product`) with
    /// the values an editor starts from: features about 50 px wide, seed `seed`.
    #[must_use]
    pub fn starting(type_name: &str, seed: u32) -> Option<Source> {
        let fbm = |basis| FbmParams {
            basis,
            frequency: 0.02,
            octaves: 5,
            lacunarity: 2.0,
            persistence: 0.5,
            seed,
            period: None,
        };
        let fibers = |layout| FiberParams {
            layout,
            length: 20.0,
            width: 1.5,
            density: 0.3,
            seed,
            period: None,
            impurities: None,
        };
        Some(match type_name {
            "gabor" => Source::Gabor(GaborSpec {
                kind: GaborKind::Anisotropic,
                frequency: 0.02,
                orientation: 0.6,
                bandwidth: 0.04,
                impulses: 64.0,
                seed,
                orientation_field: None,
                frequency_field: None,
                profile: None,
            }),
            "phasor" => Source::Gabor(GaborSpec {
                kind: GaborKind::Anisotropic,
                frequency: 0.02,
                orientation: 0.6,
                bandwidth: 0.01,
                impulses: 32.0,
                seed,
                orientation_field: None,
                frequency_field: None,
                profile: Some(PhasorProfile::Sine),
            }),
            "perlin" => Source::Fbm(fbm(Basis::Perlin)),
            "value" => Source::Fbm(fbm(Basis::Value)),
            "worley" => Source::Worley(WorleySpec {
                frequency: 0.02,
                feature: WorleyFeature::F1,
                metric: Metric::Euclidean,
                seed,
            }),
            "white" => Source::White(WhiteSpec { seed }),
            "curl" => Source::Curl(CurlSpec {
                potential: fbm(Basis::Perlin),
                component: CurlComponent::Magnitude,
            }),
            "paper" => Source::Fibers(fibers(FiberLayout::Paper)),
            "canvas" => Source::Fibers(fibers(FiberLayout::Canvas {
                weights: [1.0, 1.0],
            })),
            _ => return None,
        })
    }

    /// The seed (a product's first input's).
    #[must_use]
    pub fn seed(&self) -> u32 {
        match self {
            Source::Gabor(GaborSpec { seed, .. })
            | Source::Worley(WorleySpec { seed, .. })
            | Source::White(WhiteSpec { seed }) => *seed,
            Source::Fbm(p) | Source::Curl(CurlSpec { potential: p, .. }) => p.seed,
            Source::Fibers(p) => p.seed,
            Source::Product(inputs) => inputs.first().map_or(0, |s| s.source.seed()),
        }
    }

    /// The seed to change (`None` for a product, whose inputs have their own).
    pub fn seed_mut(&mut self) -> Option<&mut u32> {
        match self {
            Source::Gabor(GaborSpec { seed, .. })
            | Source::Worley(WorleySpec { seed, .. })
            | Source::White(WhiteSpec { seed }) => Some(seed),
            Source::Fbm(p) | Source::Curl(CurlSpec { potential: p, .. }) => Some(&mut p.seed),
            Source::Fibers(p) => Some(&mut p.seed),
            Source::Product(_) => None,
        }
    }

    /// The frequency of the visible features, cycles per pixel: the base frequency, one
    /// over the fiber length for fibers; `None` for white noise and products.
    #[must_use]
    pub fn feature_frequency(&self) -> Option<f64> {
        match self {
            Source::Gabor(GaborSpec { frequency, .. })
            | Source::Worley(WorleySpec { frequency, .. }) => Some(f64::from(*frequency)),
            Source::Fbm(p) | Source::Curl(CurlSpec { potential: p, .. }) => {
                Some(f64::from(p.frequency))
            }
            Source::Fibers(p) => Some(1.0 / f64::from(p.length)),
            Source::White(WhiteSpec { .. }) | Source::Product(_) => None,
        }
    }
}

/// Khlebnikov et al. (2013)'s screen-space feature sizes s and S, pixels: the range the human visual
/// system reads best.
pub const FEATURE_PX: [f32; 2] = [4.0, 40.0];

/// √(−ln t/π) for the Gabor truncation t: a = this / G makes a kernel span G pixels.
fn kernel_span() -> f32 {
    (-crate::GABOR_TRUNCATION.ln() / std::f32::consts::PI).sqrt()
}

impl Source {
    /// The source with data drives removed (a noise drive is kept).
    #[must_use]
    pub fn without_data(&self) -> Source {
        let mut s = self.clone();
        if let Source::Gabor(GaborSpec {
            orientation_field,
            frequency_field,
            ..
        }) = &mut s
        {
            for d in [orientation_field, frequency_field] {
                if d.as_ref()
                    .is_some_and(|d| matches!(d.by, DriveSource::Data(_)))
                {
                    *d = None;
                }
            }
        }
        s
    }
}

impl NoiseSpec {
    /// Whether a data channel drives the Gabor frequency (Khlebnikov et al. (2013)'s first attribute).
    #[must_use]
    pub fn has_data_frequency(&self) -> bool {
        matches!(
            &self.source,
            Source::Gabor(GaborSpec {
                frequency_field: Some(DriveSpec {
                    by: DriveSource::Data(_),
                    ..
                }),
                ..
            })
        )
    }

    /// Khlebnikov et al. (2013)'s frequency control (eq. 3–5) with F₀ = `f0` (= Z/S at zoom Z): the
    /// frequency drive spans log₂(S/s) octaves, so features run from S/Z (v = 0) down to
    /// s/Z (v = 1) design pixels, and the bandwidth makes a kernel span one
    /// period at v = 0. Specs without a data frequency drive are returned unchanged.
    #[must_use]
    pub fn zoom_independent(&self, f0: f32) -> NoiseSpec {
        let mut s = self.clone();
        if !self.has_data_frequency() {
            return s;
        }
        if let Source::Gabor(GaborSpec {
            frequency,
            bandwidth,
            frequency_field: Some(d),
            ..
        }) = &mut s.source
        {
            let [small, large] = FEATURE_PX;
            *frequency = ranges::GABOR_FREQUENCY.clamp(f64::from(f0), EDIT_FLOOR) as f32;
            *bandwidth =
                ranges::BANDWIDTH.clamp(f64::from(kernel_span() * *frequency), EDIT_FLOOR) as f32;
            d.amount = (large / small).log2();
        }
        s
    }

    /// Khlebnikov et al. (2013)'s weather figure with the built-in `weather` data: random-phase Gabor
    /// whose frequency and mean intensity (spline decay) show the temperature, whose
    /// orientation shows the wind direction, HSV-blended (β = 0.6) into `palette` at the
    /// pressure. Features span 40 to 4 pixels at zoom 1.
    #[must_use]
    pub fn weather_example(palette: ColorRamp, seed: u32) -> NoiseSpec {
        let data = |channel| DataRef::new(crate::WEATHER, channel);
        let drive = |channel, amount| {
            Some(DriveSpec {
                by: DriveSource::Data(data(channel)),
                amount,
            })
        };
        let gabor = NoiseSpec {
            transfer: Some(Transfer::SplineDecay(DecayValue::Data(data(1)))),
            blend: Some(Blend {
                beta: 0.6,
                base: BlendBase::Data {
                    ramp: palette,
                    value: data(3),
                },
            }),
            ..NoiseSpec::plain(Source::Gabor(GaborSpec {
                kind: GaborKind::RandomPhase,
                frequency: 0.025,
                orientation: 0.0,
                bandwidth: 0.025,
                impulses: 48.0,
                seed,
                orientation_field: drive(2, std::f32::consts::PI),
                frequency_field: drive(1, 1.0),
                profile: None,
            }))
        };
        gabor.zoom_independent(1.0 / FEATURE_PX[1])
    }

    /// A spec of `source` alone: no tiling, transfer, palette or blend.
    #[must_use]
    pub fn plain(source: Source) -> Self {
        Self {
            source,
            tile: crate::Tile::Off,
            transfer: None,
            layers: Vec::new(),
            palette: None,
            blend: None,
        }
    }

    /// The same noise seen `k` times smaller: every frequency × k, every length ÷ k,
    /// fiber density × k², each kept in its accepted range (ranges open below start at
    /// [`EDIT_FLOOR`]). Drives and product inputs are scaled too.
    #[must_use]
    pub fn scaled(&self, k: f64) -> Self {
        let mut s = self.clone();
        s.source = scale_source(&self.source, k);
        for l in &mut s.layers {
            l.noise = l.noise.scaled(k);
            if let Some(m) = &mut l.mask {
                *m = m.scaled(k);
            }
        }
        s
    }
}

fn scale(x: f32, k: f64, range: Range) -> f32 {
    range.clamp(f64::from(x) * k, EDIT_FLOOR) as f32
}

fn scale_source(source: &Source, k: f64) -> Source {
    let mut s = source.clone();
    match &mut s {
        Source::Gabor(GaborSpec {
            frequency,
            bandwidth,
            orientation_field,
            frequency_field,
            ..
        }) => {
            let f = scale(*frequency, k, ranges::GABOR_FREQUENCY);
            // The kernel shrinks with the period: the bandwidth follows the frequency.
            let k = f64::from(f) / f64::from(*frequency);
            *frequency = f;
            *bandwidth = scale(*bandwidth, k, ranges::BANDWIDTH);
            for d in [orientation_field, frequency_field].into_iter().flatten() {
                // Data stays where it is: it is stretched over the frame, not scaled.
                if let crate::DriveSource::Noise(n) = &mut d.by {
                    **n = n.scaled(k);
                }
            }
        }
        Source::Fbm(p) | Source::Curl(CurlSpec { potential: p, .. }) => {
            p.frequency = scale(p.frequency, k, ranges::FREQUENCY);
        }
        Source::Worley(WorleySpec { frequency, .. }) => {
            *frequency = scale(*frequency, k, ranges::FREQUENCY)
        }
        Source::White(WhiteSpec { .. }) => {}
        Source::Fibers(p) => {
            p.length = scale(p.length, 1.0 / k, ranges::FIBER_LENGTH);
            p.width = scale(p.width, 1.0 / k, ranges::FIBER_WIDTH);
            p.density = scale(p.density, k * k, ranges::FIBER_DENSITY);
        }
        Source::Product(inputs) => {
            for input in inputs {
                *input = input.scaled(k);
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::NOISE_TYPES;

    #[test]
    fn every_type_starts_valid_and_names_itself() {
        for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
            let source = Source::starting(t, 9).unwrap_or_else(|| panic!("{t}"));
            assert_eq!(source.type_name(), t);
            assert_eq!(source.seed(), 9);
            let spec = NoiseSpec::plain(source);
            let back = NoiseSpec::from_value(&spec.to_value()).expect("valid");
            assert_eq!(back, spec, "{t}");
        }
        assert!(Source::starting("product", 0).is_none());
    }

    #[test]
    fn scaling_moves_frequency_and_kernel_together_within_range() {
        let gabor = NoiseSpec::plain(Source::Gabor(GaborSpec {
            kind: GaborKind::Anisotropic,
            frequency: 0.05,
            orientation: 0.0,
            bandwidth: 0.04,
            impulses: 64.0,
            seed: 1,
            orientation_field: None,
            frequency_field: None,
            profile: None,
        }));
        let Source::Gabor(GaborSpec {
            frequency,
            bandwidth,
            ..
        }) = gabor.scaled(4.0).source
        else {
            panic!("still Gabor")
        };
        assert!((frequency - 0.2).abs() < 1e-6 && (bandwidth - 0.16).abs() < 1e-6);
        // 0.05 × 16 is past the Nyquist limit: clamped to 0.5, the kernel by the same 10×.
        let Source::Gabor(GaborSpec {
            frequency,
            bandwidth,
            ..
        }) = gabor.scaled(16.0).source
        else {
            panic!("still Gabor")
        };
        assert!((frequency - 0.5).abs() < 1e-6 && (bandwidth - 0.4).abs() < 1e-6);
        let paper = NoiseSpec::plain(Source::starting("paper", 0).expect("paper"));
        let Source::Fibers(p) = paper.scaled(2.0).source else {
            panic!("fibers")
        };
        assert!((p.length - 10.0).abs() < 1e-6 && (p.density - 1.2).abs() < 1e-6);
        for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
            for k in [1.0 / 64.0, 0.5, 8.0, 512.0] {
                let s = NoiseSpec::plain(Source::starting(t, 0).expect("type")).scaled(k);
                assert!(NoiseSpec::from_value(&s.to_value()).is_ok(), "{t} × {k}");
            }
        }
    }

    #[test]
    fn zoom_independent_keeps_features_between_4_and_40_screen_pixels() {
        let spec = NoiseSpec::weather_example(ColorRamp::named("viridis").expect("named"), 1);
        assert!(spec.has_data_frequency());
        for zoom in [0.5f32, 1.0, 3.0] {
            let s = spec.zoom_independent(zoom / FEATURE_PX[1]);
            let Source::Gabor(GaborSpec {
                frequency,
                bandwidth,
                frequency_field: Some(d),
                ..
            }) = &s.source
            else {
                panic!("Gabor")
            };
            // Screen period at v = 0 and v = 1.
            let widest = zoom / frequency;
            let finest = zoom / (frequency * d.amount.exp2());
            assert!(
                (widest - 40.0).abs() < 1e-3 && (finest - 4.0).abs() < 1e-3,
                "{zoom}"
            );
            assert!((bandwidth / frequency - kernel_span()).abs() < 1e-4);
        }
        let r = crate::Renderer::new(&spec, 32).expect("the weather is built in");
        assert!(r.color(16.0, 16.0).iter().all(|c| (0.0..=1.0).contains(c)));
        assert_eq!(spec.source.without_data().type_name(), "gabor");
        assert!(!NoiseSpec::plain(spec.source.without_data()).has_data_frequency());
    }
}
