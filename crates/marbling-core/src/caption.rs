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

fn at(p: Point) -> String {
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

fn plural(n: usize, one: &str, many: &str) -> String {
    if n == 1 {
        format!("1 {one}")
    } else {
        format!("{n} {many}")
    }
}

fn range(lo: f64, hi: f64) -> String {
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

/// The caption of one op.
pub fn describe_op(op: &Op) -> String {
    match op {
        Op::Drop(d) => format!(
            "a drop of {}, radius {} px, at {}",
            d.color,
            num(d.radius),
            at(d.center)
        ),
        Op::Spray(d) => format!(
            "a spray of {}, radius {} px, at {}",
            d.color,
            num(d.radius),
            at(d.center)
        ),
        Op::Drops(s) | Op::Sprays(s) => {
            let what = if matches!(op, Op::Drops(_)) {
                ("drop", "drops")
            } else {
                ("spray", "sprays")
            };
            let colors = if s.colors.len() == 1 {
                format!("of {}", s.colors[0])
            } else {
                format!("in {} colours", s.colors.len())
            };
            format!(
                "{} {colors}, radius {} px",
                plural(s.centers.len(), what.0, what.1),
                radii_text(&s.radii)
            )
        }
        Op::Tine(t) => format!(
            "a tine drawn {} through {}: shift {} px, decay {} px",
            heading(t.direction),
            at(t.origin),
            num(t.alpha),
            num(t.lambda)
        ),
        Op::Rake(r) => format!(
            "rake drawn {}: tines {} px apart, shift {} px, decay {} px",
            heading(r.direction * r.alpha.signum()),
            num(r.spacing),
            num(r.alpha.abs()),
            num(r.lambda)
        ),
        Op::Comb(c) => {
            let n = c.tines.len();
            let gaps: Vec<f64> = c.tines.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
            let apart = if gaps.is_empty() {
                String::new()
            } else {
                let lo = gaps.iter().cloned().fold(f64::INFINITY, f64::min);
                let hi = gaps.iter().cloned().fold(0.0, f64::max);
                format!(", {} px apart", range(lo, hi))
            };
            format!(
                "comb drawn {}: {}{apart}, shift {} px, decay {} px",
                heading(c.direction * c.alpha.signum()),
                plural(n, "tine", "tines"),
                num(c.alpha.abs()),
                num(c.lambda)
            )
        }
        Op::Wavy(w) => format!(
            "wavy comb moving {}: amplitude {} px, wavelength {} px",
            heading(Vec2::new(w.angle.cos(), w.angle.sin())),
            num(w.amplitude),
            num(w.wavelength)
        ),
        Op::Circular(c) => format!(
            "circular comb around {}: {} px along the circle of radius {} px, decay {} px",
            at(c.center),
            num(c.alpha),
            num(c.radius),
            num(c.lambda)
        ),
        Op::Vortex(v) => format!(
            "swirl at {}: strength {} px, decay {} px",
            at(v.center),
            num(v.alpha),
            num(v.lambda)
        ),
        Op::Shift(s) => format!(
            "the tank shifted by ({}, {}) px",
            num(s.offset.x),
            num(s.offset.y)
        ),
        Op::Turn(t) => format!(
            "the tank turned {}° about {}",
            num(t.angle.to_degrees()),
            at(t.center)
        ),
        Op::Jiggle(j) => format!(
            "the tank jiggled {}: wavelength {} px, {} px along, {} px across",
            heading(Vec2::new(j.angle.cos(), j.angle.sin())),
            num(j.wavelength),
            num(j.along),
            num(j.across)
        ),
        Op::Stylus(s) => {
            let len: f64 = s.path.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
            let tips = s.tips.as_ref().map_or(1, |t| t.len());
            format!(
                "stylus drawn {} px from {} with {}, wake {} px",
                num(len),
                at(s.path[0]),
                plural(tips, "tip", "tips"),
                num(s.wake)
            )
        }
    }
}

/// The caption of one step (a gesture's ops): one op as [`describe_op`]; several of
/// one type as "12 drops: …" with the first one's numbers.
pub fn describe(ops: &[Op]) -> String {
    match ops {
        [] => "nothing".into(),
        [op] => describe_op(op),
        [first, rest @ ..] => {
            let kind = first.type_name();
            if rest.iter().all(|o| o.type_name() == kind) {
                format!("{} {kind}s, the first {}", ops.len(), describe_op(first))
            } else {
                format!("{} ops, the first {}", ops.len(), describe_op(first))
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
    fn captions_carry_the_numbers() {
        let comb = Op::Comb(Comb {
            origin: Point::new(0.0, 20.0),
            direction: Vec2::new(1.0, 0.0),
            tines: Arc::from((0..9).map(|i| i as f64 * 40.0).collect::<Vec<_>>()),
            alpha: 30.0,
            lambda: 6.0,
        });
        assert_eq!(
            describe_op(&comb),
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
            describe_op(&back),
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
