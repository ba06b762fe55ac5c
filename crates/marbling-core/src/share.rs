//! Share links: a design's compact JSON, compressed with raw DEFLATE (RFC 1951) and
//! encoded base64url without padding, carried in a URL fragment as `#d=…`; a noise
//! spec's JSON (what `marbling noise` reads) the same way as `#n=…`.

use crate::{Design, DesignError};
use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use marbling_noise::{NoiseSpec, SpecError};

/// Largest inflated design accepted from a link, bytes (100,000 ops fit easily).
pub const MAX_LINK_JSON_BYTES: usize = 64 << 20;
/// Longest share link offered, characters: Chromium's limit on URL length (2 MiB);
/// a longer design is saved as JSON instead.
pub const MAX_LINK_CHARS: usize = 2 << 20;
/// Longest share link that carries a picture background, characters (about 64 KB):
/// pictures barely compress, so a longer link is downscaled on request
/// ([`with_link_sized_picture`]) or the design is shared as a JSON file instead.
pub const MAX_PICTURE_LINK_CHARS: usize = 64 * 1024;
/// Longest sides and JPEG qualities tried, in order, to fit a picture in a link.
const LINK_PICTURE_STEPS: [(u32, u8); 6] = [
    (512, 80),
    (384, 75),
    (256, 75),
    (192, 70),
    (128, 70),
    (96, 60),
];
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
    /// The text has no `n=` noise spec in it.
    #[error("noise link: no \"#n=\" noise spec in it")]
    MissingNoise,
    /// The inflated spec is not a valid noise spec.
    #[error("noise link: {0}")]
    Noise(SpecError),
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
    encode_text(&design.to_json_compact(), level)
}

/// `text` deflated at `level` and encoded base64url without padding.
fn encode_text(text: &str, level: u8) -> String {
    URL_SAFE_NO_PAD.encode(miniz_oxide::deflate::compress_to_vec(
        text.as_bytes(),
        level,
    ))
}

/// The text carried by fragment parameter `key=` of `link` (a whole link, `#…` or the
/// fragment alone; other `&`-separated parameters are ignored); `Ok(None)` without one.
fn decode_text(link: &str, key: &str) -> Result<Option<String>, ShareError> {
    let fragment = link.rsplit_once('#').map_or(link, |(_, f)| f);
    let Some(payload) = fragment
        .split('&')
        .find_map(|part| part.strip_prefix(key)?.strip_prefix('='))
    else {
        return Ok(None);
    };
    let deflated = URL_SAFE_NO_PAD
        .decode(payload.trim())
        .map_err(|e| ShareError::Base64(e.to_string()))?;
    let json = miniz_oxide::inflate::decompress_to_vec_with_limit(&deflated, MAX_LINK_JSON_BYTES)
        .map_err(|e| ShareError::Inflate(format!("{:?}", e.status)))?;
    String::from_utf8(json)
        .map(Some)
        .map_err(|_| ShareError::Utf8)
}

/// The URL fragment for a noise spec, `n=…` (append to `#`): its JSON as
/// [`NoiseSpec::to_value`] writes it, compressed like a design link.
pub fn noise_fragment(spec: &NoiseSpec) -> String {
    format!("n={}", encode_text(&spec.to_value().to_string(), LEVEL))
}

/// Reads a noise spec from a link or fragment with `n=…`.
pub fn decode_noise_share(link: &str) -> Result<NoiseSpec, ShareError> {
    let text = decode_text(link, "n")?.ok_or(ShareError::MissingNoise)?;
    NoiseSpec::from_json(&text).map_err(ShareError::Noise)
}

/// The URL fragment for a design, `d=…` (append to `#`).
pub fn share_fragment(design: &Design) -> String {
    format!("d={}", encode_share_payload(design))
}

/// `design` with its picture background downscaled (JPEG, longest side 512 px or
/// less) so that its fragment is at most `budget` characters: the largest that fits,
/// or `None` when even the smallest does not (too many ops). Designs without a picture
/// come back unchanged when they fit.
pub fn with_link_sized_picture(design: &Design, budget: usize) -> Option<Design> {
    let fits = |d: &Design| share_fragment(d).len() <= budget;
    let Some(image) = &design.background_image else {
        return fits(design).then(|| design.clone());
    };
    LINK_PICTURE_STEPS.iter().find_map(|&(side, quality)| {
        let mut d = design.clone();
        d.background_image = Some(image.downscaled(side, quality));
        fits(&d).then_some(d)
    })
}

/// Reads a design from a whole link (`https://…/#d=…`), a fragment (`#d=…` or `d=…`).
/// Other `&`-separated fragment parameters are ignored.
pub fn decode_share(link: &str) -> Result<Design, ShareError> {
    let text = decode_text(link, "d")?.ok_or(ShareError::Missing)?;
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

    #[test]
    fn a_noise_spec_round_trips_through_an_n_link_and_broken_ones_say_why() {
        let spec = NoiseSpec::from_json(
            r#"{"type":"worley","frequency":0.05,"feature":"f2","seed":4,"palette":"ocean","tile":true}"#,
        )
        .expect("spec");
        let fragment = noise_fragment(&spec);
        let payload = fragment.strip_prefix("n=").expect("n=");
        let raw = URL_SAFE_NO_PAD.decode(payload).expect("base64url");
        let json = miniz_oxide::inflate::decompress_to_vec(&raw).expect("raw deflate");
        assert_eq!(
            String::from_utf8(json).expect("utf8"),
            spec.to_value().to_string()
        );
        let link = format!("http://127.0.0.1:8080/?landing=0#view=1&{fragment}");
        assert_eq!(decode_noise_share(&link), Ok(spec));
        assert_eq!(decode_noise_share("#d=abc"), Err(ShareError::MissingNoise));
        assert!(matches!(
            decode_noise_share("#n=@@"),
            Err(ShareError::Base64(_))
        ));
        let bad = encode_text(r#"{"type":"perlin"}"#, 6);
        let e = decode_noise_share(&format!("#n={bad}")).expect_err("no frequency");
        assert_eq!(e.to_string(), "noise link: frequency: missing");
    }
}
