//! `marbling svg` and `marbling render --backend vector` from the outside: success,
//! refusals with one-line messages and non-zero exits, and no partial output files.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const DESIGN: &str = r##"{ "version": 1, "width": 120, "height": 90, "background": "#f3ead7",
  "ops": [
    {"type":"drop", "center":[60,45], "radius":25, "color":"#1d3557"},
    {"type":"drop", "center":[70,40], "radius":12, "color":"#e63946"},
    {"type":"spray", "center":[20,20], "radius":3, "color":"#457b9d"},
    {"type":"tine", "origin":[0,45], "direction":[1,0], "alpha":20, "lambda":6},
    {"type":"vortex", "center":[60,45], "alpha":10, "lambda":15}
  ] }"##;

/// A fresh directory holding `design.json`.
fn workdir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("marbling-svg-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    std::fs::write(dir.join("design.json"), DESIGN).expect("write design");
    dir
}

fn marbling(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_marbling"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("runs")
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn svg_writes_a_complete_document() {
    let dir = workdir("ok");
    let o = marbling(
        &dir,
        &[
            "svg",
            "design.json",
            "-o",
            "out.svg",
            "--tolerance",
            "0.5",
            "--width",
            "240",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(dir.join("out.svg")).expect("written");
    assert!(
        svg.contains(r#"width="240" height="180" viewBox="0 0 120 90""#),
        "{svg}"
    );
    assert_eq!(svg.matches("<path ").count(), 3);
    assert!(svg.trim_end().ends_with("</svg>"));
    // Only the output in the directory: no temporary left behind.
    let names: Vec<_> = std::fs::read_dir(&dir)
        .expect("dir")
        .flatten()
        .map(|e| e.file_name())
        .collect();
    assert_eq!(names.len(), 2, "{names:?}");
}

#[test]
fn svg_refuses_bad_tolerance_without_writing() {
    let dir = workdir("tol");
    for bad in ["0", "-1", "NaN", "inf"] {
        let o = marbling(
            &dir,
            &["svg", "design.json", "-o", "out.svg", "--tolerance", bad],
        );
        assert!(!o.status.success());
        let e = stderr(&o);
        assert!(e.contains("tolerance must be"), "{e}");
        assert_eq!(e.trim_end().lines().count(), 1, "{e}");
        assert!(!dir.join("out.svg").exists());
    }
}

#[test]
fn svg_reports_unwritable_output() {
    let dir = workdir("unwritable");
    let o = marbling(&dir, &["svg", "design.json", "-o", "missing/dir/out.svg"]);
    assert!(!o.status.success());
    let e = stderr(&o);
    assert!(e.contains("cannot write 'missing/dir/out.svg'"), "{e}");
    assert_eq!(e.trim_end().lines().count(), 1, "{e}");
}

#[test]
fn designs_too_complex_to_trace_exactly_are_refused_and_nothing_is_written() {
    let dir = workdir("complex");
    let o = marbling(
        &dir,
        &[
            "svg",
            "design.json",
            "-o",
            "out.svg",
            "--exact",
            "--max-vertices",
            "50",
        ],
    );
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("needs more than 50 outline vertices"),
        "{}",
        stderr(&o)
    );
    assert!(!dir.join("out.svg").exists());
}

#[test]
fn render_with_vector_backend_writes_a_png() {
    let dir = workdir("render");
    let o = marbling(
        &dir,
        &[
            "render",
            "design.json",
            "-o",
            "v.png",
            "--backend",
            "vector",
            "--scale",
            "2",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let png = std::fs::read(dir.join("v.png")).expect("written");
    assert_eq!(&png[1..4], b"PNG");
    assert!(String::from_utf8_lossy(&o.stdout).contains("backend vector"));
    let o = marbling(
        &dir,
        &[
            "render",
            "design.json",
            "-o",
            "w.png",
            "--backend",
            "vector",
            "--tolerance",
            "0",
        ],
    );
    assert!(!o.status.success());
    assert!(!dir.join("w.png").exists(), "refused render left a file");
}
