//! The noise playground's state: the typed noise spec its sliders edit (ranges, names
//! and starting values all come from `marbling-noise`), the palette it is shown in, and
//! Khlebnikov et al. (2013)'s zoom-independent frequency rules (octave steps for any noise, the paper's
//! continuous rule for a data-driven Gabor).

use crate::noise::data::NoiseData;
use marbling_core::{Design, NoiseBackground, NoiseLayer, Palette, Rgb8};
use marbling_noise::{BlendBase, ColorRamp, FEATURE_PX, NoiseSpec, Source, Tile, Transfer};
use marbling_noise::{Depth, PngContent, SurfaceMap, WhiteSpec};

/// Storage key of the noise setup (the JSON of [`NoiseSettings::export_spec`]).
pub const KEY: &str = "marbling.noise.v1";

/// What the noise panel edits.
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseSettings {
    /// The noise, in design pixels (frequencies in cycles per design pixel).
    pub spec: NoiseSpec,
    /// Index into `marbling_noise::PALETTES`.
    pub palette: usize,
    /// Keep features 4–40 screen pixels wide whatever the zoom (Khlebnikov et al. 2013).
    pub zoom_independent: bool,
    /// Strength of the grain overlays made from this noise, [0, 1].
    pub grain_strength: f64,
    /// Show a tiling spec as 2×2 copies of one tile (to check the seams).
    pub show_tiles: bool,
    /// Index into `noise_export::EXPORT_SIZES` of Export PNG's size.
    pub export_size: usize,
    /// Export PNG writes 16-bit samples (height maps).
    pub export_16bit: bool,
    /// What Export PNG writes: 0 the image, 1 + an index into
    /// `marbling_noise::SURFACE_MAPS` a 16-bit height or normal map.
    pub export_map: usize,
}

impl Default for NoiseSettings {
    fn default() -> Self {
        // Perlin fBm first: cheap enough for any GPU (Gabor costs ~100× more per pixel).
        let perlin = Source::starting("perlin", 7).unwrap_or(Source::White(WhiteSpec { seed: 7 }));
        Self {
            spec: NoiseSpec::plain(perlin),
            palette: 5,
            zoom_independent: false,
            grain_strength: 0.3,
            show_tiles: true,
            export_size: 1,
            export_16bit: false,
            export_map: 0,
        }
    }
}

impl NoiseSettings {
    /// What Export PNG writes ([`NoiseSettings::export_map`], the depth; a normal map
    /// raised `relief` output pixels).
    pub fn export_content(&self, relief: f32) -> PngContent {
        match self.export_map {
            1 => PngContent::Map(SurfaceMap::Height),
            2 => PngContent::Map(SurfaceMap::Normal { relief }),
            _ if self.export_16bit => PngContent::Image(Depth::Sixteen),
            _ => PngContent::Image(Depth::Eight),
        }
    }

    /// The factor the zoom rule multiplies the frequencies by at `zoom` screen pixels
    /// per design pixel: a power of two, 1 when the rule is off or the noise has no
    /// frequency.
    pub fn zoom_factor(&self, zoom: f64) -> f64 {
        match self.spec.source.feature_frequency() {
            // Khlebnikov et al. (2013)'s eq. 3: F₀ = Z/S exactly, not in octave steps.
            Some(f) if self.zoom_independent && self.spec.has_data_frequency() => {
                zoom / f64::from(FEATURE_PX[1]) / f
            }
            Some(f) if self.zoom_independent => zoom_octave_factor(f, zoom),
            _ => 1.0,
        }
    }

    /// The spec shown at zoom factor `factor` ([`NoiseSettings::zoom_factor`]): seed
    /// 004's frequency rule for a data-driven Gabor, else every frequency scaled.
    pub fn shown_spec(&self, factor: f64) -> NoiseSpec {
        if factor == 1.0 {
            self.export_spec()
        } else if self.zoom_independent && self.spec.has_data_frequency() {
            let f = self.spec.source.feature_frequency().unwrap_or(0.025) * factor;
            NoiseSettings {
                spec: self.spec.zoom_independent(f as f32),
                ..self.clone()
            }
            .export_spec()
        } else {
            NoiseSettings {
                spec: self.spec.scaled(factor),
                ..self.clone()
            }
            .export_spec()
        }
    }

    /// The part of `spec` a design's noise background can hold (no tiling, layers,
    /// curve or spline transfer, palette, blend or data): what the GPU canvas draws
    /// under the preview of the rest.
    pub fn base_of(spec: &NoiseSpec) -> NoiseSpec {
        let mut base = NoiseSpec::plain(match &spec.source {
            Source::Product(inputs) => inputs
                .first()
                .map_or_else(|| spec.source.clone(), |i| i.source.clone()),
            s => s.without_data(),
        });
        if let Some(t @ Transfer::Threshold(_)) = &spec.transfer {
            base.transfer = Some(t.clone());
        }
        base
    }

    /// Whether the spec has more than a design's noise background can show (the canvas
    /// then shows a preview of the whole spec over it).
    pub fn needs_preview(&self) -> bool {
        let mut plain = self.spec.clone();
        plain.palette = None;
        Self::base_of(&self.spec) != plain
    }

    /// Switches to a noise of type `type_name` at its starting values, keeping the seed.
    pub fn set_type(&mut self, type_name: &str) {
        if let Some(source) = Source::starting(type_name, self.spec.source.seed()) {
            self.spec = NoiseSpec::plain(source);
        }
    }

    /// The noise layer of the spec's base ([`NoiseSettings::base_of`]) at zoom factor
    /// `factor` (see [`NoiseSettings::zoom_factor`]), or the first problem found.
    pub fn layer(&self, factor: f64) -> Result<NoiseLayer, String> {
        let spec = Self::base_of(&self.shown_spec(factor));
        NoiseLayer::from_spec(&spec).map_err(|problems| {
            problems
                .first()
                .map_or_else(|| "invalid noise".to_owned(), ToString::to_string)
        })
    }

    /// The spec with the panel's palette in it: what *Copy spec*, the `#n=` link and the
    /// stored setup hold, and what `marbling noise` renders as the panel shows it.
    /// A blend colours with the panel's palette in place of `palette`.
    pub fn export_spec(&self) -> NoiseSpec {
        let mut spec = self.spec.clone();
        let ramp = ColorRamp::named(self.palette_name());
        match (&mut spec.blend, ramp) {
            (Some(b), Some(r)) => {
                match &mut b.base {
                    BlendBase::Ramp(x) | BlendBase::Data { ramp: x, .. } => *x = r,
                    BlendBase::Color(_) => {}
                }
                spec.palette = None;
            }
            (None, r) => spec.palette = r,
            (Some(_), None) => {}
        }
        spec
    }

    /// These settings with `spec` (from a link, a file or storage), its palette taken
    /// for the panel's and its data attached from `data`; an error naming the field
    /// when the playground cannot show it (a palette of its own stops, data not loaded).
    pub fn with_spec(
        &self,
        mut spec: NoiseSpec,
        data: &NoiseData,
    ) -> Result<NoiseSettings, String> {
        let names = marbling_noise::PALETTES;
        let index = |ramp: &ColorRamp, field: &str| {
            ramp.name()
                .and_then(|n| names.iter().position(|m| *m == n))
                .ok_or_else(|| {
                    format!(
                        "{field}: the playground shows the named palettes ({})",
                        names.join(", ")
                    )
                })
        };
        let mut palette = self.palette;
        if let Some(ramp) = spec.palette.take() {
            palette = index(&ramp, "palette")?;
        }
        if let Some(b) = &spec.blend {
            match &b.base {
                BlendBase::Ramp(r) | BlendBase::Data { ramp: r, .. } => {
                    palette = index(r, "blend.palette")?;
                }
                BlendBase::Color(_) => {}
            }
        }
        data.attach(&mut spec)?;
        marbling_noise::Renderer::new(&spec, 1).map_err(|e| e.to_string())?;
        Ok(NoiseSettings {
            spec,
            palette,
            ..self.clone()
        })
    }

    /// Turns tiling on with `period` pixels, or off.
    pub fn set_tile(&mut self, period: Option<u32>) {
        self.spec.tile = period.map_or(Tile::Off, Tile::Period);
    }

    /// The palette's name.
    pub fn palette_name(&self) -> &'static str {
        let names = marbling_noise::PALETTES;
        names[self.palette.min(names.len() - 1)]
    }

    /// A design of `size` with `layer` as its (marbled) background in this palette and no
    /// ops: what the canvas shows in the noise playground, and what its links and exports
    /// hold.
    pub fn design(&self, size: [u32; 2], layer: NoiseLayer) -> Result<Design, String> {
        let palette = Palette::named(self.palette_name()).map_err(|e| e.to_string())?;
        let mut d = Design::new(size[0], size[1], Rgb8::new(0, 0, 0));
        d.set_background_noise(Some(NoiseBackground::new(layer, palette)));
        Ok(d)
    }
}

/// Khlebnikov et al. (2013)'s zoom rule: the power of two to multiply a noise's frequency by so that its
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
    use marbling_noise::{GaborSpec, NOISE_TYPES};

    fn settings(type_name: &str) -> NoiseSettings {
        let mut s = NoiseSettings::default();
        s.set_type(type_name);
        s
    }

    #[test]
    fn every_type_makes_a_valid_design() {
        for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
            let s = settings(t);
            assert_eq!(s.spec.source.type_name(), t);
            assert_eq!(s.spec.source.seed(), 7, "the seed is kept");
            let layer = s.layer(1.0).unwrap_or_else(|e| panic!("{t}: {e}"));
            let d = s.design([64, 48], layer).expect("design");
            assert!(d.uses_v2());
            assert_eq!(d.ops.len(), 0);
            let back = Design::from_json(&d.to_json_compact()).expect("round trip");
            assert_eq!(back, d);
        }
    }

    #[test]
    fn the_exported_spec_reads_back_as_the_same_settings() {
        let mut s = settings("worley");
        s.palette = 3;
        let spec = s.export_spec();
        assert_eq!(spec.to_value()["palette"], marbling_noise::PALETTES[3]);
        let back = NoiseSettings::default()
            .with_spec(
                NoiseSpec::from_value(&spec.to_value()).expect("valid"),
                &NoiseData::default(),
            )
            .expect("shown");
        assert_eq!(back.spec, s.spec);
        assert_eq!(back.palette, 3);
        let shown = |json: &str| {
            NoiseSettings::default().with_spec(
                NoiseSpec::from_json(json).expect("valid"),
                &NoiseData::default(),
            )
        };
        let e = shown(r##"{"type":"perlin","frequency":0.1,"palette":["#000000","#123456"]}"##)
            .expect_err("own stops");
        assert!(
            e.starts_with("palette: the playground shows the named palettes"),
            "{e}"
        );
        // What a design's background cannot hold is shown by the preview, not refused.
        let tiled = shown(r#"{"type":"perlin","frequency":0.1,"tile":64}"#).expect("tile");
        assert!(tiled.needs_preview());
        assert!(!NoiseSettings::default().needs_preview());
        let e = shown(r#"{"type":"gabor","frequency":0.1,"bandwidth":0.1,"frequency_field":{"data":"x.csv","amount":1}}"#)
            .expect_err("not loaded");
        assert_eq!(
            e,
            "data: 'x.csv': is not loaded: load it in the Data section first"
        );
    }

    #[test]
    fn bad_parameters_are_reported_with_their_field() {
        let mut s = settings("perlin");
        if let Source::Fbm(p) = &mut s.spec.source {
            p.octaves = 40;
        }
        let e = s.layer(1.0).expect_err("40 octaves");
        assert!(e.starts_with("octaves: "), "{e}");
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
    fn the_zoom_factor_applies_only_when_asked_and_to_noises_with_a_frequency() {
        let mut s = settings("gabor");
        assert_eq!(s.zoom_factor(8.0), 1.0);
        s.zoom_independent = true;
        // 0.02 cycles/px at 8 screen px per design px: 400-px features → × 16.
        assert_eq!(s.zoom_factor(8.0), 16.0);
        let zoomed = s.layer(16.0).expect("valid");
        let Source::Gabor(GaborSpec { frequency, .. }) = zoomed.spec().source else {
            panic!("Gabor")
        };
        assert!((frequency - 0.32).abs() < 1e-6, "{frequency}");
        let mut white = settings("white");
        white.zoom_independent = true;
        assert_eq!(white.zoom_factor(8.0), 1.0);
    }
}
