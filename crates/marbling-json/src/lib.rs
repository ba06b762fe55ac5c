//! Reading JSON documents by path: the one reader the design parser
//! (`marbling-core`) and the noise-spec parser (`marbling-noise`) share.
//!
//! A [`PathReader`] walks a `serde_json::Value`, turns fields into typed values and
//! records every problem as a [`FieldError`] naming its JSON path
//! (`ops[3].center[1]: must be a number, got a string`). Readers return `None` for a
//! value they could not read and keep going, so one pass reports every problem.

mod path;
mod reader;
mod syntax;

pub use path::{join, short, type_of};
pub use reader::PathReader;
pub use syntax::{Syntax, parse};

use std::fmt;

/// One problem at one place of a document, e.g. `ops[12].radius: must be > 0, got -3`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldError {
    /// JSON path of the offending value (`ops[3].center[1]`, `frequency`, …); empty for
    /// the document itself.
    pub path: String,
    /// What is wrong, with the value found.
    pub message: String,
}

impl FieldError {
    /// The same problem seen from a document that holds this one at `prefix`.
    #[must_use]
    pub fn under(self, prefix: &str) -> Self {
        Self {
            path: join(prefix, &self.path),
            message: self.message,
        }
    }
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.path.is_empty() {
            write!(f, "{}", self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}
