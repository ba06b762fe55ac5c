//! The marbling tools: how a pointer gesture (press, drag, release, in design pixels)
//! becomes operations. Pure functions, so every tool is testable without a window.

use crate::marbling::drop_patterns::{self, DropPattern, PatternShape};
use crate::marbling::stroke;
use marbling_core::synth::SplitMix64;
use marbling_core::{
    Circular, Comb, Drop, DropSet, Flow, Jiggle, Op, Point, Radii, Rake, Rgb8, Shift, Spray, Tine,
    Turn, Vec2, Vortex, Wavy,
};
use marbling_noise::{Basis, FbmParams};
use std::sync::Arc;

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
    /// Drag A→B: parallel tines, endless (a rake op) or a finite comb.
    #[serde(alias = "rake")]
    Comb,
    /// Drag A→B: a wave whose motion direction is B − A.
    Wavy,
    /// Press at the centre, drag around it: a circular comb.
    Circular,
    /// Press at the centre, drag around it: a vortex.
    Vortex,
    /// Drag free-hand: a stylus (one tip or several, a free-hand comb) follows the path.
    Stylus,
    /// Drag A→B: the tank jiggles along B − A.
    Jiggle,
    /// Drag: the whole tank moves with the pointer.
    Shift,
    /// Press at the centre, drag around it: the whole tank turns.
    Turn,
    /// Drag: the tank streams along a curl noise, longer the longer the drag.
    Flow,
}

impl ToolKind {
    /// Every tool, in panel order.
    pub const ALL: [ToolKind; 12] = [
        ToolKind::Drop,
        ToolKind::Spray,
        ToolKind::Tine,
        ToolKind::Comb,
        ToolKind::Stylus,
        ToolKind::Wavy,
        ToolKind::Jiggle,
        ToolKind::Circular,
        ToolKind::Vortex,
        ToolKind::Shift,
        ToolKind::Turn,
        ToolKind::Flow,
    ];

    /// Its name in stored preferences and in `data-controls` (`tool-…`).
    pub fn name(self) -> &'static str {
        match self {
            ToolKind::Drop => "drop",
            ToolKind::Spray => "spray",
            ToolKind::Tine => "tine",
            ToolKind::Comb => "comb",
            ToolKind::Wavy => "wavy",
            ToolKind::Circular => "circular",
            ToolKind::Vortex => "vortex",
            ToolKind::Stylus => "stylus",
            ToolKind::Jiggle => "jiggle",
            ToolKind::Shift => "shift",
            ToolKind::Turn => "turn",
            ToolKind::Flow => "flow",
        }
    }

    /// Name shown in the panel.
    pub fn label(self) -> &'static str {
        match self {
            ToolKind::Drop => "Drop",
            ToolKind::Spray => "Spray",
            ToolKind::Tine => "Tine",
            ToolKind::Comb => "Comb",
            ToolKind::Wavy => "Wavy",
            ToolKind::Circular => "Circular",
            ToolKind::Vortex => "Vortex",
            ToolKind::Stylus => "Stylus",
            ToolKind::Jiggle => "Jiggle",
            ToolKind::Shift => "Shift",
            ToolKind::Turn => "Turn",
            ToolKind::Flow => "Flow",
        }
    }
}

/// The keys that pick the tools, in [`ToolKind::ALL`] order (the last two have none).
pub const TOOL_KEYS: [egui::Key; 10] = [
    egui::Key::Num1,
    egui::Key::Num2,
    egui::Key::Num3,
    egui::Key::Num4,
    egui::Key::Num5,
    egui::Key::Num6,
    egui::Key::Num7,
    egui::Key::Num8,
    egui::Key::Num9,
    egui::Key::Num0,
];

/// The drop tool's radius slider, design pixels (MIDI controllers move within it too).
pub const DROP_RADIUS: std::ops::RangeInclusive<f64> = 1.0..=300.0;
/// The stylus's wake slider, design pixels (logarithmic; MIDI controllers too).
pub const STYLUS_WAKE: std::ops::RangeInclusive<f64> = 0.5..=100.0;
/// The comb's tine spacing slider, design pixels (logarithmic; MIDI controllers too).
pub const COMB_SPACING: std::ops::RangeInclusive<f64> = 2.0..=400.0;
/// The flow's strength slider, design pixels per unit time (logarithmic; MIDI too).
pub const FLOW_STRENGTH: std::ops::RangeInclusive<f64> = 1.0..=200.0;

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
    /// Comb: number of tines (0 = endless tines across the whole sheet, a rake op).
    #[serde(alias = "rake_tines")]
    pub comb_tines: u32,
    /// Comb: distance between tines.
    #[serde(alias = "rake_spacing")]
    pub comb_spacing: f64,
    /// Comb sharpness λ.
    #[serde(alias = "rake_lambda")]
    pub comb_lambda: f64,
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
    /// How the drops of one click are laid out.
    pub drop_pattern: DropPattern,
    /// Drops of a line, coil or scatter pattern.
    pub pattern_count: u32,
    /// Distance between the drops (or rings) of a pattern.
    pub pattern_spacing: f64,
    /// Rings of a ring pattern.
    pub pattern_rings: u32,
    /// Rows of a grid pattern.
    pub pattern_rows: u32,
    /// Columns of a grid pattern.
    pub pattern_columns: u32,
    /// Jitter of a grid pattern, fraction of the spacing (0..=0.5).
    pub pattern_jitter: f64,
    /// Grid rows alternate direction.
    pub pattern_serpentine: bool,
    /// Size of a scatter pattern (4σ of a Gaussian one).
    pub pattern_spread: f64,
    /// Each drop (of a pattern, or each click) takes the next colour of the palette.
    pub cycle_colors: bool,
    /// Stylus wake L (a tip reaches 8L).
    pub stylus_wake: f64,
    /// Stylus tips (more than one: a free-hand comb).
    pub stylus_tips: u32,
    /// Distance between stylus tips.
    pub stylus_spacing: f64,
    /// Jiggle wavelength.
    pub jiggle_wavelength: f64,
    /// Jiggle amplitude along the drag (kept below wavelength/2π so it cannot fold).
    pub jiggle_along: f64,
    /// Jiggle amplitude across the drag.
    pub jiggle_across: f64,
    /// A pen's pressure (or a finger's force) scales the drop size and the stylus wake.
    pub pressure: bool,
    /// Flow: the size of the noise's features, 1/frequency.
    pub flow_size: f64,
    /// Flow: the noise's octaves.
    pub flow_octaves: u32,
    /// Flow: the strength U, design pixels per unit time.
    pub flow_strength: f64,
    /// Flow: the noise's seed.
    pub flow_seed: u32,
    /// Flow: value noise instead of Perlin noise.
    pub flow_value: bool,
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
            comb_tines: 0,
            comb_spacing: 40.0,
            comb_lambda: 6.0,
            wavy_amplitude: 15.0,
            wavy_wavelength: 120.0,
            wavy_phase: 0.0,
            circular_lambda: 12.0,
            vortex_lambda: 20.0,
            drop_pattern: DropPattern::Single,
            pattern_count: 8,
            pattern_spacing: 50.0,
            pattern_rings: 3,
            pattern_rows: 4,
            pattern_columns: 6,
            pattern_jitter: 0.0,
            pattern_serpentine: true,
            pattern_spread: 300.0,
            cycle_colors: false,
            stylus_wake: 6.0,
            stylus_tips: 1,
            stylus_spacing: 40.0,
            jiggle_wavelength: 120.0,
            jiggle_along: 5.0,
            jiggle_across: 12.0,
            pressure: true,
            flow_size: 160.0,
            flow_octaves: 2,
            flow_strength: 40.0,
            flow_seed: 1,
            flow_value: false,
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
    /// Design pixels per screen pixel when it began (a free-hand path is kept within
    /// half a screen pixel).
    pub pixel: f64,
    /// The pressure scale at each point of `path` ([`pressure_scale`]; 1 without a pen).
    pub scales: Vec<f64>,
    /// The largest pressure scale felt while the button was down; 0 before any.
    pub peak_scale: f64,
}

/// The size factor of a pointer's pressure `p` (0..=1; a mouse has none): 0.5, what a
/// device without pressure reports, is the set size; full pressure doubles it; the
/// lightest touch gives a quarter.
pub fn pressure_scale(p: Option<f64>) -> f64 {
    match p {
        Some(p) if p.is_finite() && p > 0.0 => (2.0 * p).clamp(0.25, 2.0),
        _ => 1.0,
    }
}

impl Gesture {
    /// A gesture that starts at `p`.
    pub fn new(p: Point) -> Self {
        Self {
            start: p,
            path: vec![p],
            held_seconds: 0.0,
            pixel: 1.0,
            scales: vec![1.0],
            peak_scale: 0.0,
        }
    }

    /// The gesture as the pen presses with scale `scale` now (the latest point's).
    pub fn feel(&mut self, scale: f64) {
        self.peak_scale = self.peak_scale.max(scale);
        if let Some(last) = self.scales.last_mut() {
            *last = scale;
        }
    }

    /// What a drop's size is multiplied by: the hardest press felt (1 with none).
    pub fn size_scale(&self) -> f64 {
        if self.peak_scale > 0.0 {
            self.peak_scale
        } else {
            1.0
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
/// is too small to mean anything (a click with a comb). `inks` is the ink, then the
/// colours drops cycle through (just the ink when they do not); `seed` makes spray
/// droplets and scattered patterns reproducible.
pub fn ops_for(kind: ToolKind, s: &ToolSettings, g: &Gesture, inks: &[Rgb8], seed: u64) -> Vec<Op> {
    unrounded_ops(kind, s, g, inks, seed)
        .iter()
        .map(Op::rounded)
        .collect()
}

/// The pattern the drop tool lays.
pub fn pattern_shape(s: &ToolSettings) -> PatternShape {
    PatternShape {
        pattern: s.drop_pattern,
        count: s.pattern_count,
        spacing: s.pattern_spacing,
        rings: s.pattern_rings,
        rows: s.pattern_rows,
        columns: s.pattern_columns,
        jitter: s.pattern_jitter,
        serpentine: s.pattern_serpentine,
        spread: s.pattern_spread,
    }
}

/// Radius of a drop held for `held` seconds.
pub fn drop_radius(s: &ToolSettings, held: f64) -> f64 {
    (s.drop_radius + s.drop_growth * held).min(s.drop_max_radius.max(s.drop_radius))
}

/// The drop tool's centres for a press at `a` dragged to `b` (a drag orients lines and
/// grids).
pub fn drop_centers(s: &ToolSettings, a: Point, b: Point, seed: u64) -> Vec<Point> {
    let drag = b - a;
    let along = if drag.hypot() >= 1.0 {
        drag.normalize()
    } else {
        Vec2::new(1.0, 0.0)
    };
    drop_patterns::centers(&pattern_shape(s), a, along, seed)
}

/// Offsets of the stylus tips across the path, centred on it.
pub fn stylus_tips(s: &ToolSettings) -> Option<Arc<[f64]>> {
    let n = s
        .stylus_tips
        .clamp(1, marbling_core::MAX_STYLUS_TIPS as u32);
    (n > 1).then(|| {
        let half = f64::from(n - 1) / 2.0;
        (0..n)
            .map(|i| (f64::from(i) - half) * s.stylus_spacing)
            .collect()
    })
}

/// The flow tool's settings for a drag of `length` design pixels: time = length/U (a
/// point moves about U px per unit time), cut to what [`marbling_core::MAX_FLOW_STEPS`]
/// sub-steps allow.
pub fn flow(s: &ToolSettings, length: f64) -> Flow {
    let mut f = Flow {
        noise: FbmParams {
            basis: if s.flow_value {
                Basis::Value
            } else {
                Basis::Perlin
            },
            frequency: (1.0 / s.flow_size.max(1.0)) as f32,
            octaves: s.flow_octaves.clamp(1, marbling_noise::MAX_OCTAVES),
            seed: s.flow_seed,
            ..FbmParams::default()
        },
        strength: s.flow_strength.max(0.01),
        time: 0.0,
    };
    f.time = (length / f.strength).min(f.longest_time());
    f
}

/// The largest jiggle amplitude along the drag that cannot fold the tank (|kA| ≤ 0.9).
pub fn jiggle_along_limit(wavelength: f64) -> f64 {
    0.9 * wavelength / std::f64::consts::TAU
}

fn unrounded_ops(
    kind: ToolKind,
    s: &ToolSettings,
    g: &Gesture,
    inks: &[Rgb8],
    seed: u64,
) -> Vec<Op> {
    let (a, b) = (g.start, g.end());
    let drag = b - a;
    let len = drag.hypot();
    let color = inks.first().copied().unwrap_or(Rgb8::new(0, 0, 0));
    match kind {
        ToolKind::Drop if s.drop_pattern == DropPattern::Single => {
            vec![Op::Drop(Drop {
                center: a,
                radius: drop_radius(s, g.held_seconds) * g.size_scale(),
                color,
            })]
        }
        ToolKind::Drop => {
            let centers = drop_centers(s, a, b, seed);
            vec![Op::Drops(DropSet {
                centers: centers.into(),
                radii: Radii::One(drop_radius(s, g.held_seconds) * g.size_scale()),
                colors: if s.cycle_colors && !inks.is_empty() {
                    inks.into()
                } else {
                    Arc::from([color])
                },
            })]
        }
        ToolKind::Spray => spray(s, g, color, seed),
        ToolKind::Stylus => {
            let kept = stroke::simplify_indices(&g.path, 0.5 * g.pixel);
            if kept.len() < 2 {
                return Vec::new();
            }
            let path: Vec<Point> = kept.iter().map(|&i| g.path[i]).collect();
            let scales: Vec<f64> = kept
                .iter()
                .map(|&i| g.scales.get(i).copied().unwrap_or(1.0))
                .collect();
            stroke::pressed_stylus_ops(&path, &scales, s.stylus_wake.max(0.5), stylus_tips(s))
                .into_iter()
                .map(Op::Stylus)
                .collect()
        }
        ToolKind::Shift => {
            if len < 0.5 {
                return Vec::new();
            }
            vec![Op::Shift(Shift { offset: drag })]
        }
        _ if len < 1.0
            && !matches!(kind, ToolKind::Circular | ToolKind::Vortex | ToolKind::Turn) =>
        {
            Vec::new()
        }
        ToolKind::Tine => vec![Op::Tine(Tine {
            origin: a,
            direction: drag,
            alpha: len,
            lambda: s.tine_lambda,
        })],
        ToolKind::Comb if s.comb_tines == 0 => vec![Op::Rake(Rake {
            origin: a,
            direction: drag,
            spacing: s.comb_spacing,
            alpha: len,
            lambda: s.comb_lambda,
        })],
        ToolKind::Comb => {
            let half = f64::from(s.comb_tines - 1) / 2.0;
            vec![Op::Comb(Comb {
                origin: a,
                direction: drag,
                tines: (0..s.comb_tines)
                    .map(|i| (f64::from(i) - half) * s.comb_spacing)
                    .collect(),
                alpha: len,
                lambda: s.comb_lambda,
            })]
        }
        ToolKind::Wavy => vec![Op::Wavy(Wavy {
            angle: drag.y.atan2(drag.x),
            amplitude: s.wavy_amplitude,
            wavelength: s.wavy_wavelength,
            phase: s.wavy_phase,
        })],
        ToolKind::Jiggle => {
            let wavelength = s.jiggle_wavelength.max(1.0);
            let limit = jiggle_along_limit(wavelength);
            vec![Op::Jiggle(Jiggle {
                angle: drag.y.atan2(drag.x),
                wavelength,
                along: s.jiggle_along.clamp(-limit, limit),
                across: s.jiggle_across,
                phase: 0.0,
            })]
        }
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
        ToolKind::Flow => vec![Op::Flow(flow(s, len))],
        ToolKind::Turn => {
            let angle = g.swept_angle(a);
            if angle.abs() < 1e-3 {
                return Vec::new();
            }
            vec![Op::Turn(Turn { center: a, angle })]
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
mod tests;
