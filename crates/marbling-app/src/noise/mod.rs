//! The noise playground: the typed noise spec its sliders edit, its panel and controls,
//! the data sets of data-driven Gabor, its preview and its PNG export.

pub(crate) mod controls;
pub(crate) mod data;
pub(crate) mod export;
pub(crate) mod panel;
pub(crate) mod preview;
pub(crate) mod settings;

use crate::noise::settings::NoiseSettings;

/// The noise playground's settings with a revision that counts their edits: what is
/// made from them (the layer, the preview, the stored copy, the `data-noise` hook)
/// remembers the revision it was made for instead of a copy of the settings.
#[derive(Default)]
pub(crate) struct Noise {
    settings: NoiseSettings,
    revision: u64,
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
