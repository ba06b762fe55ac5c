//! The user's preferences that outlive a reload: the tool, every tool parameter, the
//! palette, the ink and the antialiasing mode. Stored as JSON; a missing or unreadable
//! value takes its default, and out-of-range values are clamped to what the panel offers.

use crate::marbling::tools::{ToolKind, ToolSettings};
use marbling_core::ink_palette::{InkPalette, MAX_PALETTE_INKS};
use marbling_core::{Antialias, Rgb8};

/// Storage key of the preferences.
pub const KEY: &str = "marbling.prefs.v1";

/// What is kept.
#[derive(Clone, Debug, PartialEq)]
pub struct Prefs {
    /// The selected tool.
    pub tool: ToolKind,
    /// Every tool's parameters.
    pub settings: ToolSettings,
    /// Index into [`crate::INK_SETS`]; `INK_SETS.len()` is the imported palette.
    pub palette: usize,
    /// The palette last imported (a `.gpl`, a picture, pasted hex colours), if any.
    pub imported: Option<InkPalette>,
    /// The current ink.
    pub ink: Rgb8,
    /// Antialiasing of exact frames.
    pub antialias: Antialias,
}

impl Default for Prefs {
    /// A first visit's: the drop tool, the first ink set and its first ink, RGSS.
    fn default() -> Self {
        Self {
            tool: ToolKind::Drop,
            settings: ToolSettings::default(),
            palette: 0,
            imported: None,
            ink: crate::INK_SETS[0].inks[0],
            antialias: Antialias::Rgss,
        }
    }
}

#[derive(serde::Serialize, serde::Deserialize)]
struct Stored {
    tool: ToolKind,
    settings: ToolSettings,
    palette: usize,
    /// The imported palette: its name and `#rrggbb` colours.
    #[serde(default)]
    imported: Option<(String, Vec<String>)>,
    ink: String,
    antialias: String,
}

impl Prefs {
    /// The inks of the chosen palette.
    pub fn inks(&self) -> &[Rgb8] {
        match (
            self.palette.checked_sub(crate::INK_SETS.len()),
            &self.imported,
        ) {
            (Some(_), Some(p)) => &p.colors,
            _ => crate::INK_SETS[self.palette.min(crate::INK_SETS.len() - 1)].inks,
        }
    }

    /// The inks a tool lays in turn: the ink alone, or (cycling colours) the ink, then
    /// the rest of the palette after it.
    pub fn cycled_inks(&self) -> Vec<Rgb8> {
        let ink = self.ink;
        if !self.settings.cycle_colors {
            return vec![ink];
        }
        let palette = self.inks();
        match palette.iter().position(|&c| c == ink) {
            Some(i) => palette[i..].iter().chain(&palette[..i]).copied().collect(),
            None => std::iter::once(ink)
                .chain(palette.iter().copied())
                .collect(),
        }
    }

    /// The name of the chosen palette.
    pub fn palette_name(&self) -> &str {
        match (
            self.palette.checked_sub(crate::INK_SETS.len()),
            &self.imported,
        ) {
            (Some(_), Some(p)) => &p.name,
            _ => crate::INK_SETS[self.palette.min(crate::INK_SETS.len() - 1)].name,
        }
    }

    /// The paper that suits the chosen palette: a built-in set's own; an imported one
    /// has none (a new sheet keeps the current paper).
    pub fn paper(&self) -> Option<Rgb8> {
        crate::INK_SETS.get(self.palette).map(|s| s.background)
    }

    /// The chosen palette as a GIMP `.gpl` file.
    pub fn palette_gpl(&self) -> String {
        InkPalette {
            name: self.palette_name().to_owned(),
            colors: self.inks().to_vec(),
        }
        .to_gpl()
    }

    /// Makes `palette` the imported palette, chosen, its first colour the ink.
    pub fn import_palette(&mut self, palette: InkPalette) {
        if let Some(&first) = palette.colors.first() {
            self.ink = first;
        }
        self.imported = Some(palette);
        self.palette = crate::INK_SETS.len();
    }

    /// The stored text.
    pub fn encode(&self) -> String {
        serde_json::to_string(&Stored {
            tool: self.tool,
            settings: self.settings,
            palette: self.palette,
            imported: self.imported.as_ref().map(|p| {
                let hex = p.colors.iter().map(ToString::to_string).collect();
                (p.name.clone(), hex)
            }),
            ink: self.ink.to_string(),
            antialias: self.antialias.name().to_owned(),
        })
        .unwrap_or_default()
    }

    /// Reads stored preferences over `defaults`; `Err` says why none could be read.
    pub fn decode(text: &str, defaults: &Prefs) -> Result<Prefs, String> {
        let s: Stored = serde_json::from_str(text).map_err(|e| format!("preferences: {e}"))?;
        let mut settings = s.settings;
        settings.comb_tines = settings.comb_tines.min(64);
        let imported = s.imported.and_then(|(name, hex)| {
            let colors: Vec<Rgb8> = hex
                .iter()
                .filter_map(|h| h.parse().ok())
                .take(MAX_PALETTE_INKS)
                .collect();
            (!colors.is_empty()).then_some(InkPalette { name, colors })
        });
        let last = crate::INK_SETS.len() - usize::from(imported.is_none());
        Ok(Prefs {
            tool: s.tool,
            settings,
            palette: s.palette.min(last),
            imported,
            ink: s.ink.parse().unwrap_or(defaults.ink),
            antialias: Antialias::ALL
                .into_iter()
                .find(|a| a.name() == s.antialias)
                .unwrap_or(defaults.antialias),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preferences_round_trip_and_missing_fields_take_defaults() {
        let defaults = Prefs {
            tool: ToolKind::Drop,
            settings: ToolSettings::default(),
            palette: 0,
            imported: None,
            ink: Rgb8::new(1, 2, 3),
            antialias: Antialias::Rgss,
        };
        let mut p = defaults.clone();
        p.tool = ToolKind::Comb;
        p.settings.comb_tines = 9;
        p.palette = 2;
        p.antialias = Antialias::Grid4;
        assert_eq!(Prefs::decode(&p.encode(), &defaults).expect("a value"), p);
        // An imported palette is kept, chosen, and its .gpl is what it holds.
        p.import_palette(InkPalette {
            name: "Ebru".to_owned(),
            colors: vec![Rgb8::new(1, 2, 3), Rgb8::new(250, 240, 230)],
        });
        let back = Prefs::decode(&p.encode(), &defaults).expect("a value");
        assert_eq!(back, p);
        assert_eq!(
            (back.inks().len(), back.palette_name(), back.paper()),
            (2, "Ebru", None)
        );
        assert_eq!(back.ink, Rgb8::new(1, 2, 3));
        assert!(
            back.palette_gpl()
                .contains("Name: Ebru\nColumns: 2\n#\n  1   2   3\t#010203\n")
        );
        let partial = r##"{"tool":"spray","settings":{"spray_spread":99.0},"palette":1,"ink":"#ff0000","antialias":"?"}"##;
        let q = Prefs::decode(partial, &defaults).expect("a value");
        assert_eq!((q.tool, q.settings.spray_spread), (ToolKind::Spray, 99.0));
        assert_eq!(q.settings.drop_radius, ToolSettings::default().drop_radius);
        assert_eq!(
            (q.ink, q.antialias),
            (Rgb8::new(255, 0, 0), Antialias::Rgss)
        );
        // Preferences saved before the comb tool had its name still load.
        let old = r##"{"tool":"rake","settings":{"rake_tines":7,"rake_spacing":12.0},"palette":0,"ink":"#000000","antialias":"rgss"}"##;
        let o = Prefs::decode(old, &defaults).expect("a value");
        assert_eq!(
            (o.tool, o.settings.comb_tines, o.settings.comb_spacing),
            (ToolKind::Comb, 7, 12.0)
        );
        assert!(
            Prefs::decode("{", &defaults)
                .expect_err("an error")
                .starts_with("preferences: ")
        );
    }
}
