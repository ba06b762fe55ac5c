//! Value rules of the design schema, each error naming its JSON path.

use crate::design::{MAX_OPS, MAX_SIDE};
use crate::ops::{MAX_COMB_TINES, MAX_DROPS, MAX_STYLUS_POINTS, MAX_STYLUS_TIPS, MAX_STYLUS_WORK};
use crate::{Design, DropSet, Op, Radii};
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

    fn drop_set(&mut self, f: &dyn Fn(&str) -> String, d: &DropSet) {
        if self.count(&f("centers"), d.len(), 1, MAX_DROPS, "centres") {
            for (i, &c) in d.centers.iter().enumerate() {
                self.point(&format!("{}[{i}]", f("centers")), c);
            }
        }
        match &d.radii {
            Radii::One(r) => self.positive(&f("radius"), *r),
            Radii::Each(list) => {
                if list.len() != d.len() {
                    self.push(
                        f("radii"),
                        format!(
                            "must hold one radius per centre ({}), got {}",
                            d.len(),
                            list.len()
                        ),
                    );
                }
                for (i, &r) in list.iter().enumerate() {
                    self.positive(&format!("{}[{i}]", f("radii")), r);
                }
            }
        }
        if d.colors.is_empty() {
            self.push(f("colors"), "must hold at least one colour, got none");
        }
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

    /// Checks the values of op number `i`.
    pub(crate) fn op(&mut self, i: usize, op: &Op) {
        let f = |name: &str| format!("ops[{i}].{name}");
        match op {
            Op::Drop(d) => {
                self.point(&f("center"), d.center);
                self.positive(&f("radius"), d.radius);
            }
            Op::Spray(s) => {
                self.point(&f("center"), s.center);
                self.positive(&f("radius"), s.radius);
            }
            Op::Tine(t) => {
                self.point(&f("origin"), t.origin);
                self.direction(&f("direction"), t.direction);
                self.finite(&f("alpha"), t.alpha);
                self.positive(&f("lambda"), t.lambda);
            }
            Op::Rake(r) => {
                self.point(&f("origin"), r.origin);
                self.direction(&f("direction"), r.direction);
                self.positive(&f("spacing"), r.spacing);
                self.finite(&f("alpha"), r.alpha);
                self.positive(&f("lambda"), r.lambda);
            }
            Op::Wavy(w) => {
                self.finite(&f("angle"), w.angle);
                self.finite(&f("amplitude"), w.amplitude);
                self.positive(&f("wavelength"), w.wavelength);
                self.finite(&f("phase"), w.phase);
            }
            Op::Circular(c) => {
                self.point(&f("center"), c.center);
                self.positive(&f("radius"), c.radius);
                self.finite(&f("alpha"), c.alpha);
                self.positive(&f("lambda"), c.lambda);
            }
            Op::Vortex(v) => {
                self.point(&f("center"), v.center);
                self.finite(&f("alpha"), v.alpha);
                self.positive(&f("lambda"), v.lambda);
            }
            Op::Shift(s) => self.point(&f("offset"), s.offset.to_point()),
            Op::Turn(t) => {
                self.point(&f("center"), t.center);
                self.finite(&f("angle"), t.angle);
            }
            Op::Comb(c) => {
                self.point(&f("origin"), c.origin);
                self.direction(&f("direction"), c.direction);
                if self.count(
                    &f("tines"),
                    c.tines.len(),
                    1,
                    MAX_COMB_TINES,
                    "tine offsets",
                ) {
                    for (k, &o) in c.tines.iter().enumerate() {
                        self.finite(&format!("{}[{k}]", f("tines")), o);
                    }
                }
                self.finite(&f("alpha"), c.alpha);
                self.positive(&f("lambda"), c.lambda);
            }
            Op::Drops(d) | Op::Sprays(d) => self.drop_set(&f, d),
            Op::Jiggle(j) => {
                self.finite(&f("angle"), j.angle);
                self.positive(&f("wavelength"), j.wavelength);
                let along_ok = self.finite(&f("along"), j.along);
                self.finite(&f("across"), j.across);
                self.finite(&f("phase"), j.phase);
                let ka = j.k_along();
                if along_ok && j.wavelength > 0.0 && ka.abs() >= 1.0 {
                    self.push(
                        f("along"),
                        format!(
                            "must satisfy |2π·along/wavelength| < 1 (the jiggle must not fold the tank), got {:.4} for along {} and wavelength {}; use a smaller along or a longer wavelength",
                            ka.abs(),
                            j.along,
                            j.wavelength
                        ),
                    );
                }
            }
            Op::Stylus(s) => {
                let path_ok = self.count(&f("path"), s.path.len(), 2, MAX_STYLUS_POINTS, "points");
                let mut finite = path_ok;
                for (k, &p) in s.path.iter().enumerate() {
                    let ok = self.finite(&format!("{}[{k}][0]", f("path")), p.x)
                        & self.finite(&format!("{}[{k}][1]", f("path")), p.y);
                    finite &= ok;
                }
                self.positive(&f("wake"), s.wake);
                let mut tips_ok = true;
                if let Some(tips) = &s.tips {
                    tips_ok = self.count(&f("tips"), tips.len(), 1, MAX_STYLUS_TIPS, "tip offsets");
                    for (k, &o) in tips.iter().enumerate() {
                        tips_ok &= self.finite(&format!("{}[{k}]", f("tips")), o);
                    }
                }
                if finite && tips_ok && s.wake.is_finite() && s.wake > 0.0 {
                    let work = s.sub_steps().saturating_mul(s.tip_count());
                    if work > MAX_STYLUS_WORK {
                        self.push(
                            f("path"),
                            format!(
                                "needs {} sub-steps × {} tip(s) = {work}, more than {MAX_STYLUS_WORK}; use a larger wake or a shorter path",
                                s.sub_steps(),
                                s.tip_count()
                            ),
                        );
                    }
                }
            }
        }
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
            c.op(i, op);
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
