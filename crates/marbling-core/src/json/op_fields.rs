//! One op's fields in a document, as each op type's file reads and writes them
//! ([`crate::ops::OpType`]): [`FieldReader`] reports every problem at `ops[i].<field>`,
//! [`FieldWriter`] writes numbers as integers when they are.

use super::read::Reader;
use crate::Rgb8;
use kurbo::{Point, Vec2};
use marbling_json::{join, short};
use marbling_noise::{NoiseSpec, SpecError};
use serde_json::{Map, Value, json};
use std::sync::Arc;

/// Reads the fields of one op object; each method returns `None` after reporting why.
pub(crate) struct FieldReader<'r> {
    pub(super) reader: &'r mut Reader,
    /// The op's JSON path, `ops[i]`.
    pub(super) path: &'r str,
    pub(super) obj: &'r Map<String, Value>,
}

impl FieldReader<'_> {
    /// Whether the object has field `name`.
    pub(crate) fn has(&self, name: &str) -> bool {
        self.obj.contains_key(name)
    }

    /// Reports a problem at field `name`.
    pub(crate) fn push(&mut self, name: &str, message: &str) {
        self.reader.push(join(self.path, name), message);
    }

    /// A finite or infinite number (the value rules check it later).
    pub(crate) fn number(&mut self, name: &str) -> Option<f64> {
        self.reader.number(self.path, self.obj, name)
    }

    /// A point `[x, y]`, design pixels.
    pub(crate) fn point(&mut self, name: &str) -> Option<Point> {
        self.reader.pair(self.path, self.obj, name).map(Point::from)
    }

    /// A vector `[x, y]`.
    pub(crate) fn vector(&mut self, name: &str) -> Option<Vec2> {
        self.reader.pair(self.path, self.obj, name).map(Vec2::from)
    }

    /// A colour `"#rrggbb"`.
    pub(crate) fn color(&mut self, name: &str) -> Option<Rgb8> {
        self.reader.color(self.path, self.obj, name)
    }

    /// A list of numbers.
    pub(crate) fn numbers(&mut self, name: &str) -> Option<Arc<[f64]>> {
        self.reader
            .list(self.path, self.obj, name, "numbers", |r, p, v| {
                r.number_value(p, v)
            })
            .map(Arc::from)
    }

    /// A list of points `[x, y]`.
    pub(crate) fn points(&mut self, name: &str) -> Option<Arc<[Point]>> {
        self.reader
            .list(self.path, self.obj, name, "[x, y] points", |r, p, v| {
                r.pair_value(p, v).map(Point::from)
            })
            .map(Arc::from)
    }

    /// A noise spec in the `marbling-noise` format, its problems reported under the
    /// field (`ops[4].noise.octaves`).
    pub(crate) fn noise(&mut self, name: &str) -> Option<NoiseSpec> {
        let v = self.reader.field(self.path, self.obj, name)?;
        let path = join(self.path, name);
        match NoiseSpec::from_value(v) {
            Ok(spec) => Some(spec),
            Err(SpecError::Invalid(list)) => {
                self.reader
                    .errors
                    .extend(list.into_iter().map(|p| p.under(&path)));
                None
            }
            Err(other) => {
                self.reader.push(path, other.to_string());
                None
            }
        }
    }

    /// A list of colours `"#rrggbb"`.
    pub(crate) fn colors(&mut self, name: &str) -> Option<Arc<[Rgb8]>> {
        self.reader
            .list(
                self.path,
                self.obj,
                name,
                "colours \"#rrggbb\"",
                |r, p, v| {
                    let c = v.as_str().and_then(|s| s.parse::<Rgb8>().ok());
                    if c.is_none() {
                        r.push(p, format!("must be a colour \"#rrggbb\", got {}", short(v)));
                    }
                    c
                },
            )
            .map(Arc::from)
    }
}

/// Writes the fields of one op object in the order they are given.
pub(crate) struct FieldWriter {
    pub(super) map: Map<String, Value>,
}

/// A number written as an integer when it is one (shorter documents and share links).
pub(super) fn num(v: f64) -> Value {
    if v.fract() == 0.0 && v.abs() < 9.0e15 {
        json!(v as i64)
    } else {
        json!(v)
    }
}

fn pair(x: f64, y: f64) -> Value {
    json!([num(x), num(y)])
}

impl FieldWriter {
    fn put(&mut self, name: &str, v: Value) {
        self.map.insert(name.into(), v);
    }

    /// A number.
    pub(crate) fn number(&mut self, name: &str, v: f64) {
        self.put(name, num(v));
    }

    /// A point `[x, y]`.
    pub(crate) fn point(&mut self, name: &str, p: Point) {
        self.put(name, pair(p.x, p.y));
    }

    /// A vector `[x, y]`.
    pub(crate) fn vector(&mut self, name: &str, v: Vec2) {
        self.put(name, pair(v.x, v.y));
    }

    /// A colour `"#rrggbb"`.
    pub(crate) fn color(&mut self, name: &str, c: Rgb8) {
        self.put(name, json!(c.to_string()));
    }

    /// A list of numbers.
    pub(crate) fn numbers(&mut self, name: &str, list: &[f64]) {
        self.put(name, Value::Array(list.iter().map(|&v| num(v)).collect()));
    }

    /// A list of points `[x, y]`.
    pub(crate) fn points(&mut self, name: &str, list: &[Point]) {
        self.put(
            name,
            Value::Array(list.iter().map(|p| pair(p.x, p.y)).collect()),
        );
    }

    /// A noise spec, as `marbling-noise` writes it.
    pub(crate) fn noise(&mut self, name: &str, spec: &NoiseSpec) {
        self.put(name, spec.to_value());
    }

    /// A list of colours `"#rrggbb"`.
    pub(crate) fn colors(&mut self, name: &str, list: &[Rgb8]) {
        self.put(
            name,
            Value::Array(list.iter().map(|c| json!(c.to_string())).collect()),
        );
    }
}
