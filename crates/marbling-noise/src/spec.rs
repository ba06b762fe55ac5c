//! Noise specs: the JSON documents `marbling noise` reads, parsed with errors that name
//! the JSON path of every problem (`frequency: must be > 0, got -3`).
//!
//! Every spec is an object with a `type` and type-specific fields (see the crate
//! README), plus optional `tile` (repeat every output size), `transfer`, `palette` and
//! `blend`. Lengths are in output pixels, frequencies in cycles per output pixel,
//! angles in radians from +x towards +y (x right, y down).

use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams, Impurities};
use crate::gabor::GaborKind;
use crate::ramp::{ColorRamp, PALETTES, Rgb, parse_hex};
use crate::ranges;
use crate::transfer::Threshold;
use crate::{CurlComponent, Metric, WorleyFeature};
use serde_json::{Map, Value};
use std::fmt;

/// Names accepted in `type`.
pub const NOISE_TYPES: &[&str] = &[
    "gabor", "perlin", "value", "worley", "white", "curl", "paper", "canvas", "product",
];

/// Most impulses per kernel a Gabor spec may ask for.
pub const MAX_IMPULSES: f64 = ranges::IMPULSES.hi;

/// One problem at one place of a spec, e.g. `inputs[1].frequency: must be > 0, got -3`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FieldError {
    /// JSON path of the offending value (`frequency`, `orientation_field.noise.octaves`, …).
    pub path: String,
    /// What is wrong, with the value found.
    pub message: String,
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

/// Why a spec could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// Not JSON; line and column are 1-based.
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What the parser expected.
        message: String,
    },
    /// Valid JSON that is not a valid spec; every problem is listed, one per line.
    #[error("{}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n"))]
    Invalid(Vec<FieldError>),
}

/// How a Gabor parameter is driven by another field.
#[derive(Clone, Debug)]
pub struct DriveSpec {
    /// The driving noise (no transfer, palette or blend).
    pub noise: Box<NoiseSpec>,
    /// Radians (orientation) or octaves (frequency) per unit of the noise.
    pub amount: f32,
}

/// The noise a spec evaluates.
#[derive(Clone, Debug)]
pub enum Source {
    /// Sparse Gabor noise ([`crate::Gabor`]).
    Gabor {
        /// Kind.
        kind: GaborKind,
        /// F₀, cycles per pixel.
        frequency: f32,
        /// ω₀, radians.
        orientation: f32,
        /// a, 1/pixels.
        bandwidth: f32,
        /// Mean kernels per point.
        impulses: f32,
        /// Seed.
        seed: u32,
        /// Field driving the orientation.
        orientation_field: Option<DriveSpec>,
        /// Field driving the frequency.
        frequency_field: Option<DriveSpec>,
    },
    /// fBm of Perlin or value noise ([`crate::Fbm`]); `period` is filled in at build time.
    Fbm(FbmParams),
    /// Worley noise.
    Worley {
        /// Feature points per pixel along each axis (cells per pixel).
        frequency: f32,
        /// Returned distance.
        feature: WorleyFeature,
        /// Distance function.
        metric: Metric,
        /// Seed.
        seed: u32,
    },
    /// White noise per pixel.
    White {
        /// Seed.
        seed: u32,
    },
    /// Curl noise of an fBm potential.
    Curl {
        /// The potential (Perlin basis).
        potential: FbmParams,
        /// The shown scalar.
        component: CurlComponent,
    },
    /// Paper or canvas fibers.
    Fibers(FiberParams),
    /// Product of the intensities of several specs (cross-hatching).
    Product(Vec<NoiseSpec>),
}

/// Intensity transfer of a spec.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transfer {
    /// Smoothstep threshold.
    Threshold(Threshold),
    /// Seed 004's spline decay with mean intensity `value`.
    SplineDecay(DecayValue),
}

/// The value v a spline decay tracks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DecayValue {
    /// The same v everywhere.
    Constant(f32),
    /// v rising from 0 at the left edge to 1 at the right edge (a legend strip).
    RampX,
}

/// Seed 004's HSV value blend of the intensity into a base colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Blend {
    /// β, the share of the base colour's value kept (0.6 in the paper).
    pub beta: f32,
    /// The base colour: one colour, or a palette sampled from left (0) to right (1).
    pub base: BlendBase,
}

/// Base colour of a [`Blend`].
#[derive(Clone, Debug, PartialEq)]
pub enum BlendBase {
    /// One sRGB colour.
    Color(Rgb),
    /// A ramp across the image, left to right.
    Ramp(ColorRamp),
}

/// A parsed noise spec.
#[derive(Clone, Debug)]
pub struct NoiseSpec {
    /// What is evaluated.
    pub source: Source,
    /// Whether the result tiles with period equal to the output size.
    pub tile: bool,
    /// Noise → intensity; default 0.5 + n/6 clamped.
    pub transfer: Option<Transfer>,
    /// Intensity → colour.
    pub palette: Option<ColorRamp>,
    /// Intensity blended into a base colour's HSV value.
    pub blend: Option<Blend>,
}

impl NoiseSpec {
    /// Parses and checks a spec; every problem is reported with its path.
    pub fn from_json(text: &str) -> Result<Self, SpecError> {
        let value: Value = serde_json::from_str(text).map_err(|e| SpecError::Syntax {
            line: e.line(),
            column: e.column(),
            message: e.to_string(),
        })?;
        Self::from_value(&value)
    }

    /// Parses and checks a spec given as a JSON value.
    pub fn from_value(value: &Value) -> Result<Self, SpecError> {
        let mut r = Reader { errors: Vec::new() };
        let spec = r.spec("", value, Role::Top);
        match spec {
            Some(s) if r.errors.is_empty() => Ok(s),
            _ => {
                if r.errors.is_empty() {
                    r.push("", "invalid spec");
                }
                Err(SpecError::Invalid(r.errors))
            }
        }
    }

    /// Whether the output is coloured (palette or blend) rather than greyscale.
    #[must_use]
    pub fn is_colored(&self) -> bool {
        self.palette.is_some() || self.blend.is_some()
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Role {
    Top,
    ProductInput,
    Drive,
}

fn join(path: &str, name: &str) -> String {
    if path.is_empty() {
        name.to_string()
    } else {
        format!("{path}.{name}")
    }
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

fn short(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s
    }
}

fn fields_of(kind: &str) -> Option<&'static [&'static str]> {
    Some(match kind {
        "gabor" => &[
            "kind",
            "frequency",
            "orientation",
            "bandwidth",
            "impulses",
            "seed",
            "orientation_field",
            "frequency_field",
        ],
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

struct Reader {
    errors: Vec<FieldError>,
}

impl Reader {
    fn push(&mut self, path: impl Into<String>, message: impl Into<String>) {
        self.errors.push(FieldError {
            path: path.into(),
            message: message.into(),
        });
    }

    fn number(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        name: &str,
        default: Option<f64>,
        rule: Rule,
    ) -> Option<f64> {
        let p = join(path, name);
        let Some(v) = obj.get(name) else {
            if default.is_none() {
                self.push(p, "missing");
            }
            return default;
        };
        let Some(x) = v.as_f64().filter(|x| x.is_finite()) else {
            self.push(p, format!("must be a number, got {}", type_of(v)));
            return None;
        };
        let ok = match rule {
            Rule::Above(lo, hi) => {
                if x <= lo {
                    self.push(p, format!("must be > {lo}, got {x}"));
                    return None;
                }
                x <= hi
            }
            Rule::Within(lo, hi) => {
                if x < lo {
                    self.push(p, format!("must be ≥ {lo}, got {x}"));
                    return None;
                }
                x <= hi
            }
            Rule::Any => true,
        };
        if !ok {
            let hi = match rule {
                Rule::Above(_, hi) | Rule::Within(_, hi) => hi,
                Rule::Any => f64::INFINITY,
            };
            self.push(p, format!("must be ≤ {hi}, got {x}"));
            return None;
        }
        Some(x)
    }

    fn seed(&mut self, path: &str, obj: &Map<String, Value>) -> Option<u32> {
        let p = join(path, "seed");
        match obj.get("seed") {
            None => Some(0),
            Some(v) => match v.as_u64().and_then(|s| u32::try_from(s).ok()) {
                Some(s) => Some(s),
                None => {
                    self.push(
                        p,
                        format!("must be an integer in 0..=4294967295, got {}", short(v)),
                    );
                    None
                }
            },
        }
    }

    fn choice<T: Copy>(
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

    fn boolean(&mut self, path: &str, obj: &Map<String, Value>, name: &str) -> Option<bool> {
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

    fn object<'a>(
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
            Role::Top => allowed.extend_from_slice(&["tile", "transfer", "palette", "blend"]),
            Role::ProductInput => allowed.push("transfer"),
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
        let tile = self.boolean(path, obj, "tile");
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
            palette: palette.map_or(Some(None), |p| p.map(Some))?,
            blend: blend.map_or(Some(None), |b| b.map(Some))?,
        })
    }

    fn fbm(&mut self, path: &str, obj: &Map<String, Value>, basis: Basis) -> Option<FbmParams> {
        let frequency = self.number(path, obj, "frequency", None, ranges::FREQUENCY.into());
        let octaves = self.number(path, obj, "octaves", Some(1.0), ranges::OCTAVES.into());
        if octaves.is_some_and(|o| o.fract() != 0.0) {
            self.push(join(path, "octaves"), "must be a whole number");
        }
        let lacunarity = self.number(
            path,
            obj,
            "lacunarity",
            Some(2.0),
            ranges::LACUNARITY.into(),
        );
        let persistence = self.number(
            path,
            obj,
            "persistence",
            Some(0.5),
            ranges::PERSISTENCE.into(),
        );
        let seed = self.seed(path, obj);
        Some(FbmParams {
            basis,
            frequency: frequency? as f32,
            octaves: octaves? as u32,
            lacunarity: lacunarity? as f32,
            persistence: persistence? as f32,
            seed: seed?,
            period: None,
        })
    }

    fn drive(&mut self, path: &str, v: &Value) -> Option<DriveSpec> {
        let obj = self.object(path, v, &["noise", "amount"])?;
        let amount = self.number(path, obj, "amount", None, Rule::Any);
        let noise = match obj.get("noise") {
            Some(n) => self.spec(&join(path, "noise"), n, Role::Drive),
            None => {
                self.push(join(path, "noise"), "missing");
                None
            }
        };
        Some(DriveSpec {
            noise: Box::new(noise?),
            amount: amount? as f32,
        })
    }

    fn source(&mut self, path: &str, obj: &Map<String, Value>, kind: &str) -> Option<Source> {
        match kind {
            "gabor" => {
                let gk = self.choice(
                    path,
                    obj,
                    "kind",
                    GaborKind::Anisotropic,
                    &ranges::GABOR_KINDS,
                );
                let frequency =
                    self.number(path, obj, "frequency", None, ranges::GABOR_FREQUENCY.into());
                let orientation = self.number(path, obj, "orientation", Some(0.0), Rule::Any);
                // Radius √(−ln 0.05/π)/a ≤ 512 px.
                let bandwidth = self.number(path, obj, "bandwidth", None, ranges::BANDWIDTH.into());
                let impulses =
                    self.number(path, obj, "impulses", Some(64.0), ranges::IMPULSES.into());
                let seed = self.seed(path, obj);
                let orientation_field = obj
                    .get("orientation_field")
                    .map(|d| self.drive(&join(path, "orientation_field"), d));
                let frequency_field = obj
                    .get("frequency_field")
                    .map(|d| self.drive(&join(path, "frequency_field"), d));
                if gk == Some(GaborKind::Isotropic) && orientation_field.is_some() {
                    self.push(
                        join(path, "orientation_field"),
                        "not allowed for kind isotropic (its orientations are random)",
                    );
                }
                Some(Source::Gabor {
                    kind: gk?,
                    frequency: frequency? as f32,
                    orientation: orientation? as f32,
                    bandwidth: bandwidth? as f32,
                    impulses: impulses? as f32,
                    seed: seed?,
                    orientation_field: orientation_field.map_or(Some(None), |d| d.map(Some))?,
                    frequency_field: frequency_field.map_or(Some(None), |d| d.map(Some))?,
                })
            }
            "perlin" => self.fbm(path, obj, Basis::Perlin).map(Source::Fbm),
            "value" => self.fbm(path, obj, Basis::Value).map(Source::Fbm),
            "worley" => {
                let frequency = self.number(path, obj, "frequency", None, ranges::FREQUENCY.into());
                let feature = self.choice(
                    path,
                    obj,
                    "feature",
                    WorleyFeature::F1,
                    &ranges::WORLEY_FEATURES,
                );
                let metric = self.choice(
                    path,
                    obj,
                    "metric",
                    Metric::Euclidean,
                    &ranges::WORLEY_METRICS,
                );
                let seed = self.seed(path, obj);
                Some(Source::Worley {
                    frequency: frequency? as f32,
                    feature: feature?,
                    metric: metric?,
                    seed: seed?,
                })
            }
            "white" => Some(Source::White {
                seed: self.seed(path, obj)?,
            }),
            "curl" => {
                let potential = self.fbm(path, obj, Basis::Perlin);
                let component = self.choice(
                    path,
                    obj,
                    "component",
                    CurlComponent::Magnitude,
                    &ranges::CURL_COMPONENTS,
                );
                Some(Source::Curl {
                    potential: potential?,
                    component: component?,
                })
            }
            "paper" | "canvas" => self.fibers(path, obj, kind == "canvas"),
            "product" => {
                let p = join(path, "inputs");
                match obj.get("inputs") {
                    Some(Value::Array(items)) if items.len() >= 2 => {
                        let parsed: Vec<Option<NoiseSpec>> = items
                            .iter()
                            .enumerate()
                            .map(|(i, it)| self.spec(&format!("{p}[{i}]"), it, Role::ProductInput))
                            .collect();
                        parsed
                            .into_iter()
                            .collect::<Option<Vec<_>>>()
                            .map(Source::Product)
                    }
                    Some(v) => {
                        self.push(
                            p,
                            format!("must be an array of at least two specs, got {}", short(v)),
                        );
                        None
                    }
                    None => {
                        self.push(p, "missing");
                        None
                    }
                }
            }
            _ => None,
        }
    }

    fn fibers(&mut self, path: &str, obj: &Map<String, Value>, canvas: bool) -> Option<Source> {
        let length = self.number(path, obj, "length", Some(20.0), ranges::FIBER_LENGTH.into());
        let width = self.number(path, obj, "width", Some(1.5), ranges::FIBER_WIDTH.into());
        let density = self.number(
            path,
            obj,
            "density",
            Some(0.3),
            ranges::FIBER_DENSITY.into(),
        );
        let seed = self.seed(path, obj);
        let layout = if canvas {
            let p = join(path, "weights");
            match obj.get("weights") {
                None => Some(FiberLayout::Canvas {
                    weights: [1.0, 1.0],
                }),
                Some(v) => match v.as_array().map(Vec::as_slice) {
                    Some([h, w]) => match (h.as_f64(), w.as_f64()) {
                        (Some(h), Some(w)) if h >= 0.0 && w >= 0.0 && h + w > 0.0 => {
                            Some(FiberLayout::Canvas {
                                weights: [h as f32, w as f32],
                            })
                        }
                        _ => {
                            self.push(
                                p,
                                format!(
                                    "must be [horizontal, vertical] weights ≥ 0, not both 0, got {}",
                                    short(v)
                                ),
                            );
                            None
                        }
                    },
                    _ => {
                        self.push(
                            p,
                            format!(
                                "must be an array [horizontal, vertical] of two numbers, got {}",
                                short(v)
                            ),
                        );
                        None
                    }
                },
            }
        } else {
            Some(FiberLayout::Paper)
        };
        let impurities = match obj.get("impurities") {
            None => Some(None),
            Some(v) => {
                let p = join(path, "impurities");
                self.object(&p, v, &["density", "radius", "strength"])
                    .and_then(|o| {
                        let density =
                            self.number(&p, o, "density", Some(0.0005), Rule::Above(0.0, 0.1));
                        let radius =
                            self.number(&p, o, "radius", Some(1.5), Rule::Within(0.5, 16.0));
                        let strength =
                            self.number(&p, o, "strength", Some(2.0), Rule::Within(-20.0, 20.0));
                        Some(Some(Impurities {
                            density: density? as f32,
                            radius: radius? as f32,
                            strength: strength? as f32,
                        }))
                    })
            }
        };
        Some(Source::Fibers(FiberParams {
            layout: layout?,
            length: length? as f32,
            width: width? as f32,
            density: density? as f32,
            seed: seed?,
            period: None,
            impurities: impurities?,
        }))
    }

    fn transfer(&mut self, path: &str, v: &Value) -> Option<Transfer> {
        let kind = v.get("type").and_then(Value::as_str);
        match kind {
            Some("threshold") => {
                let obj = self.object(path, v, &["type", "threshold", "width", "invert"])?;
                let threshold = self.number(path, obj, "threshold", Some(0.0), Rule::Any);
                let width = self.number(path, obj, "width", Some(0.5), Rule::Above(0.0, 100.0));
                let invert = self.boolean(path, obj, "invert");
                Some(Transfer::Threshold(Threshold {
                    threshold: threshold? as f32,
                    width: width? as f32,
                    invert: invert?,
                }))
            }
            Some("spline-decay") => {
                let obj = self.object(path, v, &["type", "value"])?;
                match obj.get("value") {
                    Some(Value::String(s)) if s == "x" => {
                        Some(Transfer::SplineDecay(DecayValue::RampX))
                    }
                    Some(Value::Number(_)) => {
                        let x = self.number(path, obj, "value", None, Rule::Within(0.0, 1.0));
                        Some(Transfer::SplineDecay(DecayValue::Constant(x? as f32)))
                    }
                    Some(other) => {
                        self.push(
                            join(path, "value"),
                            format!("must be a number in [0, 1] or \"x\", got {}", short(other)),
                        );
                        None
                    }
                    None => {
                        self.push(join(path, "value"), "missing");
                        None
                    }
                }
            }
            _ => {
                match v.as_object() {
                    None => self.push(path, format!("must be an object, got {}", type_of(v))),
                    Some(_) => self.push(
                        join(path, "type"),
                        format!(
                            "must be one of threshold, spline-decay, got {}",
                            v.get("type").map_or_else(|| "nothing".to_string(), short)
                        ),
                    ),
                }
                None
            }
        }
    }

    fn palette(&mut self, path: &str, v: &Value) -> Option<ColorRamp> {
        match v {
            Value::String(name) => {
                let ramp = ColorRamp::named(name);
                if ramp.is_none() {
                    self.push(
                        path,
                        format!(
                            "unknown palette '{name}'; expected one of {} or an array of \"#rrggbb\"",
                            PALETTES.join(", ")
                        ),
                    );
                }
                ramp
            }
            Value::Array(items) if items.len() >= 2 => {
                let mut stops = Vec::new();
                for (i, it) in items.iter().enumerate() {
                    match it.as_str().and_then(parse_hex) {
                        Some(c) => stops.push(c),
                        None => self.push(
                            format!("{path}[{i}]"),
                            format!("must be a colour \"#rrggbb\", got {}", short(it)),
                        ),
                    }
                }
                (stops.len() == items.len())
                    .then(|| ColorRamp::new(stops))
                    .flatten()
            }
            _ => {
                self.push(
                    path,
                    format!(
                        "must be a palette name or an array of at least two \"#rrggbb\", got {}",
                        short(v)
                    ),
                );
                None
            }
        }
    }

    fn blend(&mut self, path: &str, v: &Value) -> Option<Blend> {
        let obj = self.object(path, v, &["beta", "color", "palette"])?;
        let beta = self.number(path, obj, "beta", Some(0.6), Rule::Within(0.0, 1.0));
        let base = match (obj.get("color"), obj.get("palette")) {
            (Some(c), None) => match c.as_str().and_then(parse_hex) {
                Some(rgb) => Some(BlendBase::Color(rgb)),
                None => {
                    self.push(
                        join(path, "color"),
                        format!("must be a colour \"#rrggbb\", got {}", short(c)),
                    );
                    None
                }
            },
            (None, Some(p)) => self.palette(&join(path, "palette"), p).map(BlendBase::Ramp),
            _ => {
                self.push(path, "needs exactly one of color, palette");
                None
            }
        };
        Some(Blend {
            beta: beta? as f32,
            base: base?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn errors(text: &str) -> Vec<String> {
        match NoiseSpec::from_json(text) {
            Err(SpecError::Invalid(e)) => e.iter().map(ToString::to_string).collect(),
            other => panic!("expected errors, got {other:?}"),
        }
    }

    #[test]
    fn parses_the_issue_gabor_spec() {
        let s = NoiseSpec::from_json(
            r#"{"type":"gabor","kind":"anisotropic","frequency":0.0625,"orientation":0.7854,"bandwidth":0.05,"impulses":64,"seed":7}"#,
        )
        .expect("valid");
        assert!(matches!(
            s.source,
            Source::Gabor {
                kind: GaborKind::Anisotropic,
                seed: 7,
                ..
            }
        ));
        assert!(!s.is_colored());
    }

    #[test]
    fn path_named_errors() {
        assert_eq!(
            errors(r#"{"type":"gabor","frequency":-3,"bandwidth":0.05}"#),
            ["frequency: must be > 0, got -3"]
        );
        assert_eq!(
            errors(r#"{"type":"blob"}"#)[0],
            "type: unknown noise type 'blob'; expected one of gabor, perlin, value, worley, white, curl, paper, canvas, product"
        );
        let e = errors(r#"{"type":"perlin","frequency":0.1,"colour":"red"}"#);
        assert!(e[0].starts_with("colour: unknown field"), "{e:?}");
        let e = errors(
            r#"{"type":"product","inputs":[{"type":"gabor","frequency":0.1,"bandwidth":0.05},{"type":"gabor","frequency":0.1,"bandwidth":0,"kind":"diagonal"}]}"#,
        );
        assert_eq!(
            e,
            [
                "inputs[1].kind: must be one of anisotropic, isotropic, random-phase, got \"diagonal\"",
                "inputs[1].bandwidth: must be ≥ 0.002, got 0"
            ]
        );
        let e = errors(
            r#"{"type":"gabor","frequency":0.1,"bandwidth":0.05,"orientation_field":{"noise":{"type":"perlin"},"amount":1}}"#,
        );
        assert_eq!(e, ["orientation_field.noise.frequency: missing"]);
        let e = errors(r#"{"type":"white","palette":"rainbow","seed":-1}"#);
        assert_eq!(e.len(), 2, "{e:?}");
        assert!(matches!(
            NoiseSpec::from_json("{\"type\":"),
            Err(SpecError::Syntax { line: 1, .. })
        ));
    }
}
