//! What the address bar's fragment holds: a design (`#d=…`), a noise (`#n=…`), or
//! nothing to open. Reading a link never touches the app: the frame loop applies it.

use marbling_core::{Design, ViewSpec, decode_noise_share, decode_share, share_fragment};
use marbling_noise::NoiseSpec;

/// The share link that opens `design` in this playground (its address and `#d=…`),
/// with `&v=x,y,zoom` when a view is given (a deep spot shared as it is seen).
pub(crate) fn design_link(design: &Design, view: Option<ViewSpec>) -> String {
    let view = view.map(|v| format!("&v={v}")).unwrap_or_default();
    format!(
        "{}#{}{view}",
        crate::platform::base_url(),
        share_fragment(design)
    )
}

/// The view a fragment's `v=x,y,zoom` part asks for (the design point at the canvas's
/// centre and screen points per design pixel), or why it cannot be had; `None` when
/// the fragment has none.
pub(crate) fn view_of(fragment: &str) -> Option<Result<ViewSpec, String>> {
    let text = fragment.split('&').find_map(|p| p.strip_prefix("v="))?;
    Some(ViewSpec::parse(text).map_err(|e| format!("share link: {e}")))
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
        let design = crate::store::file_panel::blank([40, 30]);
        let d = marbling_core::share_fragment(&design);
        assert!(is_link(&d));
        match read(&d) {
            Link::Design(Ok(back)) => assert_eq!(*back, design),
            other => panic!("{other:?}"),
        }
        assert!(matches!(read("x=1&y=2"), Link::None));
        let view = ViewSpec {
            centre: marbling_core::Point::new(12.5, 7.25),
            scale: 250_000.0,
        };
        let link = design_link(&design, Some(view));
        let fragment = link.split_once('#').map_or("", |(_, f)| f);
        assert!(fragment.ends_with("&v=12.5,7.25,250000"), "{fragment}");
        assert_eq!(view_of(fragment), Some(Ok(view)));
        assert!(matches!(read(fragment), Link::Design(Ok(_))));
        assert_eq!(view_of(&d), None);
        assert_eq!(
            view_of("d=x&v=1,2"),
            Some(Err(
                "share link: view: expected x,y,scale (three numbers), got \"1,2\"".to_owned()
            ))
        );
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
