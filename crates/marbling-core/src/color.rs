//! sRGB colours as stored in designs (`"#rrggbb"`) and their linear-light form.

use std::fmt;
use std::str::FromStr;

/// An 8-bit-per-channel sRGB colour, written `"#rrggbb"` in design documents.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb8 {
    /// Red, 0..=255 (sRGB-encoded).
    pub r: u8,
    /// Green, 0..=255 (sRGB-encoded).
    pub g: u8,
    /// Blue, 0..=255 (sRGB-encoded).
    pub b: u8,
}

/// Why a colour string was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("must be a colour \"#rrggbb\", got {0:?}")]
pub struct ColorParseError(pub String);

impl Rgb8 {
    /// White, the default paper around a letterboxed image background.
    pub const WHITE: Rgb8 = Rgb8::new(255, 255, 255);

    /// Builds a colour from its three sRGB bytes.
    pub const fn new(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b }
    }

    /// The colour in linear light, each channel in 0.0..=1.0.
    pub fn to_linear(self) -> [f32; 3] {
        [
            srgb_to_linear(self.r),
            srgb_to_linear(self.g),
            srgb_to_linear(self.b),
        ]
    }
}

impl FromStr for Rgb8 {
    type Err = ColorParseError;

    /// Parses `#rrggbb` (hex digits in either case).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let err = || ColorParseError(s.to_owned());
        let hex = s.strip_prefix('#').ok_or_else(err)?;
        if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
            return Err(err());
        }
        let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).map_err(|_| err());
        Ok(Self::new(byte(0)?, byte(2)?, byte(4)?))
    }
}

impl fmt::Display for Rgb8 {
    /// Writes the canonical lowercase `#rrggbb` form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }
}

/// sRGB transfer function (IEC 61966-2-1): encoded byte → linear light in 0..=1.
pub fn srgb_to_linear(v: u8) -> f32 {
    let c = f64::from(v) / 255.0;
    let l = if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    };
    l as f32
}

/// Inverse sRGB transfer function: linear light in 0..=1 → encoded byte (rounded, clamped).
pub fn linear_to_srgb(l: f32) -> u8 {
    let l = f64::from(l).clamp(0.0, 1.0);
    let c = if l <= 0.003_130_8 {
        l * 12.92
    } else {
        1.055 * l.powf(1.0 / 2.4) - 0.055
    };
    (c * 255.0).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_round_trip_and_case() {
        let c: Rgb8 = "#1D3557".parse().expect("valid");
        assert_eq!(c, Rgb8::new(0x1d, 0x35, 0x57));
        assert_eq!(c.to_string(), "#1d3557");
    }

    #[test]
    fn hex_rejects_bad_forms() {
        for bad in [
            "1d3557", "#1d355", "#1d35577", "#1d35zz", "", "#", "#+1d355",
        ] {
            assert!(bad.parse::<Rgb8>().is_err(), "{bad:?} accepted");
        }
    }

    #[test]
    fn every_byte_survives_linear_round_trip() {
        for v in 0..=255u8 {
            assert_eq!(linear_to_srgb(srgb_to_linear(v)), v);
        }
    }
}
