//! Reading a design from a file or standard input, with one-line error messages.

use anyhow::{Context, Result, bail};
use marbling_core::{Design, DesignError, ImageBackground, ImageFit};
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
/// An image background may name a picture file relative to the design file (or to the
/// working directory for standard input); it is read and embedded as a `data:` URI.
pub fn read_design(path: &str) -> Result<Design> {
    let text = read_text(path)?;
    let name = display_name(path);
    let text = embed_image_file(path, text)?;
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

/// Reads a turbulence document (`--flow`), every problem named with the file and its
/// path.
pub fn read_turbulence(path: &str) -> Result<marbling_core::turbulence::Turbulence> {
    let text = read_text(path)?;
    let name = display_name(path);
    marbling_core::turbulence::Turbulence::from_json(&text).map_err(|errors| {
        let lines: Vec<String> = errors.iter().map(|e| format!("{name}: {e}")).collect();
        anyhow::anyhow!(
            "{} problem(s) in the turbulence:\n{}",
            lines.len(),
            lines.join("\n")
        )
    })
}

/// `text` with a `background.image` that names a file replaced by the file's `data:`
/// URI (unchanged when it holds none, or is not JSON: the reader reports that).
fn embed_image_file(path: &str, text: String) -> Result<String> {
    let Ok(mut v) = serde_json::from_str::<serde_json::Value>(&text) else {
        return Ok(text);
    };
    let Some(file) = v
        .pointer("/background/image")
        .and_then(serde_json::Value::as_str)
        .filter(|s| !s.starts_with("data:"))
        .map(str::to_owned)
    else {
        return Ok(text);
    };
    let name = display_name(path);
    let base = if path == "-" {
        std::path::PathBuf::new()
    } else {
        std::path::Path::new(path)
            .parent()
            .map(std::path::Path::to_path_buf)
            .unwrap_or_default()
    };
    let full = base.join(&file);
    let bytes = std::fs::read(&full)
        .with_context(|| format!("{name}: background.image: cannot read '{}'", full.display()))?;
    let image = ImageBackground::from_file_bytes(&bytes, ImageFit::default())
        .map_err(|e| anyhow::anyhow!("{name}: background.image: '{file}': {e}"))?;
    v["background"]["image"] = serde_json::Value::String(image.source().to_owned());
    Ok(v.to_string())
}
