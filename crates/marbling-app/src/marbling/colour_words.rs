//! Ink colours as a reader sees them: a step caption's hex code ("100 drops of #3b2a1a")
//! is shown as a swatch of the colour and its nearest plain name ("■ dark brown").

use egui::text::{LayoutJob, TextFormat};
use egui::{Color32, FontId};
use marbling_core::Rgb8;

/// Plain colour names and the sRGB colour each stands for (the inks of the patterns and
/// palettes name themselves by the nearest one).
const NAMES: [(&str, [u8; 3]); 25] = [
    ("black", [0, 0, 0]),
    ("charcoal", [54, 54, 54]),
    ("grey", [128, 128, 128]),
    ("silver", [192, 192, 192]),
    ("white", [255, 255, 255]),
    ("cream", [243, 234, 215]),
    ("dark brown", [59, 42, 26]),
    ("brown", [120, 72, 36]),
    ("tan", [200, 160, 110]),
    ("ochre", [204, 150, 40]),
    ("gold", [224, 176, 64]),
    ("yellow", [240, 210, 40]),
    ("orange", [230, 126, 34]),
    ("red", [192, 57, 43]),
    ("dark red", [120, 20, 20]),
    ("pink", [230, 140, 160]),
    ("purple", [120, 60, 140]),
    ("violet", [160, 110, 200]),
    ("navy", [30, 40, 90]),
    ("blue", [59, 91, 146]),
    ("sky blue", [120, 170, 220]),
    ("teal", [30, 130, 130]),
    ("green", [50, 130, 70]),
    ("dark green", [25, 70, 40]),
    ("olive", [120, 120, 40]),
];

/// The plain name nearest to `c` (the "redmean" weighted distance in sRGB, close to
/// how different two colours look at this coarseness).
pub fn colour_name(c: Rgb8) -> &'static str {
    let distance = |[r, g, b]: [u8; 3]| {
        let mean = (f64::from(c.r) + f64::from(r)) / 2.0;
        let d = |a: u8, b: u8| f64::from(a) - f64::from(b);
        let (dr, dg, db) = (d(c.r, r), d(c.g, g), d(c.b, b));
        (2.0 + mean / 256.0) * dr * dr + 4.0 * dg * dg + (2.0 + (255.0 - mean) / 256.0) * db * db
    };
    NAMES
        .iter()
        .min_by(|a, b| distance(a.1).total_cmp(&distance(b.1)))
        .map_or("ink", |(name, _)| name)
}

/// The colour of a `#rrggbb` code at the start of `s` that is not followed by another
/// hex digit.
fn hex_at(s: &str) -> Option<Rgb8> {
    let digits = s.strip_prefix('#')?.get(..6)?;
    if !digits.chars().all(|c| c.is_ascii_hexdigit())
        || s[7..].starts_with(|c: char| c.is_ascii_hexdigit())
    {
        return None;
    }
    let v = u32::from_str_radix(digits, 16).ok()?;
    let [_, r, g, b] = v.to_be_bytes();
    Some(Rgb8::new(r, g, b))
}

/// `text` laid out in `font` and `color`, each `#rrggbb` in it shown as a swatch of that
/// colour and the colour's name.
pub fn caption_job(text: &str, font: FontId, color: Color32) -> LayoutJob {
    let format = |color| TextFormat::simple(font.clone(), color);
    let mut job = LayoutJob::default();
    let mut plain = String::new();
    let mut rest = text;
    while let Some(i) = rest.find('#') {
        plain.push_str(&rest[..i]);
        rest = &rest[i..];
        match hex_at(rest) {
            Some(c) => {
                job.append(&std::mem::take(&mut plain), 0.0, format(color));
                job.append("■", 0.0, format(Color32::from_rgb(c.r, c.g, c.b)));
                plain.push(' ');
                plain.push_str(colour_name(c));
                rest = &rest[7..];
            }
            None => {
                plain.push('#');
                rest = &rest[1..];
            }
        }
    }
    plain.push_str(rest);
    job.append(&plain, 0.0, format(color));
    job
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inks_are_named_by_the_nearest_plain_colour() {
        for (hex, name) in [
            (0x3b2a1a, "dark brown"),
            (0xc0392b, "red"),
            (0x3b5b92, "blue"),
            (0x0a0a0a, "black"),
            (0xf4f4f4, "white"),
            (0x1a2a6c, "navy"),
            (0x2e8b57, "green"),
            (0xffd700, "yellow"),
        ] {
            let [_, r, g, b] = u32::to_be_bytes(hex);
            assert_eq!(colour_name(Rgb8::new(r, g, b)), name, "#{hex:06x}");
        }
    }

    #[test]
    fn a_caption_shows_each_hex_code_as_a_swatch_and_a_name() {
        let job = caption_job(
            "Throw the vein colour: 100 drops of #3b2a1a, radius 14–27.9 px; #1, #+12345 and #abcdef0 stay",
            FontId::default(),
            Color32::WHITE,
        );
        assert_eq!(
            job.text,
            "Throw the vein colour: 100 drops of ■ dark brown, radius 14–27.9 px; #1, #+12345 and #abcdef0 stay"
        );
        // Three sections: the text before, the swatch in the ink's colour, the rest.
        let colours: Vec<Color32> = job.sections.iter().map(|s| s.format.color).collect();
        assert_eq!(
            colours,
            [
                Color32::WHITE,
                Color32::from_rgb(0x3b, 0x2a, 0x1a),
                Color32::WHITE
            ]
        );
        assert_eq!(
            caption_job("no codes", FontId::default(), Color32::WHITE).text,
            "no codes"
        );
    }
}
