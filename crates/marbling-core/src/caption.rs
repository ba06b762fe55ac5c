//! Plain-language captions of steps, made from the ops' numbers: "rake drawn top to
//! bottom: tines 36 px apart, shift 48 px, decay 8 px". Used where a step has no
//! recipe caption (see [`crate::recipe`]).

use crate::{Op, Point, Radii, Vec2};

/// A number for people: at most one decimal, no trailing ".0".
pub fn num(v: f64) -> String {
    let r = (v * 10.0).round() / 10.0;
    if r == r.trunc() {
        format!("{}", r as i64)
    } else {
        format!("{r:.1}")
    }
}

pub(crate) fn at(p: Point) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

/// "left to right", "top to bottom", … or "at 30°" (y down, clockwise from +x).
pub fn heading(d: Vec2) -> String {
    let deg = d.y.atan2(d.x).to_degrees();
    let deg = if deg < 0.0 { deg + 360.0 } else { deg };
    for (a, name) in [
        (0.0, "left to right"),
        (90.0, "top to bottom"),
        (180.0, "right to left"),
        (270.0, "bottom to top"),
        (360.0, "left to right"),
    ] {
        if (deg - a).abs() < 0.5 {
            return name.into();
        }
    }
    format!("at {}°", num(deg))
}

/// The arrow closest to a direction in design space (y down, so +y is ↓).
pub fn arrow(v: Vec2) -> char {
    const ARROWS: [char; 8] = ['→', '↘', '↓', '↙', '←', '↖', '↑', '↗'];
    let a = v.y.atan2(v.x).rem_euclid(std::f64::consts::TAU);
    let i = (a / std::f64::consts::FRAC_PI_4).round() as usize % 8;
    ARROWS[i]
}

pub(crate) fn plural(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

pub(crate) fn range(lo: f64, hi: f64) -> String {
    if num(lo) == num(hi) {
        num(lo)
    } else {
        format!("{}–{}", num(lo), num(hi))
    }
}

/// A drop set's radius, or its range ("12" or "12–30").
pub fn radii_text(radii: &Radii) -> String {
    match radii {
        Radii::One(r) => num(*r),
        Radii::Each(list) => {
            let (lo, hi) = list.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
                (lo.min(*r), hi.max(*r))
            });
            range(lo, hi)
        }
    }
}

/// The caption of one step (a gesture's ops): one op as [`Op::caption`]; several of
/// one type as "12 drops: …" with the first one's numbers.
pub fn describe(ops: &[Op]) -> String {
    match ops {
        [] => "nothing".into(),
        [op] => op.caption(),
        [first, rest @ ..] => {
            let kind = first.type_name();
            if rest.iter().all(|o| o.type_name() == kind) {
                format!("{} {kind}s, the first {}", ops.len(), first.caption())
            } else {
                format!("{} ops, the first {}", ops.len(), first.caption())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Comb, Drop, Rake, Rgb8};
    use std::sync::Arc;

    #[test]
    fn arrows_follow_design_space_with_y_down() {
        assert_eq!(arrow(Vec2::new(1.0, 0.0)), '→');
        assert_eq!(arrow(Vec2::new(0.0, 3.0)), '↓');
        assert_eq!(arrow(Vec2::new(-1.0, -1.1)), '↖');
        assert_eq!(arrow(Vec2::new(0.2, -5.0)), '↑');
    }

    #[test]
    fn captions_carry_the_numbers() {
        let comb = Op::Comb(Comb {
            origin: Point::new(0.0, 20.0),
            direction: Vec2::new(1.0, 0.0),
            tines: Arc::from((0..9).map(|i| i as f64 * 40.0).collect::<Vec<_>>()),
            alpha: 30.0,
            lambda: 6.0,
        });
        assert_eq!(
            comb.caption(),
            "comb drawn left to right: 9 tines, 40 px apart, shift 30 px, decay 6 px"
        );
        let back = Op::Rake(Rake {
            origin: Point::new(0.0, 0.0),
            direction: Vec2::new(0.0, 1.0),
            spacing: 36.0,
            alpha: -48.0,
            lambda: 8.0,
        });
        assert_eq!(
            back.caption(),
            "rake drawn bottom to top: tines 36 px apart, shift 48 px, decay 8 px"
        );
        let drop = Op::Drop(Drop {
            center: Point::new(10.25, 3.0),
            radius: 12.0,
            color: Rgb8::new(0x1d, 0x35, 0x57),
        });
        assert_eq!(
            describe(&[drop.clone(), drop]),
            "2 drops, the first a drop of #1d3557, radius 12 px, at (10.3, 3)"
        );
        assert_eq!(heading(Vec2::new(1.0, 1.0)), "at 45°");
        assert_eq!(
            (num(2.0), num(-0.25), num(1e-9)),
            ("2".into(), "-0.3".into(), "0".into())
        );
    }
}
