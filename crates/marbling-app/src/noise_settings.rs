//! The noise playground's parameters and the noise spec (the `marbling noise` JSON, see
//! the noise crate's README) they stand for, plus seed 004's zoom-independent frequency
//! rule.

use marbling_core::{Design, NoiseBackground, NoiseLayer, Palette, Rgb8};
use marbling_noise::ranges;
use serde_json::{Value, json};

/// The noises offered, in panel order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoiseKind {
    /// Sparse Gabor convolution noise.
    Gabor,
    /// Perlin gradient noise with fBm.
    Perlin,
    /// Value noise with fBm.
    Value,
    /// Cellular noise.
    Worley,
    /// Independent values per pixel.
    White,
    /// Divergence-free flow of a Perlin potential.
    Curl,
    /// Paper fibers.
    Paper,
    /// Woven canvas fibers.
    Canvas,
}

impl NoiseKind {
    /// Every kind, in panel order.
    pub const ALL: [NoiseKind; 8] = [
        NoiseKind::Gabor,
        NoiseKind::Perlin,
        NoiseKind::Value,
        NoiseKind::Worley,
        NoiseKind::White,
        NoiseKind::Curl,
        NoiseKind::Paper,
        NoiseKind::Canvas,
    ];

    /// The spec's `type`.
    pub fn type_name(self) -> &'static str {
        match self {
            NoiseKind::Gabor => "gabor",
            NoiseKind::Perlin => "perlin",
            NoiseKind::Value => "value",
            NoiseKind::Worley => "worley",
            NoiseKind::White => "white",
            NoiseKind::Curl => "curl",
            NoiseKind::Paper => "paper",
            NoiseKind::Canvas => "canvas",
        }
    }

    /// True for the noises with a frequency (the zoom rule applies to them).
    pub fn has_frequency(self) -> bool {
        !matches!(self, NoiseKind::White)
    }
}

/// The spec's name of choice `i` of `options` (a table of `marbling_noise::ranges`).
pub fn name_of<T>(options: &[(&'static str, T)], i: usize) -> &'static str {
    options[i.min(options.len() - 1)].0
}

/// Everything the noise panel's sliders set. Lengths are design pixels, frequencies
/// cycles per design pixel, angles radians (x right, y down).
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseSettings {
    /// Which noise.
    pub kind: NoiseKind,
    /// Index into [`marbling_noise::ranges::GABOR_KINDS`].
    pub gabor_kind: usize,
    /// Base frequency F₀ (Gabor, lattice noises, Worley cells, curl).
    pub frequency: f64,
    /// Gabor orientation ω₀.
    pub orientation: f64,
    /// Gabor bandwidth a, 1/pixels.
    pub bandwidth: f64,
    /// Gabor impulses per kernel area.
    pub impulses: u32,
    /// fBm octaves.
    pub octaves: u32,
    /// fBm frequency ratio.
    pub lacunarity: f64,
    /// fBm amplitude ratio.
    pub persistence: f64,
    /// Index into [`marbling_noise::ranges::WORLEY_FEATURES`].
    pub feature: usize,
    /// Index into [`marbling_noise::ranges::WORLEY_METRICS`].
    pub metric: usize,
    /// Index into [`marbling_noise::ranges::CURL_COMPONENTS`].
    pub component: usize,
    /// Fiber length.
    pub fiber_length: f64,
    /// Fiber width.
    pub fiber_width: f64,
    /// Fibers per square pixel.
    pub fiber_density: f64,
    /// Canvas thread weights (horizontal, vertical).
    pub weights: [f64; 2],
    /// Seed of the noise.
    pub seed: u32,
    /// Index into `marbling_noise::PALETTES`.
    pub palette: usize,
    /// Keep features 4–40 screen pixels wide whatever the zoom (seed 004).
    pub zoom_independent: bool,
    /// Strength of the grain overlays made from this noise, [0, 1].
    pub grain_strength: f64,
}

impl Default for NoiseSettings {
    fn default() -> Self {
        Self {
            // Perlin fBm first: cheap enough for any GPU (Gabor costs ~100× more per pixel).
            kind: NoiseKind::Perlin,
            gabor_kind: 0,
            frequency: 0.02,
            orientation: 0.6,
            bandwidth: 0.04,
            impulses: 64,
            octaves: 5,
            lacunarity: 2.0,
            persistence: 0.5,
            feature: 0,
            metric: 0,
            component: 0,
            fiber_length: 20.0,
            fiber_width: 1.5,
            fiber_density: 0.3,
            weights: [1.0, 1.0],
            seed: 7,
            palette: 5,
            zoom_independent: false,
            grain_strength: 0.3,
        }
    }
}

/// Largest frequency each noise accepts (its spec's range), cycles per pixel.
/// The accepted frequencies of `kind`.
pub fn frequency_range(kind: NoiseKind) -> ranges::Range {
    if kind == NoiseKind::Gabor {
        ranges::GABOR_FREQUENCY
    } else {
        ranges::FREQUENCY
    }
}

/// The smallest value the sliders give a parameter whose range is open below.
pub const SLIDER_FLOOR: f64 = 0.001;

impl NoiseSettings {
    /// The spec, with every frequency multiplied (and every length divided) by `zoom`
    /// — the factor from [`zoom_octave_factor`], 1 when not zoom-independent.
    pub fn spec_json(&self, zoom: f64) -> Value {
        let f = (self.frequency * zoom).min(frequency_range(self.kind).hi);
        let k = f / self.frequency;
        let seed = self.seed;
        match self.kind {
            NoiseKind::Gabor => json!({
                "type": "gabor",
                "kind": name_of(&ranges::GABOR_KINDS, self.gabor_kind),
                "frequency": f,
                "orientation": self.orientation,
                "bandwidth": ranges::BANDWIDTH.clamp(self.bandwidth * k, SLIDER_FLOOR),
                "impulses": self.impulses,
                "seed": seed,
            }),
            NoiseKind::Perlin | NoiseKind::Value => json!({
                "type": self.kind.type_name(),
                "frequency": f,
                "octaves": self.octaves,
                "lacunarity": self.lacunarity,
                "persistence": self.persistence,
                "seed": seed,
            }),
            NoiseKind::Curl => json!({
                "type": "curl",
                "frequency": f,
                "octaves": self.octaves,
                "lacunarity": self.lacunarity,
                "persistence": self.persistence,
                "component": name_of(&ranges::CURL_COMPONENTS, self.component),
                "seed": seed,
            }),
            NoiseKind::Worley => json!({
                "type": "worley",
                "frequency": f,
                "feature": name_of(&ranges::WORLEY_FEATURES, self.feature),
                "metric": name_of(&ranges::WORLEY_METRICS, self.metric),
                "seed": seed,
            }),
            NoiseKind::White => json!({ "type": "white", "seed": seed }),
            NoiseKind::Paper | NoiseKind::Canvas => {
                let mut spec = json!({
                    "type": self.kind.type_name(),
                    "length": ranges::FIBER_LENGTH.clamp(self.fiber_length / k, SLIDER_FLOOR),
                    "width": ranges::FIBER_WIDTH.clamp(self.fiber_width / k, SLIDER_FLOOR),
                    "density": ranges::FIBER_DENSITY.clamp(self.fiber_density * k * k, 1e-4),
                    "seed": seed,
                });
                if self.kind == NoiseKind::Canvas {
                    spec["weights"] = json!(self.weights);
                }
                spec
            }
        }
    }

    /// The noise layer of [`NoiseSettings::spec_json`], or the first problem found.
    pub fn layer(&self, zoom: f64) -> Result<NoiseLayer, String> {
        NoiseLayer::from_value(&self.spec_json(zoom)).map_err(|problems| {
            problems.first().map_or_else(
                || "invalid noise".to_owned(),
                |p| format!("{}: {}", p.path, p.message),
            )
        })
    }

    /// The palette's name.
    pub fn palette_name(&self) -> &'static str {
        let names = marbling_noise::PALETTES;
        names[self.palette.min(names.len() - 1)]
    }

    /// A design of `size` with this noise as its (marbled) background and no ops: what
    /// the canvas shows in the noise playground, and what its links and exports hold.
    pub fn design(&self, size: [u32; 2], zoom: f64) -> Result<Design, String> {
        let layer = self.layer(zoom)?;
        let palette = Palette::named(self.palette_name()).map_err(|e| e.to_string())?;
        let mut d = Design::new(size[0], size[1], Rgb8::new(0, 0, 0));
        d.set_background_noise(Some(NoiseBackground::new(layer, palette)));
        Ok(d)
    }
}

/// Seed 004's zoom rule: the power of two to multiply a noise's frequency by so that its
/// features (one period, 1/frequency design pixels) span 4 to 40 screen pixels at
/// `zoom` screen pixels per design pixel. 1 when they already do.
pub fn zoom_octave_factor(frequency: f64, zoom: f64) -> f64 {
    if !(frequency > 0.0 && zoom > 0.0) {
        return 1.0;
    }
    let screen_period = zoom / frequency;
    if screen_period > 40.0 {
        2f64.powi((screen_period / 40.0).log2().ceil() as i32)
    } else if screen_period < 4.0 {
        0.5f64.powi((4.0 / screen_period).log2().ceil() as i32)
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sliders' ends are the spec's ranges: a spec made at either end of every
    /// slider is accepted, for every kind and choice.
    #[test]
    fn every_slider_end_is_a_valid_spec() {
        let end = |r: ranges::Range, high: bool| {
            let s = r.slider(SLIDER_FLOOR);
            if high { *s.end() } else { *s.start() }
        };
        for kind in NoiseKind::ALL {
            for high in [false, true] {
                for choice in 0..3 {
                    let s = NoiseSettings {
                        kind,
                        gabor_kind: choice,
                        feature: choice,
                        metric: choice,
                        component: choice,
                        frequency: end(frequency_range(kind), high),
                        bandwidth: end(ranges::BANDWIDTH, high),
                        impulses: end(ranges::IMPULSES, high) as u32,
                        octaves: end(ranges::OCTAVES, high) as u32,
                        lacunarity: end(ranges::LACUNARITY, high),
                        persistence: end(ranges::PERSISTENCE, high),
                        fiber_length: end(ranges::FIBER_LENGTH, high),
                        fiber_width: end(ranges::FIBER_WIDTH, high),
                        fiber_density: end(ranges::FIBER_DENSITY, high),
                        ..NoiseSettings::default()
                    };
                    let spec = s.spec_json(1.0);
                    assert!(
                        marbling_noise::NoiseSpec::from_value(&spec).is_ok(),
                        "{spec}"
                    );
                }
            }
        }
    }

    #[test]
    fn every_kind_makes_a_valid_spec_and_design() {
        for kind in NoiseKind::ALL {
            let s = NoiseSettings {
                kind,
                ..NoiseSettings::default()
            };
            let d = s
                .design([64, 48], 1.0)
                .unwrap_or_else(|e| panic!("{kind:?}: {e}"));
            assert!(d.uses_v2());
            assert_eq!(d.ops.len(), 0);
            assert_eq!(s.spec_json(1.0)["type"], kind.type_name());
            let back = Design::from_json(&d.to_json_compact()).expect("round trip");
            assert_eq!(back, d);
        }
    }

    #[test]
    fn bad_parameters_are_reported_with_their_field() {
        let s = NoiseSettings {
            kind: NoiseKind::Perlin,
            octaves: 40,
            ..NoiseSettings::default()
        };
        let e = s.layer(1.0).expect_err("40 octaves");
        assert!(e.contains("octaves"), "{e}");
    }

    #[test]
    fn the_zoom_rule_keeps_features_between_4_and_40_screen_pixels() {
        for f in [0.003, 0.02, 0.05, 0.3] {
            for zoom in [0.05, 0.3, 1.0, 2.5, 17.0, 90.0, 400.0] {
                let k = zoom_octave_factor(f, zoom);
                let period = zoom / (f * k);
                assert!(
                    (4.0..=40.0).contains(&period),
                    "f {f} zoom {zoom}: {period} px"
                );
                assert_eq!(k.log2().fract(), 0.0, "not a power of two: {k}");
            }
        }
        assert_eq!(zoom_octave_factor(0.05, 1.0), 1.0);
        // Zooming in 4× on 20-px features (at the limit of 40 px) doubles the frequency
        // twice.
        assert_eq!(zoom_octave_factor(0.05, 8.0), 4.0);
    }

    #[test]
    fn zooming_scales_frequency_and_kernel_together() {
        let s = NoiseSettings {
            kind: NoiseKind::Gabor,
            frequency: 0.05,
            ..NoiseSettings::default()
        };
        let spec = s.spec_json(4.0);
        assert!((spec["frequency"].as_f64().unwrap_or(0.0) - 0.2).abs() < 1e-12);
        assert!((spec["bandwidth"].as_f64().unwrap_or(0.0) - 0.16).abs() < 1e-12);
        let paper = NoiseSettings {
            kind: NoiseKind::Paper,
            ..NoiseSettings::default()
        }
        .spec_json(2.0);
        assert!((paper["length"].as_f64().unwrap_or(0.0) - 10.0).abs() < 1e-12);
    }
}
