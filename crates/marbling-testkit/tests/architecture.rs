//! docs/ARCHITECTURE.md names every part of the code: each crate, each feature folder
//! of the app, each integration-test module and each browser test file. A new one that
//! the document does not mention fails here, so the map cannot fall behind the code.

use std::fs;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Names of the entries of `dir` that `keep` accepts, sorted.
fn names(dir: &Path, keep: impl Fn(&Path) -> bool) -> Vec<String> {
    let mut out: Vec<String> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| keep(p))
        .map(|p| {
            p.file_name()
                .expect("a name")
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    out.sort();
    out
}

/// The parts `doc` does not mention: each part is looked for as `` `NAME` `` or as a
/// path ending in NAME (`…/NAME` inside backticks).
fn unnamed(doc: &str, parts: &[String]) -> Vec<String> {
    parts
        .iter()
        .filter(|p| !doc.contains(&format!("`{p}`")) && !doc.contains(&format!("/{p}`")))
        .cloned()
        .collect()
}

/// Every part of the code the architecture document must name.
fn parts(root: &Path) -> Vec<String> {
    let mut all = Vec::new();
    // Crates.
    for c in names(&root.join("crates"), |p| p.join("Cargo.toml").exists()) {
        all.push(format!("crates/{c}"));
    }
    // The app's feature folders.
    let app = root.join("crates/marbling-app/src");
    for f in names(&app, |p| p.is_dir()) {
        all.push(format!("{f}/"));
    }
    // Integration-test modules (tests/it/*.rs but main.rs and common).
    for c in names(&root.join("crates"), |p| {
        p.join("tests/it/main.rs").exists()
    }) {
        let it = root.join("crates").join(&c).join("tests/it");
        for m in names(&it, |p| p.extension().is_some_and(|e| e == "rs")) {
            if m != "main.rs" && m != "common.rs" {
                all.push(m);
            }
        }
    }
    // Browser test files.
    for t in names(&root.join("tests/browser"), |p| {
        p.to_string_lossy().ends_with(".test.mjs")
    }) {
        all.push(t);
    }
    all
}

#[test]
fn the_architecture_names_every_crate_feature_test_module_and_browser_test() {
    let root = root();
    let doc = fs::read_to_string(root.join("docs/ARCHITECTURE.md")).expect("docs/ARCHITECTURE.md");
    let parts = parts(&root);
    assert!(parts.len() > 40, "too few parts found: {parts:?}");
    let missing = unnamed(&doc, &parts);
    assert!(
        missing.is_empty(),
        "docs/ARCHITECTURE.md does not name: {missing:?}"
    );
}

/// The check itself: a part the document does not name is reported, one it names is not.
#[test]
fn an_unnamed_part_is_reported() {
    let doc = "the `store/` folder; `crates/marbling-core`; tests in `tests/it/cli.rs`";
    let parts = [
        "store/",
        "crates/marbling-core",
        "cli.rs",
        "noise/",
        "svg_cli.rs",
    ]
    .map(String::from);
    assert_eq!(unnamed(doc, &parts), ["noise/", "svg_cli.rs"]);
}

/// docs/BENCHMARKS.md keeps the current numbers a reader needs; older runs and tuning
/// notes go to docs/perf-log/.
#[test]
fn the_benchmarks_page_stays_short() {
    let text = fs::read_to_string(root().join("docs/BENCHMARKS.md")).expect("docs/BENCHMARKS.md");
    let lines = text.lines().count();
    assert!(
        lines <= 500,
        "docs/BENCHMARKS.md has {lines} lines (at most 500; move detail to docs/perf-log/)"
    );
}
