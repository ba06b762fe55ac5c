//! The app's fonts: egui's default Ubuntu Light (proportional) whole, and Hack
//! (monospace; also where the panels' arrows and shapes come from) cut to the characters
//! the playground shows by `make fonts` (tools/fonts/subset.sh): the web module carries
//! 77 KB of Hack instead of 309 KB (docs/BENCHMARKS.md, "The first visit"). The test
//! below checks that every character of the app's text has a glyph.

use egui::{FontData, FontDefinitions, FontFamily, FontTweak};
use std::sync::Arc;

/// Hack cut to Latin-1, Greek, punctuation, arrows, operators and shapes.
const HACK_SUBSET: &[u8] = include_bytes!("../../fonts/Hack-Regular-subset.ttf");

/// Egui's default families, with the cut Hack, and Hack after Ubuntu Light for the
/// symbols it lacks (arrows, ▶, ∈).
pub fn definitions() -> FontDefinitions {
    let mut defs = FontDefinitions::empty();
    let data = [
        ("Hack", FontData::from_static(HACK_SUBSET)),
        (
            "Ubuntu-Light",
            FontData::from_static(epaint_default_fonts::UBUNTU_LIGHT),
        ),
        // The handful of icons in `egui::special_emojis`, as egui sets them up.
        (
            "egui-icons",
            FontData::from_static(epaint_default_fonts::EGUI_ICONS).tweak(FontTweak {
                scale: 0.90,
                ..Default::default()
            }),
        ),
    ];
    for (name, font) in data {
        defs.font_data.insert(name.to_owned(), Arc::new(font));
    }
    let family = |names: &[&str]| names.iter().map(|n| (*n).to_owned()).collect();
    defs.families.insert(
        FontFamily::Proportional,
        family(&["Ubuntu-Light", "Hack", "egui-icons"]),
    );
    defs.families.insert(
        FontFamily::Monospace,
        family(&["Hack", "Ubuntu-Light", "egui-icons"]),
    );
    defs
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::FontId;

    /// The characters between double quotes in the Rust sources at `path` (a file or a
    /// folder): the text the app shows, and some that it does not (a superset).
    fn quoted_chars(path: &std::path::Path, out: &mut std::collections::BTreeSet<char>) {
        if path.is_dir() {
            for entry in std::fs::read_dir(path).expect("a source folder") {
                quoted_chars(&entry.expect("an entry").path(), out);
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            let text = std::fs::read_to_string(path).expect("a source file");
            for line in text.lines().filter(|l| !l.trim_start().starts_with("//")) {
                for (k, part) in line.split('"').enumerate() {
                    if k % 2 == 1 {
                        out.extend(part.chars().filter(|c| !c.is_ascii()));
                    }
                }
            }
        }
    }

    /// Every character quoted in the app's sources, and in the core's captions,
    /// explanations and pattern recipes, has a glyph in these fonts, in both families.
    #[test]
    fn every_character_the_app_shows_has_a_glyph() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut chars = std::collections::BTreeSet::new();
        quoted_chars(&root.join("src"), &mut chars);
        for part in ["caption.rs", "explain.rs", "patterns", "making.rs"] {
            quoted_chars(&root.join("../marbling-core/src").join(part), &mut chars);
        }
        assert!(
            chars.contains(&'→') && chars.contains(&'α'),
            "the scan found too little"
        );
        let mut fonts = egui::epaint::text::Fonts::new(Default::default(), definitions());
        for family in [FontFamily::Proportional, FontFamily::Monospace] {
            let id = FontId::new(14.0, family.clone());
            let missing: String = chars
                .iter()
                .filter(|&&c| !fonts.has_glyph(&id, c))
                .collect();
            assert!(missing.is_empty(), "{family:?} lacks {missing:?}");
        }
        // The check sees a missing glyph: a CJK character is in neither font.
        assert!(!fonts.has_glyph(&FontId::proportional(14.0), '字'));
    }
}
