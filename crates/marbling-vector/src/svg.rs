//! SVG text of a traced design: a background `<rect>` (and a raster `<image>` of a
//! noise background), one filled `<path>` per ink region in painter's order with a
//! `data-method` attribute saying how it was found (`forward` or `contour`), then a
//! multiplied raster `<image>` of grain; coordinates in design pixels (the viewBox).

use crate::{Method, TraceOptions, VectorDesign, VectorError, trace};
use marbling_core::{Design, Rgb8};
use std::fmt::Write;

/// Decimal places of SVG coordinates for a design traced at `tolerance` output pixels
/// and `scale` output pixels per design pixel: the rounding grid 10^−d design pixels is
/// at most T/50 output pixels (2 decimals at T = 1, scale 1; 3 at T = 0.25).
pub fn decimals(tolerance: f64, scale: f64) -> u32 {
    let d = (50.0 * scale / tolerance).log10().ceil();
    if d.is_finite() {
        d.clamp(0.0, 9.0) as u32
    } else {
        9
    }
}

/// The SVG document of `vector`: `viewBox="0 0 W H"` in design pixels, `width`/`height`
/// attributes of W·scale × H·scale output pixels (rounded, at least 1), a background
/// rectangle and any underlay image, then one `<path>` per outline (nonzero fill rule),
/// then any grain image (`mix-blend-mode: multiply`). Path data use relative
/// line-tos on coordinates rounded to [`decimals`] places ([`contour_decimals`] for
/// contour outlines); each ring after the first starts with a relative move from the
/// previous ring's start. Rounding is done on absolute positions, so it never
/// accumulates.
pub fn to_svg(vector: &VectorDesign) -> String {
    let (w, h) = (vector.width, vector.height);
    let out_w = (f64::from(w) * vector.scale).round().max(1.0);
    let out_h = (f64::from(h) * vector.scale).round().max(1.0);
    let mut s = String::with_capacity(64 + vector.stats.vertices * 12);
    let _ = write!(
        s,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" \
         width=\"{out_w}\" height=\"{out_h}\" viewBox=\"0 0 {w} {h}\" fill-rule=\"nonzero\">\n\
         <rect width=\"{w}\" height=\"{h}\" fill=\"{}\"/>\n",
        hex(vector.background)
    );
    if let Some(layer) = &vector.underlay {
        image(&mut s, w, h, &layer.data_uri, "");
    }
    for outline in &vector.outlines {
        let _ = write!(
            s,
            "<path data-method=\"{}\" fill=\"{}\" d=\"",
            outline.method.name(),
            hex(outline.color)
        );
        let places = match outline.method {
            Method::Forward => decimals(vector.tolerance, vector.scale),
            Method::Contour => contour_decimals(vector.tolerance, vector.scale),
        };
        let unit = 10f64.powi(places as i32);
        let mut numbers = Numbers::new(&mut s, places);
        // The start of the previous ring: later rings move relative to it ('m', whose
        // further pairs are relative line-tos).
        let mut origin: Option<(i64, i64)> = None;
        for ring in &outline.rings {
            let mut prev: Option<(i64, i64)> = None;
            for p in ring {
                let q = ((p.x * unit).round() as i64, (p.y * unit).round() as i64);
                match (prev, origin) {
                    (None, None) => {
                        numbers.command('M');
                        numbers.push(q.0);
                        numbers.push(q.1);
                        numbers.command('l');
                        origin = Some(q);
                    }
                    (None, Some(o)) => {
                        numbers.command('m');
                        numbers.push(q.0 - o.0);
                        numbers.push(q.1 - o.1);
                        origin = Some(q);
                    }
                    (Some(r), _) if r == q => continue,
                    (Some(r), _) => {
                        numbers.push(q.0 - r.0);
                        numbers.push(q.1 - r.1);
                    }
                }
                prev = Some(q);
            }
            numbers.command('z');
        }
        s.push_str("\"/>\n");
    }
    if let Some(layer) = &vector.dense {
        image(&mut s, w, h, &layer.data_uri, " data-method=\"raster\"");
    }
    if let Some(layer) = &vector.grain {
        image(
            &mut s,
            w,
            h,
            &layer.data_uri,
            " style=\"mix-blend-mode:multiply\"",
        );
    }
    s.push_str("</svg>\n");
    s
}

/// An `<image>` covering the canvas, stretched to it, without smoothing between its
/// pixels (one pixel per output pixel).
fn image(s: &mut String, w: u32, h: u32, uri: &str, extra: &str) {
    let _ = writeln!(
        s,
        "<image width=\"{w}\" height=\"{h}\" preserveAspectRatio=\"none\" \
         image-rendering=\"optimizeSpeed\"{extra} href=\"{uri}\"/>"
    );
}

/// Traces `design` and returns its SVG document: what the app's "Export SVG" button
/// downloads and `marbling svg` writes.
pub fn design_to_svg(design: &Design, opts: &TraceOptions) -> Result<String, VectorError> {
    Ok(to_svg(&trace(design, opts)?))
}

/// Decimal places of a contour outline's coordinates: a grid of at most T/10 output
/// pixels (1 decimal at T = 1, scale 1), well inside the method's own T/4 simplification.
pub fn contour_decimals(tolerance: f64, scale: f64) -> u32 {
    decimals(tolerance * 5.0, scale)
}

fn hex(c: Rgb8) -> String {
    format!("#{:02x}{:02x}{:02x}", c.r, c.g, c.b)
}

/// Writes fixed-point numbers (integers in units of 10^−places) compactly: no trailing
/// zeros, no leading zero before the point, and a separator only where the grammar needs
/// one (not before '-', nor before '.' when the previous number already has a point).
struct Numbers<'a> {
    out: &'a mut String,
    places: u32,
    /// Whether the previous token was a number, and whether it contained a '.'.
    prev: Option<bool>,
    buf: String,
}

impl<'a> Numbers<'a> {
    fn new(out: &'a mut String, places: u32) -> Self {
        Self {
            out,
            places,
            prev: None,
            buf: String::new(),
        }
    }

    fn command(&mut self, c: char) {
        self.out.push(c);
        self.prev = None;
    }

    fn push(&mut self, v: i64) {
        self.buf.clear();
        let unit = 10u64.pow(self.places);
        let (int, frac) = (v.unsigned_abs() / unit, v.unsigned_abs() % unit);
        if v < 0 {
            self.buf.push('-');
        }
        if int != 0 || frac == 0 {
            let _ = write!(self.buf, "{int}");
        }
        if frac != 0 {
            let digits = format!("{frac:0width$}", width = self.places as usize);
            self.buf.push('.');
            self.buf.push_str(digits.trim_end_matches('0'));
        }
        let has_point = frac != 0;
        let first = self.buf.as_bytes()[0];
        let needs_sep = match self.prev {
            None => false,
            Some(_) if first == b'-' => false,
            Some(prev_point) => !(first == b'.' && prev_point),
        };
        if needs_sep {
            self.out.push(' ');
        }
        self.out.push_str(&self.buf);
        self.prev = Some(has_point);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fmt(places: u32, vs: &[i64]) -> String {
        let mut s = String::new();
        let mut n = Numbers::new(&mut s, places);
        for &v in vs {
            n.push(v);
        }
        s
    }

    #[test]
    fn compact_numbers() {
        assert_eq!(fmt(2, &[1234, 5600, -50, 5, 0, -100]), "12.34 56-.5.05 0-1");
        assert_eq!(fmt(2, &[50, 50]), ".5.5");
        assert_eq!(fmt(0, &[3, -4, 5]), "3-4 5");
        assert_eq!(decimals(1.0, 1.0), 2);
        assert_eq!(decimals(0.25, 1.0), 3);
        assert_eq!(contour_decimals(1.0, 1.0), 1);
    }
}
