//! Reading a noise spec from JSON (the grammar is in the crate README), each problem
//! reported with its path by the shared [`marbling_json::PathReader`].

use crate::curve::Curve;
use crate::data::DataRef;
use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams, Impurities};
use crate::gabor::GaborKind;
use crate::layer::{COMBINES, Combine, Layer, MAX_LAYERS};
use crate::ramp::{ColorRamp, PALETTES, parse_hex};
use crate::ranges;
use crate::spec::{
    Blend, BlendBase, DecayValue, DriveSource, DriveSpec, FieldError, NOISE_TYPES, NoiseSpec,
    Source, Tile, Transfer,
};
use crate::transfer::Threshold;
use crate::{CurlComponent, Metric, WorleyFeature};
use marbling_json::{PathReader, join, short, type_of};
use serde_json::{Map, Value};
use std::ops::{Deref, DerefMut};

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

    fn fbm(&mut self, path: &str, obj: &Map<String, Value>, basis: Basis) -> Option<FbmParams> {
        let frequency = self.bounded(path, obj, "frequency", None, ranges::FREQUENCY.into());
        let octaves = self.bounded(path, obj, "octaves", Some(1.0), ranges::OCTAVES.into());
        if octaves.is_some_and(|o| o.fract() != 0.0) {
            self.push(join(path, "octaves"), "must be a whole number");
        }
        let lacunarity = self.bounded(
            path,
            obj,
            "lacunarity",
            Some(2.0),
            ranges::LACUNARITY.into(),
        );
        let persistence = self.bounded(
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

    /// `tile`: absent or false (off), true (every output size) or a whole number of
    /// pixels.
    fn tile(&mut self, path: &str, obj: &Map<String, Value>) -> Option<Tile> {
        match obj.get("tile") {
            None | Some(Value::Bool(false)) => Some(Tile::Off),
            Some(Value::Bool(true)) => Some(Tile::Output),
            Some(v) => match v.as_u64() {
                Some(n) if (1..=u64::from(crate::MAX_SIZE)).contains(&n) => {
                    Some(Tile::Period(n as u32))
                }
                _ => {
                    self.push(
                        join(path, "tile"),
                        format!(
                            "must be true, false or a period in pixels (1 to {}), got {}",
                            crate::MAX_SIZE,
                            short(v)
                        ),
                    );
                    None
                }
            },
        }
    }

    /// `{"data": NAME, "channel": K}` fields of `obj` (other fields are the caller's).
    fn data_ref(&mut self, path: &str, obj: &Map<String, Value>) -> Option<DataRef> {
        let name = match obj.get("data") {
            Some(Value::String(s)) if !s.is_empty() => Some(s.clone()),
            other => {
                self.push(
                    join(path, "data"),
                    format!(
                        "must be a data set name (\"{}\") or a PNG/CSV file, got {}",
                        crate::WEATHER,
                        other.map_or_else(|| "nothing".to_string(), short)
                    ),
                );
                None
            }
        };
        let channel = self.bounded(path, obj, "channel", Some(1.0), Rule::Within(1.0, 3.0));
        if channel.is_some_and(|c| c.fract() != 0.0) {
            self.push(join(path, "channel"), "must be 1, 2 or 3");
            return None;
        }
        Some(DataRef::new(&name?, channel? as usize))
    }

    fn drive(&mut self, path: &str, v: &Value) -> Option<DriveSpec> {
        let data = v.get("data").is_some();
        let fields: &[&str] = if data {
            &["data", "channel", "amount"]
        } else {
            &["noise", "amount"]
        };
        let obj = self.object(path, v, fields)?;
        let amount = self.bounded(path, obj, "amount", None, Rule::Any);
        let by = if data {
            self.data_ref(path, obj).map(DriveSource::Data)
        } else {
            match obj.get("noise") {
                Some(n) => self
                    .spec(&join(path, "noise"), n, Role::Drive)
                    .map(|s| DriveSource::Noise(Box::new(s))),
                None => {
                    self.push(join(path, "noise"), "missing (or give \"data\")");
                    None
                }
            }
        };
        Some(DriveSpec {
            by: by?,
            amount: amount? as f32,
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
                    self.bounded(path, obj, "frequency", None, ranges::GABOR_FREQUENCY.into());
                let orientation = self.bounded(path, obj, "orientation", Some(0.0), Rule::Any);
                // Radius √(−ln 0.05/π)/a ≤ 512 px.
                let bandwidth =
                    self.bounded(path, obj, "bandwidth", None, ranges::BANDWIDTH.into());
                let impulses =
                    self.bounded(path, obj, "impulses", Some(64.0), ranges::IMPULSES.into());
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
                let frequency =
                    self.bounded(path, obj, "frequency", None, ranges::FREQUENCY.into());
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
        let length = self.bounded(path, obj, "length", Some(20.0), ranges::FIBER_LENGTH.into());
        let width = self.bounded(path, obj, "width", Some(1.5), ranges::FIBER_WIDTH.into());
        let density = self.bounded(
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
                            self.bounded(&p, o, "density", Some(0.0005), Rule::Above(0.0, 0.1));
                        let radius =
                            self.bounded(&p, o, "radius", Some(1.5), Rule::Within(0.5, 16.0));
                        let strength =
                            self.bounded(&p, o, "strength", Some(2.0), Rule::Within(-20.0, 20.0));
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
                let threshold = self.bounded(path, obj, "threshold", Some(0.0), Rule::Any);
                let width = self.bounded(
                    path,
                    obj,
                    "width",
                    Some(0.5),
                    ranges::THRESHOLD_WIDTH.into(),
                );
                let invert = self.boolean(path, obj, "invert");
                Some(Transfer::Threshold(Threshold {
                    threshold: threshold? as f32,
                    width: width? as f32,
                    invert: invert?,
                }))
            }
            Some("curve") => {
                let obj = self.object(path, v, &["type", "points"])?;
                let p = join(path, "points");
                let points: Option<Vec<[f32; 2]>> =
                    obj.get("points").and_then(Value::as_array).map(|a| {
                        a.iter()
                            .filter_map(|pt| match pt.as_array().map(Vec::as_slice) {
                                Some([x, y]) => Some([x.as_f64()? as f32, y.as_f64()? as f32]),
                                _ => None,
                            })
                            .collect()
                    });
                let count = obj.get("points").and_then(Value::as_array).map(Vec::len);
                match points {
                    Some(points) if Some(points.len()) == count => match Curve::new(points) {
                        Ok(c) => Some(Transfer::Curve(c)),
                        Err(e) => {
                            let m = e.to_string();
                            match m.strip_prefix('[') {
                                Some(rest) => {
                                    let (i, m) = rest.split_once("]: ").unwrap_or((rest, ""));
                                    self.push(format!("{p}[{i}]"), m);
                                }
                                None => self.push(p, m),
                            }
                            None
                        }
                    },
                    _ => {
                        self.push(
                            p,
                            format!(
                                "must be an array of [x, y] number pairs, got {}",
                                obj.get("points")
                                    .map_or_else(|| "nothing".to_string(), short)
                            ),
                        );
                        None
                    }
                }
            }
            Some("spline-decay") => {
                let obj = self.object(path, v, &["type", "value"])?;
                match obj.get("value") {
                    Some(Value::String(s)) if s == "x" => {
                        Some(Transfer::SplineDecay(DecayValue::RampX))
                    }
                    Some(o @ Value::Object(_)) => {
                        let vp = join(path, "value");
                        let inner = self.object(&vp, o, &["data", "channel"])?;
                        self.data_ref(&vp, inner)
                            .map(|r| Transfer::SplineDecay(DecayValue::Data(r)))
                    }
                    Some(Value::Number(_)) => {
                        let x = self.bounded(path, obj, "value", None, Rule::Within(0.0, 1.0));
                        Some(Transfer::SplineDecay(DecayValue::Constant(x? as f32)))
                    }
                    Some(other) => {
                        self.push(
                            join(path, "value"),
                            format!(
                                "must be a number in [0, 1], \"x\" or {{\"data\", \"channel\"}}, got {}",
                                short(other)
                            ),
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
                            "must be one of threshold, spline-decay, curve, got {}",
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
        let obj = self.object(path, v, &["beta", "color", "palette", "value"])?;
        let beta = self.bounded(path, obj, "beta", Some(0.6), Rule::Within(0.0, 1.0));
        if let Some(value) = obj.get("value") {
            let vp = join(path, "value");
            let Some(p) = obj.get("palette") else {
                self.push(
                    join(path, "palette"),
                    "missing: a data \"value\" picks a colour of a palette",
                );
                return None;
            };
            let ramp = self.palette(&join(path, "palette"), p);
            let inner = self.object(&vp, value, &["data", "channel"])?;
            let value = self.data_ref(&vp, inner);
            return Some(Blend {
                beta: beta? as f32,
                base: BlendBase::Data {
                    ramp: ramp?,
                    value: value?,
                },
            });
        }
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

fn combine_names() -> String {
    COMBINES
        .iter()
        .map(|(n, _)| *n)
        .collect::<Vec<_>>()
        .join(", ")
}
