//! Colour ramps: evenly spaced sRGB stops interpolated linearly, and the named palettes.

use std::fmt;

/// An sRGB colour with components in [0, 1].
pub type Rgb = [f32; 3];

/// Parses `"#rrggbb"` into an sRGB colour in [0, 1].
#[must_use]
pub fn parse_hex(s: &str) -> Option<Rgb> {
    let hex = s.strip_prefix('#')?;
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).ok();
    Some([
        f32::from(byte(0)?) / 255.0,
        f32::from(byte(2)?) / 255.0,
        f32::from(byte(4)?) / 255.0,
    ])
}

/// Names of the built-in palettes, in [`ColorRamp::named`].
pub const PALETTES: &[&str] = &[
    "grey", "ink", "sepia", "ocean", "ember", "marble", "viridis",
];

/// A colour ramp: stops at t = 0, 1/(n−1), …, 1 in sRGB, interpolated linearly.
#[derive(Clone, PartialEq)]
pub struct ColorRamp {
    stops: Vec<Rgb>,
}

impl fmt::Debug for ColorRamp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_list().entries(&self.stops).finish()
    }
}

fn hex_list(list: &[&str]) -> Vec<Rgb> {
    list.iter().filter_map(|s| parse_hex(s)).collect()
}

impl ColorRamp {
    /// A ramp through `stops` (at least two).
    #[must_use]
    pub fn new(stops: Vec<Rgb>) -> Option<Self> {
        (stops.len() >= 2).then_some(Self { stops })
    }

    /// The built-in palette `name` (see [`PALETTES`]).
    #[must_use]
    pub fn named(name: &str) -> Option<Self> {
        let stops: &[&str] = match name {
            "grey" => &["#000000", "#ffffff"],
            "ink" => &["#0b1a2e", "#1d3557", "#6d7f99", "#f3ead7"],
            "sepia" => &["#2b1a0e", "#7a5230", "#c9a66b", "#f6ead2"],
            "ocean" => &["#03172f", "#0b4f6c", "#2a9d8f", "#a8dadc", "#f1faee"],
            "ember" => &["#1a0505", "#7a1010", "#e63946", "#f4a261", "#fff3b0"],
            "marble" => &["#1d3557", "#457b9d", "#f3ead7", "#c8553d", "#582f0e"],
            "viridis" => &["#440154", "#3b528b", "#21918c", "#5ec962", "#fde725"],
            _ => return None,
        };
        Self::new(hex_list(stops))
    }

    /// The name of the built-in palette this ramp is, if it is one.
    #[must_use]
    pub fn name(&self) -> Option<&'static str> {
        PALETTES
            .iter()
            .copied()
            .find(|n| Self::named(n).as_ref() == Some(self))
    }

    /// The stops, sRGB in [0, 1], evenly spaced from t = 0 to t = 1.
    #[must_use]
    pub fn stops(&self) -> &[Rgb] {
        &self.stops
    }

    /// The colour at t ∈ [0, 1] (clamped).
    #[must_use]
    pub fn sample(&self, t: f32) -> Rgb {
        let n = self.stops.len() - 1;
        let x = t.clamp(0.0, 1.0) * n as f32;
        let i = (x.floor() as usize).min(n - 1);
        let f = x - i as f32;
        let (a, b) = (self.stops[i], self.stops[i + 1]);
        [0, 1, 2].map(|k| a[k] + f * (b[k] - a[k]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn palettes_exist_and_interpolate() {
        for name in PALETTES {
            assert!(ColorRamp::named(name).is_some(), "{name}");
        }
        let g = ColorRamp::named("grey").expect("grey");
        assert_eq!(g.sample(0.5), [0.5, 0.5, 0.5]);
        assert_eq!(g.sample(2.0), [1.0, 1.0, 1.0]);
        assert_eq!(parse_hex("#ff0080"), Some([1.0, 0.0, 128.0 / 255.0]));
        assert_eq!(parse_hex("ff0080"), None);
    }
}
