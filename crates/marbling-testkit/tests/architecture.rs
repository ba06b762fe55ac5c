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

/// Every `.rs` file under `dir`, recursively, with its text.
fn sources(dir: &Path) -> Vec<(PathBuf, String)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let p = entry.expect("a directory entry").path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                let text =
                    fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
                out.push((p, text));
            }
        }
    }
    out.sort();
    out
}

/// Whether `text` has an inherent `impl` block of the app (`impl MarblingApp {`, under
/// any path); `impl eframe::App for MarblingApp` is the frame loop's, not one.
fn impls_the_app(text: &str) -> bool {
    text.lines().any(|l| {
        let l = l.trim_start();
        l.starts_with("impl ") && l.contains("MarblingApp {") && !l.contains(" for ")
    })
}

/// The app's state is its features'; only `app.rs`, which holds them, has `impl
/// MarblingApp` (STYLE.md: features owning their state).
#[test]
fn only_app_rs_implements_the_app() {
    let src = root().join("crates/marbling-app/src");
    let found: Vec<String> = sources(&src)
        .into_iter()
        .filter(|(_, text)| impls_the_app(text))
        .map(|(p, _)| {
            p.strip_prefix(&src)
                .expect("under src")
                .display()
                .to_string()
        })
        .collect();
    assert_eq!(found, ["app.rs"], "impl MarblingApp outside app.rs");
}

/// The check itself: an inherent impl under any path is found; a trait's is not.
#[test]
fn an_app_impl_is_found() {
    assert!(impls_the_app("x\n    impl crate::app::MarblingApp {\n"));
    assert!(impls_the_app("impl MarblingApp {"));
    assert!(!impls_the_app("impl eframe::App for MarblingApp {"));
    assert!(!impls_the_app("let app = MarblingApp::new();"));
}

/// No Rust source of the workspace passes 600 lines (one idea per file).
#[test]
fn no_source_file_passes_600_lines() {
    let crates = root().join("crates");
    let long: Vec<String> = sources(&crates)
        .into_iter()
        .map(|(p, text)| (p, text.lines().count()))
        .filter(|(_, n)| *n > 600)
        .map(|(p, n)| format!("{} ({n} lines)", p.display()))
        .collect();
    assert!(long.is_empty(), "over 600 lines: {long:?}");
}
