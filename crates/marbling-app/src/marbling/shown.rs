//! What the canvas shows, as a view of a design rather than a copy of it: the current
//! design, an earlier history step (its first ops), a Play frame (the op being eased in
//! after them) or a gesture being dragged (its ops after the design's). The GPU keeps
//! the design's ops uploaded and writes only those that change
//! (`marbling_gpu::ExactRenderer::update`).

use marbling_core::{Design, Op};
use marbling_gpu::DesignPrefix;
use std::sync::Arc;

/// The paper, size and first `ops` ops of `design`, then the ops of `tail`.
#[derive(Clone, Debug, PartialEq)]
pub struct Shown {
    /// The design whose paper, size and leading ops are shown.
    pub design: Arc<Design>,
    /// How many of its ops are shown (at most all of them).
    pub ops: usize,
    /// Ops shown after them.
    pub tail: Vec<Op>,
}

impl Shown {
    /// All of `design`.
    pub fn all(design: Arc<Design>) -> Self {
        Self {
            ops: design.ops.len(),
            design,
            tail: Vec::new(),
        }
    }

    /// This with `more` ops after it.
    pub fn then(&self, more: &[Op]) -> Self {
        let mut s = self.clone();
        s.tail.extend_from_slice(more);
        s
    }

    /// The view the GPU renderers take.
    pub fn prefix(&self) -> DesignPrefix<'_> {
        DesignPrefix {
            design: &self.design,
            ops: self.ops,
            tail: &self.tail,
        }
    }

    /// Number of ops shown.
    pub fn op_count(&self) -> usize {
        self.prefix().op_count()
    }

    /// What one sample costs, in simple ops: its walk back through the ops shown
    /// ([`Op::walk_cost`]) and the noise it then reads ([`Design::surface_cost`]).
    pub fn walk_cost(&self) -> u64 {
        self.prefix().ops().map(Op::walk_cost).sum::<u64>() + self.design.surface_cost()
    }

    /// How many ops those count as toward [`marbling_core::MAX_OPS`] (every drop of a
    /// pattern counts).
    pub fn counted_ops(&self) -> usize {
        self.prefix().ops().map(Op::counted_ops).sum()
    }

    /// True when this shows the same picture as `other`: the same paper, size and ops
    /// (an Undo returns to a state that looks like an earlier one).
    pub fn looks_like(&self, other: &Shown) -> bool {
        let (a, b) = (&*self.design, &*other.design);
        (a.width, a.height, a.background) == (b.width, b.height, b.background)
            && a.background_noise == b.background_noise
            && a.background_image == b.background_image
            && a.overlays == b.overlays
            && self.op_count() == other.op_count()
            && self.prefix().ops().eq(other.prefix().ops())
    }

    /// Sheet width and height, design pixels.
    pub fn size(&self) -> (u32, u32) {
        (self.design.width, self.design.height)
    }

    /// The design shown, as a design of its own (a copy unless it is all of one).
    pub fn to_design(&self) -> Arc<Design> {
        if self.ops == self.design.ops.len() && self.tail.is_empty() {
            return self.design.clone();
        }
        let mut d = (*self.design).clone();
        d.truncate_ops(self.ops.min(d.ops.len()));
        d.ops.extend_from_slice(&self.tail);
        Arc::new(d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn a_view_materialises_as_its_prefix_then_its_tail() {
        let d = Arc::new(random_design(2, 50, 40, 12, Mix::Mixed));
        let all = Shown::all(d.clone());
        assert!(
            Arc::ptr_eq(&all.to_design(), &d),
            "no copy of a whole design"
        );
        let view = Shown {
            design: d.clone(),
            ops: 5,
            tail: vec![d.ops[9].clone()],
        };
        assert_eq!(view.op_count(), 6);
        let m = view.to_design();
        assert_eq!(m.ops[..5], d.ops[..5]);
        assert_eq!(m.ops[5], d.ops[9]);
        assert_eq!(m.ops.len(), 6);
        assert_eq!(view.then(&d.ops[..2]).op_count(), 8);
        assert_eq!(view.prefix().ops().count(), 6);
        // The same picture however it is held: a prefix and its materialised copy.
        assert!(view.looks_like(&Shown::all(m.clone())));
        assert!(!view.looks_like(&all));
        let mut repainted = (*m).clone();
        repainted.background.r ^= 1;
        assert!(!view.looks_like(&Shown::all(Arc::new(repainted))));
    }
}
