//! Share links: a design's compact JSON, compressed with raw DEFLATE (RFC 1951) and
//! encoded base64url without padding, carried in a URL fragment as `#d=…`.

use crate::{Design, DesignError};
use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;

/// Largest inflated design accepted from a link, bytes (100,000 ops fit easily).
pub const MAX_LINK_JSON_BYTES: usize = 64 << 20;
/// Longest share link offered, characters: Chromium's limit on URL length (2 MiB);
/// a longer design is saved as JSON instead.
pub const MAX_LINK_CHARS: usize = 2 << 20;
/// DEFLATE effort of links: the best compression miniz offers (made once, kept long).
const LEVEL: u8 = 9;
/// DEFLATE effort of [`encode_share_payload_fast`]: miniz's fastest, about 10× faster
/// than [`LEVEL`] for 35 % more characters.
const FAST_LEVEL: u8 = 1;

/// Why a share link could not be opened.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ShareError {
    /// The text has no `d=` design in it.
    #[error("share link: no \"#d=\" design in it")]
    Missing,
    /// The payload is not base64url.
    #[error("share link: not valid base64url ({0})")]
    Base64(String),
    /// The payload does not inflate.
    #[error("share link: the compressed design is corrupted or truncated ({0})")]
    Inflate(String),
    /// The inflated text is not UTF-8.
    #[error("share link: the design is not UTF-8 text")]
    Utf8,
    /// The inflated design is not a valid document.
    #[error("share link: {0}")]
    Design(DesignError),
}

/// The fragment payload (what follows `#d=`) for a design.
pub fn encode_share_payload(design: &Design) -> String {
    encode_payload(design, LEVEL)
}

/// A payload read like any other by [`decode_share`], compressed with the least effort:
/// for copies made often (the app's autosave), where time matters more than length.
pub fn encode_share_payload_fast(design: &Design) -> String {
    encode_payload(design, FAST_LEVEL)
}

fn encode_payload(design: &Design, level: u8) -> String {
    let json = design.to_json_compact();
    let deflated = miniz_oxide::deflate::compress_to_vec(json.as_bytes(), level);
    URL_SAFE_NO_PAD.encode(deflated)
}

/// The URL fragment for a design, `d=…` (append to `#`).
pub fn share_fragment(design: &Design) -> String {
    format!("d={}", encode_share_payload(design))
}

/// Reads a design from a whole link (`https://…/#d=…`), a fragment (`#d=…` or `d=…`).
/// Other `&`-separated fragment parameters are ignored.
pub fn decode_share(link: &str) -> Result<Design, ShareError> {
    let fragment = link.rsplit_once('#').map_or(link, |(_, f)| f);
    let payload = fragment
        .split('&')
        .find_map(|part| part.strip_prefix("d="))
        .ok_or(ShareError::Missing)?
        .trim();
    let deflated = URL_SAFE_NO_PAD
        .decode(payload)
        .map_err(|e| ShareError::Base64(e.to_string()))?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&deflated, MAX_LINK_JSON_BYTES)
        .map_err(|e| ShareError::Inflate(format!("{:?}", e.status)))?;
    let text = String::from_utf8(json).map_err(|_| ShareError::Utf8)?;
    Design::from_json(&text).map_err(ShareError::Design)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::{Mix, random_design};

    #[test]
    fn thousand_op_design_round_trips_through_a_link() {
        let d = random_design(3, 1024, 768, 1000, Mix::Mixed);
        let link = format!("http://127.0.0.1:8080/#{}", share_fragment(&d));
        assert_eq!(decode_share(&link), Ok(d.clone()));
        assert_eq!(decode_share(&share_fragment(&d)), Ok(d));
    }

    #[test]
    fn payload_is_raw_deflate_base64url_without_padding() {
        let d = Design::new(10, 10, crate::Rgb8::new(1, 2, 3));
        let payload = encode_share_payload(&d);
        assert!(!payload.contains(['=', '+', '/']), "{payload}");
        let raw = URL_SAFE_NO_PAD.decode(&payload).expect("base64url");
        let json = miniz_oxide::inflate::decompress_to_vec(&raw).expect("raw deflate");
        assert_eq!(String::from_utf8(json).expect("utf8"), d.to_json_compact());
    }

    #[test]
    fn broken_links_say_what_is_wrong() {
        assert_eq!(decode_share("http://x/#view=2"), Err(ShareError::Missing));
        assert!(matches!(decode_share("#d=@@@"), Err(ShareError::Base64(_))));
        assert!(matches!(
            decode_share("#d=AAAA"),
            Err(ShareError::Inflate(_))
        ));
        let d = random_design(1, 100, 100, 50, Mix::Mixed);
        let p = encode_share_payload(&d);
        assert!(matches!(
            decode_share(&format!("#d={}", &p[..p.len() / 2])),
            Err(ShareError::Inflate(_))
        ));
        let bad = URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
            br#"{"version":1}"#,
            6,
        ));
        let err = decode_share(&format!("#d={bad}")).expect_err("invalid design");
        assert_eq!(
            err.to_string(),
            "share link: width: missing\nheight: missing\nbackground: missing\nops: missing"
        );
    }
}
