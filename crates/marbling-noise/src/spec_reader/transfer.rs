//! What is done with a noise's value: the transfer, the palette and the HSV blend.

use super::{Reader, Rule};
use crate::curve::Curve;
use crate::ramp::{ColorRamp, PALETTES, parse_hex};
use crate::ranges;
use crate::spec::{Blend, BlendBase, DecayValue, Transfer};
use crate::transfer::Threshold;
use marbling_json::{join, short, type_of};
use serde_json::Value;

impl Reader {
    pub(super) fn transfer(&mut self, path: &str, v: &Value) -> Option<Transfer> {
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

    pub(super) fn palette(&mut self, path: &str, v: &Value) -> Option<ColorRamp> {
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

    pub(super) fn blend(&mut self, path: &str, v: &Value) -> Option<Blend> {
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
