//! The gallery: the traditional patterns (examples/patterns/, see
//! `marbling_core::patterns`) and three noise-surface designs, bundled at build time.
//! Opening the app without a link or autosave lands on it (src/landing.rs).

/// One gallery entry.
#[derive(Clone, Copy, Debug)]
pub struct Entry {
    /// File name, and the `gallery-<id>` control.
    pub id: &'static str,
    /// The design document.
    pub json: &'static str,
}

macro_rules! pattern {
    ($id:literal) => {
        Entry {
            id: $id,
            json: include_str!(concat!("../../../examples/patterns/", $id, ".json")),
        }
    };
}

macro_rules! design {
    ($id:literal) => {
        Entry {
            id: $id,
            json: include_str!(concat!("../../../examples/designs/", $id, ".json")),
        }
    };
}

/// Every entry, in gallery order: the patterns in `marbling_core::patterns::all()`
/// order, then the noise designs.
pub const ENTRIES: [Entry; 27] = [
    pattern!("stone"),
    pattern!("hair-vein"),
    pattern!("turkish-spot"),
    pattern!("french-shell"),
    pattern!("stormont"),
    pattern!("spanish-wave"),
    pattern!("west-end"),
    pattern!("gel-git"),
    pattern!("chevron"),
    pattern!("nonpareil"),
    pattern!("reversed-nonpareil"),
    pattern!("wave-nonpareil"),
    pattern!("feather"),
    pattern!("bouquet"),
    pattern!("peacock"),
    pattern!("bird-wing"),
    pattern!("serpentine"),
    pattern!("old-dutch"),
    pattern!("dutch-scallops"),
    pattern!("sal"),
    pattern!("french-curl"),
    pattern!("nightingale-nest"),
    pattern!("tulip"),
    pattern!("hearts"),
    design!("fbm-marbled"),
    design!("worley-pigment"),
    design!("on-paper"),
];

impl Entry {
    /// The design (the bundled files are checked by this module's tests).
    pub fn design(&self) -> Result<marbling_core::Design, marbling_core::DesignError> {
        marbling_core::Design::from_json(self.json)
    }

    /// The name shown under the thumbnail: the recipe's name, else the id.
    pub fn name(&self, design: &marbling_core::Design) -> String {
        design
            .recipe
            .as_ref()
            .map_or_else(|| self.id.replace('-', " "), |r| r.name.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_pattern_is_in_the_gallery_in_order_and_every_entry_parses() {
        let ids: Vec<&str> = marbling_core::patterns::all()
            .iter()
            .map(|p| p.id)
            .collect();
        assert_eq!(
            ENTRIES
                .iter()
                .map(|e| e.id)
                .take(ids.len())
                .collect::<Vec<_>>(),
            ids
        );
        for e in &ENTRIES {
            let d = e.design().unwrap_or_else(|err| panic!("{}: {err}", e.id));
            assert!(!e.name(&d).is_empty());
        }
        assert_eq!(
            ENTRIES[0].name(&ENTRIES[0].design().expect("valid")),
            "Stone (battal)"
        );
    }
}
