//! What each op type's file says about its type: the [`OpType`] trait. [`super::Op`]
//! dispatches to it through the one table of op types in `ops/mod.rs`.

use crate::explain::Formula;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;

/// One op type's document fields, value rules, rounding, scaling and caption, kept in
/// its own `ops/<op>.rs` next to its forward and inverse maps.
pub(crate) trait OpType: Sized {
    /// Field names, `type` first, in the order they are written; the reader refuses any
    /// other field.
    const FIELDS: &'static [&'static str];

    /// Reads the fields (every field is read, so every problem is reported at once).
    fn read(r: &mut FieldReader<'_>) -> Option<Self>;

    /// Writes the fields after `type`, in [`OpType::FIELDS`] order.
    fn write(&self, w: &mut FieldWriter);

    /// Reports every broken value rule.
    fn check(&self, c: &mut OpCheck<'_>);

    /// Rounds the parameters to what can matter (`ops/rounding.rs`); idempotent.
    fn round(&mut self);

    /// Scales to fraction `s` (0..=1) of its strength or radius, as the step player
    /// eases a step in; radii stay > 0 so the op stays valid.
    fn scale(&mut self, s: f64);

    /// A plain-language caption with the op's numbers; `tag` is its `type` (one field
    /// type serves both `drops` and `sprays`).
    fn caption(&self, tag: &str) -> String;

    /// A short name for lists (the history): "tine →", "12 drops".
    fn label(&self, tag: &str) -> String;

    /// Its forward and inverse maps with its numbers, for the explain view; `symbols`
    /// names only this type's symbols (`P` and `P′` are added by [`crate::explain::formula`]).
    fn formula(&self, tag: &str) -> Formula;
}
