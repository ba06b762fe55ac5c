//! The path reader: typed fields out of JSON objects, every problem recorded with its
//! path.

use crate::{FieldError, join, short, type_of};
use serde_json::{Map, Value};

/// Reads fields of a JSON document and records every problem with its path.
///
/// Each reading method returns `None` when the value could not be read (the problem is
/// recorded), so a parser can read every field, then combine the `Option`s.
#[derive(Debug, Default)]
pub struct PathReader {
    /// The problems found so far, in the order they were found.
    pub errors: Vec<FieldError>,
}

impl PathReader {
    /// Records a problem at `path`.
    pub fn push(&mut self, path: impl Into<String>, message: impl Into<String>) {
        self.errors.push(FieldError {
            path: path.into(),
            message: message.into(),
        });
    }

    /// `value` when nothing went wrong, else every problem found (at least one).
    pub fn finish<T>(mut self, value: Option<T>) -> Result<T, Vec<FieldError>> {
        match value {
            Some(v) if self.errors.is_empty() => Ok(v),
            _ => {
                if self.errors.is_empty() {
                    self.push("", "invalid document");
                }
                Err(self.errors)
            }
        }
    }

    /// `v` as an object whose keys are all in `allowed`; each other key is reported as
    /// an unknown field (and the object is still returned).
    pub fn object<'a>(
        &mut self,
        path: &str,
        v: &'a Value,
        allowed: &[&str],
    ) -> Option<&'a Map<String, Value>> {
        let Some(obj) = v.as_object() else {
            self.push(path, format!("must be an object, got {}", type_of(v)));
            return None;
        };
        for key in obj.keys().filter(|k| !allowed.contains(&k.as_str())) {
            self.push(
                join(path, key),
                format!("unknown field; expected one of {}", allowed.join(", ")),
            );
        }
        Some(obj)
    }

    /// A required field (`missing` when absent).
    pub fn field<'a>(
        &mut self,
        path: &str,
        obj: &'a Map<String, Value>,
        name: &str,
    ) -> Option<&'a Value> {
        let v = obj.get(name);
        if v.is_none() {
            self.push(join(path, name), "missing");
        }
        v
    }

    /// `v` as a (finite) number.
    pub fn number_value(&mut self, path: &str, v: &Value) -> Option<f64> {
        let n = v.as_f64().filter(|x| x.is_finite());
        if n.is_none() {
            self.push(path, format!("must be a number, got {}", type_of(v)));
        }
        n
    }

    /// A required number field.
    pub fn number(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<f64> {
        let v = self.field(path, obj, name)?;
        self.number_value(&join(path, name), v)
    }

    /// A number field that may be absent: `default` then, or `missing` when the default
    /// is `None`.
    pub fn number_or(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        default: Option<f64>,
    ) -> Option<f64> {
        match (obj.get(name), default) {
            (None, Some(d)) => Some(d),
            _ => self.number(path, obj, name),
        }
    }

    /// `v` as `[x, y]`, two numbers.
    pub fn pair_value(&mut self, path: &str, v: &Value) -> Option<(f64, f64)> {
        match v.as_array().map(Vec::as_slice) {
            Some([x, y]) => {
                let x = self.number_value(&format!("{path}[0]"), x);
                let y = self.number_value(&format!("{path}[1]"), y);
                Some((x?, y?))
            }
            _ => {
                self.push(
                    path,
                    format!("must be an array [x, y] of two numbers, got {}", short(v)),
                );
                None
            }
        }
    }

    /// A required `[x, y]` field.
    pub fn pair(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<(f64, f64)> {
        let v = self.field(path, obj, name)?;
        self.pair_value(&join(path, name), v)
    }

    /// A required array field, each item read by `item(self, path of the item, item)`;
    /// `what` names the items in the error when the field is not an array.
    pub fn list<T>(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        what: &str,
        item: impl FnMut(&mut Self, &str, &Value) -> Option<T>,
    ) -> Option<Vec<T>> {
        let v = self.field(path, obj, name)?;
        self.list_value(&join(path, name), v, what, item)
    }

    /// `v` as an array, each item read by `item(self, path of the item, item)`; every
    /// item is read (and its problems recorded) even after one fails.
    pub fn list_value<T>(
        &mut self,
        path: &str,
        v: &Value,
        what: &str,
        mut item: impl FnMut(&mut Self, &str, &Value) -> Option<T>,
    ) -> Option<Vec<T>> {
        let Some(items) = v.as_array() else {
            self.push(
                path,
                format!("must be an array of {what}, got {}", short(v)),
            );
            return None;
        };
        let read: Vec<Option<T>> = items
            .iter()
            .enumerate()
            .map(|(i, it)| item(self, &format!("{path}[{i}]"), it))
            .collect();
        read.into_iter().collect()
    }

    /// An optional string field naming one of `options`; `default` when absent.
    pub fn choice<T: Copy>(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        default: T,
        options: &[(&str, T)],
    ) -> Option<T> {
        let Some(v) = obj.get(name) else {
            return Some(default);
        };
        let found = v
            .as_str()
            .and_then(|s| options.iter().find(|(n, _)| *n == s).map(|&(_, t)| t));
        if found.is_none() {
            let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
            self.push(
                join(path, name),
                format!("must be one of {}, got {}", names.join(", "), short(v)),
            );
        }
        found
    }

    /// An optional boolean field; `false` when absent.
    pub fn boolean(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<bool> {
        match obj.get(name) {
            None => Some(false),
            Some(Value::Bool(b)) => Some(*b),
            Some(v) => {
                self.push(
                    join(path, name),
                    format!("must be true or false, got {}", type_of(v)),
                );
                None
            }
        }
    }

    /// An optional string field; empty when absent.
    pub fn text(&mut self, path: &str, v: Option<&Value>) -> Option<String> {
        match v {
            None => Some(String::new()),
            Some(Value::String(s)) => Some(s.clone()),
            Some(other) => {
                self.push(path, format!("must be a string, got {}", type_of(other)));
                None
            }
        }
    }

    /// An optional whole-number field in `0..=u32::MAX`; `default` when absent.
    pub fn whole(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        default: u32,
    ) -> Option<u32> {
        match obj.get(name) {
            None => Some(default),
            Some(v) => {
                let n = v.as_u64().and_then(|s| u32::try_from(s).ok());
                if n.is_none() {
                    self.push(
                        join(path, name),
                        format!("must be an integer in 0..={}, got {}", u32::MAX, short(v)),
                    );
                }
                n
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn every_problem_is_reported_with_its_path() {
        let doc = json!({"size": [1, "x"], "n": "3", "extra": 1, "flag": 2, "list": [1, null, 3]});
        let mut r = PathReader::default();
        let obj = r.object("", &doc, &["size", "n", "flag", "list", "gone"]);
        let obj = obj.expect("an object");
        assert_eq!(r.pair("", obj, "size"), None);
        assert_eq!(r.number("", obj, "n"), None);
        assert_eq!(r.number("", obj, "gone"), None);
        assert_eq!(r.number_or("", obj, "absent", Some(2.0)), Some(2.0));
        assert_eq!(r.boolean("", obj, "flag"), None);
        let list = r.list("", obj, "list", "numbers", |r, p, v| r.number_value(p, v));
        assert_eq!(list, None);
        let messages: Vec<String> = r.errors.iter().map(ToString::to_string).collect();
        assert_eq!(
            messages,
            [
                "extra: unknown field; expected one of size, n, flag, list, gone",
                "size[1]: must be a number, got a string",
                "n: must be a number, got a string",
                "gone: missing",
                "flag: must be true or false, got a number",
                "list[1]: must be a number, got null",
            ]
        );
    }

    #[test]
    fn a_clean_read_finishes_with_its_value() {
        let doc = json!({"kind": "b", "seed": 7, "xs": [1, 2.5]});
        let mut r = PathReader::default();
        let obj = r
            .object("spec", &doc, &["kind", "seed", "xs"])
            .expect("object");
        let kind = r.choice("spec", obj, "kind", 0, &[("a", 1), ("b", 2)]);
        let seed = r.whole("spec", obj, "seed", 0);
        let xs = r.list("spec", obj, "xs", "numbers", |r, p, v| r.number_value(p, v));
        assert_eq!(
            r.finish(Some((kind, seed, xs))),
            Ok((Some(2), Some(7), Some(vec![1.0, 2.5])))
        );
        let mut r = PathReader::default();
        let bad = r.choice("spec", obj, "seed", 0, &[("a", 1)]);
        assert_eq!(bad, None);
        let errors = r.finish(bad).expect_err("a problem");
        assert_eq!(errors[0].to_string(), "spec.seed: must be one of a, got 7");
        assert_eq!(
            PathReader::default()
                .finish::<()>(None)
                .expect_err("nothing read")[0]
                .message,
            "invalid document"
        );
    }
}
