//! The example designs shown in the gallery, with their thumbnails (rendered by the
//! CLI into docs/gallery/ and embedded at build time).

/// One gallery entry.
pub struct Example {
    /// Name shown under the thumbnail.
    pub name: &'static str,
    /// The design document.
    pub json: &'static str,
    /// A 320-pixel-wide PNG of it.
    pub thumbnail_png: &'static [u8],
}

macro_rules! example {
    ($name:literal) => {
        Example {
            name: $name,
            json: include_str!(concat!("../../../examples/designs/", $name, ".json")),
            thumbnail_png: include_bytes!(concat!("../../../docs/gallery/", $name, ".png")),
        }
    };
}

/// Every example, in gallery order.
pub const EXAMPLES: [Example; 10] = [
    example!("stone"),
    example!("gel-git"),
    example!("chevron"),
    example!("nonpareil"),
    example!("serpentine"),
    example!("bouquet"),
    example!("vortex"),
    example!("fbm-marbled"),
    example!("worley-pigment"),
    example!("on-paper"),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_example_parses_and_has_a_thumbnail() {
        for e in &EXAMPLES {
            marbling_core::Design::from_json(e.json)
                .unwrap_or_else(|err| panic!("{}: {err}", e.name));
            let img = marbling_core::RgbaImage::from_png(e.thumbnail_png).expect("thumbnail");
            assert_eq!(img.width, 320, "{}", e.name);
        }
    }
}
