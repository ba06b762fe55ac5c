//! JSON paths and values as error messages show them.

use serde_json::Value;

/// `path.name`, or `name` at the top of a document; an empty `name` leaves `path`.
#[must_use]
pub fn join(path: &str, name: &str) -> String {
    match (path.is_empty(), name.is_empty()) {
        (true, _) => name.to_owned(),
        (false, true) => path.to_owned(),
        (false, false) if name.starts_with('[') => format!("{path}{name}"),
        (false, false) => format!("{path}.{name}"),
    }
}

/// What kind of JSON value `v` is, with its article (`a number`, `an array`, `null`).
#[must_use]
pub fn type_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// `v` as JSON text for an error message, cut after 40 characters with `…`.
#[must_use]
pub fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn paths_join_with_dots_and_brackets() {
        assert_eq!(join("", "width"), "width");
        assert_eq!(join("ops[2]", "center"), "ops[2].center");
        assert_eq!(
            join("background", "noise.frequency"),
            "background.noise.frequency"
        );
        assert_eq!(join("background.noise", ""), "background.noise");
        assert_eq!(join("ops", "[3]"), "ops[3]");
    }

    #[test]
    fn long_values_are_cut() {
        assert_eq!(short(&json!([1, 2])), "[1,2]");
        let long = short(&json!("x".repeat(100)));
        assert_eq!(long.chars().count(), 41);
        assert!(long.ends_with('…'));
        assert_eq!(type_of(&json!({})), "an object");
    }
}
