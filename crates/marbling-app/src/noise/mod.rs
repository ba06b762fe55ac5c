//! The noise playground: the typed noise spec its sliders edit, its panel and controls,
//! the data sets of data-driven Gabor, its preview, its PNG export (image, height or normal
//! map) and the relief view.

pub(crate) mod controls;
pub(crate) mod data;
pub(crate) mod export;
pub(crate) mod panel;
pub(crate) mod preview;
pub(crate) mod relief;
pub(crate) mod settings;

use crate::noise::data::NoiseData;
use crate::noise::export::NoiseExport;
use crate::noise::panel::NoiseAnalysis;
use crate::noise::preview::NoisePreview;
use crate::noise::relief::ReliefView;
use crate::noise::settings::NoiseSettings;

/// The noise playground's state: the settings with a revision that counts their edits
/// (what is made from them — the layer, the preview, the stored copy, the `data-noise`
/// hook — remembers the revision it was made for instead of a copy of the settings),
/// the loaded data sets, and what is made from the settings.
#[derive(Default)]
pub(crate) struct Noise {
    settings: NoiseSettings,
    revision: u64,
    /// The revision and zoom factor the canvas shows.
    shown: Option<(u64, f64)>,
    /// Statistics of the shown noise (`Some(None)`: none can be computed).
    analysis: Option<Option<NoiseAnalysis>>,
    /// The noise layer of the shown settings, made once per change of them (parsing a
    /// spec builds its CPU field); `None` until asked for.
    layer: Option<Result<marbling_core::NoiseLayer, String>>,
    /// The data sets loaded for data-driven noise.
    data: NoiseData,
    /// Where a data file pick delivers (src/noise/data.rs).
    data_pick: crate::platform::PickSlot,
    /// The CPU picture of what the noise background cannot show.
    preview: Option<NoisePreview>,
    /// A running Export PNG of the noise (src/noise/export.rs).
    export: Option<NoiseExport>,
    /// The relief of the noise lit on a plane, and the relief of its normal map.
    relief: ReliefView,
}

impl Noise {
    /// The settings as they are.
    pub(crate) fn settings(&self) -> &NoiseSettings {
        &self.settings
    }

    /// +1 on every edit of the settings.
    pub(crate) fn revision(&self) -> u64 {
        self.revision
    }

    /// The settings to change (counts an edit: call it only to change them).
    pub(crate) fn edit(&mut self) -> &mut NoiseSettings {
        self.revision += 1;
        &mut self.settings
    }

    /// Replaces the settings.
    pub(crate) fn set(&mut self, settings: NoiseSettings) {
        *self.edit() = settings;
    }

    /// Takes `spec` (from a link or storage) with the data sets it names; on an error the
    /// settings stay as they are.
    pub(crate) fn open(&mut self, spec: marbling_noise::NoiseSpec) -> Result<(), String> {
        let settings = self.settings.with_spec(spec, &self.data)?;
        self.set(settings);
        Ok(())
    }

    /// True when the settings or the zoom `factor` changed since the last call: the
    /// layer and the statistics made for the old ones are forgotten.
    pub(crate) fn follow(&mut self, factor: f64) -> bool {
        let now = (self.revision, factor);
        if self.shown == Some(now) {
            return false;
        }
        self.shown = Some(now);
        self.analysis = None;
        self.layer = None;
        true
    }

    /// The noise layer of the settings at zoom `factor`, made once per change of them.
    pub(crate) fn layer_at(&mut self, factor: f64) -> Result<marbling_core::NoiseLayer, String> {
        let settings = &self.settings;
        self.layer
            .get_or_insert_with(|| settings.layer(factor))
            .clone()
    }

    /// Forgets what the canvas showed (another mode drew over it).
    pub(crate) fn forget_shown(&mut self) {
        self.shown = None;
    }

    /// Hands the settings to `widgets` (a panel's sliders and boxes, which change
    /// nothing in most frames) and counts an edit when they changed them.
    pub(crate) fn edit_in<R>(&mut self, widgets: impl FnOnce(&mut NoiseSettings) -> R) -> R {
        let before = self.settings.clone();
        let out = widgets(&mut self.settings);
        if self.settings != before {
            self.revision += 1;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edits_count_and_looking_does_not() {
        let mut n = Noise::default();
        let r0 = n.revision();
        n.edit_in(|_| ());
        assert_eq!(
            n.revision(),
            r0,
            "widgets that changed nothing counted an edit"
        );
        n.edit_in(|s| s.grain_strength = 0.25);
        assert_eq!(n.revision(), r0 + 1);
        n.edit().palette = 1;
        n.set(NoiseSettings::default());
        assert_eq!(n.revision(), r0 + 3);
        assert_eq!(n.settings(), &NoiseSettings::default());
    }
}
