//! The traditional pattern recipes (`marbling_core::patterns`, examples/patterns/):
//! the files are the recipes at their defaults, every step has a caption, parameters
//! scale them, and each renders like its golden (tests/snapshots/core/patterns/, at
//! 1/8 scale; regenerate only with `UPDATE_SNAPSHOTS=1 cargo test`).

use marbling_core::compare::check_snapshot;
use marbling_core::patterns::{self, Params};
use marbling_core::{Antialias, Design, RenderOptions, Rgb8, render};
use std::path::PathBuf;

/// As tests/it/snapshots.rs: libm's last-bit differences may flip a pixel on an ink edge.
const THRESHOLD: u8 = 2;
const BUDGET: f64 = 0.01;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The patterns the issue lists, by file name.
const REQUIRED: [&str; 24] = [
    "stone",
    "hair-vein",
    "turkish-spot",
    "gel-git",
    "chevron",
    "nonpareil",
    "reversed-nonpareil",
    "wave-nonpareil",
    "feather",
    "bouquet",
    "peacock",
    "bird-wing",
    "serpentine",
    "french-curl",
    "old-dutch",
    "dutch-scallops",
    "spanish-wave",
    "french-shell",
    "stormont",
    "west-end",
    "sal",
    "nightingale-nest",
    "tulip",
    "hearts",
];

#[test]
fn every_listed_pattern_exists_once_and_its_file_is_the_recipe() {
    let all = patterns::all();
    let mut ids: Vec<&str> = all.iter().map(|p| p.id).collect();
    for id in REQUIRED {
        assert!(ids.contains(&id), "missing pattern {id}");
    }
    ids.sort();
    ids.dedup();
    assert_eq!(ids.len(), all.len(), "pattern ids are unique");
    let files = std::fs::read_dir(root().join("examples/patterns"))
        .expect("examples/patterns")
        .count();
    assert_eq!(
        files,
        all.len(),
        "one file per pattern in examples/patterns"
    );
    for p in all {
        let made = p.design(&Params::default()).expect("defaults work");
        let path = root().join(format!("examples/patterns/{}.json", p.id));
        let file = std::fs::read_to_string(&path).expect("pattern file");
        assert!(
            file == made.to_json_pretty(),
            "{} differs from its recipe; regenerate with \
             `cargo run -p marbling-cli -- pattern --all examples/patterns`",
            path.display()
        );
        assert_eq!(Design::from_json(&file).expect("valid"), made);
    }
}

#[test]
fn every_step_has_a_written_caption_and_the_recipe_its_name() {
    for p in patterns::all() {
        let d = p.design(&Params::default()).expect("defaults work");
        let r = d.recipe.as_ref().expect("a recipe");
        assert_eq!(r.name, p.name);
        assert!(r.history.len() > 40, "{}: a line of history", p.id);
        let steps = d.gesture_sizes().len();
        assert!(steps >= 2, "{}: made in steps", p.id);
        assert_eq!(r.captions.len(), steps, "{}: one caption per step", p.id);
        assert!(r.captions.iter().all(|c| c.len() > 10), "{}", p.id);
        assert_eq!(d.step_captions(), r.captions);
        let bounds = d.step_bounds();
        assert_eq!((bounds[0], bounds[steps]), (0, d.ops.len()));
    }
}

#[test]
fn every_pattern_renders_like_its_golden() {
    let mut failures = Vec::new();
    for p in patterns::all() {
        let path = root().join(format!("examples/patterns/{}.json", p.id));
        let d = Design::from_json(&std::fs::read_to_string(&path).expect("file")).expect("valid");
        let img = render(
            &d,
            &RenderOptions {
                scale: 0.125,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
        assert_eq!((img.width, img.height), (80, 50));
        if let Err(e) = check_snapshot(
            &marbling_testkit::goldens("core").join(format!("patterns/{}.png", p.id)),
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
fn parameters_scale_recolour_and_respace_a_pattern() {
    let p = patterns::find("nonpareil").expect("nonpareil");
    let base = p.design(&Params::default()).expect("defaults");
    let big = p
        .design(&Params {
            width: 1280,
            height: 800,
            ..Params::default()
        })
        .expect("twice the size");
    assert_eq!((big.width, big.height), (1280, 800));
    assert_eq!(big.gesture_sizes(), base.gesture_sizes());
    // The same picture at twice the size: compare the two renders at one size.
    let opts = |scale| RenderOptions {
        scale,
        antialias: Antialias::Rgss,
    };
    let a = render(&base, &opts(0.25)).expect("render");
    let b = render(&big, &opts(0.125)).expect("render");
    assert_eq!((a.width, a.height), (b.width, b.height));
    let differing = marbling_core::compare::compare(&a, &b, 48)
        .expect("same size")
        .fraction();
    assert!(differing < 0.02, "scaled pattern differs in {differing}");

    let red = Rgb8::new(200, 0, 0);
    let recoloured = p
        .design(&Params {
            colors: Some(vec![red, Rgb8::new(0, 0, 200)]),
            background: Some(Rgb8::new(250, 250, 250)),
            spacing: Some(24.0),
            ..Params::default()
        })
        .expect("two inks");
    assert_eq!(recoloured.background, Rgb8::new(250, 250, 250));
    assert!(recoloured.to_json_compact().contains("#c80000"));
    assert!(recoloured.to_json_compact().contains("\"spacing\":24"));
    assert!(
        recoloured
            .step_captions()
            .iter()
            .any(|c| c.contains("24 px apart"))
    );

    for (params, message) in [
        (
            Params {
                width: 0,
                ..Params::default()
            },
            "width must be 16 to",
        ),
        (
            Params {
                colors: Some(vec![]),
                ..Params::default()
            },
            "colors: give at least one ink",
        ),
        (
            Params {
                spacing: Some(f64::NAN),
                ..Params::default()
            },
            "spacing must be 2 px",
        ),
    ] {
        let err = p.design(&params).expect_err("refused");
        assert!(err.contains(message), "{err}");
    }
    let err = patterns::find("marbled")
        .map(|p| p.id)
        .expect_err("unknown");
    assert!(
        err.contains("unknown pattern \"marbled\"") && err.contains("chevron"),
        "{err}"
    );
}
