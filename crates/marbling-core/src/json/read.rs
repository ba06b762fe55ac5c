//! The design reader: JSON value → [`Design`], every problem with its path.

use super::op_fields::FieldReader;
use crate::design::{CURRENT_VERSION, SUPPORTED_VERSIONS};
use crate::ops::{OP_TYPES_V3, OP_TYPES_V4, op_fields};
use crate::validate::{Checker, FieldError};
use crate::{Design, GestureSpan, Op, Recipe, Rgb8};
use marbling_json::{PathReader, join, short, type_of};
use serde_json::{Map, Value};
use std::ops::{Deref, DerefMut};

/// Reads a design from its JSON value: the design, or every problem found.
pub(super) fn design(value: &Value) -> Result<Design, Vec<FieldError>> {
    let mut reader = Reader {
        json: PathReader::default(),
        version: CURRENT_VERSION,
    };
    let design = reader.design(value);
    reader.json.finish(design)
}

const TOP_FIELDS: &[&str] = &[
    "version",
    "width",
    "height",
    "background",
    "overlays",
    "ops",
    "gestures",
    "recipe",
];
const TOP_FIELDS_V1: &[&str] = &[
    "version",
    "width",
    "height",
    "background",
    "ops",
    "gestures",
    "recipe",
];

/// The shared path reader plus the design schema's own parts and rules.
pub(super) struct Reader {
    json: PathReader,
    /// The document's `"version"` (v3 op types need 3).
    version: u64,
}

impl Deref for Reader {
    type Target = PathReader;
    fn deref(&self) -> &PathReader {
        &self.json
    }
}

impl DerefMut for Reader {
    fn deref_mut(&mut self) -> &mut PathReader {
        &mut self.json
    }
}

impl Reader {
    /// The schema's value rules, reporting into this reader's problems.
    pub(super) fn rules(&mut self) -> Checker<'_> {
        Checker {
            errors: &mut self.json.errors,
        }
    }

    pub(super) fn color(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
    ) -> Option<Rgb8> {
        let v = self.field(path, obj, name)?;
        let parsed = v.as_str().map(str::parse::<Rgb8>);
        match parsed {
            Some(Ok(c)) => Some(c),
            _ => {
                self.push(
                    join(path, name),
                    format!("must be a colour \"#rrggbb\", got {}", short(v)),
                );
                None
            }
        }
    }

    fn side(&mut self, obj: &Map<String, Value>, name: &str) -> Option<u32> {
        let v = self.field("", obj, name)?;
        match v.as_u64().and_then(|n| u32::try_from(n).ok()) {
            Some(n) => {
                self.rules().side(name, n);
                Some(n)
            }
            None => {
                self.push(
                    name,
                    format!(
                        "must be an integer in 1..={}, got {}",
                        crate::MAX_SIDE,
                        short(v)
                    ),
                );
                None
            }
        }
    }

    fn op(&mut self, i: usize, v: &Value) -> Option<Op> {
        let path = format!("ops[{i}]");
        let Some(obj) = v.as_object() else {
            self.push(path, format!("must be an object, got {}", type_of(v)));
            return None;
        };
        let kind = match obj.get("type") {
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                self.push(
                    format!("{path}.type"),
                    format!("must be a string, got {}", short(other)),
                );
                return None;
            }
            None => {
                self.push(format!("{path}.type"), "missing");
                return None;
            }
        };
        let Some(fields) = op_fields(kind) else {
            self.push(
                format!("{path}.type"),
                format!(
                    "unknown op type {kind:?}; expected one of {}",
                    crate::OP_TYPES.join(", ")
                ),
            );
            return None;
        };
        self.object(&path, v, fields)?;
        let version = self.version;
        let needs = if OP_TYPES_V4.contains(&kind) {
            4
        } else if OP_TYPES_V3.contains(&kind) {
            3
        } else {
            1
        };
        if version < needs {
            self.push(
                format!("{path}.type"),
                format!(
                    "op type {kind:?} needs \"version\": {needs} (this document is version {version})"
                ),
            );
        }
        let mut reader = FieldReader {
            reader: self,
            path: &path,
            obj,
        };
        let op = Op::read(kind, &mut reader)?;
        op.check(&mut self.rules().op(i));
        Some(op)
    }

    fn design(&mut self, v: &Value) -> Option<Design> {
        let v1 = v.get("version").and_then(Value::as_u64) == Some(1);
        let obj = self.object("", v, if v1 { TOP_FIELDS_V1 } else { TOP_FIELDS })?;
        let version = self.field("", obj, "version")?;
        match version.as_u64() {
            Some(n) if SUPPORTED_VERSIONS.contains(&n) => self.version = n,
            _ => {
                let supported: Vec<String> =
                    SUPPORTED_VERSIONS.iter().map(u64::to_string).collect();
                self.push(
                    "version",
                    format!(
                        "unsupported version {}; this build reads version {}",
                        short(version),
                        supported.join(", ")
                    ),
                );
                return None;
            }
        }
        let width = self.side(obj, "width");
        let height = self.side(obj, "height");
        let background = match self.field("", obj, "background") {
            Some(Value::Object(_)) if v1 => {
                self.push(
                    "background",
                    "a noise or image background needs \"version\": 2; version 1 takes a colour \"#rrggbb\"",
                );
                None
            }
            Some(b @ Value::Object(m)) if m.contains_key("image") => self
                .image_background(b)
                .map(|(paper, image)| (paper, None, Some(image))),
            Some(b @ Value::Object(_)) => self
                .noise_background(b)
                .map(|n| (n.mid_color(), Some(n), None)),
            Some(_) => self.color("", obj, "background").map(|c| (c, None, None)),
            None => None,
        };
        let overlays = match obj.get("overlays") {
            None => Some(Vec::new()),
            Some(Value::Array(items)) => items
                .iter()
                .enumerate()
                .map(|(i, item)| self.overlay(i, item))
                .collect::<Vec<_>>()
                .into_iter()
                .collect::<Option<Vec<_>>>(),
            Some(other) => {
                self.push(
                    "overlays",
                    format!("must be an array, got {}", type_of(other)),
                );
                None
            }
        };
        if let Some(list) = &overlays {
            self.rules().overlay_kinds(list.iter().map(|o| o.kind));
        }
        let ops = match self.field("", obj, "ops") {
            Some(Value::Array(items)) => {
                let ops: Vec<Option<Op>> = items
                    .iter()
                    .enumerate()
                    .map(|(i, item)| self.op(i, item))
                    .collect();
                self.rules().op_count(
                    ops.iter()
                        .map(|o| o.as_ref().map_or(1, Op::counted_ops))
                        .sum(),
                );
                ops.into_iter().collect::<Option<Vec<Op>>>()
            }
            Some(other) => {
                self.push("ops", format!("must be an array, got {}", type_of(other)));
                None
            }
            None => None,
        };
        let gestures = self.gestures(obj.get("gestures"));
        if let (Some(ops), Some(gestures)) = (&ops, &gestures) {
            self.rules().gestures(gestures, ops.len());
        }
        let recipe = self.recipe(obj.get("recipe"));
        if let (Some(ops), Some(gestures), Some(Some(r))) = (&ops, &gestures, &recipe) {
            let merged: usize = gestures.iter().map(|g| g.count.saturating_sub(1)).sum();
            let steps = ops.len().saturating_sub(merged);
            if r.captions.len() > steps {
                self.push(
                    "recipe.captions",
                    format!(
                        "at most one caption per step: {} captions for {steps} steps",
                        r.captions.len()
                    ),
                );
            }
        }
        let (background, background_noise, background_image) = background?;
        Some(Design {
            width: width?,
            height: height?,
            background,
            background_noise,
            background_image,
            overlays: overlays?,
            ops: ops?,
            gestures: gestures?,
            recipe: recipe?,
        })
    }

    /// `"recipe": {"name", "history", "captions"}` (absent: none).
    fn recipe(&mut self, v: Option<&Value>) -> Option<Option<Recipe>> {
        let Some(v) = v else { return Some(None) };
        let obj = self.object("recipe", v, &["name", "history", "captions"])?;
        let text =
            |me: &mut Self, key: &str, v: Option<&Value>| me.text(&format!("recipe.{key}"), v);
        let name = text(self, "name", obj.get("name"));
        let history = text(self, "history", obj.get("history"));
        let captions = match obj.get("captions") {
            None => Some(Vec::new()),
            Some(Value::Array(items)) => items
                .iter()
                .enumerate()
                .map(|(i, c)| text(self, &format!("captions[{i}]"), Some(c)))
                .collect::<Vec<_>>()
                .into_iter()
                .collect(),
            Some(other) => {
                self.push(
                    "recipe.captions",
                    format!("must be an array of strings, got {}", type_of(other)),
                );
                None
            }
        };
        let recipe = Recipe {
            name: name?,
            history: history?,
            captions: captions?,
        };
        self.rules().recipe(&recipe);
        Some(Some(recipe))
    }

    /// `"gestures": [[first, count], …]` (absent: none); the spans' order and bounds
    /// are checked by [`Checker::gestures`].
    fn gestures(&mut self, v: Option<&Value>) -> Option<Vec<GestureSpan>> {
        let items = match v {
            None => return Some(Vec::new()),
            Some(Value::Array(items)) => items,
            Some(other) => {
                self.push(
                    "gestures",
                    format!(
                        "must be an array of [first, count] pairs, got {}",
                        type_of(other)
                    ),
                );
                return None;
            }
        };
        let mut spans = Vec::with_capacity(items.len());
        let mut ok = true;
        for (i, item) in items.iter().enumerate() {
            let pair = item.as_array().filter(|a| a.len() == 2).and_then(|a| {
                let first = usize::try_from(a[0].as_u64()?).ok()?;
                let count = usize::try_from(a[1].as_u64()?).ok()?;
                Some(GestureSpan { first, count })
            });
            match pair {
                Some(span) => spans.push(span),
                None => {
                    ok = false;
                    self.push(
                        format!("gestures[{i}]"),
                        format!(
                            "must be [first, count], two whole numbers, got {}",
                            short(item)
                        ),
                    );
                }
            }
        }
        ok.then_some(spans)
    }
}
