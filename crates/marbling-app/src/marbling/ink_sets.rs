//! Built-in ink sets (the panel's ink palettes), named after the papers they suit.
//! Not to be confused with a noise background's colour ramp (`marbling_core::Palette`).

use marbling_core::Rgb8;

/// A named set of ink colours and a suggested background.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InkSet {
    /// Name shown in the panel.
    pub name: &'static str,
    /// Paper colour that suits the inks.
    pub background: Rgb8,
    /// Ink colours.
    pub inks: &'static [Rgb8],
}

const fn c(hex: u32) -> Rgb8 {
    Rgb8::new((hex >> 16) as u8, (hex >> 8) as u8, hex as u8)
}

/// The ink sets offered in the app.
pub const INK_SETS: [InkSet; 5] = [
    InkSet {
        name: "Ottoman earth",
        background: c(0xf4ecd8),
        inks: &[
            c(0x1d3557),
            c(0xc0392b),
            c(0xe9c46a),
            c(0x2a9d8f),
            c(0xf4f1de),
        ],
    },
    InkSet {
        name: "Indigo & saffron",
        background: c(0xf7f3e8),
        inks: &[
            c(0x14213d),
            c(0xfca311),
            c(0xe5e5e5),
            c(0x3d5a80),
            c(0x98c1d9),
        ],
    },
    InkSet {
        name: "Rose",
        background: c(0xf7efe2),
        inks: &[
            c(0x6d597a),
            c(0xb56576),
            c(0xe56b6f),
            c(0xeaac8b),
            c(0x355070),
        ],
    },
    InkSet {
        name: "Florentine",
        background: c(0xefe6d2),
        inks: &[
            c(0x7a1f1f),
            c(0x0b3d2e),
            c(0xc9a227),
            c(0x1b263b),
            c(0xd8c3a5),
        ],
    },
    InkSet {
        name: "Ink & paper",
        background: c(0xfafafa),
        inks: &[
            c(0x111111),
            c(0x444444),
            c(0x888888),
            c(0xbbbbbb),
            c(0xffffff),
        ],
    },
];
