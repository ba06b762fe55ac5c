//! Drop patterns: many drops (or spray droplets) in one op, exactly the sequence of
//! single `drop` (or `spray`) ops i = 0, 1, … with colour `colors[i mod len]`.

use super::{Drop, Op, Spray};
use crate::Rgb8;
use kurbo::Point;
use std::sync::Arc;

/// Most drops in one op.
pub const MAX_DROPS: usize = 10_000;

/// The radius of every drop, or one per drop.
#[derive(Clone, Debug, PartialEq)]
pub enum Radii {
    /// Every drop has this radius, design pixels (`"radius"`).
    One(f64),
    /// Drop i has radius i, design pixels (`"radii"`, as long as `centers`).
    Each(Arc<[f64]>),
}

/// Drops at `centers`, laid in order.
#[derive(Clone, Debug, PartialEq)]
pub struct DropSet {
    /// Centres, design pixels, in the order the drops fall; 1..=[`MAX_DROPS`].
    pub centers: Arc<[Point]>,
    /// Their radii.
    pub radii: Radii,
    /// Colours, cycled: drop i has `colors[i mod len]` (at least one).
    pub colors: Arc<[Rgb8]>,
}

impl DropSet {
    /// Number of drops.
    pub fn len(&self) -> usize {
        self.centers.len()
    }

    /// True when there are no drops (never for a valid op).
    pub fn is_empty(&self) -> bool {
        self.centers.is_empty()
    }

    /// Radius of drop `i` (0 past the end of a short `radii` list).
    pub fn radius(&self, i: usize) -> f64 {
        match &self.radii {
            Radii::One(r) => *r,
            Radii::Each(list) => list.get(i).copied().unwrap_or(0.0),
        }
    }

    /// Colour of drop `i`.
    pub fn color(&self, i: usize) -> Rgb8 {
        self.colors[i % self.colors.len()]
    }

    /// The single ops this set stands for, in order: drops, or spray droplets when
    /// `spray`.
    pub fn expand(&self, spray: bool) -> impl DoubleEndedIterator<Item = Op> + '_ {
        (0..self.len()).map(move |i| {
            let (center, radius, color) = (self.centers[i], self.radius(i), self.color(i));
            if spray {
                Op::Spray(Spray {
                    center,
                    radius,
                    color,
                })
            } else {
                Op::Drop(Drop {
                    center,
                    radius,
                    color,
                })
            }
        })
    }
}
