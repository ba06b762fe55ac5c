//! The gallery: the traditional patterns, made by their recipes in
//! `marbling_core::patterns` (the same designs as examples/patterns/, which the core's
//! tests keep in step), and three noise-surface designs bundled from examples/designs/.
//! Opening the app without a link or autosave lands on it (src/shell/landing.rs).

use marbling_core::Design;
use marbling_core::patterns::{self, Params, Pattern};

/// Where an entry's design comes from.
#[derive(Clone, Copy)]
enum Source {
    /// A traditional pattern at its defaults (640 × 400, seed 1).
    Pattern(&'static Pattern),
    /// A design document bundled at build time.
    Json(&'static str),
}

/// One gallery entry.
#[derive(Clone, Copy)]
pub struct Entry {
    /// File name, and the `gallery-<id>` control.
    pub id: &'static str,
    source: Source,
}

impl std::fmt::Debug for Entry {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Entry({})", self.id)
    }
}

macro_rules! design {
    ($id:literal) => {
        Entry {
            id: $id,
            source: Source::Json(include_str!(concat!(
                "../../../../examples/designs/",
                $id,
                ".json"
            ))),
        }
    };
}

/// Every entry, in gallery order: the patterns in `marbling_core::patterns::all()`
/// order, then the noise designs.
pub fn entries() -> Vec<Entry> {
    patterns::all()
        .into_iter()
        .map(|p| Entry {
            id: p.id,
            source: Source::Pattern(p),
        })
        .chain([
            design!("fbm-marbled"),
            design!("worley-pigment"),
            design!("on-paper"),
        ])
        .collect()
}

impl Entry {
    /// The design (every entry is checked by this module's tests).
    pub fn design(&self) -> Result<Design, String> {
        match self.source {
            Source::Pattern(p) => p.design(&Params::default()),
            Source::Json(json) => Design::from_json(json).map_err(|e| e.to_string()),
        }
    }

    /// The name shown under the thumbnail: the recipe's name, else the id.
    pub fn name(&self, design: &Design) -> String {
        design
            .recipe
            .as_ref()
            .map_or_else(|| self.id.replace('-', " "), |r| r.name.clone())
    }

    /// What its card shows before the design is made: name, sheet size (design px) and
    /// paper colour. A pattern's are known without making it; a bundled design is read.
    pub fn card(&self) -> Result<Card, String> {
        match self.source {
            Source::Pattern(p) => {
                let params = Params::default();
                Ok(Card {
                    name: p.name.to_owned(),
                    size: (params.width, params.height),
                    paper: p.background,
                })
            }
            Source::Json(_) => self.design().map(|d| Card {
                name: self.name(&d),
                size: (d.width, d.height),
                paper: d.background,
            }),
        }
    }
}

/// An entry's card, known without making its design.
#[derive(Clone, Debug, PartialEq)]
pub struct Card {
    /// Shown under the thumbnail.
    pub name: String,
    /// The design's size, design pixels (where its thumbnail sits in the atlas cell).
    pub size: (u32, u32),
    /// The paper colour, shown while the thumbnails come.
    pub paper: marbling_core::Rgb8,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pattern_is_in_the_gallery_in_order_and_every_entry_opens() {
        let entries = entries();
        let ids: Vec<&str> = patterns::all().iter().map(|p| p.id).collect();
        assert_eq!(
            entries
                .iter()
                .map(|e| e.id)
                .take(ids.len())
                .collect::<Vec<_>>(),
            ids
        );
        assert_eq!(entries.len(), ids.len() + 3);
        for e in &entries {
            let d = e.design().unwrap_or_else(|err| panic!("{}: {err}", e.id));
            let card = e.card().expect("a card");
            assert_eq!(card.name, e.name(&d), "{}", e.id);
            assert_eq!(card.size, (d.width, d.height), "{}", e.id);
            assert_eq!(card.paper, d.background, "{}", e.id);
        }
        assert_eq!(
            entries[0].name(&entries[0].design().expect("valid")),
            "Stone (battal)"
        );
    }

    /// The gallery opens the very designs of examples/patterns/ (the README's gallery and
    /// the files a user downloads).
    #[test]
    fn a_pattern_entry_is_its_example_file() {
        let e = entries()[8];
        let file = std::fs::read_to_string(format!(
            "{}/../../examples/patterns/{}.json",
            env!("CARGO_MANIFEST_DIR"),
            e.id
        ))
        .expect("the example file");
        assert_eq!(
            e.design().expect("valid"),
            Design::from_json(&file).expect("valid")
        );
    }
}
