//! Reading a noise spec from JSON (the grammar is in the crate README), each problem
//! reported with its path by the shared [`marbling_json::PathReader`].

use crate::layer::{COMBINES, Combine, Layer, MAX_LAYERS};
use crate::ranges;
use crate::spec::{FieldError, NOISE_TYPES, NoiseSpec};
use marbling_json::{PathReader, join, short, type_of};
use serde_json::{Map, Value};
use std::ops::{Deref, DerefMut};

mod fields;
mod source;
mod transfer;

/// Reads a top-level spec; every problem found, with its path.
pub(crate) fn read_spec(value: &Value) -> Result<NoiseSpec, Vec<FieldError>> {
    let mut r = Reader(PathReader::default());
    let spec = r.spec("", value, Role::Top);
    if spec.is_none() && r.errors.is_empty() {
        r.push("", "invalid spec");
    }
    r.0.finish(spec)
}

/// Where a spec sits, which decides the fields it may have.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Role {
    Top,
    ProductInput,
    Drive,
    /// An entry of `layers`, or a layer's `mask`.
    Layer,
}

/// A phasor's fields: a Gabor's, then `profile`.
const GABOR_FIELDS: [&str; 9] = [
    "kind",
    "frequency",
    "orientation",
    "bandwidth",
    "impulses",
    "seed",
    "orientation_field",
    "frequency_field",
    "profile",
];

fn fields_of(kind: &str) -> Option<&'static [&'static str]> {
    Some(match kind {
        "gabor" => &GABOR_FIELDS[..GABOR_FIELDS.len() - 1],
        "phasor" => &GABOR_FIELDS,
        "perlin" | "value" => &["frequency", "octaves", "lacunarity", "persistence", "seed"],
        "worley" => &["frequency", "feature", "metric", "seed"],
        "white" => &["seed"],
        "curl" => &[
            "frequency",
            "octaves",
            "lacunarity",
            "persistence",
            "seed",
            "component",
        ],
        "paper" => &["length", "width", "density", "seed", "impurities"],
        "canvas" => &[
            "length",
            "width",
            "density",
            "seed",
            "impurities",
            "weights",
        ],
        "product" => &["inputs"],
        _ => return None,
    })
}

/// A numeric range rule.
#[derive(Clone, Copy)]
enum Rule {
    /// x > lo and x ≤ hi.
    Above(f64, f64),
    /// lo ≤ x ≤ hi.
    Within(f64, f64),
    /// Any finite number.
    Any,
}

impl From<ranges::Range> for Rule {
    fn from(r: ranges::Range) -> Self {
        if r.open_below {
            Rule::Above(r.lo, r.hi)
        } else {
            Rule::Within(r.lo, r.hi)
        }
    }
}

/// The shared path reader plus the noise grammar's own rules.
struct Reader(PathReader);

impl Deref for Reader {
    type Target = PathReader;
    fn deref(&self) -> &PathReader {
        &self.0
    }
}

impl DerefMut for Reader {
    fn deref_mut(&mut self) -> &mut PathReader {
        &mut self.0
    }
}

impl Reader {
    /// A number field within `rule`; `default` when absent (`missing` when that is
    /// `None`).
    fn bounded(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        default: Option<f64>,
        rule: Rule,
    ) -> Option<f64> {
        let present = obj.contains_key(name);
        let x = self.number_or(path, obj, name, default)?;
        if !present {
            return Some(x);
        }
        let (below, hi) = match rule {
            Rule::Above(lo, _) if x <= lo => (Some(format!("must be > {lo}, got {x}")), lo),
            Rule::Within(lo, _) if x < lo => (Some(format!("must be ≥ {lo}, got {x}")), lo),
            Rule::Above(_, hi) | Rule::Within(_, hi) => (None, hi),
            Rule::Any => return Some(x),
        };
        let problem = below.or_else(|| (x > hi).then(|| format!("must be ≤ {hi}, got {x}")));
        match problem {
            Some(m) => {
                self.push(join(path, name), m);
                None
            }
            None => Some(x),
        }
    }

    /// The optional `seed` field (0 when absent).
    fn seed(&mut self, path: &str, obj: &Map<String, Value>) -> Option<u32> {
        self.whole(path, obj, "seed", 0)
    }

    fn spec(&mut self, path: &str, v: &Value, role: Role) -> Option<NoiseSpec> {
        let Some(obj) = v.as_object() else {
            self.push(path, format!("must be an object, got {}", type_of(v)));
            return None;
        };
        let kind = match obj.get("type") {
            None => {
                self.push(
                    join(path, "type"),
                    format!("missing; expected one of {}", NOISE_TYPES.join(", ")),
                );
                return None;
            }
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                self.push(
                    join(path, "type"),
                    format!("must be a string, got {}", type_of(other)),
                );
                return None;
            }
        };
        let Some(own) = fields_of(kind) else {
            self.push(
                join(path, "type"),
                format!(
                    "unknown noise type '{kind}'; expected one of {}",
                    NOISE_TYPES.join(", ")
                ),
            );
            return None;
        };
        let mut allowed: Vec<&str> = vec!["type"];
        allowed.extend_from_slice(own);
        match role {
            Role::Top => {
                allowed.extend_from_slice(&["tile", "transfer", "layers", "palette", "blend"]);
            }
            Role::ProductInput => allowed.push("transfer"),
            Role::Layer => allowed.extend_from_slice(&["transfer", "combine", "weight", "mask"]),
            Role::Drive => {}
        }
        if kind == "product" {
            allowed.retain(|f| *f != "transfer");
            if role != Role::Top {
                self.push(
                    join(path, "type"),
                    "a product can only be the top-level spec",
                );
                return None;
            }
        }
        self.object(path, v, &allowed)?;
        let source = self.source(path, obj, kind);
        let tile = self.tile(path, obj);
        let layers = match obj.get("layers") {
            None => Some(Vec::new()),
            Some(v) => self.layers(&join(path, "layers"), v),
        };
        let transfer = obj
            .get("transfer")
            .map(|t| self.transfer(&join(path, "transfer"), t));
        let palette = obj
            .get("palette")
            .map(|p| self.palette(&join(path, "palette"), p));
        let blend = obj
            .get("blend")
            .map(|b| self.blend(&join(path, "blend"), b));
        if palette.is_some() && blend.is_some() {
            self.push(
                join(path, "blend"),
                "cannot be combined with palette; give the blend its own palette",
            );
        }
        Some(NoiseSpec {
            source: source?,
            tile: tile?,
            transfer: transfer.map_or(Some(None), |t| t.map(Some))?,
            layers: layers?,
            palette: palette.map_or(Some(None), |p| p.map(Some))?,
            blend: blend.map_or(Some(None), |b| b.map(Some))?,
        })
    }

    fn layers(&mut self, path: &str, v: &Value) -> Option<Vec<Layer>> {
        let Some(items) = v.as_array().filter(|a| (1..=MAX_LAYERS).contains(&a.len())) else {
            self.push(
                path,
                format!(
                    "must be an array of 1 to {MAX_LAYERS} layers, got {}",
                    short(v)
                ),
            );
            return None;
        };
        let parsed: Vec<Option<Layer>> = items
            .iter()
            .enumerate()
            .map(|(i, item)| self.layer(&format!("{path}[{i}]"), item))
            .collect();
        parsed.into_iter().collect()
    }

    fn layer(&mut self, path: &str, v: &Value) -> Option<Layer> {
        let noise = self.spec(path, v, Role::Layer);
        let obj = v.as_object()?;
        let combine = match obj.get("combine") {
            None => {
                self.push(
                    join(path, "combine"),
                    format!("missing; expected one of {}", combine_names()),
                );
                None
            }
            Some(_) => self.choice(path, obj, "combine", Combine::Add, &COMBINES),
        };
        let weight = self.bounded(path, obj, "weight", Some(1.0), Rule::Within(0.0, 1.0));
        let mask = match (combine, obj.get("mask")) {
            (Some(Combine::Mask), Some(m)) => {
                self.spec(&join(path, "mask"), m, Role::Layer).map(Some)
            }
            (Some(Combine::Mask), None) => {
                self.push(
                    join(path, "mask"),
                    "missing: combine \"mask\" needs a mask noise",
                );
                None
            }
            (Some(_), Some(_)) => {
                self.push(join(path, "mask"), "only read with combine \"mask\"");
                None
            }
            (_, _) => Some(None),
        };
        Some(Layer {
            noise: noise?,
            combine: combine?,
            weight: weight? as f32,
            mask: mask?,
        })
    }
}

fn combine_names() -> String {
    COMBINES
        .iter()
        .map(|(n, _)| *n)
        .collect::<Vec<_>>()
        .join(", ")
}
