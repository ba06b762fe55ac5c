//! The design's history, one step per user gesture: a spray stroke, a rake, a new sheet,
//! an opened file, a paper colour. Undo and redo move by whole steps; viewing an earlier
//! step and then editing starts a new branch, and the abandoned steps are kept as a
//! [`Branch`] that can be restored (nothing is ever silently deleted).
//!
//! The state after step k is the fold of steps `0..k` over the starting paper: a
//! [`Change::Document`] replaces the whole design, [`Change::Ops`] appends one gesture's
//! ops, [`Change::Paper`] changes the background and overlays. The current design is
//! kept folded; earlier states are folded on demand.

use crate::labels::gesture_label;
use crate::shown::Shown;
use marbling_core::{Design, MAX_OPS, NoiseBackground, Op, Overlay, Rgb8};
use std::sync::Arc;

/// The paper under the ink: background colour, noise background and grain overlays.
#[derive(Clone, Debug, PartialEq)]
pub struct Paper {
    /// The plain background colour (with a noise background, the colour standing for it).
    pub background: Rgb8,
    /// Schema v2 noise background, if any.
    pub background_noise: Option<NoiseBackground>,
    /// Schema v2 grain overlays.
    pub overlays: Vec<Overlay>,
}

impl Paper {
    /// The paper of `d`.
    pub fn of(d: &Design) -> Self {
        Self {
            background: d.background,
            background_noise: d.background_noise.clone(),
            overlays: d.overlays.clone(),
        }
    }

    fn apply_to(&self, d: &mut Design) {
        d.background = self.background;
        d.set_background_noise(self.background_noise.clone());
        d.overlays = self.overlays.clone();
    }
}

/// What one step does to the design.
#[derive(Clone, Debug, PartialEq)]
pub enum Change {
    /// Appends one gesture's ops (at least one).
    Ops(Vec<Op>),
    /// The design becomes this one (New, Open, a link, the gallery, a restored branch).
    Document(Box<Design>),
    /// The paper changes from `before` to `after`; the ops stay.
    Paper {
        /// The paper before the step.
        before: Box<Paper>,
        /// The paper after it.
        after: Box<Paper>,
    },
}

/// One entry of the history list.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// What the history list shows ("spray stroke, 340 droplets", "rake ↓ 9 tines").
    pub label: String,
    /// What the step does.
    pub change: Change,
}

/// Steps abandoned by editing after an undo or while an earlier step was shown.
#[derive(Clone, Debug, PartialEq)]
pub struct Branch {
    /// What the restore entry shows.
    pub label: String,
    /// The design where the branch left the history.
    pub fork: Design,
    /// The abandoned steps, oldest first.
    pub steps: Vec<Step>,
    /// The design at the branch's last step.
    pub design: Design,
}

/// Why an edit was not made; the history is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum EditError {
    /// The design would have more than [`MAX_OPS`] ops.
    #[error(
        "the design has {have} ops and this adds {adding}: more than {MAX_OPS} cannot be saved or shared, so nothing was added"
    )]
    TooManyOps {
        /// Ops in the design now.
        have: usize,
        /// Ops the edit would add.
        adding: usize,
    },
}

/// The steps, the undone steps (redo), the step being viewed and the abandoned branches.
#[derive(Clone, Debug, PartialEq)]
pub struct History {
    /// The design before the first step (the paper of the starting design, no ops).
    start: Design,
    steps: Vec<Step>,
    /// Undone steps, the most recently undone last.
    undone: Vec<Step>,
    /// The design after all steps (shared with the canvas: see [`History::shown`]).
    design: Arc<Design>,
    /// When set, only the first `n` steps are shown (a click on a history entry).
    viewing: Option<usize>,
    branches: Vec<Branch>,
}

impl History {
    /// A history whose current state is `design`, one step per gesture of its ops (a
    /// document without `gestures` gives one step per op).
    pub fn new(design: Design) -> Self {
        let mut start = design.clone();
        start.truncate_ops(0);
        let mut steps = Vec::new();
        let mut at = 0;
        for n in design.gesture_sizes() {
            let ops = design.ops[at..at + n].to_vec();
            at += n;
            steps.push(Step {
                label: gesture_label(&ops),
                change: Change::Ops(ops),
            });
        }
        Self {
            start,
            steps,
            undone: Vec::new(),
            design: Arc::new(design),
            viewing: None,
            branches: Vec::new(),
        }
    }

    /// The whole current design.
    pub fn design(&self) -> &Design {
        &self.design
    }

    /// The whole current design, shared (no copy).
    pub fn design_shared(&self) -> &Arc<Design> {
        &self.design
    }

    /// The design as shown: the current one, or the state after the viewed step, as
    /// a view of the current design where it can be (no document or paper step after
    /// the viewed one: the first ops of the current design), otherwise folded anew.
    pub fn shown(&self) -> Shown {
        let Some(k) = self.viewing else {
            return Shown::all(self.design.clone());
        };
        let later = &self.steps[k.min(self.steps.len())..];
        let mut dropped = 0;
        for s in later {
            match &s.change {
                Change::Ops(ops) => dropped += ops.len(),
                _ => return Shown::all(Arc::new(self.fold(k))),
            }
        }
        Shown {
            design: self.design.clone(),
            ops: self.design.ops.len() - dropped,
            tail: Vec::new(),
        }
    }

    /// The paper as shown (see [`History::shown`]).
    pub fn shown_paper(&self) -> Paper {
        Paper::of(&self.shown().design)
    }

    /// The steps, oldest first.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// The abandoned branches, oldest first.
    pub fn branches(&self) -> &[Branch] {
        &self.branches
    }

    /// Number of steps shown (all of them unless an earlier step is viewed).
    pub fn shown_steps(&self) -> usize {
        self.viewing.unwrap_or(self.steps.len())
    }

    /// True while an earlier step than the last is shown.
    pub fn is_viewing_earlier(&self) -> bool {
        self.viewing.is_some()
    }

    /// Shows the state after the first `n` steps (`None` or `n ≥` the step count: all).
    pub fn view(&mut self, n: Option<usize>) {
        self.viewing = n.filter(|&n| n < self.steps.len());
    }

    /// The design after the first `k` steps.
    pub fn state_at(&self, k: usize) -> Design {
        if k >= self.steps.len() {
            return (*self.design).clone();
        }
        self.fold(k)
    }

    /// The design after the first `k` steps, folded from the last document step before
    /// it (whether or not the kept current design is up to date).
    fn fold(&self, k: usize) -> Design {
        let k = k.min(self.steps.len());
        let from = self.steps[..k]
            .iter()
            .rposition(|s| matches!(s.change, Change::Document(_)));
        let mut d = match from {
            Some(j) => match &self.steps[j].change {
                Change::Document(d) => (**d).clone(),
                _ => unreachable!("rposition found a document step"),
            },
            None => self.start.clone(),
        };
        let first = from.map_or(0, |j| j + 1);
        for s in &self.steps[first..k] {
            apply(&mut d, &s.change);
        }
        d
    }

    /// Adds one gesture's ops as one step. Editing while an earlier step is shown, or
    /// after an undo, keeps the steps it abandons as a restorable [`Branch`].
    pub fn push_ops(&mut self, ops: Vec<Op>) -> Result<(), EditError> {
        if ops.is_empty() {
            return Ok(());
        }
        let base_ops = self.shown().counted_ops();
        let adding = ops.iter().map(Op::counted_ops).sum::<usize>();
        if base_ops + adding > MAX_OPS {
            return Err(EditError::TooManyOps {
                have: base_ops,
                adding,
            });
        }
        let label = gesture_label(&ops);
        self.push(Step {
            label,
            change: Change::Ops(ops),
        });
        Ok(())
    }

    /// Replaces the whole design as one step (undo brings the previous one back).
    pub fn push_document(&mut self, design: Design, label: impl Into<String>) {
        self.push(Step {
            label: label.into(),
            change: Change::Document(Box::new(design)),
        });
    }

    /// Changes the paper as one step; nothing happens if it is already `paper`. With
    /// `merge`, a newest step that is also a merging paper change is changed instead
    /// (a colour picker dragged through many colours is one step).
    pub fn push_paper(&mut self, paper: Paper, label: impl Into<String>, merge: bool) {
        let label = label.into();
        let before = self.shown_paper();
        if before == paper {
            return;
        }
        if merge
            && self.viewing.is_none()
            && self.undone.is_empty()
            && let Some(Step {
                label: last_label,
                change: Change::Paper { after, .. },
            }) = self.steps.last_mut()
            && last_label.starts_with(MERGING)
        {
            paper.apply_to(Arc::make_mut(&mut self.design));
            **after = paper;
            *last_label = format!("{MERGING}{label}");
            return;
        }
        let label = if merge {
            format!("{MERGING}{label}")
        } else {
            label
        };
        self.push(Step {
            label,
            change: Change::Paper {
                before: Box::new(before),
                after: Box::new(paper),
            },
        });
    }

    /// Restores branch `i`: a step back to where it forked, then its steps again, so
    /// undo walks back through them one by one (the branch stays listed).
    pub fn restore(&mut self, i: usize) -> bool {
        let Some(b) = self.branches.get(i).cloned() else {
            return false;
        };
        self.push_document(b.fork, format!("restore branch: {}", b.label));
        for step in b.steps {
            self.push(step);
        }
        true
    }

    fn push(&mut self, step: Step) {
        let at = self.shown_steps();
        if at < self.steps.len() || !self.undone.is_empty() {
            self.abandon_from(at);
        }
        self.viewing = None;
        self.undone.clear();
        apply(Arc::make_mut(&mut self.design), &step.change);
        self.steps.push(step);
    }

    /// Keeps steps `at..` and the undone steps as a branch, then drops them.
    fn abandon_from(&mut self, at: usize) {
        let fork = self.fold(at);
        let mut abandoned = self.steps.split_off(at.min(self.steps.len()));
        abandoned.extend(self.undone.drain(..).rev());
        self.design = Arc::new(fork.clone());
        if let Some(last) = abandoned.last() {
            let n = abandoned.len();
            let label = if n == 1 {
                last.label.clone()
            } else {
                format!("{n} steps, up to “{}”", last.label)
            };
            let mut design = fork.clone();
            for s in &abandoned {
                apply(&mut design, &s.change);
            }
            self.branches.push(Branch {
                label,
                fork,
                steps: abandoned,
                design,
            });
        }
    }

    /// The current design's noise background and grain overlays.
    pub fn surface(&self) -> Surface {
        (
            self.design.background_noise.clone(),
            self.design.overlays.clone(),
        )
    }

    /// Undoes the newest step; false when there is none.
    pub fn undo(&mut self) -> bool {
        self.viewing = None;
        let Some(step) = self.steps.pop() else {
            return false;
        };
        match &step.change {
            Change::Ops(ops) => {
                let n = self.design.ops.len() - ops.len();
                Arc::make_mut(&mut self.design).truncate_ops(n);
            }
            Change::Paper { before, .. } => before.apply_to(Arc::make_mut(&mut self.design)),
            Change::Document(_) => self.design = Arc::new(self.fold(self.steps.len())),
        }
        self.undone.push(step);
        true
    }

    /// Redoes the most recently undone step; false when there is none.
    pub fn redo(&mut self) -> bool {
        self.viewing = None;
        match self.undone.pop() {
            Some(step) => {
                apply(Arc::make_mut(&mut self.design), &step.change);
                self.steps.push(step);
                true
            }
            None => false,
        }
    }

    /// True when there is something to undo.
    pub fn can_undo(&self) -> bool {
        !self.steps.is_empty()
    }

    /// True when there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.undone.is_empty()
    }
}

/// What starts the label of a paper step that later picks merge into.
const MERGING: &str = "paper ";

/// A design's noise background and grain overlays.
pub type Surface = (Option<NoiseBackground>, Vec<Overlay>);

/// Applies one step's change to `d`.
fn apply(d: &mut Design, change: &Change) {
    match change {
        Change::Ops(ops) => {
            let first = d.ops.len();
            d.ops.extend_from_slice(ops);
            if ops.len() >= 2 {
                d.gestures.push(marbling_core::GestureSpan {
                    first,
                    count: ops.len(),
                });
            }
        }
        Change::Document(new) => *d = (**new).clone(),
        Change::Paper { after, .. } => after.apply_to(d),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{Point, Spray, Tine, Vec2};

    fn spray(x: f64) -> Op {
        Op::Spray(Spray {
            center: Point::new(x, 0.0),
            radius: 1.0,
            color: Rgb8::new(0, 0, 0),
        })
    }

    fn tine(y: f64) -> Op {
        Op::Tine(Tine {
            origin: Point::new(0.0, y),
            direction: Vec2::new(0.0, 1.0),
            alpha: 10.0,
            lambda: 4.0,
        })
    }

    fn blank() -> Design {
        Design::new(10, 10, Rgb8::new(1, 1, 1))
    }

    fn xs(d: &Design) -> Vec<f64> {
        d.ops
            .iter()
            .map(|o| match o {
                Op::Spray(s) => s.center.x,
                _ => -1.0,
            })
            .collect()
    }

    #[test]
    fn a_stroke_is_one_step_undone_and_redone_whole() {
        let mut h = History::new(blank());
        h.push_ops(vec![spray(0.0)]).expect("a value");
        h.push_ops((1..=340).map(|i| spray(f64::from(i))).collect())
            .expect("a value");
        h.push_ops((0..9).map(|i| tine(f64::from(i))).collect())
            .expect("a value");
        assert_eq!(h.steps().len(), 3);
        assert_eq!(h.steps()[1].label, "spray stroke, 340 droplets");
        assert_eq!(h.steps()[2].label, "rake ↓ 9 tines");
        assert_eq!(h.design().gesture_sizes(), vec![1, 340, 9]);
        let full = h.design().clone();
        assert!(h.undo());
        assert_eq!(h.design().ops.len(), 341);
        assert!(h.undo());
        assert_eq!(xs(h.design()), vec![0.0]);
        assert!(h.design().gestures.is_empty());
        assert!(h.redo() && h.redo() && !h.redo());
        assert_eq!(h.design(), &full);
    }

    #[test]
    fn grouping_survives_a_round_trip_through_json() {
        let mut h = History::new(blank());
        h.push_ops(vec![spray(0.0)]).expect("a value");
        h.push_ops(vec![spray(1.0), spray(2.0), spray(3.0)])
            .expect("a value");
        h.push_ops(vec![spray(4.0)]).expect("a value");
        let json = h.design().to_json_pretty();
        assert!(json.contains("\"gestures\": [[1,3]]"), "{json}");
        let back = Design::from_json(&json).expect("valid");
        let again = History::new(back);
        assert_eq!(again.steps(), h.steps());
        assert_eq!(again.design(), h.design());
        // A document without gestures loads as one step per op.
        let mut plain = h.design().clone();
        plain.gestures.clear();
        assert_eq!(History::new(plain).steps().len(), 5);
    }

    #[test]
    fn new_then_undo_restores_the_design_and_paper_is_undoable() {
        let mut h = History::new(blank());
        h.push_ops(vec![spray(0.0), spray(1.0)]).expect("a value");
        let made = h.design().clone();
        h.push_document(Design::new(30, 20, Rgb8::new(9, 9, 9)), "new sheet");
        assert_eq!((h.design().width, h.design().ops.len()), (30, 0));
        assert!(h.undo());
        assert_eq!(h.design(), &made);
        let mut paper = Paper::of(&made);
        paper.background = Rgb8::new(200, 10, 10);
        h.push_paper(paper.clone(), "#c80a0a", true);
        paper.background = Rgb8::new(200, 10, 11);
        h.push_paper(paper, "#c80a0b", true);
        assert_eq!(h.steps().len(), 2, "picks in a row are one step");
        assert_eq!(h.steps()[1].label, "paper #c80a0b");
        assert_eq!(h.design().background, Rgb8::new(200, 10, 11));
        assert_eq!(h.design().ops, made.ops);
        assert!(h.undo());
        assert_eq!(h.design(), &made);
        assert!(h.redo());
        assert_eq!(h.design().background, Rgb8::new(200, 10, 11));
    }

    #[test]
    fn editing_an_earlier_step_branches_and_the_abandoned_steps_are_restorable() {
        let mut h = History::new(blank());
        for i in 0..5 {
            h.push_ops(vec![spray(f64::from(i)), spray(f64::from(i) + 0.5)])
                .expect("a value");
        }
        let full = h.design().clone();
        h.view(Some(2));
        assert_eq!(h.shown().op_count(), 4);
        assert_eq!(h.design(), &full);
        h.view(Some(99));
        assert_eq!(h.shown_steps(), 5);
        h.view(Some(2));
        h.push_ops(vec![spray(9.0)]).expect("a value");
        assert_eq!(xs(h.design()), vec![0.0, 0.5, 1.0, 1.5, 9.0]);
        assert_eq!(h.branches().len(), 1);
        assert_eq!(h.branches()[0].steps.len(), 3);
        assert_eq!(h.branches()[0].design, full);
        assert!(h.restore(0));
        assert_eq!(h.design(), &full);
        // The restored steps come back one by one: undo walks through them, then to
        // the fork, then to the edit that made the branch.
        assert!(h.undo());
        assert_eq!(h.design().ops.len(), 8);
        assert!(h.undo() && h.undo());
        assert_eq!(h.design().ops.len(), 4);
        assert!(h.undo());
        assert_eq!(xs(h.design()), vec![0.0, 0.5, 1.0, 1.5, 9.0]);
    }

    #[test]
    fn a_new_step_after_undo_keeps_the_undone_steps_as_a_branch() {
        let mut h = History::new(blank());
        h.push_ops(vec![spray(1.0)]).expect("a value");
        h.push_ops(vec![spray(2.0)]).expect("a value");
        h.undo();
        h.push_ops(vec![spray(3.0)]).expect("a value");
        assert!(!h.can_redo());
        assert_eq!(xs(h.design()), vec![1.0, 3.0]);
        assert_eq!(xs(&h.branches()[0].design), vec![1.0, 2.0]);
    }

    #[test]
    fn earlier_states_fold_over_documents_and_paper() {
        let mut h = History::new(blank());
        h.push_ops(vec![spray(1.0)]).expect("a value");
        let mut other = Design::new(20, 20, Rgb8::new(5, 5, 5));
        other.ops = vec![spray(7.0), spray(8.0)];
        other.set_gesture_sizes([2]);
        h.push_document(other.clone(), "opened other.json");
        h.push_ops(vec![spray(9.0)]).expect("a value");
        let mut p = Paper::of(h.design());
        p.background = Rgb8::new(0, 0, 200);
        h.push_paper(p, "paper", false);
        assert_eq!(xs(&h.state_at(1)), vec![1.0]);
        assert_eq!(h.state_at(2), other);
        assert_eq!(xs(&h.state_at(3)), vec![7.0, 8.0, 9.0]);
        assert_eq!(h.state_at(3).background, Rgb8::new(5, 5, 5));
        assert_eq!(h.state_at(4).background, Rgb8::new(0, 0, 200));
        assert_eq!(h.state_at(4), *h.design());
        // Undo through everything lands on the start.
        while h.undo() {}
        assert_eq!(h.design(), &blank());
    }

    #[test]
    fn an_edit_past_the_op_cap_is_refused_and_changes_nothing() {
        let mut d = blank();
        d.ops = (0..MAX_OPS - 10).map(|i| spray(i as f64)).collect();
        let mut h = History::new(d);
        let before = h.clone();
        let err = h
            .push_ops((0..11).map(|i| spray(f64::from(i))).collect())
            .expect_err("an error");
        assert_eq!(
            err,
            EditError::TooManyOps {
                have: MAX_OPS - 10,
                adding: 11
            }
        );
        assert!(err.to_string().contains("nothing was added"));
        assert_eq!(h, before);
        h.push_ops((0..10).map(|i| spray(f64::from(i))).collect())
            .expect("a value");
        assert_eq!(h.design().ops.len(), MAX_OPS);
        assert!(h.design().validate().is_ok());
    }

    #[test]
    fn every_drop_of_a_pattern_counts_toward_the_cap() {
        use marbling_core::{DropSet, Point, Radii};
        let mut d = blank();
        d.ops = (0..MAX_OPS - 10).map(|i| spray(i as f64)).collect();
        let mut h = History::new(d);
        let pattern = |n: usize| {
            Op::Drops(DropSet {
                centers: (0..n).map(|i| Point::new(i as f64, 5.0)).collect(),
                radii: Radii::One(2.0),
                colors: std::sync::Arc::from([Rgb8::new(1, 2, 3)]),
            })
        };
        let err = h.push_ops(vec![pattern(11)]).expect_err("over the cap");
        assert_eq!(
            err,
            EditError::TooManyOps {
                have: MAX_OPS - 10,
                adding: 11
            }
        );
        h.push_ops(vec![pattern(10)]).expect("at the cap");
        assert_eq!(h.design().counted_ops(), MAX_OPS);
        assert!(h.design().validate().is_ok());
    }
}
