//! Ink palettes brought in from elsewhere: a GIMP `.gpl` file, a list of hex colours
//! pasted as text, or the main colours of a picture (k-means on its pixels); and the
//! `.gpl` written back. Not the noise background's colour ramp ([`crate::Palette`]).

use crate::{Rgb8, RgbaImage};
use std::fmt::Write as _;

/// Most colours an imported palette keeps (a larger `.gpl` keeps its first ones).
pub const MAX_PALETTE_INKS: usize = 16;
/// The colours a picture may be reduced to.
pub const PICTURE_INKS: std::ops::RangeInclusive<usize> = 2..=10;
/// Pixels of a picture looked at by k-means (an even spread of them), at most.
const KMEANS_SAMPLES: usize = 40_000;
/// k-means rounds, at most (it stops sooner once no pixel changes cluster).
const KMEANS_ROUNDS: usize = 30;

/// A named list of ink colours.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InkPalette {
    /// Name (the `.gpl`'s `Name:`, or where it came from).
    pub name: String,
    /// The colours, 1 to [`MAX_PALETTE_INKS`].
    pub colors: Vec<Rgb8>,
}

/// Why a palette could not be read; each names the line, colour or number at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PaletteImportError {
    /// The file does not start with `GIMP Palette`.
    #[error("line 1: a GIMP palette starts with \"GIMP Palette\", got {0:?}")]
    NotGpl(String),
    /// A colour line of a `.gpl` is not three numbers 0–255.
    #[error("line {line}: expected three numbers 0–255 (R G B) and a name, got {text:?}")]
    BadGplLine {
        /// 1-based line number.
        line: usize,
        /// The line.
        text: String,
    },
    /// A word of a pasted list is not a hex colour.
    #[error("colour {index}: {text:?} is not a hex colour (#rrggbb or #rgb)")]
    BadHex {
        /// 1-based position in the list.
        index: usize,
        /// The word.
        text: String,
    },
    /// Nothing to make a palette of.
    #[error("no colours in {0}")]
    Empty(&'static str),
    /// A picture's colour count outside [`PICTURE_INKS`].
    #[error("a picture gives 2 to 10 colours, not {0}")]
    BadCount(usize),
    /// Neither text nor a picture.
    #[error("not a GIMP palette, a picture (PNG, JPEG, WebP) or text of hex colours")]
    NotText,
    /// The picture file could not be read.
    #[error("{0}")]
    Picture(#[from] crate::ImageError),
}

impl InkPalette {
    /// Reads a file of any kind this module knows, told apart by its content: a GIMP
    /// palette, a picture (PNG, JPEG, WebP: its `k` main colours) or text of hex colours.
    /// A palette without a name of its own takes `file_name`'s stem.
    pub fn import(file_name: &str, bytes: &[u8], k: usize) -> Result<Self, PaletteImportError> {
        let text = std::str::from_utf8(bytes)
            .ok()
            .map(|t| t.trim_start_matches('\u{feff}'));
        let picture = bytes.starts_with(b"\x89PNG")
            || bytes.starts_with(&[0xff, 0xd8])
            || (bytes.starts_with(b"RIFF") && bytes.get(8..12) == Some(b"WEBP"));
        let stem = std::path::Path::new(file_name).file_stem().map_or_else(
            || file_name.to_owned(),
            |s| s.to_string_lossy().into_owned(),
        );
        let mut palette = match text {
            Some(t) if t.trim_start().starts_with("GIMP Palette") => {
                return Self::from_gpl(t.trim_start());
            }
            _ if picture => Self::from_picture_file(bytes, k)?,
            Some(t) => Self::from_hex_list(t)?,
            None => return Err(PaletteImportError::NotText),
        };
        palette.name = stem;
        Ok(palette)
    }

    /// Reads a GIMP palette (`GIMP Palette`, `Name:`/`Columns:` headers, `#` comments,
    /// lines of `R G B [name]`); keeps the first [`MAX_PALETTE_INKS`] colours.
    pub fn from_gpl(text: &str) -> Result<Self, PaletteImportError> {
        let mut lines = text.lines().enumerate();
        let first = lines.next().map_or("", |(_, l)| l.trim());
        if first != "GIMP Palette" {
            return Err(PaletteImportError::NotGpl(first.chars().take(40).collect()));
        }
        let mut name = String::from("GIMP palette");
        let mut colors = Vec::new();
        for (i, raw) in lines {
            let line = raw.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            if let Some(n) = line.strip_prefix("Name:") {
                name = n.trim().to_owned();
                continue;
            }
            if line.starts_with("Columns:") {
                continue;
            }
            let bad = || PaletteImportError::BadGplLine {
                line: i + 1,
                text: line.chars().take(40).collect(),
            };
            let mut words = line.split_whitespace();
            let mut channel = || -> Result<u8, PaletteImportError> {
                words
                    .next()
                    .and_then(|w| w.parse::<u8>().ok())
                    .ok_or_else(bad)
            };
            let (r, g, b) = (channel()?, channel()?, channel()?);
            if colors.len() < MAX_PALETTE_INKS {
                colors.push(Rgb8::new(r, g, b));
            }
        }
        if colors.is_empty() {
            return Err(PaletteImportError::Empty("the GIMP palette"));
        }
        Ok(Self { name, colors })
    }

    /// Reads hex colours separated by spaces, commas, semicolons or new lines
    /// (`#1d3557, e63946 #abc`); keeps the first [`MAX_PALETTE_INKS`].
    pub fn from_hex_list(text: &str) -> Result<Self, PaletteImportError> {
        let words = text
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|w| !w.is_empty());
        let mut colors = Vec::new();
        for (i, word) in words.enumerate() {
            let color = parse_hex(word).ok_or_else(|| PaletteImportError::BadHex {
                index: i + 1,
                text: word.chars().take(20).collect(),
            })?;
            if colors.len() < MAX_PALETTE_INKS {
                colors.push(color);
            }
        }
        if colors.is_empty() {
            return Err(PaletteImportError::Empty("the text"));
        }
        Ok(Self {
            name: "Pasted".to_owned(),
            colors,
        })
    }

    /// The `k` main colours of a picture file (PNG, JPEG or WebP; see
    /// [`InkPalette::from_image`]).
    pub fn from_picture_file(bytes: &[u8], k: usize) -> Result<Self, PaletteImportError> {
        if !PICTURE_INKS.contains(&k) {
            return Err(PaletteImportError::BadCount(k));
        }
        let pixels = crate::image_background::ImagePixels::decode(bytes)?;
        Self::from_image(
            &RgbaImage {
                width: pixels.width,
                height: pixels.height,
                pixels: pixels.rgba,
            },
            k,
        )
    }

    /// The `k` main colours of `image` (k-means in sRGB on an even spread of its opaque
    /// pixels, started from colours far apart), the most common first.
    pub fn from_image(image: &RgbaImage, k: usize) -> Result<Self, PaletteImportError> {
        if !PICTURE_INKS.contains(&k) {
            return Err(PaletteImportError::BadCount(k));
        }
        let opaque = image.pixels.chunks_exact(4).filter(|p| p[3] >= 128);
        let count = opaque.clone().count();
        let step = count.div_ceil(KMEANS_SAMPLES).max(1);
        let points: Vec<[f64; 3]> = opaque
            .step_by(step)
            .map(|p| [f64::from(p[0]), f64::from(p[1]), f64::from(p[2])])
            .collect();
        if points.is_empty() {
            return Err(PaletteImportError::Empty("the picture (no opaque pixels)"));
        }
        let colors = kmeans(&points, k);
        Ok(Self {
            name: "Picture".to_owned(),
            colors,
        })
    }

    /// The palette as a GIMP `.gpl` file (each colour named by its hex).
    pub fn to_gpl(&self) -> String {
        let mut out = String::from("GIMP Palette\n");
        let name: String = self.name.chars().filter(|c| !c.is_control()).collect();
        let _ = writeln!(out, "Name: {name}");
        let _ = writeln!(out, "Columns: {}", self.colors.len());
        out.push_str("#\n");
        for c in &self.colors {
            let _ = writeln!(out, "{:3} {:3} {:3}\t{c}", c.r, c.g, c.b);
        }
        out
    }
}

/// `#rrggbb`, `rrggbb`, `#rgb` or `rgb`.
fn parse_hex(word: &str) -> Option<Rgb8> {
    let hex = word.strip_prefix('#').unwrap_or(word);
    if !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return None;
    }
    let digit = |i: usize| u8::from_str_radix(&hex[i..=i], 16).ok();
    match hex.len() {
        6 => format!("#{hex}").parse().ok(),
        3 => Some(Rgb8::new(digit(0)? * 17, digit(1)? * 17, digit(2)? * 17)),
        _ => None,
    }
}

fn distance2(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum()
}

/// k-means of `points` into at most `k` clusters (fewer when there are fewer distinct
/// colours): the first centre the point nearest the mean, each next the point farthest
/// from the centres so far; Lloyd rounds until no point moves. Centres, largest first.
fn kmeans(points: &[[f64; 3]], k: usize) -> Vec<Rgb8> {
    let mean = points
        .iter()
        .fold([0.0; 3], |a, p| [a[0] + p[0], a[1] + p[1], a[2] + p[2]]);
    let mean = mean.map(|v| v / points.len() as f64);
    let nearest = |c: &[f64; 3]| {
        points
            .iter()
            .min_by(|a, b| distance2(a, c).total_cmp(&distance2(b, c)))
            .copied()
    };
    let mut centres: Vec<[f64; 3]> = nearest(&mean).into_iter().collect();
    let mut gap: Vec<f64> = points.iter().map(|p| distance2(p, &centres[0])).collect();
    while centres.len() < k {
        let Some((far, d)) = gap
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(i, d)| (points[i], *d))
        else {
            break;
        };
        if d == 0.0 {
            break;
        }
        centres.push(far);
        for (g, p) in gap.iter_mut().zip(points) {
            *g = g.min(distance2(p, &far));
        }
    }
    let mut owner = vec![usize::MAX; points.len()];
    let mut sizes = vec![0usize; centres.len()];
    for _ in 0..KMEANS_ROUNDS {
        let mut moved = false;
        for (o, p) in owner.iter_mut().zip(points) {
            let best = (0..centres.len())
                .min_by(|&a, &b| distance2(p, &centres[a]).total_cmp(&distance2(p, &centres[b])))
                .unwrap_or(0);
            moved |= *o != best;
            *o = best;
        }
        let mut sums = vec![[0.0; 3]; centres.len()];
        sizes.iter_mut().for_each(|s| *s = 0);
        for (&o, p) in owner.iter().zip(points) {
            sizes[o] += 1;
            for ch in 0..3 {
                sums[o][ch] += p[ch];
            }
        }
        for ((c, s), &n) in centres.iter_mut().zip(&sums).zip(&sizes) {
            if n > 0 {
                *c = s.map(|v| v / n as f64);
            }
        }
        if !moved {
            break;
        }
    }
    let mut order: Vec<usize> = (0..centres.len()).filter(|&i| sizes[i] > 0).collect();
    order.sort_by_key(|&i| std::cmp::Reverse(sizes[i]));
    let byte = |v: f64| v.round().clamp(0.0, 255.0) as u8;
    order
        .into_iter()
        .map(|i| {
            Rgb8::new(
                byte(centres[i][0]),
                byte(centres[i][1]),
                byte(centres[i][2]),
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const GPL: &str = "GIMP Palette\nName: Ebru\nColumns: 3\n#\n 29  53  87\tIndigo\n230  57  70 Red\n# a comment\n\n244 236 216\n";

    #[test]
    fn a_gpl_reads_and_writes_back() -> Result<(), PaletteImportError> {
        let p = InkPalette::from_gpl(GPL)?;
        assert_eq!(p.name, "Ebru");
        assert_eq!(
            p.colors,
            [
                Rgb8::new(29, 53, 87),
                Rgb8::new(230, 57, 70),
                Rgb8::new(244, 236, 216)
            ]
        );
        assert_eq!(InkPalette::from_gpl(&p.to_gpl())?, p);
        assert!(p.to_gpl().contains(" 29  53  87\t#1d3557\n"));
        Ok(())
    }

    #[test]
    fn a_bad_gpl_is_named_by_line() {
        assert_eq!(
            InkPalette::from_gpl("JASC-PAL\n0100\n"),
            Err(PaletteImportError::NotGpl("JASC-PAL".to_owned()))
        );
        let err = InkPalette::from_gpl("GIMP Palette\nName: x\n10 20 30\n300 0 0 Too red\n");
        assert_eq!(
            err.map_err(|e| e.to_string()),
            Err(
                "line 4: expected three numbers 0–255 (R G B) and a name, got \"300 0 0 Too red\""
                    .to_owned()
            )
        );
        assert_eq!(
            InkPalette::from_gpl("GIMP Palette\nName: empty\n"),
            Err(PaletteImportError::Empty("the GIMP palette"))
        );
    }

    #[test]
    fn pasted_hex_lists_read_every_form_and_name_a_bad_word() -> Result<(), PaletteImportError> {
        let p = InkPalette::from_hex_list("#1d3557, e63946;\n#abc  FFF")?;
        assert_eq!(
            p.colors,
            [
                Rgb8::new(0x1d, 0x35, 0x57),
                Rgb8::new(0xe6, 0x39, 0x46),
                Rgb8::new(0xaa, 0xbb, 0xcc),
                Rgb8::new(255, 255, 255)
            ]
        );
        assert_eq!(
            InkPalette::from_hex_list("#112233 #12345 #000"),
            Err(PaletteImportError::BadHex {
                index: 2,
                text: "#12345".to_owned()
            })
        );
        assert_eq!(
            InkPalette::from_hex_list(" ,; "),
            Err(PaletteImportError::Empty("the text"))
        );
        let many: String = (0..40).map(|i| format!("#0000{i:02x} ")).collect();
        assert_eq!(
            InkPalette::from_hex_list(&many)?.colors.len(),
            MAX_PALETTE_INKS
        );
        Ok(())
    }

    #[test]
    fn import_tells_the_kinds_apart() -> Result<(), PaletteImportError> {
        assert_eq!(
            InkPalette::import("ebru.gpl", GPL.as_bytes(), 5)?.name,
            "Ebru"
        );
        let hex = InkPalette::import("colours.txt", b"#102030 #405060", 5)?;
        assert_eq!((hex.name.as_str(), hex.colors.len()), ("colours", 2));
        let png = RgbaImage::filled(4, 4, [200, 10, 10, 255])
            .to_png()
            .map_err(|_| PaletteImportError::NotText)?;
        let pic = InkPalette::import("red.png", &png, 3)?;
        assert_eq!(
            (pic.name.as_str(), pic.colors.as_slice()),
            ("red", &[Rgb8::new(200, 10, 10)][..])
        );
        assert_eq!(
            InkPalette::import("x.bin", &[0xff, 0xfe, 0x00, 0x80], 3),
            Err(PaletteImportError::NotText)
        );
        let broken = InkPalette::import("bad.png", b"\x89PNG\r\n\x1a\n broken", 3);
        assert!(
            matches!(broken, Err(PaletteImportError::Picture(_))),
            "{broken:?}"
        );
        Ok(())
    }

    #[test]
    fn a_picture_of_three_flat_colours_gives_those_three_most_common_first()
    -> Result<(), PaletteImportError> {
        // 60 % indigo, 30 % red, 10 % paper, with a little noise on each.
        let (w, h) = (100u32, 50u32);
        let mut img = RgbaImage::filled(w, h, [0, 0, 0, 255]);
        for y in 0..h {
            for x in 0..w {
                let base: [u8; 3] = match x {
                    0..60 => [29, 53, 87],
                    60..90 => [230, 57, 70],
                    _ => [244, 236, 216],
                };
                let jitter = ((x * 7 + y * 13) % 5) as u8;
                let i = ((y * w + x) * 4) as usize;
                for (px, b) in img.pixels[i..i + 3].iter_mut().zip(base) {
                    *px = b.saturating_add(jitter).saturating_sub(2);
                }
            }
        }
        let p = InkPalette::from_image(&img, 3)?;
        let want = [[29, 53, 87], [230, 57, 70], [244, 236, 216]];
        assert_eq!(p.colors.len(), 3);
        for (got, want) in p.colors.iter().zip(want) {
            let d = [got.r, got.g, got.b]
                .iter()
                .zip(want)
                .map(|(a, b)| a.abs_diff(b))
                .max();
            assert!(d <= Some(1), "{got} vs {want:?}");
        }
        // More clusters than colours: no empty or repeated ones.
        let flat = RgbaImage::filled(8, 8, [10, 20, 30, 255]);
        assert_eq!(
            InkPalette::from_image(&flat, 5)?.colors,
            [Rgb8::new(10, 20, 30)]
        );
        assert_eq!(
            InkPalette::from_image(&flat, 11),
            Err(PaletteImportError::BadCount(11))
        );
        let clear = RgbaImage::filled(8, 8, [10, 20, 30, 0]);
        assert!(InkPalette::from_image(&clear, 3).is_err());
        Ok(())
    }
}
