//! A design's recipe: what a traditional pattern is called, where it comes from, and a
//! caption for each step (gesture) of its making, e.g. "comb drawn left to right:
//! 9 tines, 40 px apart".
//!
//! Stored as the optional top-level `"recipe": {"name", "history", "captions"}` of a
//! design document in every schema version; it does not change the picture. Steps
//! without a caption (a user's own additions) are described by [`crate::caption`].

use crate::Design;

/// Longest recipe name, characters.
pub const MAX_RECIPE_NAME: usize = 80;
/// Longest history line, characters.
pub const MAX_RECIPE_HISTORY: usize = 400;
/// Longest step caption, characters.
pub const MAX_CAPTION: usize = 240;

/// Name, history and step captions of a pattern recipe.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Recipe {
    /// The pattern's name ("Chevron"), 1..=[`MAX_RECIPE_NAME`] characters.
    pub name: String,
    /// One line on where the pattern comes from, ≤ [`MAX_RECIPE_HISTORY`] characters.
    pub history: String,
    /// Caption of step k (the k-th gesture, see [`Design::gesture_sizes`]); at most one
    /// per step, each ≤ [`MAX_CAPTION`] characters.
    pub captions: Vec<String>,
}

impl Design {
    /// A caption for every step of the design, oldest first: the recipe's where it has
    /// one, else a description of the step's ops ([`crate::caption::describe`]).
    pub fn step_captions(&self) -> Vec<String> {
        let own = self.recipe.as_ref().map_or(&[][..], |r| &r.captions[..]);
        let mut at = 0;
        self.gesture_sizes()
            .into_iter()
            .enumerate()
            .map(|(k, n)| {
                let ops = &self.ops[at..at + n];
                at += n;
                own.get(k)
                    .cloned()
                    .unwrap_or_else(|| crate::caption::describe(ops))
            })
            .collect()
    }

    /// The ops at which each step starts, oldest first, then `ops.len()`: step k is
    /// `ops[b[k]..b[k + 1]]`.
    pub fn step_bounds(&self) -> Vec<usize> {
        let mut bounds = vec![0];
        for n in self.gesture_sizes() {
            bounds.push(bounds.last().unwrap_or(&0) + n);
        }
        bounds
    }
}
