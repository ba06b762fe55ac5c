//! Stylus: a free-hand stroke through the tank, exactly invertible and area preserving.
//!
//! A tip at S moving along the unit direction n has the stream function
//! ψ(q) = y·e^{−ρ/L}·c(ρ/R), with q = P − S, x = q·n, y = q·n⊥, n⊥ = (−n.y, n.x),
//! ρ = |q|, R = [`WAKE_REACH`]·L and c(t) = (1 − t²)³ for t < 1, 0 beyond: a tip moves
//! nothing farther than R. Its velocity per unit of stylus travel is
//! u = (∂ψ/∂y)·n − (∂ψ/∂x)·n⊥ (divergence free, u = n at the tip).
//!
//! Each path segment of length ℓ > 0 is cut into N = max(1, ⌈2ℓ/L⌉) sub-steps of length
//! δ = ℓ/N. In a sub-step every tip sits at the sub-step's midpoint (tip i offset by
//! oᵢ·n⊥) and their velocities add up. A sub-step maps P to the P′ solving the implicit
//! midpoint rule P′ = P + δ·u((P + P′)/2): symplectic, so exactly area preserving, and
//! time reversible, so the inverse is the same rule with −δ, sub-steps in reverse
//! order. With M = (P + P′)/2 it reads M = P + (δ/2)·u(M), P′ = 2M − P; M is found by
//! Newton's method to 1e-12 relative.

use super::OpType;
use super::midpoint::newton_update;
use super::rounding as round;
use crate::caption::{at, num, plural};
use crate::explain::Formula;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::{Point, Vec2};
use std::sync::Arc;

/// R / L: how far a tip reaches, in wakes.
pub const WAKE_REACH: f64 = 8.0;
/// Most points of one stylus path.
pub const MAX_STYLUS_POINTS: usize = 2048;
/// Most sub-steps × tips of one stylus op.
pub const MAX_STYLUS_WORK: usize = 4096;
/// Most tips of one stylus.
pub const MAX_STYLUS_TIPS: usize = 256;
/// Newton iterations at most per sub-step (it converges in 3 to 6).
const MAX_NEWTON: usize = 40;

/// A free-hand stroke (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Stylus {
    /// The path the tips follow, design pixels; 2..=[`MAX_STYLUS_POINTS`] points.
    pub path: Arc<[Point]>,
    /// Wake L, design pixels, > 0: the size of the disturbance (a tip reaches 8L).
    pub wake: f64,
    /// Offsets of the tips across the path (along n⊥), design pixels; `None` is one tip
    /// on the path.
    pub tips: Option<Arc<[f64]>>,
}

/// One straight piece of a stylus path, compiled: its sub-steps and tips.
#[derive(Clone, Debug, PartialEq)]
pub struct StylusSegment {
    /// Where the segment starts, design pixels.
    pub start: Point,
    /// Unit direction of travel.
    pub n: Vec2,
    /// Length ℓ, design pixels.
    pub length: f64,
    /// Number of sub-steps N.
    pub steps: u32,
    /// Sub-step length δ = ℓ/N, design pixels.
    pub delta: f64,
    /// Wake L, design pixels.
    pub wake: f64,
    /// Tip offsets along n⊥, design pixels.
    pub tips: Arc<[f64]>,
    /// Smallest and largest tip offset.
    pub tip_range: (f64, f64),
}

impl Stylus {
    /// The tip offsets (one tip at 0 when none are given).
    pub fn tip_offsets(&self) -> Arc<[f64]> {
        self.tips.clone().unwrap_or_else(|| Arc::from([0.0]))
    }

    /// Number of tips.
    pub fn tip_count(&self) -> usize {
        self.tips.as_ref().map_or(1, |t| t.len())
    }

    /// Sub-steps of the whole path (segments of zero length have none).
    pub fn sub_steps(&self) -> usize {
        self.path
            .windows(2)
            .map(|w| sub_steps_of((w[1] - w[0]).hypot(), self.wake))
            .sum()
    }

    /// The path's segments of non-zero length, in order.
    pub fn segments(&self) -> Vec<StylusSegment> {
        let tips = self.tip_offsets();
        let lo = tips.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = tips.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        self.path
            .windows(2)
            .filter_map(|w| {
                let d = w[1] - w[0];
                let length = d.hypot();
                (length > 0.0).then(|| {
                    let steps = sub_steps_of(length, self.wake);
                    StylusSegment {
                        start: w[0],
                        n: d / length,
                        length,
                        steps: steps as u32,
                        delta: length / steps as f64,
                        wake: self.wake,
                        tips: tips.clone(),
                        tip_range: (lo, hi),
                    }
                })
            })
            .collect()
    }

    /// Moves `p` through the whole stroke.
    pub fn forward(&self, p: Point) -> Point {
        self.segments().iter().fold(p, |p, s| s.forward(p))
    }

    /// Undoes [`Stylus::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        self.segments().iter().rev().fold(p, |p, s| s.inverse(p))
    }
}

/// N = max(1, ⌈2ℓ/L⌉) sub-steps for a segment of length ℓ > 0 (0 for ℓ = 0).
pub fn sub_steps_of(length: f64, wake: f64) -> usize {
    if length <= 0.0 {
        return 0;
    }
    let n = (2.0 * length / wake).ceil();
    if n.is_finite() && n >= 1.0 {
        n.min(usize::MAX as f64 / 2.0) as usize
    } else {
        1
    }
}

/// The summed velocity of tips at (0, oᵢ) at local point (x, y) (x along n, y along
/// n⊥, from the sub-step's midpoint) and its Jacobian [∂uₓ/∂x, ∂uₓ/∂y, ∂u_y/∂x,
/// ∂u_y/∂y], all in the local frame.
pub(crate) fn tip_field(x: f64, y: f64, tips: &[f64], wake: f64) -> ([f64; 2], [f64; 4]) {
    let reach = WAKE_REACH * wake;
    let mut u = [0.0; 2];
    let mut j = [0.0; 4];
    for &o in tips {
        let yl = y - o;
        let rho = (x * x + yl * yl).sqrt();
        if rho >= reach {
            continue;
        }
        // g(ρ) = e^{−ρ/L}·c(ρ/R) and its first two derivatives.
        let t = rho / reach;
        let w = 1.0 - t * t;
        let c = w * w * w;
        let c1 = -6.0 * t * w * w;
        let c2 = w * (30.0 * t * t - 6.0);
        let e = (-rho / wake).exp();
        let g = e * c;
        let g1 = e * (-c / wake + c1 / reach);
        let g2 = e * (c / (wake * wake) - 2.0 * c1 / (wake * reach) + c2 / (reach * reach));
        let (ex, ey) = if rho > 0.0 {
            (x / rho, yl / rho)
        } else {
            (0.0, 0.0)
        };
        // ψ = y·g(ρ): first and second derivatives in terms of the unit (ex, ey).
        let psi_x = rho * ex * ey * g1;
        let psi_y = g + rho * ey * ey * g1;
        let psi_xx = ey * (g1 * ey * ey + ex * ex * rho * g2);
        let psi_xy = ex * (g1 * ex * ex + ey * ey * rho * g2);
        let psi_yy = ey * (g1 * (3.0 - ey * ey) + ey * ey * rho * g2);
        u[0] += psi_y;
        u[1] -= psi_x;
        j[0] += psi_xy;
        j[1] += psi_yy;
        j[2] -= psi_xx;
        j[3] -= psi_xy;
    }
    (u, j)
}

/// One implicit-midpoint sub-step in the local frame of its midpoint: solves
/// M = q + h·u(M) by Newton's method and returns 2M − q (h = δ/2 forward, −δ/2 back).
/// A point out of every tip's reach is returned unchanged.
pub(crate) fn sub_step(qx: f64, qy: f64, h: f64, tips: &[f64], wake: f64) -> (f64, f64) {
    let reach2 = (WAKE_REACH * wake).powi(2);
    if tips
        .iter()
        .all(|&o| qx * qx + (qy - o) * (qy - o) >= reach2)
    {
        return (qx, qy);
    }
    solve_sub_step(qx, qy, h, tips, wake)
}

/// [`sub_step`]'s Newton solve, for any point (out of reach it returns the point).
fn solve_sub_step(qx: f64, qy: f64, h: f64, tips: &[f64], wake: f64) -> (f64, f64) {
    let (u, _) = tip_field(qx, qy, tips, wake);
    let (mut mx, mut my) = (qx + h * u[0], qy + h * u[1]);
    let tol = 1e-13 * (wake + qx.abs() + qy.abs());
    for _ in 0..MAX_NEWTON {
        let (u, j) = tip_field(mx, my, tips, wake);
        let [dx, dy] = newton_update([mx, my], [qx, qy], h, u, j);
        mx -= dx;
        my -= dy;
        if dx.abs() + dy.abs() <= tol {
            break;
        }
    }
    (2.0 * mx - qx, 2.0 * my - qy)
}

impl StylusSegment {
    /// R = 8L, design pixels.
    pub fn reach(&self) -> f64 {
        WAKE_REACH * self.wake
    }

    /// n⊥ = (−n.y, n.x).
    pub fn across(&self) -> Vec2 {
        Vec2::new(-self.n.y, self.n.x)
    }

    /// Whether `p` lies where this segment can move it: within R of the path's
    /// rectangle swept by the tips, in the segment's frame.
    pub fn touches(&self, p: Point) -> bool {
        let q = p - self.start;
        let (x, y) = (q.dot(self.n), q.dot(self.across()));
        let r = self.reach();
        x > -r && x < self.length + r && y > self.tip_range.0 - r && y < self.tip_range.1 + r
    }

    /// Moves `p` through the segment's sub-steps in order.
    pub fn forward(&self, p: Point) -> Point {
        self.walk(p, true)
    }

    /// Undoes [`StylusSegment::forward`]: sub-steps in reverse order, each with −δ.
    pub fn inverse(&self, p: Point) -> Point {
        self.walk(p, false)
    }

    /// [`StylusSegment::inverse`] without culling: every sub-step solved, whatever the
    /// distance (the same result; the reference the culled walk is tested and
    /// benchmarked against).
    pub fn inverse_unculled(&self, p: Point) -> Point {
        let nt = self.across();
        let q = p - self.start;
        let (mut x, mut y) = (q.dot(self.n), q.dot(nt));
        let mut moved = false;
        for j in (0..self.steps).rev() {
            let xj = (f64::from(j) + 0.5) * self.delta;
            let (nx, ny) = solve_sub_step(x - xj, y, -0.5 * self.delta, &self.tips, self.wake);
            if nx != x - xj || ny != y {
                (x, y) = (xj + nx, ny);
                moved = true;
            }
        }
        if !moved {
            return p;
        }
        self.start + self.n * x + nt * y
    }

    fn walk(&self, p: Point, forward: bool) -> Point {
        if !self.touches(p) {
            return p;
        }
        let q = p - self.start;
        let nt = self.across();
        let (mut x, mut y) = (q.dot(self.n), q.dot(nt));
        let (r, delta, steps) = (self.reach(), self.delta, i64::from(self.steps));
        let h = if forward { 0.5 * delta } else { -0.5 * delta };
        let mut moved = false;
        let mut step = |j: i64, x: &mut f64, y: &mut f64| {
            let xj = (j as f64 + 0.5) * delta;
            if (*x - xj).abs() < r {
                let (nx, ny) = sub_step(*x - xj, *y, h, &self.tips, self.wake);
                if nx != *x - xj || ny != *y {
                    (*x, *y) = (xj + nx, ny);
                    moved = true;
                }
            }
        };
        if forward {
            // Sub-steps whose midpoint lies R or more before x cannot reach the point.
            let mut j = (((x - r) / delta - 0.5).floor() as i64).clamp(0, steps);
            while j < steps && (j as f64 + 0.5) * delta < x + r {
                step(j, &mut x, &mut y);
                j += 1;
            }
        } else {
            let mut j = (((x + r) / delta - 0.5).ceil() as i64).clamp(-1, steps - 1);
            while j >= 0 && (j as f64 + 0.5) * delta > x - r {
                step(j, &mut x, &mut y);
                j -= 1;
            }
        }
        if !moved {
            return p;
        }
        self.start + self.n * x + nt * y
    }
}

impl OpType for Stylus {
    const FIELDS: &'static [&'static str] = &["type", "path", "wake", "tips"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (path, wake) = (r.points("path"), r.number("wake"));
        let tips = if r.has("tips") {
            r.numbers("tips").map(Some)
        } else {
            Some(None)
        };
        Some(Stylus {
            path: path?,
            wake: wake?,
            tips: tips?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.points("path", &self.path);
        w.number("wake", self.wake);
        if let Some(tips) = &self.tips {
            w.numbers("tips", tips);
        }
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        let path_ok = c.count("path", self.path.len(), 2, MAX_STYLUS_POINTS, "points");
        let mut finite = path_ok;
        for (k, &p) in self.path.iter().enumerate() {
            let ok =
                c.finite(&format!("path[{k}][0]"), p.x) & c.finite(&format!("path[{k}][1]"), p.y);
            finite &= ok;
        }
        c.positive("wake", self.wake);
        let mut tips_ok = true;
        if let Some(tips) = &self.tips {
            tips_ok = c.count("tips", tips.len(), 1, MAX_STYLUS_TIPS, "tip offsets");
            for (k, &o) in tips.iter().enumerate() {
                tips_ok &= c.finite(&format!("tips[{k}]"), o);
            }
        }
        if finite && tips_ok && self.wake.is_finite() && self.wake > 0.0 {
            let work = self.sub_steps().saturating_mul(self.tip_count());
            if work > MAX_STYLUS_WORK {
                c.push(
                    "path",
                    format!(
                        "needs {} sub-steps × {} tip(s) = {work}, more than {MAX_STYLUS_WORK}; use a larger wake or a shorter path",
                        self.sub_steps(),
                        self.tip_count()
                    ),
                );
            }
        }
    }

    fn round(&mut self) {
        self.path = self.path.iter().map(|&p| round::point(p)).collect();
        self.wake = round::positive(self.wake);
        self.tips = self
            .tips
            .as_ref()
            .map(|t| t.iter().map(|&o| round::length(o)).collect());
    }

    /// A stroke is drawn along its path: the first fraction `s` of its length.
    fn scale(&mut self, s: f64) {
        self.path = path_part(&self.path, s);
    }

    fn caption(&self, _tag: &str) -> String {
        let len: f64 = self.path.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
        format!(
            "stylus drawn {} px from {} with {}, wake {} px",
            num(len),
            at(self.path[0]),
            plural(self.tip_count(), "tip", "tips"),
            num(self.wake)
        )
    }

    fn label(&self, _tag: &str) -> String {
        if self.tip_count() > 1 {
            format!("stylus of {} tips", self.tip_count())
        } else {
            "stylus stroke".to_owned()
        }
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "each sub-step δ along the path: P′ = P + δ·u((P + P′)/2), u from \
                 ψ = y·e^(−ρ/L)·(1 − (ρ/8L)²)³ around every tip"
                .into(),
            inverse: "the sub-steps undone newest first with −δ".into(),
            values: format!(
                "L = {}, {} sub-steps, {} tip(s)",
                num(self.wake),
                self.sub_steps(),
                self.tip_count()
            ),
            symbols: "δ: one sub-step along the path (px), u: the flow's direction, ψ: \
                 the stream function it follows, y: the distance across the path, ρ: the distance from a \
                 tip (px), L: the wake, how far the flow reaches (px)"
                .into(),
            area_preserving: true,
        }
    }
}

/// The first fraction `s` (0..=1) of a path's length (at least two points).
fn path_part(path: &[Point], s: f64) -> Arc<[Point]> {
    let total: f64 = path.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
    let mut left = total * s.clamp(0.0, 1.0);
    let mut out = vec![path[0]];
    for w in path.windows(2) {
        let len = (w[1] - w[0]).hypot();
        if left >= len {
            out.push(w[1]);
            left -= len;
        } else {
            out.push(w[0] + (w[1] - w[0]) * (left / len));
            break;
        }
    }
    if out.len() < 2 {
        out.push(path[0]);
    }
    out.into()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::SplitMix64;

    /// The culling (the segment's rectangle, the sub-steps' window) changes nothing.
    #[test]
    fn the_culled_walk_equals_the_unculled_one() {
        let s = Stylus {
            path: Arc::from([
                Point::new(10.0, 10.0),
                Point::new(120.0, 60.0),
                Point::new(60.0, 150.0),
            ]),
            wake: 3.0,
            tips: Some(Arc::from([-20.0, 0.0, 15.0])),
        };
        let mut rng = SplitMix64(5);
        let mut moved = 0;
        for seg in s.segments() {
            for _ in 0..400 {
                let p = Point::new(rng.range(-40.0, 200.0), rng.range(-40.0, 200.0));
                let (a, b) = (seg.inverse(p), seg.inverse_unculled(p));
                assert!((a - b).hypot() <= 1e-9, "{p:?}: {a:?} vs {b:?}");
                moved += usize::from(a != p);
            }
        }
        assert!(
            moved > 50,
            "too few points near the path to mean anything: {moved}"
        );
    }
}
