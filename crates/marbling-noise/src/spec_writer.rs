//! The noise spec's writer: [`NoiseSpec::to_value`] gives the JSON that
//! [`NoiseSpec::from_value`] reads back as the same spec (every field written, defaults
//! included; numbers in their shortest f32 form; colours as `"#rrggbb"`, a built-in
//! palette by its name).

use crate::data::DataRef;
use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams};
use crate::layer::Layer;
use crate::ramp::{ColorRamp, Rgb};
use crate::ranges;
use crate::spec::{
    BlendBase, DecayValue, DriveSource, DriveSpec, NoiseSpec, Source, Tile, Transfer,
};
use crate::spec::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use serde_json::{Map, Value, json};

/// An f32 as the JSON number of its shortest decimal form (0.1f32 → 0.1).
fn num(x: f32) -> Value {
    x.to_string()
        .parse::<f64>()
        .ok()
        .and_then(serde_json::Number::from_f64)
        .map_or(Value::Null, Value::Number)
}

/// The spec's name of `value` in a [`ranges`] table.
fn name<T: PartialEq>(options: &[(&'static str, T)], value: &T) -> Value {
    options
        .iter()
        .find(|(_, v)| v == value)
        .map_or(Value::Null, |(n, _)| json!(n))
}

fn hex(c: Rgb) -> Value {
    let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
    json!(format!("#{r:02x}{g:02x}{b:02x}"))
}

/// A built-in palette by its name, any other ramp as its stops.
fn ramp(r: &ColorRamp) -> Value {
    r.name().map_or_else(
        || Value::Array(r.stops().iter().map(|&c| hex(c)).collect()),
        |name| json!(name),
    )
}

fn fbm_fields(o: &mut Map<String, Value>, p: &FbmParams) {
    o.insert("frequency".into(), num(p.frequency));
    o.insert("octaves".into(), json!(p.octaves));
    o.insert("lacunarity".into(), num(p.lacunarity));
    o.insert("persistence".into(), num(p.persistence));
    o.insert("seed".into(), json!(p.seed));
}

fn data_ref(r: &DataRef) -> Value {
    json!({ "data": r.name, "channel": r.channel })
}

fn drive(d: &DriveSpec) -> Value {
    match &d.by {
        DriveSource::Noise(n) => json!({ "noise": n.to_value(), "amount": num(d.amount) }),
        DriveSource::Data(r) => {
            json!({ "data": r.name, "channel": r.channel, "amount": num(d.amount) })
        }
    }
}

fn transfer(t: &Transfer) -> Value {
    match t {
        Transfer::Threshold(t) => json!({
            "type": "threshold",
            "threshold": num(t.threshold),
            "width": num(t.width),
            "invert": t.invert
        }),
        Transfer::SplineDecay(v) => {
            let value = match v {
                DecayValue::Constant(x) => num(*x),
                DecayValue::RampX => json!("x"),
                DecayValue::Data(r) => data_ref(r),
            };
            json!({ "type": "spline-decay", "value": value })
        }
        Transfer::Curve(c) => json!({
            "type": "curve",
            "points": c.points().iter().map(|p| json!([num(p[0]), num(p[1])])).collect::<Vec<_>>()
        }),
    }
}

fn layer(l: &Layer) -> Value {
    let mut v = l.noise.to_value();
    if let Some(o) = v.as_object_mut() {
        o.insert("combine".into(), json!(l.combine.name()));
        o.insert("weight".into(), num(l.weight));
        if let Some(m) = &l.mask {
            o.insert("mask".into(), m.to_value());
        }
    }
    v
}

fn fibers(o: &mut Map<String, Value>, p: &FiberParams) {
    let canvas = matches!(p.layout, FiberLayout::Canvas { .. });
    o.insert(
        "type".into(),
        json!(if canvas { "canvas" } else { "paper" }),
    );
    o.insert("length".into(), num(p.length));
    o.insert("width".into(), num(p.width));
    o.insert("density".into(), num(p.density));
    o.insert("seed".into(), json!(p.seed));
    if let FiberLayout::Canvas { weights } = p.layout {
        o.insert("weights".into(), json!([num(weights[0]), num(weights[1])]));
    }
    if let Some(i) = p.impurities {
        o.insert(
            "impurities".into(),
            json!({ "density": num(i.density), "radius": num(i.radius), "strength": num(i.strength) }),
        );
    }
}

impl NoiseSpec {
    /// The spec as JSON, in the form [`NoiseSpec::from_value`] reads:
    /// `from_value(&s.to_value())` is `s` again.
    pub fn to_value(&self) -> Value {
        let mut o = Map::new();
        match &self.source {
            Source::Gabor(GaborSpec {
                kind,
                frequency,
                orientation,
                bandwidth,
                impulses,
                seed,
                orientation_field,
                frequency_field,
                profile,
            }) => {
                o.insert("type".into(), json!(self.source.type_name()));
                o.insert("kind".into(), name(&ranges::GABOR_KINDS, kind));
                if let Some(p) = profile {
                    o.insert("profile".into(), name(&ranges::PHASOR_PROFILES, p));
                }
                o.insert("frequency".into(), num(*frequency));
                o.insert("orientation".into(), num(*orientation));
                o.insert("bandwidth".into(), num(*bandwidth));
                o.insert("impulses".into(), num(*impulses));
                o.insert("seed".into(), json!(seed));
                if let Some(d) = orientation_field {
                    o.insert("orientation_field".into(), drive(d));
                }
                if let Some(d) = frequency_field {
                    o.insert("frequency_field".into(), drive(d));
                }
            }
            Source::Fbm(p) => {
                let kind = match p.basis {
                    Basis::Perlin => "perlin",
                    Basis::Value => "value",
                };
                o.insert("type".into(), json!(kind));
                fbm_fields(&mut o, p);
            }
            Source::Worley(WorleySpec {
                frequency,
                feature,
                metric,
                seed,
            }) => {
                o.insert("type".into(), json!("worley"));
                o.insert("frequency".into(), num(*frequency));
                o.insert("feature".into(), name(&ranges::WORLEY_FEATURES, feature));
                o.insert("metric".into(), name(&ranges::WORLEY_METRICS, metric));
                o.insert("seed".into(), json!(seed));
            }
            Source::White(WhiteSpec { seed }) => {
                o.insert("type".into(), json!("white"));
                o.insert("seed".into(), json!(seed));
            }
            Source::Curl(CurlSpec {
                potential,
                component,
            }) => {
                o.insert("type".into(), json!("curl"));
                fbm_fields(&mut o, potential);
                o.insert(
                    "component".into(),
                    name(&ranges::CURL_COMPONENTS, component),
                );
            }
            Source::Fibers(p) => fibers(&mut o, p),
            Source::Product(inputs) => {
                o.insert("type".into(), json!("product"));
                o.insert(
                    "inputs".into(),
                    Value::Array(inputs.iter().map(NoiseSpec::to_value).collect()),
                );
            }
        }
        match self.tile {
            Tile::Off => {}
            Tile::Output => {
                o.insert("tile".into(), json!(true));
            }
            Tile::Period(p) => {
                o.insert("tile".into(), json!(p));
            }
        }
        if let Some(t) = &self.transfer {
            o.insert("transfer".into(), transfer(t));
        }
        if !self.layers.is_empty() {
            o.insert(
                "layers".into(),
                Value::Array(self.layers.iter().map(layer).collect()),
            );
        }
        if let Some(p) = &self.palette {
            o.insert("palette".into(), ramp(p));
        }
        if let Some(b) = &self.blend {
            let mut blend = Map::new();
            blend.insert("beta".into(), num(b.beta));
            match &b.base {
                BlendBase::Color(c) => blend.insert("color".into(), hex(*c)),
                BlendBase::Ramp(r) => blend.insert("palette".into(), ramp(r)),
                BlendBase::Data { ramp: r, value } => {
                    blend.insert("palette".into(), ramp(r));
                    blend.insert("value".into(), data_ref(value))
                }
            };
            o.insert("blend".into(), Value::Object(blend));
        }
        Value::Object(o)
    }
}

#[cfg(test)]
mod tests {
    use crate::{NoiseSpec, Renderer};

    /// Every example spec written and read back renders the same picture, and writing
    /// it again gives the same JSON.
    #[test]
    fn every_example_round_trips() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/noise");
        let mut n = 0;
        for entry in std::fs::read_dir(&dir).expect("examples/noise") {
            let path = entry.expect("entry").path();
            let text = std::fs::read_to_string(&path).expect("read");
            let spec = NoiseSpec::from_json(&text).expect("valid example");
            let written = spec.to_value();
            let back = NoiseSpec::from_value(&written)
                .unwrap_or_else(|e| panic!("{}: {e}\n{written}", path.display()));
            assert_eq!(back.to_value(), written, "{}", path.display());
            let a = Renderer::new(&spec, 24).expect("renders").render();
            let b = Renderer::new(&back, 24).expect("renders").render();
            assert_eq!(a.pixels, b.pixels, "{}", path.display());
            n += 1;
        }
        assert!(n >= 20, "only {n} examples");
    }

    /// Every optional field away from its default survives the round trip (a writer
    /// that dropped one would read back as the default and render differently).
    #[test]
    fn non_default_fields_round_trip() {
        let specs = [
            r##"{"type":"canvas","length":30,"width":2,"density":0.5,"seed":3,"weights":[2,0.25],"impurities":{"density":0.01,"radius":3,"strength":-4},"tile":true,"transfer":{"type":"threshold","threshold":0.3,"width":0.2,"invert":true},"palette":["#000000","#ff8800"]}"##,
            r##"{"type":"gabor","kind":"random-phase","frequency":0.08,"orientation":0.5,"bandwidth":0.03,"impulses":32,"seed":5,"orientation_field":{"noise":{"type":"value","frequency":0.01,"seed":2},"amount":2},"frequency_field":{"noise":{"type":"perlin","frequency":0.02,"octaves":3,"seed":4},"amount":-0.5},"transfer":{"type":"spline-decay","value":0.3},"blend":{"beta":0.4,"color":"#336699"}}"##,
            r##"{"type":"curl","frequency":0.02,"octaves":4,"lacunarity":3,"persistence":0.4,"seed":8,"component":"y","blend":{"beta":0.7,"palette":["#112233","#445566","#778899"]}}"##,
            r##"{"type":"worley","frequency":0.05,"feature":"f2-f1","metric":"chebyshev","seed":6,"transfer":{"type":"spline-decay","value":"x"}}"##,
            r##"{"type":"perlin","frequency":0.03,"tile":16,"transfer":{"type":"curve","points":[[0,0.1],[0.4,0.2],[1,0.9]]},"layers":[{"type":"worley","frequency":0.1,"combine":"multiply","weight":0.5},{"type":"white","seed":3,"combine":"mask","mask":{"type":"value","frequency":0.05,"transfer":{"type":"threshold","threshold":0.2,"width":0.1,"invert":false}}}]}"##,
            r##"{"type":"gabor","kind":"random-phase","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"weather","channel":1,"amount":3.3},"orientation_field":{"data":"weather","channel":2,"amount":3.14159},"transfer":{"type":"spline-decay","value":{"data":"weather","channel":1}},"blend":{"beta":0.6,"palette":"viridis","value":{"data":"weather","channel":3}}}"##,
        ];
        for text in specs {
            let spec = NoiseSpec::from_json(text).expect("valid");
            let written = spec.to_value();
            let back = NoiseSpec::from_value(&written).unwrap_or_else(|e| panic!("{e}\n{written}"));
            let a = Renderer::new(&spec, 32).expect("renders").render();
            let b = Renderer::new(&back, 32).expect("renders").render();
            assert_eq!(a.pixels, b.pixels, "{text}");
            // Every field given is written (defaults may be added).
            let given: serde_json::Value = serde_json::from_str(text).expect("json");
            for key in given.as_object().expect("object").keys() {
                assert!(written.get(key).is_some(), "{key} dropped from {written}");
            }
        }
    }

    #[test]
    fn numbers_are_written_short_and_colours_as_hex() {
        let spec = NoiseSpec::from_json(
            r##"{"type":"perlin","frequency":0.1,"palette":["#102030","#ffffff"]}"##,
        )
        .expect("valid");
        let v = spec.to_value();
        assert_eq!(v["frequency"], serde_json::json!(0.1));
        assert_eq!(v["palette"], serde_json::json!(["#102030", "#ffffff"]));
        assert_eq!(v["octaves"], serde_json::json!(1));
    }
}
