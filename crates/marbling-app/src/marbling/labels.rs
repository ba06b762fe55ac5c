//! What the history list calls a gesture: "drop", "spray stroke, 340 droplets",
//! "rake ↓ 9 tines", "tine →", "vortex".

use marbling_core::{Op, Vec2};

/// The arrow closest to a direction in design space (y down, so +y is ↓).
pub fn arrow(v: Vec2) -> char {
    const ARROWS: [char; 8] = ['→', '↘', '↓', '↙', '←', '↖', '↑', '↗'];
    let a = v.y.atan2(v.x).rem_euclid(std::f64::consts::TAU);
    let i = (a / std::f64::consts::FRAC_PI_4).round() as usize % 8;
    ARROWS[i]
}

/// The label of one gesture's ops.
pub fn gesture_label(ops: &[Op]) -> String {
    let n = ops.len();
    match ops {
        [] => "nothing".to_owned(),
        [op] => single(op),
        [Op::Spray(_), ..] if ops.iter().all(|o| matches!(o, Op::Spray(_))) => {
            format!("spray stroke, {n} droplets")
        }
        [Op::Tine(t), ..] if ops.iter().all(|o| matches!(o, Op::Tine(_))) => {
            format!("rake {} {n} tines", arrow(t.direction))
        }
        [first, ..] if ops.iter().all(|o| o.type_name() == first.type_name()) => {
            format!("{n} × {}", single(first))
        }
        _ => format!("{n} ops"),
    }
}

fn single(op: &Op) -> String {
    match op {
        Op::Drop(_) => "drop".to_owned(),
        Op::Spray(_) => "spray droplet".to_owned(),
        Op::Tine(t) => format!("tine {}", arrow(t.direction)),
        Op::Rake(r) => format!("rake {} (whole sheet)", arrow(r.direction)),
        Op::Wavy(_) => "wavy comb".to_owned(),
        Op::Circular(_) => "circular comb".to_owned(),
        Op::Vortex(_) => "vortex".to_owned(),
        Op::Shift(s) => format!("shift {}", arrow(s.offset)),
        Op::Turn(_) => "turn".to_owned(),
        Op::Comb(c) => format!("comb of {} tines {}", c.tines.len(), arrow(c.direction)),
        Op::Drops(d) => format!("{} drops", d.len()),
        Op::Sprays(d) => format!("{} spray droplets", d.len()),
        Op::Jiggle(_) => "jiggle".to_owned(),
        Op::Stylus(s) if s.tip_count() > 1 => format!("stylus of {} tips", s.tip_count()),
        Op::Stylus(_) => "stylus stroke".to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrows_follow_design_space_with_y_down() {
        assert_eq!(arrow(Vec2::new(1.0, 0.0)), '→');
        assert_eq!(arrow(Vec2::new(0.0, 3.0)), '↓');
        assert_eq!(arrow(Vec2::new(-1.0, -1.1)), '↖');
        assert_eq!(arrow(Vec2::new(0.2, -5.0)), '↑');
    }
}
