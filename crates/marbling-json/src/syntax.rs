//! Text that is not JSON.

use serde_json::Value;

/// Where and why a text is not JSON; line and column are 1-based.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("line {line}, column {column}: {message}")]
pub struct Syntax {
    /// 1-based line of the problem.
    pub line: usize,
    /// 1-based column of the problem.
    pub column: usize,
    /// What the JSON parser expected (without serde's trailing "at line … column …").
    pub message: String,
}

/// Parses `text` as JSON.
pub fn parse(text: &str) -> Result<Value, Syntax> {
    serde_json::from_str(text).map_err(|e| {
        let full = e.to_string();
        let message = match full.rfind(" at line ") {
            Some(i) => full[..i].to_owned(),
            None => full,
        };
        Syntax {
            line: e.line(),
            column: e.column(),
            message,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn syntax_errors_say_where_once() {
        let e = parse("{\n  \"a\": 1,\n  oops\n}").expect_err("not JSON");
        assert_eq!((e.line, e.column), (3, 3));
        assert!(!e.message.contains("line"), "{}", e.message);
        assert!(
            e.to_string()
                .starts_with("line 3, column 3: key must be a string"),
            "{e}"
        );
    }
}
