//! Comb: a finite comb whose tines move together along one direction.

use kurbo::{Point, Vec2};
use std::sync::Arc;

/// Most tines of one comb.
pub const MAX_COMB_TINES: usize = 256;

/// Tines at signed offsets `tines` across the line through `origin` along `direction`,
/// all moving along it: M = unit direction, N = (−M.y, M.x), s = (P − A)·N,
/// d = minᵢ |s − oᵢ|, P′ = P + αλ/(d + λ)·M. The shift is constant along M, so the map
/// inverts exactly.
#[derive(Clone, Debug, PartialEq)]
pub struct Comb {
    /// A point on the line the tine offsets are measured from, design pixels.
    pub origin: Point,
    /// Direction of motion (non-zero; its length does not matter).
    pub direction: Vec2,
    /// Offsets of the tines along N, design pixels; 1..=[`MAX_COMB_TINES`] of them.
    pub tines: Arc<[f64]>,
    /// Shift at a tine, design pixels (negative moves against `direction`).
    pub alpha: f64,
    /// Decay length, design pixels, > 0.
    pub lambda: f64,
}

impl Comb {
    /// The displacement applied at `p`.
    pub fn shift(&self, p: Point) -> Vec2 {
        let m = self.direction.normalize();
        let n = Vec2::new(-m.y, m.x);
        let s = (p - self.origin).dot(n);
        let d = self
            .tines
            .iter()
            .map(|o| (s - o).abs())
            .fold(f64::INFINITY, f64::min);
        m * (self.alpha * self.lambda / (d + self.lambda))
    }

    /// Moves `p` with the comb.
    pub fn forward(&self, p: Point) -> Point {
        p + self.shift(p)
    }

    /// Undoes [`Comb::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        p - self.shift(p)
    }
}
