//! Golden images (≤ 256 px) of schema v2 designs — the example designs with a noise
//! background or grain overlays, rendered at 1/4 scale — in tests/snapshots/core/v2-*.png.
//! Regenerate only with `UPDATE_SNAPSHOTS=1 cargo test`.

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
fn v2_examples_match_their_goldens() {
    let mut failures = Vec::new();
    for name in ["fbm-marbled", "worley-pigment", "on-paper"] {
        let path = root().join(format!("examples/designs/{name}.json"));
        let text = std::fs::read_to_string(&path).expect("example design");
        let d = Design::from_json(&text).expect("valid example");
        assert_eq!(d.version(), 2, "{name} uses schema v2");
        let img = render(
            &d,
            &RenderOptions {
                scale: 0.25,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
        assert!(img.width <= 256 && img.height <= 256);
        if let Err(e) = check_snapshot(
            &marbling_testkit::goldens("core").join(format!("v2-{name}.png")),
            &img,
            THRESHOLD,
            BUDGET,
        ) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
