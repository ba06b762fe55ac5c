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
//!
//! Schema v4 (`"version": 4`) adds the `flow` op
//! (`{"type": "flow", "noise": SPEC, "strength": U, "time": T}`, SPEC a `perlin` or
//! `value` spec of `marbling-noise`; see [`crate::Flow`]).

mod op_fields;
mod read;
mod read_surface;
mod write;

pub(crate) use op_fields::{FieldReader, FieldWriter};

use crate::Design;
use crate::validate::ValidationErrors;

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

impl Design {
    /// Reads a design document, checking its structure and every value rule.
    /// All problems are reported at once, each with its JSON path.
    pub fn from_json(text: &str) -> Result<Design, DesignError> {
        let value = marbling_json::parse(text).map_err(|e| DesignError::Syntax {
            line: e.line,
            column: e.column,
            message: e.message,
        })?;
        read::design(&value).map_err(|errors| DesignError::Invalid(ValidationErrors(errors)))
    }
}

#[cfg(test)]
mod tests {
    use crate::Design;
    use crate::ops::op_fields;

    /// The writer names each op's fields as the schema's list does, in its order; the
    /// reader already refuses any field outside the list.
    #[test]
    fn the_writer_uses_the_schemas_field_names() {
        let ops = [
            r##"{"type":"drop","center":[10,10],"radius":5,"color":"#112233"}"##,
            r##"{"type":"spray","center":[10,10],"radius":5,"color":"#112233"}"##,
            r#"{"type":"tine","origin":[0,5],"direction":[1,0],"alpha":20,"lambda":8}"#,
            r#"{"type":"rake","origin":[0,5],"direction":[1,0],"spacing":9,"alpha":20,"lambda":8}"#,
            r#"{"type":"wavy","angle":0.5,"amplitude":3,"wavelength":40,"phase":0.1}"#,
            r#"{"type":"circular","center":[30,20],"radius":9,"alpha":20,"lambda":8}"#,
            r#"{"type":"vortex","center":[30,20],"alpha":20,"lambda":8}"#,
            r#"{"type":"shift","offset":[3,-2]}"#,
            r#"{"type":"turn","center":[30,20],"angle":0.3}"#,
            r#"{"type":"comb","origin":[0,5],"direction":[1,0],"tines":[-4,3],"alpha":20,"lambda":8}"#,
            r##"{"type":"drops","centers":[[5,5],[9,9]],"radius":2,"colors":["#ffffff"]}"##,
            r##"{"type":"sprays","centers":[[5,5],[9,9]],"radii":[2,3],"colors":["#ffffff"]}"##,
            r#"{"type":"jiggle","angle":0.2,"wavelength":60,"along":2,"across":1,"phase":0}"#,
            r#"{"type":"stylus","path":[[1,1],[20,9]],"wake":6,"tips":[-2,2]}"#,
            r#"{"type":"flow","noise":{"type":"value","frequency":0.05,"octaves":2},"strength":3,"time":0.5}"#,
        ];
        let text = format!(
            r##"{{"version":4,"width":64,"height":48,"background":"#000000","ops":[{}]}}"##,
            ops.join(",")
        );
        let design = Design::from_json(&text).expect("every op type");
        let written = design.to_value();
        let written = written["ops"].as_array().expect("ops");
        assert_eq!(written.len(), crate::OP_TYPES.len());
        for op in written {
            let kind = op["type"].as_str().expect("type");
            let keys: Vec<&str> = op
                .as_object()
                .expect("op")
                .keys()
                .map(String::as_str)
                .collect();
            let schema = op_fields(kind).expect("a schema type");
            let mut expected = schema.iter().copied().filter(|f| keys.contains(f));
            assert!(
                keys.iter().all(|k| expected.next() == Some(*k)),
                "{kind}: writes {keys:?}, the schema lists {schema:?}"
            );
        }
    }
}
