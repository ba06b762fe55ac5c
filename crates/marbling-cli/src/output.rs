//! Where a command's one-line summary goes.

/// Prints `summary` for a command whose file went to `output`: on standard error when
/// the file itself went to standard output (`-`), else on standard output.
pub fn say(output: &str, summary: &str) {
    if output == "-" {
        eprintln!("{summary}");
    } else {
        println!("{summary}");
    }
}
