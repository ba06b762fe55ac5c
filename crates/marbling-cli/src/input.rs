//! Reading a design from a file or standard input, with one-line error messages.

use anyhow::{Context, Result, bail};
use marbling_core::{Design, DesignError};
use std::io::Read;

/// The text of `path`, or of standard input when `path` is `-`.
pub fn read_text(path: &str) -> Result<String> {
    if path == "-" {
        let mut s = String::new();
        std::io::stdin()
            .read_to_string(&mut s)
            .context("cannot read standard input")?;
        Ok(s)
    } else {
        std::fs::read_to_string(path).with_context(|| format!("cannot read '{path}'"))
    }
}

/// How the input is named in messages.
pub fn display_name(path: &str) -> &str {
    if path == "-" { "<stdin>" } else { path }
}

/// Reads and validates a design; every problem is reported, prefixed with the input name.
pub fn read_design(path: &str) -> Result<Design> {
    let text = read_text(path)?;
    let name = display_name(path);
    match Design::from_json(&text) {
        Ok(d) => Ok(d),
        Err(DesignError::Syntax {
            line,
            column,
            message,
        }) => {
            bail!("{name}:{line}:{column}: invalid JSON: {message}")
        }
        Err(DesignError::Invalid(errors)) => {
            let lines: Vec<String> = errors.0.iter().map(|e| format!("{name}: {e}")).collect();
            bail!(
                "{} problem(s) in the design:\n{}",
                lines.len(),
                lines.join("\n")
            )
        }
    }
}
