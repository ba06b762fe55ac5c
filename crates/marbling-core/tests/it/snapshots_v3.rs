//! Golden images (≤ 256 px) of the schema v3 example designs, one per op type v3 adds
//! (examples/designs/v3-*.json), rendered at 1/2 scale, in
//! tests/snapshots/core/v3-*.png. Regenerate only with `UPDATE_SNAPSHOTS=1 cargo test`.

use marbling_core::compare::check_snapshot;
use marbling_core::{Antialias, Design, RenderOptions, render};
use std::path::PathBuf;

/// As tests/it/snapshots.rs: libm's last-bit differences may flip a pixel on an ink edge.
const THRESHOLD: u8 = 2;
const BUDGET: f64 = 0.005;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

#[test]
fn v3_examples_match_their_goldens() {
    let mut failures = Vec::new();
    for (name, op) in [
        ("shift", "shift"),
        ("turn", "turn"),
        ("comb", "comb"),
        ("drops", "drops"),
        ("sprays", "sprays"),
        ("jiggle", "jiggle"),
        ("stylus", "stylus"),
    ] {
        let path = root().join(format!("examples/designs/v3-{name}.json"));
        let text = std::fs::read_to_string(&path).expect("example design");
        let d = Design::from_json(&text).expect("valid example");
        assert_eq!(d.version(), 3, "{name} uses schema v3");
        assert!(
            d.ops.iter().any(|o| o.type_name() == op),
            "{name} holds a {op} op"
        );
        let img = render(
            &d,
            &RenderOptions {
                scale: 0.5,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
        assert!(img.width <= 256 && img.height <= 256);
        if let Err(e) = check_snapshot(
            &marbling_testkit::goldens("core").join(format!("v3-{name}.png")),
            &img,
            THRESHOLD,
            BUDGET,
        ) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
