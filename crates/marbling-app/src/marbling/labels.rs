//! What the history list calls a gesture: "drop", "spray stroke, 340 droplets",
//! "rake ↓ 9 tines", "tine →", "vortex".

use marbling_core::Op;
use marbling_core::caption::arrow;

/// The label of one gesture's ops.
pub fn gesture_label(ops: &[Op]) -> String {
    let n = ops.len();
    match ops {
        [] => "nothing".to_owned(),
        [op] => op.label(),
        [Op::Spray(_), ..] if ops.iter().all(|o| matches!(o, Op::Spray(_))) => {
            format!("spray stroke, {n} droplets")
        }
        [Op::Tine(t), ..] if ops.iter().all(|o| matches!(o, Op::Tine(_))) => {
            format!("rake {} {n} tines", arrow(t.direction))
        }
        [first, ..] if ops.iter().all(|o| o.type_name() == first.type_name()) => {
            format!("{n} × {}", first.label())
        }
        _ => format!("{n} ops"),
    }
}
