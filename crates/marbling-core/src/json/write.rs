//! The design writer: [`Design`] → JSON in schema field order.

use super::op_fields::{FieldWriter, num};
use crate::design::CURRENT_VERSION;
use crate::surface::{Overlay, Palette};
use crate::{Design, Op, Rgb8};
use serde_json::{Map, Value, json};

/// An op as its JSON object: `type`, then its fields ([`crate::ops::OpType::write`]).
fn op_value(op: &Op) -> Value {
    let mut w = FieldWriter { map: Map::new() };
    w.map.insert("type".into(), json!(op.type_name()));
    op.write(&mut w);
    Value::Object(w.map)
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
