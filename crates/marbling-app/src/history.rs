//! The design's history: the committed ops, an undo/redo stack, and which prefix of the
//! history is being looked at.

use marbling_core::{Design, Op};

/// A design plus the ops that were undone (for redo) and the op count being viewed.
#[derive(Clone, Debug, PartialEq)]
pub struct History {
    design: Design,
    /// Undone ops, the most recently undone last.
    redo: Vec<Op>,
    /// When set, only the first `n` ops are shown (clicking an entry of the history list).
    viewing: Option<usize>,
}

impl History {
    /// A history whose current state is `design`.
    pub fn new(design: Design) -> Self {
        Self {
            design,
            redo: Vec::new(),
            viewing: None,
        }
    }

    /// The whole current design.
    pub fn design(&self) -> &Design {
        &self.design
    }

    /// The design as shown: all ops, or the viewed prefix.
    pub fn shown(&self) -> Design {
        let mut d = self.design.clone();
        if let Some(n) = self.viewing {
            d.ops.truncate(n);
        }
        d
    }

    /// Number of ops shown.
    pub fn shown_len(&self) -> usize {
        self.viewing.unwrap_or(self.design.ops.len())
    }

    /// Shows only the first `n` ops (`None` or `n ≥ len`: all of them).
    pub fn view(&mut self, n: Option<usize>) {
        self.viewing = n.filter(|&n| n < self.design.ops.len());
    }

    /// Appends an op. If an earlier prefix was being viewed, the ops after it are
    /// dropped first (like typing after undo); the redo stack is cleared.
    pub fn push(&mut self, op: Op) {
        if let Some(n) = self.viewing.take() {
            self.design.ops.truncate(n);
        }
        self.design.ops.push(op);
        self.redo.clear();
    }

    /// Undoes the newest op; false when there is none.
    pub fn undo(&mut self) -> bool {
        self.viewing = None;
        match self.design.ops.pop() {
            Some(op) => {
                self.redo.push(op);
                true
            }
            None => false,
        }
    }

    /// Redoes the most recently undone op; false when there is none.
    pub fn redo(&mut self) -> bool {
        self.viewing = None;
        match self.redo.pop() {
            Some(op) => {
                self.design.ops.push(op);
                true
            }
            None => false,
        }
    }

    /// True when there is something to undo.
    pub fn can_undo(&self) -> bool {
        !self.design.ops.is_empty()
    }

    /// True when there is something to redo.
    pub fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// Replaces the whole design (New, Open, a share link, the gallery); the old one can
    /// not be redone into the new one, so the redo stack is cleared.
    pub fn replace(&mut self, design: Design) {
        *self = Self::new(design);
    }

    /// Changes the background colour of the current design (a plain colour replaces a
    /// noise background).
    pub fn set_background(&mut self, c: marbling_core::Rgb8) {
        self.design.background_noise = None;
        self.design.background = c;
    }

    /// The design's noise background and grain overlays (schema v2).
    pub fn surface(&self) -> Surface {
        (
            self.design.background_noise.clone(),
            self.design.overlays.clone(),
        )
    }

    /// Replaces the design's noise background and grain overlays; the ops stay.
    pub fn set_surface(&mut self, (background, overlays): Surface) {
        self.design.set_background_noise(background);
        self.design.overlays = overlays;
    }
}

/// A design's noise background and grain overlays.
pub type Surface = (
    Option<marbling_core::NoiseBackground>,
    Vec<marbling_core::Overlay>,
);

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::{Point, Rgb8, Spray};

    fn spray(x: f64) -> Op {
        Op::Spray(Spray {
            center: Point::new(x, 0.0),
            radius: 1.0,
            color: Rgb8::new(0, 0, 0),
        })
    }

    #[test]
    fn undo_redo_is_unlimited_and_exact() {
        let mut h = History::new(Design::new(10, 10, Rgb8::new(1, 1, 1)));
        for i in 0..1000 {
            h.push(spray(f64::from(i)));
        }
        let full = h.design().clone();
        for _ in 0..1000 {
            assert!(h.undo());
        }
        assert!(!h.undo() && h.design().ops.is_empty());
        for _ in 0..1000 {
            assert!(h.redo());
        }
        assert!(!h.redo());
        assert_eq!(h.design(), &full);
    }

    #[test]
    fn a_new_op_after_undo_clears_redo() {
        let mut h = History::new(Design::new(10, 10, Rgb8::new(1, 1, 1)));
        h.push(spray(1.0));
        h.push(spray(2.0));
        h.undo();
        h.push(spray(3.0));
        assert!(!h.can_redo());
        assert_eq!(h.design().ops, vec![spray(1.0), spray(3.0)]);
    }

    #[test]
    fn viewing_a_prefix_then_editing_branches_from_it() {
        let mut h = History::new(Design::new(10, 10, Rgb8::new(1, 1, 1)));
        for i in 0..5 {
            h.push(spray(f64::from(i)));
        }
        h.view(Some(2));
        assert_eq!(h.shown().ops.len(), 2);
        assert_eq!(h.design().ops.len(), 5);
        h.view(Some(9));
        assert_eq!(h.shown_len(), 5);
        h.view(Some(2));
        h.push(spray(9.0));
        assert_eq!(h.design().ops, vec![spray(0.0), spray(1.0), spray(9.0)]);
    }
}
