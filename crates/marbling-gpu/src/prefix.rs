//! What a render shows of a design without copying it: the paper and leading ops of a
//! design, then more ops — an earlier history step, a Play frame (the op being eased in),
//! a gesture being dragged (its ops). An uploaded design follows one of these by writing
//! only the ops that changed ([`crate::ExactRenderer::update`]).

use marbling_core::{Design, Op};

/// The paper, size and first `ops` ops of `design`, then the ops of `tail`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DesignPrefix<'a> {
    /// The design whose paper, size and leading ops are shown.
    pub design: &'a Design,
    /// How many of its ops (at most all of them).
    pub ops: usize,
    /// Ops walked after them.
    pub tail: &'a [Op],
}

impl<'a> DesignPrefix<'a> {
    /// The op lists walked, oldest first: the design's leading ops, then the tail.
    pub fn parts(&self) -> [&'a [Op]; 2] {
        let design: &'a Design = self.design;
        let ops = &design.ops[..self.ops.min(design.ops.len())];
        [ops, self.tail]
    }

    /// Number of ops walked.
    pub fn op_count(&self) -> usize {
        self.ops.min(self.design.ops.len()) + self.tail.len()
    }

    /// The ops walked, oldest first.
    pub fn ops(&self) -> impl Iterator<Item = &'a Op> + 'a {
        let [a, b] = self.parts();
        a.iter().chain(b)
    }
}

impl<'a> From<&'a Design> for DesignPrefix<'a> {
    /// The whole design.
    fn from(design: &'a Design) -> Self {
        Self {
            design,
            ops: design.ops.len(),
            tail: &[],
        }
    }
}
