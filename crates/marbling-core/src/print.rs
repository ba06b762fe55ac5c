//! Print sizes: a sheet in millimetres, centimetres or inches at a DPI, with a bleed,
//! turned into the output pixels and the [`Window`] of the design they show.
//!
//! The design covers the trimmed sheet (scaled to fill it, centred, what overhangs
//! cropped), and the bleed is more of the design around it, walked back like every
//! other point — never a border. Pixel sides are `round(mm / 25.4 × dpi)`.

use crate::Design;
use crate::render::Window;
use std::fmt;
use std::str::FromStr;

/// Millimetres per inch.
pub const MM_PER_INCH: f64 = 25.4;
/// DPI offered by the app's print panel.
pub const PRINT_DPIS: [f64; 3] = [150.0, 300.0, 600.0];
/// Accepted DPI range.
pub const DPI_RANGE: std::ops::RangeInclusive<f64> = 10.0..=4800.0;
/// Accepted bleed, millimetres per side.
pub const BLEED_RANGE_MM: std::ops::RangeInclusive<f64> = 0.0..=50.0;
/// Accepted sheet side, millimetres (up to 10 m).
pub const SIDE_RANGE_MM: std::ops::RangeInclusive<f64> = 1.0..=10_000.0;

/// A named paper size, portrait (width ≤ height), millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperPreset {
    /// Name shown and accepted by `--print` (case-insensitive).
    pub name: &'static str,
    /// Short side, mm.
    pub short_mm: f64,
    /// Long side, mm.
    pub long_mm: f64,
}

/// The presets: ISO A4 and A3, US Letter and the 50×70 cm sheet of marbled end-papers.
pub const PAPER_PRESETS: [PaperPreset; 4] = [
    PaperPreset {
        name: "A4",
        short_mm: 210.0,
        long_mm: 297.0,
    },
    PaperPreset {
        name: "A3",
        short_mm: 297.0,
        long_mm: 420.0,
    },
    PaperPreset {
        name: "Letter",
        short_mm: 215.9,
        long_mm: 279.4,
    },
    PaperPreset {
        name: "Endpaper",
        short_mm: 500.0,
        long_mm: 700.0,
    },
];

impl PaperPreset {
    /// The preset turned to the design's orientation (landscape for a wide design).
    pub fn for_design(&self, design: &Design) -> SheetSize {
        let (w, h) = if design.width > design.height {
            (self.long_mm, self.short_mm)
        } else {
            (self.short_mm, self.long_mm)
        };
        SheetSize {
            width_mm: w,
            height_mm: h,
        }
    }

    /// The preset called `name` (case-insensitive; "US Letter" and "50x70cm" too).
    pub fn named(name: &str) -> Option<&'static PaperPreset> {
        let n = name.trim().to_ascii_lowercase().replace([' ', '-'], "");
        let n = match n.as_str() {
            "usletter" => "letter",
            "50x70cm" | "endpapers" => "endpaper",
            other => other,
        };
        PAPER_PRESETS
            .iter()
            .find(|p| p.name.to_ascii_lowercase() == n)
    }
}

/// A length unit of a sheet size.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Millimetres.
    Mm,
    /// Centimetres.
    Cm,
    /// Inches.
    In,
}

impl Unit {
    /// Every unit, in the order the app offers them.
    pub const ALL: [Unit; 3] = [Unit::Mm, Unit::Cm, Unit::In];

    /// Millimetres in one unit.
    pub fn mm(self) -> f64 {
        match self {
            Unit::Mm => 1.0,
            Unit::Cm => 10.0,
            Unit::In => MM_PER_INCH,
        }
    }

    /// The suffix written after a size (`mm`, `cm`, `in`).
    pub fn suffix(self) -> &'static str {
        match self {
            Unit::Mm => "mm",
            Unit::Cm => "cm",
            Unit::In => "in",
        }
    }
}

/// The trimmed sheet's size, millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SheetSize {
    /// Width, mm.
    pub width_mm: f64,
    /// Height, mm.
    pub height_mm: f64,
}

impl FromStr for SheetSize {
    type Err = PrintError;

    /// `WxH` with a unit suffix: `297x210mm`, `21x29.7cm`, `8.5x11in` (× or X too).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let bad = || PrintError::BadSize(s.to_owned());
        let t = s.trim().to_ascii_lowercase();
        let unit = Unit::ALL
            .into_iter()
            .find(|u| t.ends_with(u.suffix()))
            .ok_or_else(bad)?;
        let number = &t[..t.len() - unit.suffix().len()];
        let (w, h) = number.split_once(['x', '×']).ok_or_else(bad)?;
        let side = |v: &str| v.trim().parse::<f64>().map_err(|_| bad());
        let size = SheetSize {
            width_mm: side(w)? * unit.mm(),
            height_mm: side(h)? * unit.mm(),
        };
        for v in [size.width_mm, size.height_mm] {
            if !(v.is_finite() && SIDE_RANGE_MM.contains(&v)) {
                return Err(PrintError::SideOutOfRange(v));
            }
        }
        Ok(size)
    }
}

/// What went wrong with a print size.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PrintError {
    /// The size is not `WxH` with a unit.
    #[error(
        "expected a sheet size like 297x210mm, 21x29.7cm or 8.5x11in (or A4, A3, Letter, Endpaper), got {0:?}"
    )]
    BadSize(String),
    /// A side is outside [`SIDE_RANGE_MM`].
    #[error("a sheet side must be 1 to 10,000 mm, got {0} mm")]
    SideOutOfRange(f64),
    /// The DPI is outside [`DPI_RANGE`].
    #[error("the DPI must be 10 to 4800, got {0}")]
    BadDpi(f64),
    /// The bleed is not a length.
    #[error("expected a bleed like 3mm, 0.3cm or 0.125in, got {0:?}")]
    BadBleedText(String),
    /// The bleed is outside [`BLEED_RANGE_MM`].
    #[error("the bleed must be 0 to 50 mm, got {0} mm")]
    BadBleed(f64),
}

/// A print: the trimmed sheet, its resolution and the bleed around it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Print {
    /// The trimmed sheet.
    pub sheet: SheetSize,
    /// Dots (output pixels) per inch.
    pub dpi: f64,
    /// Extra design on every side, millimetres, cut off after printing.
    pub bleed_mm: f64,
}

impl Print {
    /// Checks the DPI and bleed ranges (the sheet is checked when parsed).
    pub fn check(&self) -> Result<(), PrintError> {
        for v in [self.sheet.width_mm, self.sheet.height_mm] {
            if !(v.is_finite() && SIDE_RANGE_MM.contains(&v)) {
                return Err(PrintError::SideOutOfRange(v));
            }
        }
        if !(self.dpi.is_finite() && DPI_RANGE.contains(&self.dpi)) {
            return Err(PrintError::BadDpi(self.dpi));
        }
        if !(self.bleed_mm.is_finite() && BLEED_RANGE_MM.contains(&self.bleed_mm)) {
            return Err(PrintError::BadBleed(self.bleed_mm));
        }
        Ok(())
    }

    /// Output pixels for `mm` millimetres.
    pub fn pixels_for(&self, mm: f64) -> f64 {
        mm / MM_PER_INCH * self.dpi
    }

    /// The bleed, whole output pixels per side.
    pub fn bleed_pixels(&self) -> u32 {
        self.pixels_for(self.bleed_mm).round() as u32
    }

    /// The trimmed sheet, whole output pixels (each side at least 1).
    pub fn trim_pixels(&self) -> (u32, u32) {
        let side = |mm: f64| self.pixels_for(mm).round().max(1.0) as u32;
        (side(self.sheet.width_mm), side(self.sheet.height_mm))
    }

    /// The whole output with its bleed, pixels.
    pub fn pixels(&self) -> (u32, u32) {
        let (w, h) = self.trim_pixels();
        let b = 2 * self.bleed_pixels();
        (w + b, h + b)
    }

    /// Pixels per metre, as a PNG's `pHYs` chunk stores the DPI.
    pub fn pixels_per_metre(&self) -> u32 {
        (self.dpi * 1000.0 / MM_PER_INCH).round() as u32
    }

    /// The window of `design` this print shows: the design scaled to cover the trimmed
    /// sheet and centred on it, the bleed more of the design around.
    pub fn window(&self, design: &Design) -> Window {
        let (tw, th) = self.trim_pixels();
        let (dw, dh) = (f64::from(design.width), f64::from(design.height));
        let scale = (f64::from(tw) / dw).max(f64::from(th) / dh);
        let b = f64::from(self.bleed_pixels());
        let (w, h) = self.pixels();
        Window {
            x0: (dw - f64::from(tw) / scale) / 2.0 - b / scale,
            y0: (dh - f64::from(th) / scale) / 2.0 - b / scale,
            scale,
            width: w,
            height: h,
        }
    }
}

impl fmt::Display for Print {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}×{} mm at {} DPI",
            self.sheet.width_mm, self.sheet.height_mm, self.dpi
        )?;
        if self.bleed_mm > 0.0 {
            write!(f, " with a {} mm bleed", self.bleed_mm)?;
        }
        Ok(())
    }
}

/// Reads a `--bleed`: millimetres with an optional unit (`3mm`, `0.3cm`, `0.125in`, `3`).
pub fn parse_bleed(s: &str) -> Result<f64, PrintError> {
    let t = s.trim().to_ascii_lowercase();
    let (number, unit) = Unit::ALL
        .into_iter()
        .find_map(|u| t.strip_suffix(u.suffix()).map(|n| (n.to_owned(), u)))
        .unwrap_or((t.clone(), Unit::Mm));
    let mm = number
        .trim()
        .parse::<f64>()
        .map_err(|_| PrintError::BadBleedText(s.trim().to_owned()))?
        * unit.mm();
    if !(mm.is_finite() && BLEED_RANGE_MM.contains(&mm)) {
        return Err(PrintError::BadBleed(mm));
    }
    Ok(mm)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn design(w: u32, h: u32) -> Design {
        Design::new(w, h, crate::Rgb8::new(240, 236, 224))
    }

    #[test]
    fn sizes_parse_in_every_unit() -> Result<(), PrintError> {
        let a4: SheetSize = "297x210mm".parse()?;
        assert_eq!((a4.width_mm, a4.height_mm), (297.0, 210.0));
        let cm: SheetSize = "21×29.7cm".parse()?;
        assert!((cm.width_mm - 210.0).abs() < 1e-9 && (cm.height_mm - 297.0).abs() < 1e-9);
        let inch: SheetSize = "8.5X11in".parse()?;
        assert!((inch.width_mm - 215.9).abs() < 1e-9);
        for bad in [
            "297x210",
            "297mm",
            "axbmm",
            "0x10mm",
            "20000x10mm",
            "nanx5mm",
        ] {
            assert!(bad.parse::<SheetSize>().is_err(), "{bad} parsed");
        }
        assert_eq!(parse_bleed("3mm"), Ok(3.0));
        assert_eq!(parse_bleed("3"), Ok(3.0));
        assert!((parse_bleed("0.125in")? - 3.175).abs() < 1e-12);
        assert_eq!(parse_bleed("-1mm"), Err(PrintError::BadBleed(-1.0)));
        assert_eq!(
            parse_bleed(" wide "),
            Err(PrintError::BadBleedText("wide".to_owned()))
        );
        Ok(())
    }

    #[test]
    fn pixels_are_millimetres_over_25_4_times_dpi() {
        let print = Print {
            sheet: SheetSize {
                width_mm: 297.0,
                height_mm: 210.0,
            },
            dpi: 300.0,
            bleed_mm: 3.0,
        };
        // 297 mm / 25.4 × 300 = 3507.87 → 3508; 210 → 2480.3 → 2480; 3 mm → 35.4 → 35.
        assert_eq!(print.trim_pixels(), (3508, 2480));
        assert_eq!(print.bleed_pixels(), 35);
        assert_eq!(print.pixels(), (3578, 2550));
        assert_eq!(print.pixels_per_metre(), 11811);
        assert_eq!(print.to_string(), "297×210 mm at 300 DPI with a 3 mm bleed");
        assert!(print.check().is_ok());
        assert_eq!(
            Print { dpi: 5.0, ..print }.check(),
            Err(PrintError::BadDpi(5.0))
        );
    }

    #[test]
    fn the_design_covers_the_trim_and_the_bleed_reaches_past_it() {
        // A 1000×500 design on a square 100 mm sheet at 254 DPI (10 px/mm), 5 mm bleed:
        // the trim is 1000×1000 px, so the design's height fills it (scale 2) and its
        // width overhangs by 500 design px, 250 cropped each side.
        let print = Print {
            sheet: SheetSize {
                width_mm: 100.0,
                height_mm: 100.0,
            },
            dpi: 254.0,
            bleed_mm: 5.0,
        };
        let w = print.window(&design(1000, 500));
        assert_eq!((w.width, w.height), (1100, 1100));
        assert!((w.scale - 2.0).abs() < 1e-12);
        // Output pixel 50 (the trim's left edge) is design x 250; pixel 0 is 25 to its left.
        assert!((w.x0 - 225.0).abs() < 1e-12, "{}", w.x0);
        assert!((w.y0 + 25.0).abs() < 1e-12, "{}", w.y0);
    }

    #[test]
    fn presets_turn_to_the_design() {
        let a4 = PaperPreset::named("a4").map(|p| p.for_design(&design(1024, 640)));
        assert_eq!(
            a4,
            Some(SheetSize {
                width_mm: 297.0,
                height_mm: 210.0
            })
        );
        let letter = PaperPreset::named("US Letter").map(|p| p.for_design(&design(500, 800)));
        assert_eq!(letter.map(|s| s.width_mm), Some(215.9));
        assert!(PaperPreset::named("50x70cm").is_some());
        assert!(PaperPreset::named("B5").is_none());
    }
}
