//! Reading and writing design documents (schema v1 and v2 JSON), with errors that name
//! the JSON path of every problem.
//!
//! Schema v2 (`"version": 2`) differs from v1 in two places only:
//! - `background` is a colour `"#rrggbb"` as in v1, or an object
//!   `{"noise": SPEC, "palette": P}`: SPEC a `marbling-noise` spec (design pixels), P a
//!   palette name or an array of 2..=8 `"#rrggbb"` (default `"grey"`);
//! - optional `"overlays": [{"type": "paper-grain" | "pigment-grain", "noise": SPEC,
//!   "strength": s}]`, s in [0, 1].
//!
//! See [`crate::surface`] for how they colour a render.
//!
//! Schema v3 (`"version": 3`) adds seven op types (shift, turn, comb, drops, sprays,
//! jiggle, stylus; see [`crate::Op`]). A design is written with the lowest version that
//! holds it: 1 when it uses neither v2's surfaces nor v3's ops.

use crate::design::{CURRENT_VERSION, SUPPORTED_VERSIONS};
use crate::ops::OP_TYPES_V3;
use crate::surface::{GrainKind, NoiseBackground, NoiseLayer, Overlay, Palette};
use crate::validate::Checker;
use crate::{
    Circular, Comb, Design, Drop, DropSet, GestureSpan, Jiggle, Op, Radii, Rake, Recipe, Rgb8,
    Shift, Spray, Stylus, Tine, Turn, ValidationErrors, Vortex, Wavy,
};
use kurbo::{Point, Vec2};
use serde_json::{Map, Value, json};
use std::sync::Arc;

/// Why a design document could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DesignError {
    /// The text is not JSON; line and column are 1-based.
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line of the problem.
        line: usize,
        /// 1-based column of the problem.
        column: usize,
        /// What the JSON parser expected.
        message: String,
    },
    /// The JSON does not describe a valid design; every problem is listed.
    #[error("{0}")]
    Invalid(ValidationErrors),
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

/// Field names of each op type, `type` first, in the order they are written.
fn op_fields(kind: &str) -> Option<&'static [&'static str]> {
    Some(match kind {
        "drop" | "spray" => &["type", "center", "radius", "color"],
        "tine" => &["type", "origin", "direction", "alpha", "lambda"],
        "rake" => &["type", "origin", "direction", "spacing", "alpha", "lambda"],
        "wavy" => &["type", "angle", "amplitude", "wavelength", "phase"],
        "circular" => &["type", "center", "radius", "alpha", "lambda"],
        "vortex" => &["type", "center", "alpha", "lambda"],
        "shift" => &["type", "offset"],
        "turn" => &["type", "center", "angle"],
        "comb" => &["type", "origin", "direction", "tines", "alpha", "lambda"],
        "drops" | "sprays" => &["type", "centers", "radius", "radii", "colors"],
        "jiggle" => &["type", "angle", "wavelength", "along", "across", "phase"],
        "stylus" => &["type", "path", "wake", "tips"],
        _ => return None,
    })
}

fn type_of(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// Turns JSON values into typed parts, recording every problem with its path.
struct Reader {
    c: Checker,
    /// The document's `"version"` (v3 op types need 3).
    version: u64,
}

impl Reader {
    fn object<'a>(
        &mut self,
        path: &str,
        v: &'a Value,
        allowed: &[&str],
    ) -> Option<&'a Map<String, Value>> {
        let Some(obj) = v.as_object() else {
            self.c
                .push(path, format!("must be an object, got {}", type_of(v)));
            return None;
        };
        for key in obj.keys().filter(|k| !allowed.contains(&k.as_str())) {
            self.c.push(
                join(path, key),
                format!("unknown field; expected one of {}", allowed.join(", ")),
            );
        }
        Some(obj)
    }

    fn field<'a>(
        &mut self,
        path: &str,
        obj: &'a Map<String, Value>,
        name: &str,
    ) -> Option<&'a Value> {
        let v = obj.get(name);
        if v.is_none() {
            self.c.push(join(path, name), "missing");
        }
        v
    }

    fn number(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<f64> {
        let v = self.field(path, obj, name)?;
        self.number_value(&join(path, name), v)
    }

    fn number_value(&mut self, path: &str, v: &Value) -> Option<f64> {
        let n = v.as_f64();
        if n.is_none() {
            self.c
                .push(path, format!("must be a number, got {}", type_of(v)));
        }
        n
    }

    fn pair(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<(f64, f64)> {
        let v = self.field(path, obj, name)?;
        let path = join(path, name);
        match v.as_array().map(Vec::as_slice) {
            Some([x, y]) => {
                let x = self.number_value(&format!("{path}[0]"), x);
                let y = self.number_value(&format!("{path}[1]"), y);
                Some((x?, y?))
            }
            _ => {
                self.c.push(
                    path,
                    format!("must be an array [x, y] of two numbers, got {}", short(v)),
                );
                None
            }
        }
    }

    fn point(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Point> {
        self.pair(path, obj, name).map(Point::from)
    }

    fn vector(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Vec2> {
        self.pair(path, obj, name).map(Vec2::from)
    }

    fn color(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Rgb8> {
        let v = self.field(path, obj, name)?;
        let parsed = v.as_str().map(str::parse::<Rgb8>);
        match parsed {
            Some(Ok(c)) => Some(c),
            _ => {
                self.c.push(
                    join(path, name),
                    format!("must be a colour \"#rrggbb\", got {}", short(v)),
                );
                None
            }
        }
    }

    /// An array field, each item read by `item(self, path of item, item)`.
    fn list<T>(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        what: &str,
        mut item: impl FnMut(&mut Self, &str, &Value) -> Option<T>,
    ) -> Option<Arc<[T]>> {
        let v = self.field(path, obj, name)?;
        let path = join(path, name);
        let Some(items) = v.as_array() else {
            self.c.push(
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
        read.into_iter().collect::<Option<Vec<T>>>().map(Arc::from)
    }

    fn numbers(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Arc<[f64]>> {
        self.list(path, obj, name, "numbers", |r, p, v| r.number_value(p, v))
    }

    fn points(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Arc<[Point]>> {
        self.list(path, obj, name, "[x, y] points", |r, p, v| {
            match v.as_array().map(Vec::as_slice) {
                Some([x, y]) => {
                    let x = r.number_value(&format!("{p}[0]"), x);
                    let y = r.number_value(&format!("{p}[1]"), y);
                    Some(Point::new(x?, y?))
                }
                _ => {
                    r.c.push(
                        p,
                        format!("must be an array [x, y] of two numbers, got {}", short(v)),
                    );
                    None
                }
            }
        })
    }

    fn colors(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<Arc<[Rgb8]>> {
        self.list(path, obj, name, "colours \"#rrggbb\"", |r, p, v| {
            match v.as_str().map(str::parse::<Rgb8>) {
                Some(Ok(c)) => Some(c),
                _ => {
                    r.c.push(p, format!("must be a colour \"#rrggbb\", got {}", short(v)));
                    None
                }
            }
        })
    }

    /// A drop pattern's fields: `centers`, `radius` or `radii` (one of them), `colors`.
    fn drop_set(&mut self, p: &str, obj: &Map<String, Value>) -> Option<DropSet> {
        let centers = self.points(p, obj, "centers");
        let radii = match (obj.contains_key("radius"), obj.contains_key("radii")) {
            (true, false) => self.number(p, obj, "radius").map(Radii::One),
            (false, true) => self.numbers(p, obj, "radii").map(Radii::Each),
            (both, _) => {
                let m = if both {
                    "give either \"radius\" (one for all) or \"radii\" (one per centre), not both"
                } else {
                    "missing; give \"radius\" (one for all) or \"radii\" (one per centre)"
                };
                self.c.push(join(p, "radius"), m);
                None
            }
        };
        let colors = self.colors(p, obj, "colors");
        Some(DropSet {
            centers: centers?,
            radii: radii?,
            colors: colors?,
        })
    }

    fn side(&mut self, obj: &Map<String, Value>, name: &str) -> Option<u32> {
        let v = self.field("", obj, name)?;
        match v.as_u64().and_then(|n| u32::try_from(n).ok()) {
            Some(n) => {
                self.c.side(name, n);
                Some(n)
            }
            None => {
                self.c.push(
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
            self.c
                .push(path, format!("must be an object, got {}", type_of(v)));
            return None;
        };
        let kind = match obj.get("type") {
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                self.c.push(
                    format!("{path}.type"),
                    format!("must be a string, got {}", short(other)),
                );
                return None;
            }
            None => {
                self.c.push(format!("{path}.type"), "missing");
                return None;
            }
        };
        let Some(fields) = op_fields(kind) else {
            self.c.push(
                format!("{path}.type"),
                format!(
                    "unknown op type {kind:?}; expected one of {}",
                    crate::OP_TYPES.join(", ")
                ),
            );
            return None;
        };
        self.object(&path, v, fields)?;
        if self.version < 3 && OP_TYPES_V3.contains(&kind) {
            self.c.push(
                format!("{path}.type"),
                format!(
                    "op type {kind:?} needs \"version\": 3 (this document is version {})",
                    self.version
                ),
            );
        }
        let p = path.as_str();
        let op = match kind {
            "drop" | "spray" => {
                let (center, radius, color) = (
                    self.point(p, obj, "center"),
                    self.number(p, obj, "radius"),
                    self.color(p, obj, "color"),
                );
                let (center, radius, color) = (center?, radius?, color?);
                if kind == "drop" {
                    Op::Drop(Drop {
                        center,
                        radius,
                        color,
                    })
                } else {
                    Op::Spray(Spray {
                        center,
                        radius,
                        color,
                    })
                }
            }
            "tine" => {
                let (origin, direction) = (
                    self.point(p, obj, "origin"),
                    self.vector(p, obj, "direction"),
                );
                let (alpha, lambda) = (self.number(p, obj, "alpha"), self.number(p, obj, "lambda"));
                Op::Tine(Tine {
                    origin: origin?,
                    direction: direction?,
                    alpha: alpha?,
                    lambda: lambda?,
                })
            }
            "rake" => {
                let (origin, direction) = (
                    self.point(p, obj, "origin"),
                    self.vector(p, obj, "direction"),
                );
                let spacing = self.number(p, obj, "spacing");
                let (alpha, lambda) = (self.number(p, obj, "alpha"), self.number(p, obj, "lambda"));
                Op::Rake(Rake {
                    origin: origin?,
                    direction: direction?,
                    spacing: spacing?,
                    alpha: alpha?,
                    lambda: lambda?,
                })
            }
            "wavy" => {
                let (angle, amplitude) = (
                    self.number(p, obj, "angle"),
                    self.number(p, obj, "amplitude"),
                );
                let (wavelength, phase) = (
                    self.number(p, obj, "wavelength"),
                    self.number(p, obj, "phase"),
                );
                Op::Wavy(Wavy {
                    angle: angle?,
                    amplitude: amplitude?,
                    wavelength: wavelength?,
                    phase: phase?,
                })
            }
            "circular" => {
                let (center, radius) =
                    (self.point(p, obj, "center"), self.number(p, obj, "radius"));
                let (alpha, lambda) = (self.number(p, obj, "alpha"), self.number(p, obj, "lambda"));
                Op::Circular(Circular {
                    center: center?,
                    radius: radius?,
                    alpha: alpha?,
                    lambda: lambda?,
                })
            }
            "vortex" => {
                let center = self.point(p, obj, "center");
                let (alpha, lambda) = (self.number(p, obj, "alpha"), self.number(p, obj, "lambda"));
                Op::Vortex(Vortex {
                    center: center?,
                    alpha: alpha?,
                    lambda: lambda?,
                })
            }
            "shift" => Op::Shift(Shift {
                offset: self.vector(p, obj, "offset")?,
            }),
            "turn" => {
                let (center, angle) = (self.point(p, obj, "center"), self.number(p, obj, "angle"));
                Op::Turn(Turn {
                    center: center?,
                    angle: angle?,
                })
            }
            "comb" => {
                let (origin, direction) = (
                    self.point(p, obj, "origin"),
                    self.vector(p, obj, "direction"),
                );
                let tines = self.numbers(p, obj, "tines");
                let (alpha, lambda) = (self.number(p, obj, "alpha"), self.number(p, obj, "lambda"));
                Op::Comb(Comb {
                    origin: origin?,
                    direction: direction?,
                    tines: tines?,
                    alpha: alpha?,
                    lambda: lambda?,
                })
            }
            "drops" => Op::Drops(self.drop_set(p, obj)?),
            "sprays" => Op::Sprays(self.drop_set(p, obj)?),
            "jiggle" => {
                let (angle, wavelength) = (
                    self.number(p, obj, "angle"),
                    self.number(p, obj, "wavelength"),
                );
                let (along, across, phase) = (
                    self.number(p, obj, "along"),
                    self.number(p, obj, "across"),
                    self.number(p, obj, "phase"),
                );
                Op::Jiggle(Jiggle {
                    angle: angle?,
                    wavelength: wavelength?,
                    along: along?,
                    across: across?,
                    phase: phase?,
                })
            }
            _ => {
                let (path_points, wake) =
                    (self.points(p, obj, "path"), self.number(p, obj, "wake"));
                let tips = match obj.get("tips") {
                    None => Some(None),
                    Some(_) => self.numbers(p, obj, "tips").map(Some),
                };
                Op::Stylus(Stylus {
                    path: path_points?,
                    wake: wake?,
                    tips: tips?,
                })
            }
        };
        self.c.op(i, &op);
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
                self.c.push(
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
                self.c.push(
                    "background",
                    "a noise background needs \"version\": 2; version 1 takes a colour \"#rrggbb\"",
                );
                None
            }
            Some(b @ Value::Object(_)) => {
                self.noise_background(b).map(|n| (n.mid_color(), Some(n)))
            }
            Some(_) => self.color("", obj, "background").map(|c| (c, None)),
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
                self.c.push(
                    "overlays",
                    format!("must be an array, got {}", type_of(other)),
                );
                None
            }
        };
        if let Some(list) = &overlays {
            self.c.overlay_kinds(list.iter().map(|o| o.kind));
        }
        let ops = match self.field("", obj, "ops") {
            Some(Value::Array(items)) => {
                let ops: Vec<Option<Op>> = items
                    .iter()
                    .enumerate()
                    .map(|(i, item)| self.op(i, item))
                    .collect();
                self.c.op_count(
                    ops.iter()
                        .map(|o| o.as_ref().map_or(1, Op::counted_ops))
                        .sum(),
                );
                ops.into_iter().collect::<Option<Vec<Op>>>()
            }
            Some(other) => {
                self.c
                    .push("ops", format!("must be an array, got {}", type_of(other)));
                None
            }
            None => None,
        };
        let gestures = self.gestures(obj.get("gestures"));
        if let (Some(ops), Some(gestures)) = (&ops, &gestures) {
            self.c.gestures(gestures, ops.len());
        }
        let recipe = self.recipe(obj.get("recipe"));
        if let (Some(ops), Some(gestures), Some(Some(r))) = (&ops, &gestures, &recipe) {
            let merged: usize = gestures.iter().map(|g| g.count.saturating_sub(1)).sum();
            let steps = ops.len().saturating_sub(merged);
            if r.captions.len() > steps {
                self.c.push(
                    "recipe.captions",
                    format!(
                        "at most one caption per step: {} captions for {steps} steps",
                        r.captions.len()
                    ),
                );
            }
        }
        let (background, background_noise) = background?;
        Some(Design {
            width: width?,
            height: height?,
            background,
            background_noise,
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
        let text = |me: &mut Self, key: &str, v: Option<&Value>| -> Option<String> {
            match v {
                None => Some(String::new()),
                Some(Value::String(s)) => Some(s.clone()),
                Some(other) => {
                    me.c.push(
                        format!("recipe.{key}"),
                        format!("must be a string, got {}", type_of(other)),
                    );
                    None
                }
            }
        };
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
                self.c.push(
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
        self.c.recipe(&recipe);
        Some(Some(recipe))
    }

    /// `"gestures": [[first, count], …]` (absent: none); the spans' order and bounds
    /// are checked by [`Checker::gestures`].
    fn gestures(&mut self, v: Option<&Value>) -> Option<Vec<GestureSpan>> {
        let items = match v {
            None => return Some(Vec::new()),
            Some(Value::Array(items)) => items,
            Some(other) => {
                self.c.push(
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
                    self.c.push(
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

    /// A noise spec at `path`, its problems reported under that path.
    fn noise(&mut self, path: &str, v: Option<&Value>) -> Option<NoiseLayer> {
        let Some(v) = v else {
            self.c.push(path, "missing");
            return None;
        };
        match NoiseLayer::from_value(v) {
            Ok(n) => Some(n),
            Err(problems) => {
                for p in problems {
                    self.c.push(join(path, &p.path), p.message);
                }
                None
            }
        }
    }

    fn palette(&mut self, path: &str, v: Option<&Value>) -> Option<Palette> {
        let result = match v {
            None => Palette::named("grey"),
            Some(Value::String(name)) => Palette::named(name),
            Some(Value::Array(items)) => {
                let mut stops = Vec::new();
                for (i, it) in items.iter().enumerate() {
                    match it.as_str().map(str::parse::<Rgb8>) {
                        Some(Ok(c)) => stops.push(c),
                        _ => self.c.push(
                            format!("{path}[{i}]"),
                            format!("must be a colour \"#rrggbb\", got {}", short(it)),
                        ),
                    }
                }
                if stops.len() != items.len() {
                    return None;
                }
                Palette::from_stops(stops)
            }
            Some(other) => {
                self.c.push(
                    path,
                    format!(
                        "must be a palette name or an array of \"#rrggbb\", got {}",
                        short(other)
                    ),
                );
                return None;
            }
        };
        result.map_err(|e| self.c.push(path, e.to_string())).ok()
    }

    fn noise_background(&mut self, v: &Value) -> Option<NoiseBackground> {
        let obj = self.object("background", v, &["noise", "palette"])?;
        let noise = self.noise("background.noise", obj.get("noise"));
        let palette = self.palette("background.palette", obj.get("palette"));
        Some(NoiseBackground::new(noise?, palette?))
    }

    fn overlay(&mut self, i: usize, v: &Value) -> Option<Overlay> {
        let path = format!("overlays[{i}]");
        let obj = self.object(&path, v, &["type", "noise", "strength"])?;
        let kind = match obj.get("type") {
            Some(Value::String(s)) if s == "paper-grain" => Some(GrainKind::Paper),
            Some(Value::String(s)) if s == "pigment-grain" => Some(GrainKind::Pigment),
            Some(other) => {
                self.c.push(
                    format!("{path}.type"),
                    format!(
                        "unknown overlay type {}; expected one of {}",
                        short(other),
                        crate::OVERLAY_TYPES.join(", ")
                    ),
                );
                None
            }
            None => {
                self.c.push(format!("{path}.type"), "missing");
                None
            }
        };
        let noise = self.noise(&format!("{path}.noise"), obj.get("noise"));
        let strength = self.number(&path, obj, "strength");
        if let Some(s) = strength {
            self.c.strength(&format!("{path}.strength"), s);
        }
        Some(Overlay {
            kind: kind?,
            noise: noise?,
            strength: strength?,
        })
    }
}

fn join(path: &str, name: &str) -> String {
    if path.is_empty() {
        name.to_owned()
    } else {
        format!("{path}.{name}")
    }
}

/// A value quoted for an error message, cut short when long.
fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s
    }
}

/// A number written as an integer when it is one (shorter documents and share links).
fn num(v: f64) -> Value {
    if v.fract() == 0.0 && v.abs() < 9.0e15 {
        json!(v as i64)
    } else {
        json!(v)
    }
}

fn pair(x: f64, y: f64) -> Value {
    json!([num(x), num(y)])
}

fn op_value(op: &Op) -> Value {
    let t = op.type_name();
    match op {
        Op::Drop(Drop {
            center,
            radius,
            color,
        })
        | Op::Spray(Spray {
            center,
            radius,
            color,
        }) => {
            json!({"type": t, "center": pair(center.x, center.y), "radius": num(*radius), "color": color.to_string()})
        }
        Op::Tine(o) => json!({"type": t, "origin": pair(o.origin.x, o.origin.y),
            "direction": pair(o.direction.x, o.direction.y), "alpha": num(o.alpha), "lambda": num(o.lambda)}),
        Op::Rake(o) => json!({"type": t, "origin": pair(o.origin.x, o.origin.y),
            "direction": pair(o.direction.x, o.direction.y), "spacing": num(o.spacing),
            "alpha": num(o.alpha), "lambda": num(o.lambda)}),
        Op::Wavy(o) => json!({"type": t, "angle": num(o.angle), "amplitude": num(o.amplitude),
            "wavelength": num(o.wavelength), "phase": num(o.phase)}),
        Op::Circular(o) => json!({"type": t, "center": pair(o.center.x, o.center.y),
            "radius": num(o.radius), "alpha": num(o.alpha), "lambda": num(o.lambda)}),
        Op::Vortex(o) => json!({"type": t, "center": pair(o.center.x, o.center.y),
            "alpha": num(o.alpha), "lambda": num(o.lambda)}),
        Op::Shift(o) => json!({"type": t, "offset": pair(o.offset.x, o.offset.y)}),
        Op::Turn(o) => json!({"type": t, "center": pair(o.center.x, o.center.y),
            "angle": num(o.angle)}),
        Op::Comb(o) => json!({"type": t, "origin": pair(o.origin.x, o.origin.y),
            "direction": pair(o.direction.x, o.direction.y), "tines": nums(&o.tines),
            "alpha": num(o.alpha), "lambda": num(o.lambda)}),
        Op::Drops(d) | Op::Sprays(d) => {
            let mut m = Map::new();
            m.insert("type".into(), json!(t));
            m.insert("centers".into(), points(&d.centers));
            match &d.radii {
                Radii::One(r) => m.insert("radius".into(), num(*r)),
                Radii::Each(list) => m.insert("radii".into(), nums(list)),
            };
            let colors = d.colors.iter().map(|c| json!(c.to_string())).collect();
            m.insert("colors".into(), Value::Array(colors));
            Value::Object(m)
        }
        Op::Jiggle(o) => json!({"type": t, "angle": num(o.angle), "wavelength": num(o.wavelength),
            "along": num(o.along), "across": num(o.across), "phase": num(o.phase)}),
        Op::Stylus(o) => {
            let mut m = Map::new();
            m.insert("type".into(), json!(t));
            m.insert("path".into(), points(&o.path));
            m.insert("wake".into(), num(o.wake));
            if let Some(tips) = &o.tips {
                m.insert("tips".into(), nums(tips));
            }
            Value::Object(m)
        }
    }
}

fn nums(list: &[f64]) -> Value {
    Value::Array(list.iter().map(|&v| num(v)).collect())
}

fn points(list: &[Point]) -> Value {
    Value::Array(list.iter().map(|p| pair(p.x, p.y)).collect())
}

fn palette_value(p: &Palette) -> Value {
    match &p.name {
        Some(name) => json!(name),
        None => Value::Array(p.stops.iter().map(|c| json!(c.to_string())).collect()),
    }
}

fn overlay_value(o: &Overlay) -> Value {
    json!({"type": o.kind.name(), "noise": o.noise.json().clone(), "strength": num(o.strength)})
}

impl Design {
    /// Reads a design document, checking its structure and every value rule.
    /// All problems are reported at once, each with its JSON path.
    pub fn from_json(text: &str) -> Result<Design, DesignError> {
        let value: Value = serde_json::from_str(text).map_err(|e| {
            let full = e.to_string();
            let message = match full.rfind(" at line ") {
                Some(i) => full[..i].to_owned(),
                None => full,
            };
            DesignError::Syntax {
                line: e.line(),
                column: e.column(),
                message,
            }
        })?;
        let mut reader = Reader {
            c: Checker::default(),
            version: CURRENT_VERSION,
        };
        let design = reader.design(&value);
        match (design, reader.c.errors.is_empty()) {
            (Some(d), true) => Ok(d),
            _ => Err(DesignError::Invalid(ValidationErrors(reader.c.errors))),
        }
    }

    /// The document as a JSON value in schema field order, with the lowest version that
    /// holds it ([`Design::version`]): a v1 design is exactly the v1 document.
    pub fn to_value(&self) -> Value {
        debug_assert!(CURRENT_VERSION >= self.version());
        let mut m = Map::new();
        m.insert("version".into(), json!(self.version()));
        m.insert("width".into(), json!(self.width));
        m.insert("height".into(), json!(self.height));
        m.insert("background".into(), self.background_value());
        if !self.overlays.is_empty() {
            m.insert(
                "overlays".into(),
                Value::Array(self.overlays.iter().map(overlay_value).collect()),
            );
        }
        m.insert(
            "ops".into(),
            Value::Array(self.ops.iter().map(op_value).collect()),
        );
        if !self.gestures.is_empty() {
            m.insert("gestures".into(), self.gestures_value());
        }
        if let Some(r) = self.recipe_value() {
            m.insert("recipe".into(), r);
        }
        Value::Object(m)
    }

    /// The recipe with at most one caption per step (undo may have taken steps away).
    fn recipe_value(&self) -> Option<Value> {
        let r = self.recipe.as_ref()?;
        let steps = self.gesture_sizes().len();
        Some(json!({
            "name": r.name,
            "history": r.history,
            "captions": r.captions[..r.captions.len().min(steps)],
        }))
    }

    fn gestures_value(&self) -> Value {
        Value::Array(
            self.gestures
                .iter()
                .map(|g| json!([g.first, g.count]))
                .collect(),
        )
    }

    fn background_value(&self) -> Value {
        match &self.background_noise {
            None => json!(self.background.to_string()),
            Some(n) => {
                json!({"noise": n.noise.json().clone(), "palette": palette_value(&n.palette)})
            }
        }
    }

    /// The document as indented JSON, one op (and one overlay) per line.
    pub fn to_json_pretty(&self) -> String {
        let mut out = String::from("{\n");
        let v = self.to_value();
        for key in ["version", "width", "height", "background"] {
            out += &format!("  {:?}: {},\n", key, v[key]);
        }
        if !self.overlays.is_empty() {
            out += "  \"overlays\": [";
            for (i, o) in self.overlays.iter().enumerate() {
                out += if i == 0 { "\n    " } else { ",\n    " };
                out += &overlay_value(o).to_string();
            }
            out += "\n  ],\n";
        }
        out += "  \"ops\": [";
        for (i, op) in self.ops.iter().enumerate() {
            out += if i == 0 { "\n    " } else { ",\n    " };
            out += &op_value(op).to_string();
        }
        out += if self.ops.is_empty() { "]" } else { "\n  ]" };
        if !self.gestures.is_empty() {
            out += &format!(",\n  \"gestures\": {}", self.gestures_value());
        }
        if let Some(r) = self.recipe_value() {
            out += &format!(
                ",\n  \"recipe\": {{\n    \"name\": {},\n    \"history\": {},\n    \"captions\": [",
                r["name"], r["history"]
            );
            let captions = r["captions"].as_array().map_or(&[][..], |c| &c[..]);
            for (i, c) in captions.iter().enumerate() {
                out += if i == 0 { "\n      " } else { ",\n      " };
                out += &c.to_string();
            }
            out += if captions.is_empty() {
                "]\n  }"
            } else {
                "\n    ]\n  }"
            };
        }
        out += "\n}\n";
        out
    }

    /// The document as compact JSON (for share links).
    pub fn to_json_compact(&self) -> String {
        self.to_value().to_string()
    }
}
