//! Helpers shared by the core tests: the messages of a refused document.

use marbling_core::{Design, DesignError};

/// The messages of an invalid document, each naming its JSON path.
pub fn errors(text: &str) -> Vec<String> {
    match Design::from_json(text) {
        Err(DesignError::Invalid(e)) => e.0.iter().map(ToString::to_string).collect(),
        other => panic!("expected validation errors, got {other:?}"),
    }
}

/// Asserts that the invalid document `text` is refused with the message `expected`.
pub fn assert_error(text: &str, expected: &str) {
    marbling_testkit::assert_listed(&errors(text), expected);
}
