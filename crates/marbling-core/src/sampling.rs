//! Antialiasing sample patterns: where inside each output pixel the design is sampled
//! and with what weight.
//!
//! Samples are averaged in linear light (then encoded back to sRGB), because a pixel
//! that is 50 % covered by black ink on white paper reflects half the light: averaging
//! the sRGB codes instead would make every ink edge look too dark and thin.

use std::fmt;
use std::str::FromStr;

/// One sample: offset from the pixel's top-left corner in output pixels, and weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Offset to the right, output pixels (0.5 = pixel centre).
    pub dx: f64,
    /// Offset downwards, output pixels.
    pub dy: f64,
    /// Weight in the pixel's average; a pattern's weights sum to 1.
    pub weight: f32,
}

const fn s(dx: f64, dy: f64, weight: f32) -> Sample {
    Sample { dx, dy, weight }
}

/// The single centre sample.
pub const CENTER: [Sample; 1] = [s(0.5, 0.5, 1.0)];
/// Rotated-grid 2×2 supersampling.
pub const RGSS: [Sample; 4] = [
    s(0.375, 0.125, 0.25),
    s(0.875, 0.375, 0.25),
    s(0.125, 0.625, 0.25),
    s(0.625, 0.875, 0.25),
];
/// Regular 4×4 grid at cell centres, row-major.
pub const GRID4: [Sample; 16] = {
    let mut g = [s(0.0, 0.0, 0.0625); 16];
    let mut i = 0;
    while i < 16 {
        g[i] = s(
            ((i % 4) as f64 + 0.5) / 4.0,
            ((i / 4) as f64 + 0.5) / 4.0,
            0.0625,
        );
        i += 1;
    }
    g
};
/// Quincunx: the centre (weight 1/2) and the four corners (1/8 each), corners shared
/// with the neighbouring pixels as in the classic pattern.
pub const QUINCUNX: [Sample; 5] = [
    s(0.5, 0.5, 0.5),
    s(0.0, 0.0, 0.125),
    s(1.0, 0.0, 0.125),
    s(0.0, 1.0, 0.125),
    s(1.0, 1.0, 0.125),
];
/// 8-rooks: one sample in every row and every column of an 8×8 sub-grid
/// (offsets of the common 8× multisample pattern, in 1/16 pixel).
pub const ROOKS8: [Sample; 8] = [
    s(0.5 + 1.0 / 16.0, 0.5 - 3.0 / 16.0, 0.125),
    s(0.5 - 1.0 / 16.0, 0.5 + 3.0 / 16.0, 0.125),
    s(0.5 + 5.0 / 16.0, 0.5 + 1.0 / 16.0, 0.125),
    s(0.5 - 3.0 / 16.0, 0.5 - 5.0 / 16.0, 0.125),
    s(0.5 - 5.0 / 16.0, 0.5 + 5.0 / 16.0, 0.125),
    s(0.5 - 7.0 / 16.0, 0.5 - 1.0 / 16.0, 0.125),
    s(0.5 + 3.0 / 16.0, 0.5 + 7.0 / 16.0, 0.125),
    s(0.5 + 7.0 / 16.0, 0.5 - 7.0 / 16.0, 0.125),
];

/// How each output pixel is sampled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Antialias {
    /// One sample at the pixel centre; exact colours, jagged edges.
    None,
    /// Rotated-grid 2×2 (4 samples), the default.
    #[default]
    Rgss,
    /// Regular 4×4 grid (16 samples).
    Grid4,
    /// Quincunx (centre + shared corners, 5 taps).
    Quincunx,
    /// 8-rooks (8 samples).
    Rooks8,
    /// RGSS first; the 4×4 grid (16 samples) replaces it only where the first 4 samples
    /// do not all have the same colour.
    Adaptive,
}

impl Antialias {
    /// Every mode, in the order shown to users.
    pub const ALL: [Antialias; 6] = [
        Antialias::None,
        Antialias::Rgss,
        Antialias::Grid4,
        Antialias::Quincunx,
        Antialias::Rooks8,
        Antialias::Adaptive,
    ];

    /// The mode's name as used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Antialias::None => "none",
            Antialias::Rgss => "rgss",
            Antialias::Grid4 => "grid4",
            Antialias::Quincunx => "quincunx",
            Antialias::Rooks8 => "rooks8",
            Antialias::Adaptive => "adaptive",
        }
    }

    /// The samples taken for every pixel (for `Adaptive`, the first pass; see
    /// [`Antialias::refinement`]).
    pub fn samples(self) -> &'static [Sample] {
        match self {
            Antialias::None => &CENTER,
            Antialias::Rgss | Antialias::Adaptive => &RGSS,
            Antialias::Grid4 => &GRID4,
            Antialias::Quincunx => &QUINCUNX,
            Antialias::Rooks8 => &ROOKS8,
        }
    }

    /// The samples that replace the first pass where its samples disagree, if any.
    pub fn refinement(self) -> Option<&'static [Sample]> {
        (self == Antialias::Adaptive).then_some(&GRID4[..])
    }
}

impl fmt::Display for Antialias {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// An unknown antialiasing mode name.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown antialiasing mode {0:?}; expected one of none, rgss, grid4, quincunx, rooks8, adaptive"
)]
pub struct UnknownAntialias(pub String);

impl FromStr for Antialias {
    type Err = UnknownAntialias;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Antialias::ALL
            .into_iter()
            .find(|a| a.name() == s)
            .ok_or_else(|| UnknownAntialias(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_sum_to_one_and_names_round_trip() {
        for a in Antialias::ALL {
            let sum: f32 = a.samples().iter().map(|s| s.weight).sum();
            assert!((sum - 1.0).abs() < 1e-6, "{a}: {sum}");
            assert_eq!(a.name().parse::<Antialias>(), Ok(a));
        }
        assert!("ssaa".parse::<Antialias>().is_err());
    }

    #[test]
    fn rooks8_is_one_per_row_and_column() {
        let mut cols = [0; 8];
        let mut rows = [0; 8];
        for s in ROOKS8 {
            cols[(s.dx * 8.0) as usize] += 1;
            rows[(s.dy * 8.0) as usize] += 1;
        }
        assert_eq!(cols, [1; 8]);
        assert_eq!(rows, [1; 8]);
    }
}
