//! A QR code of a share link, for a teacher's projector or a phone held up to a screen:
//! the link's bytes in the smallest QR version that holds them at error correction
//! level L (a screen is not a worn print, and L holds the most), drawn black on white
//! with the standard quiet zone of four modules. Encoded by the `qrcode` crate.
//!
//! Version 40 at level L holds [`MAX_QR_LINK_BYTES`] bytes; a longer link is refused
//! ([`QrError::TooLong`]) and its design can be tried in its shortest form
//! ([`shortest_for_link`]: every op rounded, the picture downscaled).

use crate::image::RgbaImage;
use crate::{Design, share_fragment, with_link_sized_picture};
use qrcode::{EcLevel, QrCode};

/// Most bytes a QR code holds (version 40, level L, byte mode).
pub const MAX_QR_LINK_BYTES: usize = 2953;

/// Light modules around the code, each side (the standard's quiet zone).
pub const QUIET_ZONE: usize = 4;

/// Why a link has no QR code.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum QrError {
    /// The link is longer than a QR code holds.
    #[error("the link is {bytes} characters; a QR code holds at most {MAX_QR_LINK_BYTES}")]
    TooLong {
        /// The link's length, bytes.
        bytes: usize,
    },
}

/// A link's QR code: its modules, quiet zone included, row by row.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkQr {
    /// Modules per side, the quiet zone included.
    pub side: usize,
    /// `side × side` modules, row by row; true is dark.
    pub dark: Vec<bool>,
    /// The QR version, 1..=40 (its size: 17 + 4·version modules without the quiet zone).
    pub version: i16,
}

/// The QR code of `link`, or why it has none.
pub fn link_qr(link: &str) -> Result<LinkQr, QrError> {
    let too_long = QrError::TooLong { bytes: link.len() };
    if link.len() > MAX_QR_LINK_BYTES {
        return Err(too_long);
    }
    let code =
        QrCode::with_error_correction_level(link.as_bytes(), EcLevel::L).map_err(|_| too_long)?;
    let inner = code.width();
    let side = inner + 2 * QUIET_ZONE;
    let mut dark = vec![false; side * side];
    for (i, c) in code.to_colors().into_iter().enumerate() {
        let (x, y) = (i % inner, i / inner);
        dark[(y + QUIET_ZONE) * side + x + QUIET_ZONE] = c == qrcode::Color::Dark;
    }
    let version = match code.version() {
        qrcode::Version::Normal(v) | qrcode::Version::Micro(v) => v,
    };
    Ok(LinkQr {
        side,
        dark,
        version,
    })
}

impl LinkQr {
    /// The code as an image, `module_px` pixels per module, black on white.
    pub fn to_image(&self, module_px: u32) -> RgbaImage {
        let m = module_px.max(1) as usize;
        let px = self.side * m;
        let mut pixels = Vec::with_capacity(px * px * 4);
        for y in 0..px {
            for x in 0..px {
                let v = if self.dark[(y / m) * self.side + x / m] {
                    0
                } else {
                    255
                };
                pixels.extend_from_slice(&[v, v, v, 255]);
            }
        }
        RgbaImage {
            width: px as u32,
            height: px as u32,
            pixels,
        }
    }
}

/// `design` in the shortest form a link can carry it: every op rounded
/// ([`crate::Op::rounded`]) and a picture background downscaled until the link's
/// fragment fits `budget` characters (`None` when even the smallest picture does not).
/// What it shows changes by at most half a rounding step per op and the picture's
/// detail.
pub fn shortest_for_link(design: &Design, budget: usize) -> Option<Design> {
    let mut d = design.clone();
    d.ops = d.ops.iter().map(crate::Op::rounded).collect();
    if share_fragment(&d).len() <= budget {
        return Some(d);
    }
    with_link_sized_picture(&d, budget)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};

    /// Reads a QR image back with the `rqrr` decoder.
    fn decode(img: &RgbaImage) -> String {
        let (w, h) = (img.width as usize, img.height as usize);
        let mut prepared =
            rqrr::PreparedImage::prepare_from_greyscale(w, h, |x, y| img.pixels[(y * w + x) * 4]);
        let grids = prepared.detect_grids();
        assert_eq!(grids.len(), 1, "one code in the picture");
        grids[0].decode().expect("decodes").1
    }

    #[test]
    fn a_link_comes_back_from_its_qr_code() {
        let d = random_design(5, 320, 200, 6, Mix::Mixed);
        let link = format!("http://127.0.0.1:8080/#{}", share_fragment(&d));
        let qr = link_qr(&link).expect("a short link fits");
        assert_eq!(qr.side, 17 + 4 * qr.version as usize + 2 * QUIET_ZONE);
        let img = qr.to_image(4);
        assert_eq!(img.width as usize, 4 * qr.side);
        assert_eq!(decode(&img), link);
    }

    #[test]
    fn a_link_too_long_for_a_qr_code_is_refused_with_its_length() {
        let link = format!("http://x/#d={}", "A".repeat(MAX_QR_LINK_BYTES));
        let e = link_qr(&link).expect_err("too long");
        assert_eq!(e, QrError::TooLong { bytes: link.len() });
        assert!(e.to_string().contains("at most 2953"), "{e}");
        // The longest link that fits still has a code (version 40).
        let edge = "a".repeat(MAX_QR_LINK_BYTES);
        assert_eq!(link_qr(&edge).map(|q| q.version), Ok(40));
    }

    #[test]
    fn the_shortest_form_rounds_the_ops_and_is_never_longer() {
        let d = random_design(7, 640, 480, 40, Mix::Mixed);
        let short = shortest_for_link(&d, usize::MAX).expect("fits");
        assert!(share_fragment(&short).len() <= share_fragment(&d).len());
        assert!(short.ops.iter().all(|op| op.rounded() == *op));
        assert_eq!(short.ops.len(), d.ops.len());
        assert_eq!(
            shortest_for_link(&d, 10),
            None,
            "no design fits 10 characters"
        );
    }
}
