//! The design writer: [`Design`] → JSON in schema field order.

use crate::design::CURRENT_VERSION;
use crate::surface::{Overlay, Palette};
use crate::{Design, Drop, Op, Radii, Rgb8, Spray};
use kurbo::Point;
use serde_json::{Map, Value, json};

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
        if let Some(img) = &self.background_image {
            let mut v = json!({"image": img.source(), "fit": img.fit.name()});
            if self.background != Rgb8::WHITE {
                v["paper"] = json!(self.background.to_string());
            }
            return v;
        }
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
