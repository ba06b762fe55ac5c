//! The marbling tools: how a pointer gesture (press, drag, release, in design pixels)
//! becomes operations. Pure functions, so every tool is testable without a window.

use marbling_core::synth::SplitMix64;
use marbling_core::{Circular, Drop, Op, Point, Rake, Rgb8, Spray, Tine, Vec2, Vortex, Wavy};

/// The tools of the side panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ToolKind {
    /// Click to drop ink; press and hold to grow the drop.
    Drop,
    /// Drag to spray droplets.
    Spray,
    /// Drag A→B: one tine through A along B − A.
    Tine,
    /// Drag A→B: parallel tines.
    Rake,
    /// Drag A→B: a wave whose motion direction is B − A.
    Wavy,
    /// Press at the centre, drag around it: a circular comb.
    Circular,
    /// Press at the centre, drag around it: a vortex.
    Vortex,
}

impl ToolKind {
    /// Every tool, in panel order.
    pub const ALL: [ToolKind; 7] = [
        ToolKind::Drop,
        ToolKind::Spray,
        ToolKind::Tine,
        ToolKind::Rake,
        ToolKind::Wavy,
        ToolKind::Circular,
        ToolKind::Vortex,
    ];

    /// Name shown in the panel.
    pub fn label(self) -> &'static str {
        match self {
            ToolKind::Drop => "Drop",
            ToolKind::Spray => "Spray",
            ToolKind::Tine => "Tine",
            ToolKind::Rake => "Rake",
            ToolKind::Wavy => "Wavy comb",
            ToolKind::Circular => "Circular comb",
            ToolKind::Vortex => "Vortex",
        }
    }
}

/// Every tool parameter of the side panel (design pixels unless stated). Stored with
/// the other preferences (`prefs.rs`); a missing field takes its default.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct ToolSettings {
    /// Radius of a drop on a plain click.
    pub drop_radius: f64,
    /// How fast a held drop grows, design pixels per second.
    pub drop_growth: f64,
    /// Largest radius a held drop reaches.
    pub drop_max_radius: f64,
    /// Droplets per 10 design pixels of drag.
    pub spray_density: f64,
    /// Smallest droplet radius.
    pub spray_min_radius: f64,
    /// Largest droplet radius.
    pub spray_max_radius: f64,
    /// How far from the pointer droplets land.
    pub spray_spread: f64,
    /// Tine sharpness λ (small = a sharp tine that only moves ink close to it).
    pub tine_lambda: f64,
    /// Rake: number of tines (0 = tines across the whole sheet).
    pub rake_tines: u32,
    /// Rake: distance between tines.
    pub rake_spacing: f64,
    /// Rake sharpness λ.
    pub rake_lambda: f64,
    /// Wavy comb amplitude.
    pub wavy_amplitude: f64,
    /// Wavy comb wavelength.
    pub wavy_wavelength: f64,
    /// Wavy comb phase, radians.
    pub wavy_phase: f64,
    /// Circular comb sharpness λ.
    pub circular_lambda: f64,
    /// Vortex sharpness λ.
    pub vortex_lambda: f64,
}

impl Default for ToolSettings {
    fn default() -> Self {
        Self {
            drop_radius: 30.0,
            drop_growth: 40.0,
            drop_max_radius: 300.0,
            spray_density: 3.0,
            spray_min_radius: 1.5,
            spray_max_radius: 5.0,
            spray_spread: 25.0,
            tine_lambda: 8.0,
            rake_tines: 0,
            rake_spacing: 40.0,
            rake_lambda: 6.0,
            wavy_amplitude: 15.0,
            wavy_wavelength: 120.0,
            wavy_phase: 0.0,
            circular_lambda: 12.0,
            vortex_lambda: 20.0,
        }
    }
}

/// A pointer gesture in design pixels.
#[derive(Clone, Debug, PartialEq)]
pub struct Gesture {
    /// Where the button went down.
    pub start: Point,
    /// Every pointer position since, the latest last (at least `start`).
    pub path: Vec<Point>,
    /// Seconds the button has been held.
    pub held_seconds: f64,
}

impl Gesture {
    /// A gesture that starts at `p`.
    pub fn new(p: Point) -> Self {
        Self {
            start: p,
            path: vec![p],
            held_seconds: 0.0,
        }
    }

    /// The latest pointer position.
    pub fn end(&self) -> Point {
        *self.path.last().unwrap_or(&self.start)
    }

    /// Signed angle (radians) swept by the pointer around `c` along the path; positive
    /// is clockwise on screen (y down), the sense in which a positive α rotates.
    pub fn swept_angle(&self, c: Point) -> f64 {
        self.path
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0] - c, w[1] - c);
                if a.hypot2() == 0.0 || b.hypot2() == 0.0 {
                    0.0
                } else {
                    a.cross(b).atan2(a.dot(b))
                }
            })
            .sum()
    }
}

/// The ops a gesture makes with a tool, rounded to what can matter ([`Op::rounded`], so
/// the document and its link hold exactly what was previewed); empty when the gesture
/// is too small to mean anything (a click with a comb). `seed` makes spray droplets
/// reproducible.
pub fn ops_for(kind: ToolKind, s: &ToolSettings, g: &Gesture, color: Rgb8, seed: u64) -> Vec<Op> {
    unrounded_ops(kind, s, g, color, seed)
        .iter()
        .map(Op::rounded)
        .collect()
}

fn unrounded_ops(kind: ToolKind, s: &ToolSettings, g: &Gesture, color: Rgb8, seed: u64) -> Vec<Op> {
    let (a, b) = (g.start, g.end());
    let drag = b - a;
    let len = drag.hypot();
    match kind {
        ToolKind::Drop => {
            let radius = (s.drop_radius + s.drop_growth * g.held_seconds)
                .min(s.drop_max_radius.max(s.drop_radius));
            vec![Op::Drop(Drop {
                center: a,
                radius,
                color,
            })]
        }
        ToolKind::Spray => spray(s, g, color, seed),
        _ if len < 1.0 && !matches!(kind, ToolKind::Circular | ToolKind::Vortex) => Vec::new(),
        ToolKind::Tine => vec![Op::Tine(Tine {
            origin: a,
            direction: drag,
            alpha: len,
            lambda: s.tine_lambda,
        })],
        ToolKind::Rake if s.rake_tines == 0 => vec![Op::Rake(Rake {
            origin: a,
            direction: drag,
            spacing: s.rake_spacing,
            alpha: len,
            lambda: s.rake_lambda,
        })],
        ToolKind::Rake => {
            let m = drag / len;
            let n = Vec2::new(-m.y, m.x);
            let half = f64::from(s.rake_tines - 1) / 2.0;
            (0..s.rake_tines)
                .map(|i| {
                    let origin = a + n * ((f64::from(i) - half) * s.rake_spacing);
                    Op::Tine(Tine {
                        origin,
                        direction: drag,
                        alpha: len,
                        lambda: s.rake_lambda,
                    })
                })
                .collect()
        }
        ToolKind::Wavy => vec![Op::Wavy(Wavy {
            angle: drag.y.atan2(drag.x),
            amplitude: s.wavy_amplitude,
            wavelength: s.wavy_wavelength,
            phase: s.wavy_phase,
        })],
        ToolKind::Circular => {
            let radius = (g.path.iter().map(|p| (*p - a).hypot()).fold(0.0, f64::max)).max(1.0);
            let alpha = g.swept_angle(a) * radius;
            if alpha.abs() < 0.5 {
                return Vec::new();
            }
            vec![Op::Circular(Circular {
                center: a,
                radius,
                alpha,
                lambda: s.circular_lambda,
            })]
        }
        ToolKind::Vortex => {
            let reach = g.path.iter().map(|p| (*p - a).hypot()).fold(0.0, f64::max);
            let alpha = g.swept_angle(a) * reach;
            if alpha.abs() < 0.5 {
                return Vec::new();
            }
            vec![Op::Vortex(Vortex {
                center: a,
                alpha,
                lambda: s.vortex_lambda,
            })]
        }
    }
}

/// Droplets scattered around the drag path: `spray_density` per 10 px travelled (at
/// least one), each within `spray_spread` of the path, radius in the size range.
fn spray(s: &ToolSettings, g: &Gesture, color: Rgb8, seed: u64) -> Vec<Op> {
    let mut rng = SplitMix64(seed);
    let travelled: f64 = g.path.windows(2).map(|w| (w[1] - w[0]).hypot()).sum();
    let count = ((travelled / 10.0 * s.spray_density).round() as usize).clamp(1, 2000);
    let (lo, hi) = (
        s.spray_min_radius.min(s.spray_max_radius),
        s.spray_min_radius.max(s.spray_max_radius),
    );
    (0..count)
        .map(|_| {
            let at = point_along(&g.path, rng.unit() * travelled);
            let offset = Vec2::from_angle(rng.range(0.0, std::f64::consts::TAU))
                * (s.spray_spread * rng.unit().sqrt());
            Op::Spray(Spray {
                center: at + offset,
                radius: rng.range(lo, hi).max(0.1),
                color,
            })
        })
        .collect()
}

/// The point at arc length `t` along a polyline.
fn point_along(path: &[Point], mut t: f64) -> Point {
    for w in path.windows(2) {
        let l = (w[1] - w[0]).hypot();
        if t <= l && l > 0.0 {
            return w[0].lerp(w[1], t / l);
        }
        t -= l;
    }
    *path.last().unwrap_or(&Point::ZERO)
}

#[cfg(test)]
mod tests {
    use super::*;

    const INK: Rgb8 = Rgb8::new(1, 2, 3);

    fn drag(a: (f64, f64), b: (f64, f64)) -> Gesture {
        let mut g = Gesture::new(Point::new(a.0, a.1));
        g.path.push(Point::new(b.0, b.1));
        g
    }

    #[test]
    fn a_held_drop_grows_up_to_its_cap() {
        let s = ToolSettings::default();
        let mut g = Gesture::new(Point::new(5.0, 6.0));
        assert_eq!(
            ops_for(ToolKind::Drop, &s, &g, INK, 0),
            vec![Op::Drop(Drop {
                center: g.start,
                radius: 30.0,
                color: INK
            })]
        );
        g.held_seconds = 2.0;
        let Op::Drop(d) = ops_for(ToolKind::Drop, &s, &g, INK, 0)[0] else {
            panic!()
        };
        assert_eq!(d.radius, 110.0);
        g.held_seconds = 1000.0;
        let Op::Drop(d) = ops_for(ToolKind::Drop, &s, &g, INK, 0)[0] else {
            panic!()
        };
        assert_eq!(d.radius, 300.0);
    }

    #[test]
    fn a_tine_runs_through_a_along_the_drag_with_its_length_as_strength() {
        let s = ToolSettings::default();
        let ops = ops_for(
            ToolKind::Tine,
            &s,
            &drag((10.0, 20.0), (13.0, 24.0)),
            INK,
            0,
        );
        assert_eq!(
            ops,
            vec![Op::Tine(Tine {
                origin: Point::new(10.0, 20.0),
                direction: Vec2::new(3.0, 4.0),
                alpha: 5.0,
                lambda: 8.0
            })]
        );
        assert!(ops_for(ToolKind::Tine, &s, &drag((1.0, 1.0), (1.2, 1.0)), INK, 0).is_empty());
    }

    #[test]
    fn a_rake_is_a_whole_sheet_rake_or_that_many_tines() {
        let mut s = ToolSettings::default();
        let ops = ops_for(ToolKind::Rake, &s, &drag((0.0, 0.0), (0.0, 50.0)), INK, 0);
        assert!(matches!(
            ops[..],
            [Op::Rake(Rake {
                spacing: 40.0,
                alpha: 50.0,
                ..
            })]
        ));
        s.rake_tines = 3;
        let ops = ops_for(
            ToolKind::Rake,
            &s,
            &drag((100.0, 0.0), (100.0, 50.0)),
            INK,
            0,
        );
        let xs: Vec<f64> = ops
            .iter()
            .map(|o| {
                if let Op::Tine(t) = o {
                    t.origin.x
                } else {
                    f64::NAN
                }
            })
            .collect();
        assert_eq!(xs, [140.0, 100.0, 60.0]);
    }

    #[test]
    fn wavy_takes_its_angle_from_the_drag() {
        let s = ToolSettings::default();
        let Op::Wavy(w) = ops_for(ToolKind::Wavy, &s, &drag((0.0, 0.0), (0.0, 10.0)), INK, 0)[0]
        else {
            panic!()
        };
        // Angles are rounded to 1e-4 rad (`Op::rounded`).
        assert!((w.angle - std::f64::consts::FRAC_PI_2).abs() <= 0.5e-4);
    }

    #[test]
    fn circular_and_vortex_follow_the_pointer_around_the_centre() {
        let s = ToolSettings::default();
        // A quarter turn clockwise on screen (y down) at radius 100.
        let mut g = Gesture::new(Point::new(0.0, 0.0));
        for i in 0..=10 {
            let t = f64::from(i) / 10.0 * std::f64::consts::FRAC_PI_2;
            g.path.push(Point::new(100.0 * t.cos(), 100.0 * t.sin()));
        }
        let Op::Circular(c) = ops_for(ToolKind::Circular, &s, &g, INK, 0)[0] else {
            panic!()
        };
        assert!((c.radius - 100.0).abs() < 1e-9);
        // Strengths are rounded to 0.01 design px (`Op::rounded`).
        assert!(
            (c.alpha - 50.0 * std::f64::consts::PI).abs() <= 0.005,
            "{}",
            c.alpha
        );
        let Op::Vortex(v) = ops_for(ToolKind::Vortex, &s, &g, INK, 0)[0] else {
            panic!()
        };
        assert!(v.alpha > 0.0);
        // A click without travel makes nothing.
        assert!(ops_for(ToolKind::Vortex, &s, &Gesture::new(Point::ZERO), INK, 0).is_empty());
    }

    #[test]
    fn spray_scatters_reproducible_droplets_near_the_path() {
        let s = ToolSettings::default();
        let g = drag((0.0, 0.0), (100.0, 0.0));
        let ops = ops_for(ToolKind::Spray, &s, &g, INK, 42);
        assert_eq!(ops.len(), 30);
        assert_eq!(ops, ops_for(ToolKind::Spray, &s, &g, INK, 42));
        for op in &ops {
            let Op::Spray(d) = op else { panic!() };
            assert!(
                d.center.y.abs() <= s.spray_spread + 1e-9 && (-25.0..=125.0).contains(&d.center.x)
            );
            assert!((s.spray_min_radius..=s.spray_max_radius).contains(&d.radius));
        }
    }
}
