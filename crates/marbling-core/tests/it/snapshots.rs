//! Golden images (≤ 256 px) for every op and every antialiasing mode, in
//! tests/snapshots/core/. Regenerate only with `UPDATE_SNAPSHOTS=1 cargo test`.

use marbling_core::compare::{check_snapshot, check_snapshot_with, compare};
use marbling_core::{Antialias, Design, RenderOptions, RgbaImage, render};
use std::path::PathBuf;

/// Channel difference tolerated per pixel, and the share of pixels allowed beyond it
/// (libm's last-bit differences between platforms may flip a pixel on an ink edge).
const THRESHOLD: u8 = 2;
const BUDGET: f64 = 0.005;

fn snapshot_dir() -> PathBuf {
    marbling_testkit::goldens("core")
}

/// Three drops to deform, then `op` (a JSON op object).
fn design_with(op: &str) -> Design {
    let text = format!(
        r##"{{"version":1,"width":128,"height":96,"background":"#f3ead7","ops":[
        {{"type":"drop","center":[64,48],"radius":30,"color":"#1d3557"}},
        {{"type":"drop","center":[40,40],"radius":16,"color":"#e63946"}},
        {{"type":"drop","center":[84,56],"radius":14,"color":"#e9c46a"}},
        {op}]}}"##
    );
    Design::from_json(&text).expect("valid test design")
}

fn op_designs() -> Vec<(&'static str, Design)> {
    vec![
        (
            "drop",
            design_with(r##"{"type":"drop","center":[70,44],"radius":12,"color":"#2a9d8f"}"##),
        ),
        (
            "spray",
            design_with(r##"{"type":"spray","center":[60,50],"radius":6,"color":"#2a9d8f"}"##),
        ),
        (
            "tine",
            design_with(
                r#"{"type":"tine","origin":[0,48],"direction":[1,0.2],"alpha":30,"lambda":6}"#,
            ),
        ),
        (
            "rake",
            design_with(
                r#"{"type":"rake","origin":[0,0],"direction":[0,1],"spacing":16,"alpha":14,"lambda":4}"#,
            ),
        ),
        (
            "wavy",
            design_with(
                r#"{"type":"wavy","angle":1.5708,"amplitude":8,"wavelength":40,"phase":0.5}"#,
            ),
        ),
        (
            "circular",
            design_with(
                r#"{"type":"circular","center":[64,48],"radius":24,"alpha":30,"lambda":6}"#,
            ),
        ),
        (
            "vortex",
            design_with(r#"{"type":"vortex","center":[64,48],"alpha":40,"lambda":10}"#),
        ),
    ]
}

fn render_at(d: &Design, antialias: Antialias) -> RgbaImage {
    render(
        d,
        &RenderOptions {
            scale: 1.0,
            antialias,
        },
    )
    .expect("render")
}

#[test]
fn every_op_matches_its_golden() {
    let mut failures = Vec::new();
    for (name, d) in op_designs() {
        let img = render_at(&d, Antialias::Rgss);
        if let Err(e) = check_snapshot(
            &snapshot_dir().join(format!("op-{name}.png")),
            &img,
            THRESHOLD,
            BUDGET,
        ) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_antialiasing_mode_matches_its_golden() {
    let d = design_with(r#"{"type":"vortex","center":[64,48],"alpha":40,"lambda":10}"#);
    let mut failures = Vec::new();
    for aa in Antialias::ALL {
        let img = render_at(&d, aa);
        if let Err(e) = check_snapshot(
            &snapshot_dir().join(format!("aa-{aa}.png")),
            &img,
            THRESHOLD,
            BUDGET,
        ) {
            failures.push(e);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn each_op_changes_the_picture() {
    // The goldens would be worthless if an op did nothing: each differs from the base.
    let base = render_at(
        &design_with(r##"{"type":"spray","center":[-50,-50],"radius":1,"color":"#000000"}"##),
        Antialias::Rgss,
    );
    for (name, d) in op_designs() {
        let diff = compare(&base, &render_at(&d, Antialias::Rgss), THRESHOLD).expect("size");
        assert!(diff.fraction() > 0.005, "{name} changed only {diff:?}");
    }
}

#[test]
/// The one test of the comparator every golden and agreement test relies on.
fn the_comparator_fails_on_a_perturbed_image() {
    let dir = std::env::temp_dir().join(format!("marbling-snap-{}", std::process::id()));
    let golden = dir.join("golden.png");
    let img = render_at(&op_designs()[0].1, Antialias::Rgss);
    std::fs::create_dir_all(&dir).expect("tmp");
    std::fs::write(&golden, img.to_png().expect("png")).expect("write");
    assert_eq!(
        check_snapshot_with(&golden, &img, THRESHOLD, BUDGET, false),
        Ok(())
    );

    // Shift a 10×10 block's colour by 3/255: 100 of 12288 pixels = 0.8 % > 0.5 %.
    let mut perturbed = img.clone();
    for y in 10..20 {
        for x in 10..20 {
            let mut p = perturbed.pixel(x, y);
            p[1] = p[1].wrapping_add(3);
            perturbed.set_pixel(x, y, p);
        }
    }
    let err =
        check_snapshot_with(&golden, &perturbed, THRESHOLD, BUDGET, false).expect_err("must fail");
    assert!(err.contains("100 of 12288 pixels"), "{err}");
    assert!(dir.join("golden.diff.png").exists() && dir.join("golden.actual.png").exists());
    // A change within the threshold passes; a different size fails.
    let mut slight = img.clone();
    slight.pixels[4] = slight.pixels[4].saturating_add(1);
    assert_eq!(
        check_snapshot_with(&golden, &slight, THRESHOLD, BUDGET, false),
        Ok(())
    );
    let small = RgbaImage::filled(3, 3, [0, 0, 0, 255]);
    assert!(check_snapshot_with(&golden, &small, THRESHOLD, BUDGET, false).is_err());
    std::fs::remove_dir_all(&dir).ok();
    // `compare`, which every agreement test uses: a channel off by exactly the threshold
    // is not counted, one level more is.
    for (offset, counted) in [(THRESHOLD, 0), (THRESHOLD + 1, 1)] {
        let mut off = img.clone();
        off.pixels[0] = off.pixels[0].wrapping_add(offset);
        let d = marbling_core::compare::compare(&img, &off, THRESHOLD).expect("same size");
        assert_eq!(d.differing, counted, "offset {offset}");
    }
}
