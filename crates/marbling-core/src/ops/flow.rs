//! Flow: the tank streams along a curl noise for a while (Kung 2019, ch. 5), exactly.
//!
//! The stream function is ψ(P) = U·n(P)/(2πf): n a Perlin or value fBm of unit
//! variance (`marbling-noise`'s, in design pixels), f its first octave's frequency and U
//! the strength, so points move about U design px per unit time. The velocity
//! u = (∂ψ/∂y, −∂ψ/∂x) is divergence free. The op moves each point along u for time T in
//! N equal sub-steps Δt = T/N of the implicit midpoint rule P′ = P + Δt·u((P + P′)/2):
//! symplectic, so exactly area preserving, and time reversible, so the inverse is the
//! same rule with −Δt. N is the least count with |u|·|Δt| ≤ [`FLOW_STEP_PX`] for the
//! bound of |u| over the plane. With M = (P + P′)/2 a sub-step reads
//! M = P + (Δt/2)·u(M), P′ = 2M − P; M is found by Newton's method to 1e-13 relative.

use super::OpType;
use super::midpoint::newton_update;
use super::rounding as round;
use crate::caption::num;
use crate::explain::Formula;
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::Point;
use marbling_noise::{Basis, Fbm, Fbm64, FbmParams, NoiseSpec, Source};
use std::f64::consts::TAU;

/// Most sub-steps of one flow.
pub const MAX_FLOW_STEPS: usize = 4096;
/// Longest move of one sub-step, design pixels.
pub const FLOW_STEP_PX: f64 = 0.5;
/// Newton iterations at most per sub-step (from an explicit first guess it converges
/// in 2 to 4).
const MAX_NEWTON: usize = 30;

/// A flow along a curl noise (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Flow {
    /// The noise n: an untiled Perlin or value fBm, design pixels.
    pub noise: FbmParams,
    /// U, design pixels per unit time (any sign).
    pub strength: f64,
    /// T, units of time (any sign; −T undoes T).
    pub time: f64,
}

/// A flow compiled for walking: the f64 noise, ψ's factor and the sub-steps.
#[derive(Clone, Debug, PartialEq)]
pub struct FlowField {
    fbm: Fbm64,
    /// U/(2πf): ψ = factor·n.
    pub factor: f64,
    /// Sub-steps N.
    pub steps: u32,
    /// Δt = T/N.
    pub dt: f64,
}

impl Flow {
    /// The f32 fBm of the noise (the GPU's octaves).
    pub fn fbm(&self) -> Fbm {
        Fbm::new(FbmParams {
            period: None,
            ..self.noise
        })
    }

    /// U/(2πf).
    fn factor(&self) -> f64 {
        self.strength / (TAU * f64::from(self.noise.frequency))
    }

    /// A bound of |u| over the plane, design px per unit time: |U|/(2πf) times the
    /// noise's gradient bound ([`Fbm64::gradient_bound`]).
    pub fn speed_bound(&self) -> f64 {
        self.factor().abs() * Fbm64::new(&self.fbm()).gradient_bound()
    }

    /// The longest |T| whose sub-steps stay within [`MAX_FLOW_STEPS`], less 0.1 % so
    /// that rounding never pushes a flow of that time over (∞ when U is 0).
    pub fn longest_time(&self) -> f64 {
        0.999 * MAX_FLOW_STEPS as f64 * FLOW_STEP_PX / self.speed_bound()
    }

    /// N: the least count with [`Flow::speed_bound`]·|T|/N ≤ [`FLOW_STEP_PX`] (0 when T
    /// or U is 0; saturating for values no valid flow holds).
    pub fn sub_steps(&self) -> usize {
        let n = (self.time.abs() * self.speed_bound() / FLOW_STEP_PX).ceil();
        if n.is_nan() {
            usize::MAX
        } else {
            n.min(usize::MAX as f64 / 2.0) as usize
        }
    }

    /// The compiled flow (sub-steps clamped to [`MAX_FLOW_STEPS`]).
    pub fn field(&self) -> FlowField {
        let steps = self.sub_steps().min(MAX_FLOW_STEPS) as u32;
        FlowField {
            fbm: Fbm64::new(&self.fbm()),
            factor: self.factor(),
            steps,
            dt: if steps == 0 {
                0.0
            } else {
                self.time / f64::from(steps)
            },
        }
    }

    /// Moves `p` along the flow for time T.
    pub fn forward(&self, p: Point) -> Point {
        self.field().forward(p)
    }

    /// Undoes [`Flow::forward`].
    pub fn inverse(&self, p: Point) -> Point {
        self.field().inverse(p)
    }

    /// The noise as a spec of the `marbling-noise` format.
    pub fn noise_spec(&self) -> NoiseSpec {
        NoiseSpec::from_source(Source::Fbm(self.noise))
    }
}

impl FlowField {
    /// The velocity u at (x, y) and its Jacobian [∂uₓ/∂x, ∂uₓ/∂y, ∂u_y/∂x, ∂u_y/∂y].
    pub fn velocity(&self, x: f64, y: f64) -> ([f64; 2], [f64; 4]) {
        let j = self.fbm.jet(x, y);
        let c = self.factor;
        (
            [c * j.dy, -c * j.dx],
            [c * j.dxy, c * j.dyy, -c * j.dxx, -c * j.dxy],
        )
    }

    /// The stream function ψ at (x, y), design px² per unit time.
    pub fn stream(&self, x: f64, y: f64) -> f64 {
        self.factor * self.fbm.jet(x, y).n
    }

    /// One implicit-midpoint sub-step of `h` = ±Δt/2: M = q + h·u(M) by Newton's method
    /// from the explicit guess M = q + h·u(q), then 2M − q. `last` is the velocity and
    /// Jacobian of the previous sub-step's last Newton iteration and where they were
    /// taken: u(q) is then extrapolated from them (exact to second order, which Newton
    /// corrects) instead of evaluated, and this step's are left there for the next.
    fn sub_step(&self, qx: f64, qy: f64, h: f64, last: &mut Option<Sample>) -> (f64, f64) {
        let u = match *last {
            Some(Sample { at, u, j }) => {
                let (dx, dy) = (qx - at[0], qy - at[1]);
                [u[0] + j[0] * dx + j[1] * dy, u[1] + j[2] * dx + j[3] * dy]
            }
            None => self.velocity(qx, qy).0,
        };
        let (mut mx, mut my) = (qx + h * u[0], qy + h * u[1]);
        // Newton converges quadratically: after an update of dx the error is about
        // |h·D²u|·dx², so once an update is ≤ 1e-9 px the next would be far below f64
        // rounding (absolute, not relative to |q|: the map must stay smooth to the
        // finite differences of the area tests wherever the point is).
        let tol = 1e-9 + 1e-15 * (qx.abs() + qy.abs());
        for _ in 0..MAX_NEWTON {
            let (u, j) = self.velocity(mx, my);
            *last = Some(Sample { at: [mx, my], u, j });
            let [dx, dy] = newton_update([mx, my], [qx, qy], h, u, j);
            mx -= dx;
            my -= dy;
            let update = dx.abs() + dy.abs();
            if update <= tol || update.is_nan() {
                break;
            }
        }
        (2.0 * mx - qx, 2.0 * my - qy)
    }

    fn walk(&self, p: Point, h: f64) -> Point {
        let (mut x, mut y) = (p.x, p.y);
        let mut last = None;
        for _ in 0..self.steps {
            (x, y) = self.sub_step(x, y, h, &mut last);
        }
        Point::new(x, y)
    }

    /// Moves `p` through the N sub-steps.
    pub fn forward(&self, p: Point) -> Point {
        self.walk(p, 0.5 * self.dt)
    }

    /// Undoes [`FlowField::forward`]: the same sub-steps with −Δt (the field does not
    /// change with time, so their order does not matter).
    pub fn inverse(&self, p: Point) -> Point {
        self.walk(p, -0.5 * self.dt)
    }

    /// Where `p` goes over the first fraction `e` (0..=1) of the flow: about `points` + 1
    /// points from `p` on, evenly spaced in time (the step player draws them).
    pub fn path(&self, p: Point, e: f64, points: u32) -> Vec<Point> {
        let total = (e.clamp(0.0, 1.0) * f64::from(self.steps)).round() as u32;
        let every = (total / points.max(1)).max(1);
        let (mut x, mut y) = (p.x, p.y);
        let mut out = vec![p];
        let mut last = None;
        for i in 0..total {
            (x, y) = self.sub_step(x, y, 0.5 * self.dt, &mut last);
            if (i + 1) % every == 0 || i + 1 == total {
                out.push(Point::new(x, y));
            }
        }
        out
    }

    /// The noise's octaves as the GPU reads them: (frequency, amplitude/σ) per octave.
    pub fn octaves(&self) -> &[(f64, f64, u32)] {
        self.fbm.octaves()
    }

    /// The noise's basis.
    pub fn basis(&self) -> Basis {
        self.fbm.basis()
    }
}

/// The fBm a flow follows, if `spec` is one: a `perlin` or `value` spec alone; else why
/// not.
pub fn flow_noise(spec: &NoiseSpec) -> Result<FbmParams, &'static str> {
    match spec.source {
        Source::Fbm(params) if spec.is_plain() => Ok(params),
        Source::Fbm(_) => {
            Err("a flow's noise is the fBm alone: no tile, transfer, layers, palette or blend")
        }
        _ => Err("must be a \"perlin\" or \"value\" noise (a flow follows the curl of an fBm)"),
    }
}

/// The velocity and its Jacobian where Newton last took them.
#[derive(Clone, Copy, Debug)]
struct Sample {
    at: [f64; 2],
    u: [f64; 2],
    j: [f64; 4],
}

/// "Perlin" or "value".
fn basis_name(b: Basis) -> &'static str {
    match b {
        Basis::Perlin => "Perlin",
        Basis::Value => "value",
    }
}

impl OpType for Flow {
    const FIELDS: &'static [&'static str] = &["type", "noise", "strength", "time"];

    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let (spec, strength, time) = (r.noise("noise"), r.number("strength"), r.number("time"));
        let noise = spec.and_then(|spec| {
            flow_noise(&spec)
                .map_err(|message| r.push("noise", message))
                .ok()
        });
        Some(Flow {
            noise: noise?,
            strength: strength?,
            time: time?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.noise("noise", &self.noise_spec());
        w.number("strength", self.strength);
        w.number("time", self.time);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        let ok = c.finite("strength", self.strength) & c.finite("time", self.time);
        let steps = if ok { self.sub_steps() } else { 0 };
        if steps > MAX_FLOW_STEPS {
            c.push(
                "time",
                format!(
                    "needs {steps} sub-steps of at most {FLOW_STEP_PX} px, more than {MAX_FLOW_STEPS}; use a shorter time, a smaller strength or a larger noise"
                ),
            );
        }
    }

    fn round(&mut self) {
        self.strength = round::length(self.strength);
        self.time = round::time(self.time);
    }

    /// A flow eases in over its time.
    fn scale(&mut self, s: f64) {
        self.time *= s;
    }

    fn caption(&self, _tag: &str) -> String {
        format!(
            "flow along {} noise of {} px ({} octave{}), strength {} px, for time {}",
            basis_name(self.noise.basis),
            num(1.0 / f64::from(self.noise.frequency)),
            self.noise.octaves,
            if self.noise.octaves == 1 { "" } else { "s" },
            num(self.strength),
            num(self.time)
        )
    }

    fn label(&self, _tag: &str) -> String {
        "flow".to_owned()
    }

    fn formula(&self, _tag: &str) -> Formula {
        Formula {
            forward: "each of N sub-steps Δt = T/N: P′ = P + Δt·u((P + P′)/2), \
                      u = (∂ψ/∂y, −∂ψ/∂x), ψ = U·n(P)/(2πf)"
                .into(),
            inverse: "the same sub-steps with −Δt".into(),
            values: format!(
                "U = {}, T = {}, f = 1/{} px, N = {}",
                num(self.strength),
                num(self.time),
                num(1.0 / f64::from(self.noise.frequency)),
                self.sub_steps()
            ),
            symbols: "n: the noise (unit variance), f: its frequency, U: the strength \
                      (px per unit time), T: the time, ψ: the stream function, u: the \
                      velocity along its level lines, N: sub-steps of at most ½ px"
                .into(),
            area_preserving: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::synth::SplitMix64;

    pub(crate) fn sample() -> Flow {
        Flow {
            noise: FbmParams {
                frequency: 1.0 / 64.0,
                octaves: 3,
                seed: 7,
                ..FbmParams::default()
            },
            strength: 20.0,
            time: 1.5,
        }
    }

    /// inverse∘forward = id to 1e-9 relative, the Jacobian is 1 ± 1e-6, and points
    /// move (so the test means something).
    #[test]
    fn inverse_undoes_forward_and_area_is_kept() {
        for basis in [Basis::Perlin, Basis::Value] {
            let mut f = sample();
            f.noise.basis = basis;
            let field = f.field();
            assert!(field.steps > 10, "{}", field.steps);
            let mut rng = SplitMix64(3);
            let mut moved = 0.0_f64;
            for _ in 0..40 {
                let p = Point::new(rng.range(0.0, 400.0), rng.range(0.0, 300.0));
                let q = field.forward(p);
                moved = moved.max((q - p).hypot());
                let back = field.inverse(q);
                assert!(
                    (back - p).hypot() <= 1e-9 * (1.0 + p.to_vec2().hypot()),
                    "{basis:?} {p:?} → {q:?} → {back:?}"
                );
                // Central differences of 1e-5 px: their truncation error (h²) and
                // rounding error (ε/h) both stay under the budget, as in
                // tests/it/ops_properties.rs.
                let h = 1e-5;
                let dx = (field.forward(p + (h, 0.0)) - field.forward(p - (h, 0.0))) / (2.0 * h);
                let dy = (field.forward(p + (0.0, h)) - field.forward(p - (0.0, h))) / (2.0 * h);
                let jac = dx.x * dy.y - dx.y * dy.x;
                let largest = [dx.x, dx.y, dy.x, dy.y]
                    .map(f64::abs)
                    .into_iter()
                    .fold(0.0, f64::max);
                let budget = 1e-6 * (1.0 + largest);
                assert!(
                    (jac - 1.0).abs() < budget,
                    "{basis:?} Jacobian {jac} at {p:?}"
                );
            }
            assert!(
                moved > 5.0,
                "{basis:?}: the flow moved points only {moved} px"
            );
        }
    }

    /// Every sub-step moves a point at most ½ px, and the count is the least that does
    /// for the bound (halving it would break the rule somewhere in the bound's sense).
    #[test]
    fn sub_steps_move_at_most_half_a_pixel() {
        let f = sample();
        let field = f.field();
        let mut rng = SplitMix64(8);
        let mut most = 0.0_f64;
        for _ in 0..2000 {
            let p = Point::new(rng.range(0.0, 500.0), rng.range(0.0, 500.0));
            let (x, y) = field.sub_step(p.x, p.y, 0.5 * field.dt, &mut None);
            most = most.max((x - p.x).hypot(y - p.y));
        }
        assert!(most <= FLOW_STEP_PX, "{most}");
        assert!(
            most > 0.3 * FLOW_STEP_PX,
            "{most}: the sub-steps are needlessly small"
        );
        let reversed = Flow {
            time: -f.time,
            ..f.clone()
        };
        assert_eq!(reversed.sub_steps(), f.sub_steps());
    }

    /// −T undoes T, and T = 0 or U = 0 moves nothing.
    #[test]
    fn reversed_time_undoes_and_zero_is_identity() {
        let f = sample();
        let back = Flow {
            time: -f.time,
            ..f.clone()
        };
        let p = Point::new(123.4, 56.7);
        let q = back.forward(f.forward(p));
        assert!((q - p).hypot() < 1e-9, "{q:?}");
        for still in [
            Flow {
                time: 0.0,
                ..f.clone()
            },
            Flow { strength: 0.0, ..f },
        ] {
            assert_eq!(still.sub_steps(), 0);
            assert_eq!(still.forward(p), p);
        }
    }
}
