//! The mathematics of one op in readable text, with its actual numbers, for the explain
//! view: the forward map (where older ink goes), its inverse (what the renderer walks
//! back through), and the values, e.g. `P′ = P + αλ/(d+λ)·M` with `α = 60, λ = 8`.

use crate::caption::num;
use crate::{Op, Point, Radii, Vec2};

/// An op's forward map, inverse map and numbers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Formula {
    /// Where a point of older ink goes.
    pub forward: String,
    /// Where a point came from (the exact renderer's step).
    pub inverse: String,
    /// The op's values in the formulas' symbols.
    pub values: String,
    /// What every symbol of the formulas means, with units.
    pub symbols: String,
    /// Whether the map keeps every area (all but the jiggle with A ≠ 0).
    pub area_preserving: bool,
}

fn pt(p: Point) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

fn unit(v: Vec2) -> String {
    let u = v.normalize();
    format!("({}, {})", num2(u.x), num2(u.y))
}

fn num2(v: f64) -> String {
    let r = (v * 100.0).round() / 100.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r}")
    }
}

const DROP_FORWARD: &str = "P′ = C + (P − C)·√(1 + r²/|P − C|²)";
const DROP_INVERSE: &str =
    "P = C + (P′ − C)·√(1 − r²/|P′ − C|²); inside the disc |P′ − C| < r: this drop's ink";
const TINE_FORWARD: &str = "P′ = P + α·λ/(d + λ)·M";
const TINE_INVERSE: &str = "P = P′ − α·λ/(d + λ)·M (d is the same before and after)";

/// The formulas of `op` with its numbers.
pub fn formula(op: &Op) -> Formula {
    let (forward, inverse, values, area) = match op {
        Op::Drop(d) => (
            DROP_FORWARD.into(),
            DROP_INVERSE.into(),
            format!("C = {}, r = {}", pt(d.center), num(d.radius)),
            true,
        ),
        Op::Drops(s) => {
            let r = match &s.radii {
                Radii::One(r) => num(*r),
                Radii::Each(list) => format!("{} (first of {})", num(list[0]), list.len()),
            };
            (
                format!("{DROP_FORWARD}, once per drop in order"),
                format!("the drops undone newest first: {DROP_INVERSE}"),
                format!(
                    "{} drops, C₁ = {}, r₁ = {r}",
                    s.centers.len(),
                    pt(s.centers[0])
                ),
                true,
            )
        }
        Op::Spray(d) => (
            "P′ = P (a spray lays ink on top without moving anything)".into(),
            "P = P′; inside |P′ − C| < r: this spray's ink".into(),
            format!("C = {}, r = {}", pt(d.center), num(d.radius)),
            true,
        ),
        Op::Sprays(s) => (
            "P′ = P (sprays lay ink on top without moving anything)".into(),
            "P = P′; inside a spray's disc: its ink".into(),
            format!("{} sprays, C₁ = {}", s.centers.len(), pt(s.centers[0])),
            true,
        ),
        Op::Tine(t) => (
            format!("{TINE_FORWARD}, d = |(P − O)·N|"),
            TINE_INVERSE.into(),
            format!(
                "α = {}, λ = {}, O = {}, M = {}",
                num(t.alpha),
                num(t.lambda),
                pt(t.origin),
                unit(t.direction)
            ),
            true,
        ),
        Op::Rake(r) => (
            format!(
                "{TINE_FORWARD}, d = distance to the nearest tine line (lines every s along N)"
            ),
            TINE_INVERSE.into(),
            format!(
                "α = {}, λ = {}, s = {}, M = {}",
                num(r.alpha),
                num(r.lambda),
                num(r.spacing),
                unit(r.direction)
            ),
            true,
        ),
        Op::Comb(c) => (
            format!("{TINE_FORWARD}, d = min over i of |(P − O)·N − t_i|"),
            TINE_INVERSE.into(),
            format!(
                "α = {}, λ = {}, {} tines, M = {}",
                num(c.alpha),
                num(c.lambda),
                c.tines.len(),
                unit(c.direction)
            ),
            true,
        ),
        Op::Wavy(w) => (
            "P′ = P + A·sin(2π(P·N)/ℓ + φ)·M".into(),
            "P = P′ − A·sin(2π(P′·N)/ℓ + φ)·M".into(),
            format!(
                "A = {}, ℓ = {}, φ = {}, M at {}°",
                num(w.amplitude),
                num(w.wavelength),
                num2(w.phase),
                num(w.angle.to_degrees())
            ),
            true,
        ),
        Op::Circular(c) => (
            "P′ = C + R(θ)(P − C), θ = α·λ/(|ρ − r| + λ)/ρ, ρ = |P − C|".into(),
            "P = C + R(−θ)(P′ − C) (ρ is the same before and after)".into(),
            format!(
                "C = {}, r = {}, α = {}, λ = {}",
                pt(c.center),
                num(c.radius),
                num(c.alpha),
                num(c.lambda)
            ),
            true,
        ),
        Op::Vortex(v) => (
            "P′ = C + R(θ)(P − C), θ = α·λ/(ρ + λ)/ρ, ρ = |P − C|".into(),
            "P = C + R(−θ)(P′ − C)".into(),
            format!(
                "C = {}, α = {}, λ = {}",
                pt(v.center),
                num(v.alpha),
                num(v.lambda)
            ),
            true,
        ),
        Op::Shift(s) => (
            "P′ = P + D".into(),
            "P = P′ − D".into(),
            format!("D = ({}, {})", num(s.offset.x), num(s.offset.y)),
            true,
        ),
        Op::Turn(t) => (
            "P′ = C + R(θ)(P − C)".into(),
            "P = C + R(−θ)(P′ − C)".into(),
            format!("C = {}, θ = {}°", pt(t.center), num(t.angle.to_degrees())),
            true,
        ),
        Op::Jiggle(j) => (
            "P′ = P + A·sin φ·u + B·cos φ·v, φ = 2π(P·u)/λ + φ₀".into(),
            "solve P·u = P′·u − A·sin φ for φ (Newton), then P = P′ − A·sin φ·u − B·cos φ·v".into(),
            format!(
                "A = {}, B = {}, λ = {}, u at {}°; area scales by 1 + 2πA/λ·cos φ",
                num(j.along),
                num(j.across),
                num(j.wavelength),
                num(j.angle.to_degrees())
            ),
            j.along == 0.0,
        ),
        Op::Stylus(s) => (
            "each sub-step δ along the path: P′ = P + δ·u((P + P′)/2), u from \
             ψ = y·e^(−ρ/L)·(1 − (ρ/8L)²)³ around every tip"
                .into(),
            "the sub-steps undone newest first with −δ".into(),
            format!(
                "L = {}, {} sub-steps, {} tip(s)",
                num(s.wake),
                s.sub_steps(),
                s.tips.as_ref().map_or(1, |t| t.len())
            ),
            true,
        ),
    };
    Formula {
        forward,
        inverse,
        values,
        symbols: format!(
            "P: a point of older ink, P′: where this step moves it; {}",
            symbols(op)
        ),
        area_preserving: area,
    }
}

/// Tine-family symbols shared by the tine, rake and comb.
const TINE_SYMBOLS: &str = "M: the unit direction the tines are drawn, N: M turned 90°, \
     α: how far ink on a tine's line moves (px), λ: how fast that fades with d (px)";

/// What the symbols of `op`'s formulas mean.
fn symbols(op: &Op) -> String {
    match op {
        Op::Drop(_) | Op::Drops(_) => {
            "C: the drop's centre, r: its radius (px); the drop pushes older ink out of its disc"
                .into()
        }
        Op::Spray(_) | Op::Sprays(_) => "C: the droplet's centre, r: its radius (px)".into(),
        Op::Tine(_) => format!(
            "O: a point on the tine's line, d: P's distance from that line (px), {TINE_SYMBOLS}"
        ),
        Op::Rake(_) => format!(
            "O: a point on one tine's line, s: the spacing of the lines (px), d: P's distance \
             from the nearest (px), {TINE_SYMBOLS}"
        ),
        Op::Comb(_) => format!(
            "O: the comb's origin, t_i: tine i's offset from O along N (px), d: P's distance \
             from the nearest tine's line (px), {TINE_SYMBOLS}"
        ),
        Op::Wavy(_) => "M: the unit direction ink moves, N: M turned 90°, A: the amplitude \
             (px), ℓ: the wavelength along N (px), φ: the phase (radians)"
            .into(),
        Op::Circular(_) => "C: the centre, r: the circular tine's radius (px), ρ: P's distance \
             from C (px), θ: the angle P turns, R(θ): the turn by θ, α: how far ink on the \
             tine's circle moves along it (px), λ: how fast that fades (px)"
            .into(),
        Op::Vortex(_) => "C: the centre, ρ: P's distance from C (px), θ: the angle P turns, \
             R(θ): the turn by θ, α: the swirl's strength (px), λ: how fast it fades (px)"
            .into(),
        Op::Shift(_) => "D: how far the whole tank moves (px)".into(),
        Op::Turn(_) => "C: the centre, θ: the angle, R(θ): the turn by θ".into(),
        Op::Jiggle(_) => "u: the unit direction of the wave, v: u turned 90°, A: the swing \
             along u (px), B: the swing across (px), λ: the wavelength (px), φ₀: the phase, \
             φ: the phase at P"
            .into(),
        Op::Stylus(_) => "δ: one sub-step along the path (px), u: the flow's direction, ψ: \
             the stream function it follows, y: the distance across the path, ρ: the distance from a \
             tip (px), L: the wake, how far the flow reaches (px)"
            .into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Tine;

    #[test]
    fn a_tine_shows_its_numbers() {
        let f = formula(&Op::Tine(Tine {
            origin: Point::new(0.0, 200.0),
            direction: Vec2::new(2.0, 0.0),
            alpha: 60.0,
            lambda: 8.0,
        }));
        assert_eq!(f.forward, "P′ = P + α·λ/(d + λ)·M, d = |(P − O)·N|");
        assert_eq!(f.values, "α = 60, λ = 8, O = (0, 200), M = (1, 0)");
        assert!(f.area_preserving);
        assert!(f.symbols.contains("N: M turned 90°"), "{}", f.symbols);
    }

    /// Every symbol a formula uses is defined in its `symbols` line (a letter of the
    /// formulas' alphabet that appears in the formulas must appear before a colon).
    #[test]
    fn every_symbol_of_every_formula_is_defined() {
        let mut ops: Vec<Op> = Vec::new();
        for p in crate::patterns::all() {
            let design = p.design(&Default::default()).expect("a pattern's design");
            ops.extend(design.ops.iter().cloned());
        }
        let alphabet = [
            "C", "r", "O", "M", "N", "d", "α", "λ", "s", "t_i", "A", "ℓ", "φ", "ρ", "θ", "R(θ)",
            "D", "u", "v", "B", "φ₀", "δ", "ψ", "y", "L",
        ];
        for op in &ops {
            let f = formula(op);
            let text = format!("{} {}", f.forward, f.inverse);
            for sym in alphabet {
                let used = text
                    .split(|c: char| !(c.is_alphanumeric() || "_₀'".contains(c)))
                    .any(|w| w == sym)
                    || (sym == "R(θ)" && text.contains("R(θ)"));
                if used {
                    assert!(
                        f.symbols.contains(&format!("{sym}:")),
                        "{}: {sym} is used in {text:?} but not defined in {:?}",
                        op.type_name(),
                        f.symbols
                    );
                }
            }
        }
    }
}
