//! Fields shared by several sources: `tile`, data references and drives.

use super::{Reader, Role, Rule};
use crate::data::DataRef;
use crate::spec::{DriveSource, DriveSpec, Tile};
use marbling_json::{join, short};
use serde_json::{Map, Value};

impl Reader {
    /// `tile`: absent or false (off), true (every output size) or a whole number of
    /// pixels.
    pub(super) fn tile(&mut self, path: &str, obj: &Map<String, Value>) -> Option<Tile> {
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
    pub(super) fn data_ref(&mut self, path: &str, obj: &Map<String, Value>) -> Option<DataRef> {
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

    pub(super) fn drive(&mut self, path: &str, v: &Value) -> Option<DriveSpec> {
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
}
