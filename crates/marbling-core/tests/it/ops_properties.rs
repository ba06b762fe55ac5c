//! Every op is a homeomorphism: inverse ∘ forward = identity (1e-9 relative), and it
//! preserves area: the forward map's Jacobian determinant is 1 (within 1e-6) — except
//! the jiggle, whose determinant is 1 + kA·cos φ (checked against that formula).

use marbling_core::{
    Back, Circular, Comb, Drop, DropSet, Flow, Jiggle, Op, Point, Radii, Rake, Rgb8, Shift, Spray,
    Stylus, Tine, Turn, Vec2, Vortex, Wavy,
};
use marbling_noise::{Basis, FbmParams};
use proptest::prelude::*;
use std::f64::consts::TAU;
use std::sync::Arc;

const INK: Rgb8 = Rgb8::new(10, 20, 30);

fn coord() -> impl Strategy<Value = f64> {
    -500.0..1500.0f64
}

fn point() -> impl Strategy<Value = Point> {
    (coord(), coord()).prop_map(|(x, y)| Point::new(x, y))
}

fn direction() -> impl Strategy<Value = Vec2> {
    (0.0..std::f64::consts::TAU, 0.1..10.0f64).prop_map(|(a, len)| Vec2::from_angle(a) * len)
}

fn op() -> impl Strategy<Value = Op> {
    let alpha = -200.0..200.0f64;
    let lambda = 0.5..100.0f64;
    prop_oneof![
        (point(), 1.0..200.0f64).prop_map(|(center, radius)| Op::Drop(Drop {
            center,
            radius,
            color: INK
        })),
        (point(), 0.5..20.0f64).prop_map(|(center, radius)| Op::Spray(Spray {
            center,
            radius,
            color: INK
        })),
        (point(), direction(), alpha.clone(), lambda.clone()).prop_map(
            |(origin, direction, alpha, lambda)| Op::Tine(Tine {
                origin,
                direction,
                alpha,
                lambda
            })
        ),
        (
            point(),
            direction(),
            2.0..200.0f64,
            alpha.clone(),
            lambda.clone()
        )
            .prop_map(
                |(origin, direction, spacing, alpha, lambda)| Op::Rake(Rake {
                    origin,
                    direction,
                    spacing,
                    alpha,
                    lambda
                })
            ),
        (
            0.0..std::f64::consts::TAU,
            -60.0..60.0f64,
            5.0..500.0f64,
            -10.0..10.0f64
        )
            .prop_map(|(angle, amplitude, wavelength, phase)| Op::Wavy(Wavy {
                angle,
                amplitude,
                wavelength,
                phase
            })),
        (point(), 1.0..400.0f64, alpha.clone(), lambda.clone()).prop_map(
            |(center, radius, alpha, lambda)| Op::Circular(Circular {
                center,
                radius,
                alpha,
                lambda
            })
        ),
        (point(), alpha.clone(), lambda.clone()).prop_map(|(center, alpha, lambda)| Op::Vortex(
            Vortex {
                center,
                alpha,
                lambda
            }
        )),
        v3_op(),
    ]
}

/// The ops schema v3 adds.
fn v3_op() -> impl Strategy<Value = Op> {
    let alpha = -200.0..200.0f64;
    let lambda = 0.5..100.0f64;
    prop_oneof![
        (direction(), 0.0..40.0f64).prop_map(|(d, k)| Op::Shift(Shift { offset: d * k })),
        (point(), -10.0..10.0f64).prop_map(|(center, angle)| Op::Turn(Turn { center, angle })),
        (
            point(),
            direction(),
            prop::collection::vec(-300.0..300.0f64, 1..8),
            alpha,
            lambda
        )
            .prop_map(|(origin, direction, tines, alpha, lambda)| Op::Comb(Comb {
                origin,
                direction,
                tines: tines.into(),
                alpha,
                lambda
            })),
        (
            prop::collection::vec(point(), 1..5),
            1.0..100.0f64,
            any::<bool>()
        )
            .prop_map(|(centers, radius, spray)| {
                let set = DropSet {
                    centers: centers.into(),
                    radii: Radii::One(radius),
                    colors: Arc::from([INK, Rgb8::new(200, 100, 0)]),
                };
                if spray {
                    Op::Sprays(set)
                } else {
                    Op::Drops(set)
                }
            }),
        (
            0.0..TAU,
            5.0..500.0f64,
            -0.95..0.95f64,
            -60.0..60.0f64,
            -10.0..10.0f64
        )
            .prop_map(|(angle, wavelength, ka, across, phase)| Op::Jiggle(Jiggle {
                angle,
                wavelength,
                along: ka * wavelength / TAU,
                across,
                phase
            })),
        stylus(),
        flow(),
    ]
}

/// A stroke of 2..=5 points from somewhere on the sheet, one tip or up to four.
fn stylus() -> impl Strategy<Value = Op> {
    (
        point(),
        prop::collection::vec((0.0..TAU, 1.0..200.0f64), 1..5),
        2.0..40.0f64,
        prop::option::of(prop::collection::vec(-50.0..50.0f64, 1..4)),
    )
        .prop_map(|(start, steps, wake, tips)| {
            let mut at = start;
            let mut path = vec![start];
            for (a, len) in steps {
                at += Vec2::from_angle(a) * len;
                path.push(at);
            }
            Op::Stylus(Stylus {
                path: path.into(),
                wake,
                tips: tips.map(Into::into),
            })
        })
}

/// A flow along Perlin or value noise whose finest octave is 20–200 px (1–3 octaves),
/// for a time of either sign (a few hundred sub-steps at most). Finer noise streamed
/// longer is chaotic: points 1e-5 px apart part by far more than the map's smoothness
/// lets central differences measure its Jacobian (det J read as 0.9991 for an octave of
/// 3 px stretched 57×), so such flows are left to the round trip.
fn flow() -> impl Strategy<Value = Op> {
    (
        prop::bool::ANY,
        20.0..200.0f32,
        1..4u32,
        any::<u32>(),
        -20.0..20.0f64,
        -1.5..1.5f64,
    )
        .prop_map(|(perlin, finest, octaves, seed, strength, time)| {
            Op::Flow(Flow {
                noise: FbmParams {
                    basis: if perlin { Basis::Perlin } else { Basis::Value },
                    frequency: 1.0 / (finest * (1 << (octaves - 1)) as f32),
                    octaves,
                    seed,
                    ..FbmParams::default()
                },
                strength,
                time,
            })
        })
}

/// Points where an op is hard to invert: near its centre (`eps` × its size away), on its
/// tine lines. Closer than about √ε·r to a drop centre, f64 cannot tell the forward image
/// from the drop's circle itself (|P' − C|² = r² + ρ²), so that is where "near" stops.
fn tricky_point(op: &Op, t: f64, eps: f64) -> Point {
    match op {
        Op::Drop(Drop { center, radius, .. }) | Op::Spray(Spray { center, radius, .. }) => {
            *center + Vec2::from_angle(t * 7.0) * (eps * radius)
        }
        Op::Circular(Circular { center, lambda, .. })
        | Op::Vortex(Vortex { center, lambda, .. }) => {
            *center + Vec2::from_angle(t * 7.0) * (eps * lambda)
        }
        Op::Tine(Tine {
            origin, direction, ..
        }) => *origin + direction.normalize() * (t * 300.0),
        Op::Rake(r) => {
            let m = r.direction.normalize();
            r.origin + m * (t * 300.0) + Vec2::new(-m.y, m.x) * (r.spacing * (t * 10.0).round())
        }
        Op::Wavy(_) | Op::Shift(_) | Op::Turn(_) | Op::Jiggle(_) | Op::Flow(_) => {
            Point::new(t * 100.0, eps)
        }
        Op::Comb(c) => {
            let m = c.direction.normalize();
            let k = ((t + 1.0) * 10.0) as usize % c.tines.len();
            c.origin + m * (t * 300.0) + Vec2::new(-m.y, m.x) * (c.tines[k] + eps)
        }
        Op::Drops(d) | Op::Sprays(d) => {
            d.centers[0] + Vec2::from_angle(t * 7.0) * (eps * d.radius(0))
        }
        Op::Stylus(st) => {
            let (a, b) = (st.path[0], st.path[1]);
            a + (b - a) * ((t + 1.0) / 2.0) + Vec2::from_angle(t * 7.0) * (eps * st.wake)
        }
    }
}

fn round_trip(op: &Op, p: Point) -> Result<(), TestCaseError> {
    let q = op.forward(p);
    let back = match op.inverse(q) {
        Back::Moved(b) => b,
        // A spray covers but does not move: the forward image is the point itself.
        Back::Ink(_) if matches!(op, Op::Spray(_) | Op::Sprays(_)) => return Ok(()),
        Back::Ink(_) => {
            return Err(TestCaseError::fail(format!(
                "{op:?}: forward({p:?}) = {q:?} lands in ink"
            )));
        }
    };
    let scale = p.to_vec2().hypot().max(1.0);
    let err = (back - p).hypot() / scale;
    // A swirl turns P by θ(ρ), ρ = |P − C|; ρ is known to |P|·ε, so θ carries a relative
    // error of |P|·ε/ρ and the point one of θ·|P|·ε: huge next to a strong swirl's centre.
    let budget = 1e-9 + 8.0 * swirl_angle(op, p).abs() * f64::EPSILON;
    prop_assert!(
        err <= budget,
        "{op:?}: {p:?} -> {q:?} -> {back:?}, relative error {err:e} (budget {budget:e})"
    );
    Ok(())
}

/// A point 1e-5 px from a strong vortex's centre comes back 1.7e-6 px off (θ ≈ 1.6e7
/// rad): inside the swirl budget, outside the plain 1e-9 one.
#[test]
fn the_swirl_budget_covers_a_strong_vortex_centre() {
    let op = Op::Vortex(Vortex {
        center: Point::new(-356.9847327270762, 1102.6199514278621),
        alpha: 154.15406815036633,
        lambda: 0.9532908675512324,
    });
    let p = Point::new(-356.9847227019945, 1102.6199514278621);
    let Back::Moved(back) = op.inverse(op.forward(p)) else {
        panic!("a vortex lays no ink");
    };
    let err = (back - p).hypot() / p.to_vec2().hypot();
    assert!(err > 1e-9, "the plain budget would pass: {err:e}");
    assert!(round_trip(&op, p).is_ok(), "{err:e}");
}

/// The angle a vortex or circular comb turns `p` by (radians; 0 for other ops).
fn swirl_angle(op: &Op, p: Point) -> f64 {
    match op {
        Op::Vortex(v) => {
            let rho = (p - v.center).hypot();
            v.alpha * v.lambda / ((rho + v.lambda) * rho)
        }
        Op::Circular(c) => {
            let rho = (p - c.center).hypot();
            c.alpha * c.lambda / (((rho - c.radius).abs() + c.lambda) * rho)
        }
        _ => 0.0,
    }
}

/// Forward-map Jacobian by central differences: its determinant, and its largest entry
/// in magnitude.
fn jacobian(op: &Op, p: Point, h: f64) -> (f64, f64) {
    let fx = (op.forward(p + Vec2::new(h, 0.0)) - op.forward(p - Vec2::new(h, 0.0))) / (2.0 * h);
    let fy = (op.forward(p + Vec2::new(0.0, h)) - op.forward(p - Vec2::new(0.0, h))) / (2.0 * h);
    let largest = [fx.x, fx.y, fy.x, fy.y]
        .into_iter()
        .fold(0.0_f64, |m, v| m.max(v.abs()));
    (fx.x * fy.y - fx.y * fy.x, largest)
}

/// True when `p` is within `margin` of a place where the map is not smooth (centres,
/// tine lines, rake midlines, the circular comb's strongest circle).
fn near_singular(op: &Op, p: Point, margin: f64) -> bool {
    let line_dist = |origin: Point, dir: Vec2| {
        let m = dir.normalize();
        ((p - origin).dot(Vec2::new(-m.y, m.x))).abs()
    };
    match op {
        Op::Drop(d) => (p - d.center).hypot() < margin.max(1e-3 * d.radius),
        Op::Spray(_) | Op::Wavy(_) => false,
        Op::Tine(t) => line_dist(t.origin, t.direction) < margin,
        Op::Rake(r) => {
            let d = line_dist(r.origin, r.direction) % (r.spacing / 2.0);
            d < margin || r.spacing / 2.0 - d < margin
        }
        Op::Circular(c) => {
            let rho = (p - c.center).hypot();
            rho < 1.0 || (rho - c.radius).abs() < margin
        }
        Op::Vortex(v) => (p - v.center).hypot() < 1.0,
        Op::Shift(_) | Op::Turn(_) | Op::Jiggle(_) | Op::Sprays(_) => false,
        Op::Comb(c) => {
            // Tine lines, and lines halfway between two tines (where the nearest changes).
            let m = c.direction.normalize();
            let s = (p - c.origin).dot(Vec2::new(-m.y, m.x));
            let mut d: Vec<f64> = c.tines.iter().map(|o| (s - o).abs()).collect();
            d.sort_by(f64::total_cmp);
            d[0] < margin || (d.len() > 1 && d[1] - d[0] < 2.0 * margin)
        }
        Op::Drops(d) => d
            .centers
            .iter()
            .any(|&c| (p - c).hypot() < margin.max(1e-3 * d.radius(0))),
        Op::Stylus(_) | Op::Flow(_) => false,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn inverse_undoes_forward(op in op(), p in point()) {
        round_trip(&op, p)?;
    }

    #[test]
    fn inverse_undoes_forward_near_centres_and_tine_lines(op in op(), t in -1.0..1.0f64, e in -5.0..1.0f64) {
        round_trip(&op, tricky_point(&op, t, 10f64.powf(e)))?;
    }

    #[test]
    fn forward_undoes_inverse_outside_ink(op in op(), p in point()) {
        if let Back::Moved(q) = op.inverse(p) {
            let again = op.forward(q);
            let err = (again - p).hypot() / p.to_vec2().hypot().max(1.0);
            prop_assert!(err <= 1e-9, "{op:?}: {p:?} -> {q:?} -> {again:?}");
        }
    }

    #[test]
    fn forward_preserves_area(op in op(), p in point()) {
        let h = 1e-5;
        prop_assume!(!near_singular(&op, p, 0.05));
        let (det, largest) = jacobian(&op, p, h);
        // The jiggle is the one op that is not area preserving: 1 + kA·cos φ.
        let expected = match &op {
            Op::Jiggle(j) => j.jacobian(p),
            _ => 1.0,
        };
        // Each difference quotient carries a rounding error of about ε·|p|/h (≈ 3e-8 at
        // |p| = 1,400), multiplied in the determinant by the other entries: a steep comb
        // (λ < 1, α λ / (d + λ)² in the hundreds) legitimately lands near 1e-6, so the
        // budget grows with the largest entry. A map that is not area preserving is off
        // by far more (see the test below).
        let budget = 1e-6 * (1.0 + largest);
        prop_assert!((det - expected).abs() <= budget, "{op:?} at {p:?}: det J = {det}, expected {expected}, budget {budget:e}");
    }
}

#[test]
fn jacobian_check_detects_a_non_area_preserving_map() {
    // A drop's forward map with the square root left out stretches area: the same
    // finite-difference check must see a determinant far from 1.
    let c = Point::new(0.0, 0.0);
    let r2: f64 = 50.0 * 50.0;
    let f = |p: Point| c + (p - c) * (1.0 + r2 / (p - c).hypot2());
    let (p, h) = (Point::new(80.0, 30.0), 1e-3);
    let fx = (f(p + Vec2::new(h, 0.0)) - f(p - Vec2::new(h, 0.0))) / (2.0 * h);
    let fy = (f(p + Vec2::new(0.0, h)) - f(p - Vec2::new(0.0, h))) / (2.0 * h);
    let det = fx.x * fy.y - fx.y * fy.x;
    assert!((det - 1.0).abs() > 0.01, "det {det}");
}

#[test]
fn formulas_match_design_md_at_known_points() {
    // drop: P' = C + (P − C)·√(1 + r²/ρ²); ρ = 3, r = 4 → factor 5/3.
    let d = Drop {
        center: Point::new(1.0, 1.0),
        radius: 4.0,
        color: INK,
    };
    assert_eq!(d.forward(Point::new(4.0, 1.0)), Point::new(6.0, 1.0));
    // tine: shift αλ/(d + λ) along M; d = 2, α = 10, λ = 2 → 5.
    let t = Tine {
        origin: Point::ZERO,
        direction: Vec2::new(0.0, 3.0),
        alpha: 10.0,
        lambda: 2.0,
    };
    assert_eq!(t.forward(Point::new(2.0, 7.0)), Point::new(2.0, 12.0));
    // rake: spacing 10, d = 13 → d' = 3; shift 10·2/(3 + 2) = 4.
    let r = Rake {
        origin: Point::ZERO,
        direction: Vec2::new(1.0, 0.0),
        spacing: 10.0,
        alpha: 10.0,
        lambda: 2.0,
    };
    let q = r.forward(Point::new(0.0, 13.0));
    assert!((q - Point::new(4.0, 13.0)).hypot() < 1e-12, "{q:?}");
    // wavy: t = 0 → m = (1, 0), n = (0, −1), v = −y; y = −25, wavelength 100 → sin(π/2) = 1.
    let w = Wavy {
        angle: 0.0,
        amplitude: 7.0,
        wavelength: 100.0,
        phase: 0.0,
    };
    let q = w.forward(Point::new(3.0, -25.0));
    assert!((q - Point::new(10.0, -25.0)).hypot() < 1e-12, "{q:?}");
    // circular: ρ = r → d = 0, l = α, θ = α/ρ; α = π·10/2 on ρ = 10 turns a quarter (y down: +x → +y).
    let c = Circular {
        center: Point::ZERO,
        radius: 10.0,
        alpha: std::f64::consts::PI * 5.0,
        lambda: 3.0,
    };
    let q = c.forward(Point::new(10.0, 0.0));
    assert!((q - Point::new(0.0, 10.0)).hypot() < 1e-12, "{q:?}");
    // vortex: d = ρ; ρ = 1, λ = 1, α = π → θ = π·1/2/1 = π/2.
    let v = Vortex {
        center: Point::ZERO,
        alpha: std::f64::consts::PI,
        lambda: 1.0,
    };
    let q = v.forward(Point::new(1.0, 0.0));
    assert!((q - Point::new(0.0, 1.0)).hypot() < 1e-12, "{q:?}");
}
