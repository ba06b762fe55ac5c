//! The mathematics of one op in readable text, with its actual numbers, for the explain
//! view: the forward map (where older ink goes), its inverse (what the renderer walks
//! back through), and the values, e.g. `P′ = P + αλ/(d+λ)·M` with `α = 60, λ = 8`.

use crate::caption::num;
use crate::{Op, Point, Vec2};

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

pub(crate) fn pt(p: Point) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

pub(crate) fn unit(v: Vec2) -> String {
    let u = v.normalize();
    format!("({}, {})", num2(u.x), num2(u.y))
}

pub(crate) fn num2(v: f64) -> String {
    let r = (v * 100.0).round() / 100.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r}")
    }
}

pub(crate) const DROP_FORWARD: &str = "P′ = C + (P − C)·√(1 + r²/|P − C|²)";
pub(crate) const DROP_INVERSE: &str =
    "P = C + (P′ − C)·√(1 − r²/|P′ − C|²); inside the disc |P′ − C| < r: this drop's ink";
pub(crate) const TINE_FORWARD: &str = "P′ = P + α·λ/(d + λ)·M";
pub(crate) const TINE_INVERSE: &str = "P = P′ − α·λ/(d + λ)·M (d is the same before and after)";

/// Symbols of every drop's formulas.
pub(crate) const DROP_SYMBOLS: &str =
    "C: the drop's centre, r: its radius (px); the drop pushes older ink out of its disc";
/// Symbols of every spray's formulas.
pub(crate) const SPRAY_SYMBOLS: &str = "C: the droplet's centre, r: its radius (px)";
/// Tine-family symbols shared by the tine, rake and comb.
pub(crate) const TINE_SYMBOLS: &str = "M: the unit direction the tines are drawn, N: M turned 90°, \
     α: how far ink on a tine's line moves (px), λ: how fast that fades with d (px)";

/// The formulas of `op` with its numbers (each op type's own, in `ops/<op>.rs`).
pub fn formula(op: &Op) -> Formula {
    let f = op.type_formula();
    Formula {
        symbols: format!(
            "P: a point of older ink, P′: where this step moves it; {}",
            f.symbols
        ),
        ..f
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
