//! Running the `marbling` binary from integration tests.

use std::io::Write;
use std::process::{Command, Output, Stdio};

/// Runs `marbling ARGS`, feeding `stdin` when given, and collects its output.
pub fn marbling(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_marbling"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn marbling");
    if let Some(text) = stdin {
        // The command may exit (e.g. on a bad option) before reading its input.
        let _ = child
            .stdin
            .take()
            .expect("stdin")
            .write_all(text.as_bytes());
    }
    drop(child.stdin.take());
    child.wait_with_output().expect("wait")
}
