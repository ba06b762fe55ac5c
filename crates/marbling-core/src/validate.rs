//! Value rules of the design schema, each error naming its JSON path.

use crate::Design;
use crate::design::{MAX_OPS, MAX_SIDE};
use kurbo::{Point, Vec2};
use std::fmt;

pub use marbling_json::FieldError;

/// All the rules a design breaks; displayed one per line.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub struct ValidationErrors(pub Vec<FieldError>);

impl fmt::Display for ValidationErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, e) in self.0.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

/// Checks values against the schema's rules, adding each broken rule to `errors`.
pub(crate) struct Checker<'a> {
    pub(crate) errors: &'a mut Vec<FieldError>,
}

impl Checker<'_> {
    pub(crate) fn push(&mut self, path: impl Into<String>, message: impl Into<String>) {
        self.errors.push(FieldError {
            path: path.into(),
            message: message.into(),
        });
    }

    fn finite(&mut self, path: &str, v: f64) -> bool {
        if !v.is_finite() {
            self.push(path, format!("must be a finite number, got {v}"));
        }
        v.is_finite()
    }

    fn positive(&mut self, path: &str, v: f64) {
        if self.finite(path, v) && v <= 0.0 {
            self.push(path, format!("must be > 0, got {v}"));
        }
    }

    fn point(&mut self, path: &str, p: Point) {
        self.finite(&format!("{path}[0]"), p.x);
        self.finite(&format!("{path}[1]"), p.y);
    }

    fn direction(&mut self, path: &str, v: Vec2) {
        let ok = self.finite(&format!("{path}[0]"), v.x) & self.finite(&format!("{path}[1]"), v.y);
        if ok && v.hypot2() == 0.0 {
            self.push(path, format!("must be non-zero, got [{}, {}]", v.x, v.y));
        }
    }

    pub(crate) fn side(&mut self, path: &str, v: u32) {
        if !(1..=MAX_SIDE).contains(&v) {
            self.push(path, format!("must be in 1..={MAX_SIDE}, got {v}"));
        }
    }

    /// An overlay strength: finite, in [0, 1].
    pub(crate) fn strength(&mut self, path: &str, v: f64) {
        if self.finite(path, v) && !(0.0..=1.0).contains(&v) {
            self.push(path, format!("must be in [0, 1], got {v}"));
        }
    }

    /// At most one overlay of each kind (the GPU renderer draws one of each).
    pub(crate) fn overlay_kinds(&mut self, kinds: impl Iterator<Item = crate::GrainKind>) {
        let mut seen = Vec::new();
        for (i, k) in kinds.enumerate() {
            if seen.contains(&k) {
                self.push(
                    format!("overlays[{i}].type"),
                    format!("at most one {} overlay is allowed", k.name()),
                );
            }
            seen.push(k);
        }
    }

    /// The design's ops, counted as [`Op::counted_ops`] does.
    pub(crate) fn op_count(&mut self, n: usize) {
        if n > MAX_OPS {
            self.push(
                "ops",
                format!(
                    "at most {MAX_OPS} ops are allowed (each drop of a pattern counts), got {n}"
                ),
            );
        }
    }

    /// A list's length in `lo..=hi`.
    fn count(&mut self, path: &str, n: usize, lo: usize, hi: usize, what: &str) -> bool {
        let ok = (lo..=hi).contains(&n);
        if !ok {
            self.push(path, format!("must hold {lo}..={hi} {what}, got {n}"));
        }
        ok
    }

    /// Gesture spans: at least 2 ops each, inside the `ops` list, sorted and disjoint.
    /// A recipe's text lengths (the caption count is checked against the steps by the
    /// reader; the writer drops captions of steps that no longer exist).
    pub(crate) fn recipe(&mut self, r: &crate::Recipe) {
        use crate::{MAX_CAPTION, MAX_RECIPE_HISTORY, MAX_RECIPE_NAME};
        let mut text = |path: String, s: &str, lo: usize, hi: usize| {
            let n = s.chars().count();
            if !(lo..=hi).contains(&n) {
                self.push(
                    path,
                    format!("must be {lo} to {hi} characters long, got {n}"),
                );
            }
        };
        text("recipe.name".into(), &r.name, 1, MAX_RECIPE_NAME);
        text("recipe.history".into(), &r.history, 0, MAX_RECIPE_HISTORY);
        for (i, c) in r.captions.iter().enumerate() {
            text(format!("recipe.captions[{i}]"), c, 1, MAX_CAPTION);
        }
    }

    pub(crate) fn gestures(&mut self, spans: &[crate::GestureSpan], ops: usize) {
        let mut end = 0;
        for (i, g) in spans.iter().enumerate() {
            let path = format!("gestures[{i}]");
            if g.count < 2 {
                self.push(
                    path,
                    format!(
                        "a gesture has at least 2 ops, got {} (a lone op needs no entry)",
                        g.count
                    ),
                );
            } else if g.first.saturating_add(g.count) > ops {
                self.push(
                    path,
                    format!(
                        "ops {}..{} lie past the last op ({ops} ops)",
                        g.first,
                        g.first.saturating_add(g.count)
                    ),
                );
            } else if g.first < end {
                self.push(
                    path,
                    format!("starts at op {} inside gestures[{}], which ends at op {end}; gestures are sorted and disjoint", g.first, i - 1),
                );
            }
            end = end.max(g.first.saturating_add(g.count));
        }
    }

    /// The rules of op number `index`.
    pub(crate) fn op(&mut self, index: usize) -> OpCheck<'_> {
        OpCheck {
            checker: Checker {
                errors: &mut *self.errors,
            },
            index,
        }
    }
}

/// The value rules as each op type's file applies them ([`crate::ops::OpType::check`]):
/// field names are relative to the op (`"radius"`, `"tines[3]"`), errors name
/// `ops[i].<field>`.
pub(crate) struct OpCheck<'a> {
    checker: Checker<'a>,
    index: usize,
}

impl OpCheck<'_> {
    fn path(&self, field: &str) -> String {
        format!("ops[{}].{field}", self.index)
    }

    /// Reports a broken rule at `field`.
    pub(crate) fn push(&mut self, field: &str, message: impl Into<String>) {
        let path = self.path(field);
        self.checker.push(path, message);
    }

    /// A finite number; false (reported) when not.
    pub(crate) fn finite(&mut self, field: &str, v: f64) -> bool {
        let path = self.path(field);
        self.checker.finite(&path, v)
    }

    /// A finite number > 0.
    pub(crate) fn positive(&mut self, field: &str, v: f64) {
        let path = self.path(field);
        self.checker.positive(&path, v);
    }

    /// A point with finite coordinates.
    pub(crate) fn point(&mut self, field: &str, p: Point) {
        let path = self.path(field);
        self.checker.point(&path, p);
    }

    /// A finite, non-zero direction.
    pub(crate) fn direction(&mut self, field: &str, v: Vec2) {
        let path = self.path(field);
        self.checker.direction(&path, v);
    }

    /// A list's length in `lo..=hi` (`what` names its items); false (reported) when not.
    pub(crate) fn count(
        &mut self,
        field: &str,
        n: usize,
        lo: usize,
        hi: usize,
        what: &str,
    ) -> bool {
        let path = self.path(field);
        self.checker.count(&path, n, lo, hi, what)
    }
}

impl Design {
    /// Checks every value rule of the schema and reports all broken ones with their paths.
    /// Use it on designs built in code; [`crate::Design::from_json`] applies it already.
    pub fn validate(&self) -> Result<(), ValidationErrors> {
        let mut errors = Vec::new();
        let mut c = Checker {
            errors: &mut errors,
        };
        c.side("width", self.width);
        c.side("height", self.height);
        c.op_count(self.counted_ops());
        for (i, op) in self.ops.iter().enumerate() {
            op.check(&mut c.op(i));
        }
        c.gestures(&self.gestures, self.ops.len());
        if let Some(r) = &self.recipe {
            c.recipe(r);
        }
        if let Some(n) = &self.background_noise {
            let k = n.palette.stops.len();
            if !(2..=crate::MAX_PALETTE_STOPS).contains(&k) {
                c.push(
                    "background.palette",
                    crate::PaletteError::StopCount(k).to_string(),
                );
            }
        }
        for (i, o) in self.overlays.iter().enumerate() {
            c.strength(&format!("overlays[{i}].strength"), o.strength);
        }
        c.overlay_kinds(self.overlays.iter().map(|o| o.kind));
        if errors.is_empty() {
            Ok(())
        } else {
            Err(ValidationErrors(errors))
        }
    }
}
