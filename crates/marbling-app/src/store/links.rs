//! What the address bar's fragment holds: a design (`#d=…`), a noise (`#n=…`), or
//! nothing to open. Reading a link never touches the app: the frame loop applies it.

use marbling_core::{Design, decode_noise_share, decode_share, share_fragment};
use marbling_noise::NoiseSpec;

/// The share link that opens `design` in this playground (its address and `#d=…`).
pub(crate) fn design_link(design: &Design) -> String {
    format!("{}#{}", crate::platform::base_url(), share_fragment(design))
}

/// What a fragment asks for, or why it cannot be had.
#[derive(Debug)]
pub(crate) enum Link {
    /// No `d=` or `n=` part: nothing to open.
    None,
    /// A noise spec (`n=`; wins over a `d=` in the same fragment).
    Noise(Result<Box<NoiseSpec>, String>),
    /// A design (`d=`).
    Design(Result<Box<Design>, String>),
}

/// The fragment's `&`-separated parts start with `key` (`"d="`, `"n="`).
fn has(fragment: &str, key: &str) -> bool {
    fragment.split('&').any(|p| p.starts_with(key))
}

/// True when `fragment` holds a design or noise link (which then wins over the
/// gallery landing, whether it opens or not).
pub(crate) fn is_link(fragment: &str) -> bool {
    has(fragment, "n=") || has(fragment, "d=")
}

/// Reads `fragment` (without `#`).
pub(crate) fn read(fragment: &str) -> Link {
    if has(fragment, "n=") {
        Link::Noise(
            decode_noise_share(fragment)
                .map(Box::new)
                .map_err(|e| e.to_string()),
        )
    } else if has(fragment, "d=") {
        Link::Design(
            decode_share(fragment)
                .map(Box::new)
                .map_err(|e| e.to_string()),
        )
    } else {
        Link::None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fragment_is_a_design_a_noise_or_nothing() {
        let design = crate::app::blank([40, 30]);
        let d = marbling_core::share_fragment(&design);
        assert!(is_link(&d));
        match read(&d) {
            Link::Design(Ok(back)) => assert_eq!(*back, design),
            other => panic!("{other:?}"),
        }
        assert!(matches!(read("x=1&y=2"), Link::None));
        assert!(!is_link("x=1"));
        match read("d=%%") {
            Link::Design(Err(e)) => assert!(e.contains("base64url"), "{e}"),
            other => panic!("{other:?}"),
        }
        match read("d=%%&n=%%") {
            Link::Noise(Err(e)) => assert!(e.contains("base64url"), "{e}"),
            other => panic!("{other:?}"),
        }
    }
}
