//! The design's history, one step per user gesture: a spray stroke, a rake, a new sheet,
//! an opened file, a paper colour. Undo and redo move by whole steps; viewing an earlier
//! step and then editing starts a new branch, and the abandoned steps are kept as a
//! [`Branch`] that can be restored (nothing is ever silently deleted).
//!
//! The state after step k is the fold of steps `0..k` over the starting paper: a
//! [`Change::Document`] replaces the whole design, [`Change::Ops`] appends one gesture's
//! ops, [`Change::Paper`] changes the background and overlays. The current design is
//! kept folded; earlier states are folded on demand.

pub(crate) mod panel;

use crate::marbling::labels::gesture_label;
use crate::marbling::shown::Shown;
use marbling_core::{Design, ImageBackground, MAX_OPS, NoiseBackground, Op, Overlay, Rgb8};
use std::sync::Arc;

/// Abandoned branches kept, newest last: older ones are dropped.
pub const MAX_BRANCHES: usize = 16;

/// The paper under the ink: background colour, noise or picture background and grain
/// overlays.
#[derive(Clone, Debug, PartialEq)]
pub struct Paper {
    /// The plain background colour (with a noise background, the colour standing for it).
    pub background: Rgb8,
    /// Schema v2 noise background, if any.
    pub background_noise: Option<NoiseBackground>,
    /// Schema v2 picture background, if any (never with a noise background).
    pub background_image: Option<ImageBackground>,
    /// Schema v2 grain overlays.
    pub overlays: Vec<Overlay>,
}

impl Paper {
    /// The paper of `d`.
    pub fn of(d: &Design) -> Self {
        Self {
            background: d.background,
            background_noise: d.background_noise.clone(),
            background_image: d.background_image.clone(),
            overlays: d.overlays.clone(),
        }
    }

    fn apply_to(&self, d: &mut Design) {
        d.background = self.background;
        d.set_background_noise(self.background_noise.clone());
        d.set_background_image(self.background_image.clone());
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

    /// Keeps steps `at..` and the undone steps as a branch, then drops them; only the newest
    /// [`MAX_BRANCHES`] branches are kept.
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
            // Each branch holds two designs: the oldest go, so that editing for hours
            // holds a bounded history.
            let over = self.branches.len().saturating_sub(MAX_BRANCHES);
            self.branches.drain(..over);
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

    /// The undone steps in the order Redo brings them back (the next one first).
    pub fn undone(&self) -> impl Iterator<Item = &Step> {
        self.undone.iter().rev()
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
mod tests;
