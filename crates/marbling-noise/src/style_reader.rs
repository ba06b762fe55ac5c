//! Reading a style spec ([`crate::StyleSpec`]) from JSON, every problem reported with
//! its field by the shared [`marbling_json::PathReader`].

use crate::ramp::parse_hex;
use crate::ranges::Range;
use crate::style::{
    ANCHORINGS, DEPTH_TESTS, FIBER_LENGTH, FIBER_WIDTH, FIBERS_PER_PIXEL, FOLLOWS, MARK_BANDWIDTH,
    MARK_FREQUENCY, MARK_FREQUENCY_SHADING, MARK_IMPULSES, MARK_SHADING, MARK_SOFTNESS, MARK_TONE,
    OPACITY, STYLE_KINDS, StyleKind, StyleSpec,
};
use marbling_json::{FieldError, PathReader, short};
use serde_json::{Map, Value};

const FIELDS: [&str; 19] = [
    "style",
    "frequency",
    "bandwidth",
    "impulses",
    "orientation",
    "follow",
    "tone",
    "softness",
    "shading",
    "frequency_shading",
    "fibers_per_pixel",
    "length",
    "width",
    "weave",
    "ink",
    "opacity",
    "anchoring",
    "depth_test",
    "seed",
];

/// Reads a style spec: `style` picks the preset, the other fields override it.
pub(crate) fn read_style(value: &Value) -> Result<StyleSpec, Vec<FieldError>> {
    let mut r = PathReader::default();
    let spec = read(&mut r, value);
    r.finish(spec)
}

fn read(r: &mut PathReader, value: &Value) -> Option<StyleSpec> {
    let obj = r.object("", value, &FIELDS)?;
    let kind = match obj.get("style") {
        Some(v) => match v.as_str().and_then(StyleKind::from_name) {
            Some(k) => k,
            None => {
                let names: Vec<&str> = STYLE_KINDS.iter().map(|(n, _)| *n).collect();
                r.push(
                    "style",
                    format!("must be one of {}, got {}", names.join(", "), short(v)),
                );
                return None;
            }
        },
        None => {
            r.push("style", "missing");
            return None;
        }
    };
    let mut s = StyleSpec::preset(kind);
    let mut ok = true;
    let mut num = |r: &mut PathReader, name: &str, range: Range, into: &mut f32| {
        if obj.contains_key(name) {
            match bounded(r, obj, name, range) {
                Some(x) => *into = x,
                None => ok = false,
            }
        }
    };
    num(r, "frequency", MARK_FREQUENCY, &mut s.marks.frequency);
    num(r, "bandwidth", MARK_BANDWIDTH, &mut s.marks.bandwidth);
    num(r, "impulses", MARK_IMPULSES, &mut s.marks.impulses);
    num(
        r,
        "orientation",
        Range::within(-360.0, 360.0),
        &mut s.marks.orientation,
    );
    num(r, "tone", MARK_TONE, &mut s.marks.tone);
    num(r, "softness", MARK_SOFTNESS, &mut s.marks.softness);
    num(r, "shading", MARK_SHADING, &mut s.marks.shading);
    num(
        r,
        "frequency_shading",
        MARK_FREQUENCY_SHADING,
        &mut s.marks.frequency_shading,
    );
    num(
        r,
        "fibers_per_pixel",
        FIBERS_PER_PIXEL,
        &mut s.fibres.per_pixel,
    );
    num(r, "opacity", OPACITY, &mut s.opacity);
    let pair = |r: &mut PathReader, name: &str, range: Range, into: &mut [f32; 2]| {
        let Some(v) = obj.get(name) else { return true };
        let Some((a, b)) = r.pair_value(name, v) else {
            return false;
        };
        if !(range.contains(a) && range.contains(b) && a <= b) {
            r.push(
                name,
                format!(
                    "must be [low, high] with {} ≤ low ≤ high ≤ {}, got {}",
                    range.lo,
                    range.hi,
                    short(v)
                ),
            );
            return false;
        }
        *into = [a as f32, b as f32];
        true
    };
    let lengths = pair(r, "length", FIBER_LENGTH, &mut s.fibres.length);
    let widths = pair(r, "width", FIBER_WIDTH, &mut s.fibres.width);
    let weave = weave(r, obj, &mut s.fibres.weave);
    let follow = r.choice("", obj, "follow", s.marks.follow, &FOLLOWS);
    let anchoring = r.choice("", obj, "anchoring", s.anchoring, &ANCHORINGS);
    let depth_test = r.choice("", obj, "depth_test", s.depth_test, &DEPTH_TESTS);
    let seed = r.whole("", obj, "seed", s.seed);
    if let Some(v) = obj.get("ink") {
        match v.as_str().and_then(parse_hex) {
            Some(c) => s.ink = c,
            None => {
                r.push(
                    "ink",
                    format!("must be a colour \"#rrggbb\", got {}", short(v)),
                );
                ok = false;
            }
        }
    }
    s.marks.follow = follow?;
    s.anchoring = anchoring?;
    s.depth_test = depth_test?;
    s.seed = seed?;
    (ok && lengths && widths && weave).then_some(s)
}

fn bounded(r: &mut PathReader, obj: &Map<String, Value>, name: &str, range: Range) -> Option<f32> {
    let x = r.number("", obj, name)?;
    if range.contains(x) {
        return Some(x as f32);
    }
    let low = if range.open_below { "above" } else { "from" };
    r.push(
        name,
        format!(
            "must be a number {low} {} to {}, got {x}",
            range.lo, range.hi
        ),
    );
    None
}

/// `weave`: two weights ≥ 0, not both 0.
fn weave(r: &mut PathReader, obj: &Map<String, Value>, into: &mut [f32; 2]) -> bool {
    let Some(v) = obj.get("weave") else {
        return true;
    };
    let Some((h, w)) = r.pair_value("weave", v) else {
        return false;
    };
    if !(h >= 0.0 && w >= 0.0 && h + w > 0.0) {
        r.push(
            "weave",
            format!(
                "must be [horizontal, vertical] weights ≥ 0, not both 0, got {}",
                short(v)
            ),
        );
        return false;
    }
    *into = [h as f32, w as f32];
    true
}

#[cfg(test)]
mod tests {
    use crate::{SpecError, StyleKind, StyleSpec};

    fn problems(text: &str) -> String {
        match StyleSpec::from_json(text) {
            Ok(_) => String::new(),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn fields_override_the_preset() {
        let s = StyleSpec::from_json(
            r##"{"style":"stipple","frequency":0.1,"ink":"#ff0000","anchoring":"screen"}"##,
        )
        .map_err(|e| e.to_string());
        let Ok(s) = s else {
            panic!("{s:?}");
        };
        assert_eq!(s.kind, StyleKind::Stipple);
        assert_eq!(s.marks.frequency, 0.1);
        assert_eq!(s.ink, [1.0, 0.0, 0.0]);
        assert_eq!(s.anchoring, crate::Anchoring::Screen);
        assert_eq!(
            s.marks.bandwidth,
            StyleSpec::preset(StyleKind::Stipple).marks.bandwidth
        );
    }

    #[test]
    fn bad_fields_are_named() {
        assert!(problems(r#"{"frequency":0.1}"#).contains("style: missing"));
        assert!(problems(r#"{"style":"oil"}"#).contains("style: must be one of hatching, stipple"));
        assert!(
            problems(r#"{"style":"paper","length":[40,20]}"#)
                .contains("length: must be [low, high]")
        );
        assert!(
            problems(r#"{"style":"paper","fibers_per_pixel":0}"#)
                .contains("fibers_per_pixel: must be a number above 0 to 0.5, got 0")
        );
        assert!(problems(r#"{"style":"canvas","weave":[0,0]}"#).contains("weave: must be"));
        assert!(problems(r#"{"style":"hatching","hue":3}"#).contains("hue: unknown field"));
        assert!(problems(r#"{"style":"hatching","ink":"red"}"#).contains("ink: must be a colour"));
        assert!(
            problems(r#"{"style":"hatching","follow":"wind"}"#)
                .contains("follow: must be one of screen, curvature, stretch")
        );
        assert!(matches!(
            StyleSpec::from_json("{"),
            Err(SpecError::Syntax { .. })
        ));
    }
}
