//! Drop patterns: where the drops of one click fall (line, rings, grid, coil, uniform
//! and Gaussian scatter), in the order they fall. Seeded, so the ghost drops shown
//! before the click are the drops the click makes.

use marbling_core::synth::SplitMix64;
use marbling_core::{Point, Vec2};
use std::f64::consts::TAU;

/// Most drops one click lays (the op allows 10,000; a pattern this big is already a
/// whole sheet).
pub const MAX_PATTERN_DROPS: usize = 2_000;

/// How the drops of one click are laid out.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DropPattern {
    /// One drop.
    #[default]
    Single,
    /// `count` drops in a line through the click, `spacing` apart, along the drag.
    Line,
    /// Concentric rings around the click: ring k at radius k·spacing with ⌈2πk⌉ drops.
    Ring,
    /// `rows` × `columns` drops, `spacing` apart, jittered, in serpentine order.
    Grid,
    /// `count` drops along an Archimedean spiral out from the click, turns `spacing`
    /// apart, drops `spacing` apart along it.
    Coil,
    /// `count` drops uniformly in a square of side `spread` around the click.
    Scatter,
    /// `count` drops normally around the click, σ = `spread`/4.
    Gaussian,
}

impl DropPattern {
    /// Every pattern, in panel order.
    pub const ALL: [DropPattern; 7] = [
        DropPattern::Single,
        DropPattern::Line,
        DropPattern::Ring,
        DropPattern::Grid,
        DropPattern::Coil,
        DropPattern::Scatter,
        DropPattern::Gaussian,
    ];

    /// Name shown in the panel.
    pub fn label(self) -> &'static str {
        match self {
            DropPattern::Single => "single",
            DropPattern::Line => "line",
            DropPattern::Ring => "rings",
            DropPattern::Grid => "grid",
            DropPattern::Coil => "coil",
            DropPattern::Scatter => "scatter",
            DropPattern::Gaussian => "gaussian",
        }
    }
}

/// The parameters of a pattern (design pixels).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PatternShape {
    /// Which pattern.
    pub pattern: DropPattern,
    /// Drops of a line, coil or scatter.
    pub count: u32,
    /// Distance between neighbouring drops (line, grid, coil) or rings.
    pub spacing: f64,
    /// Rings around the centre drop.
    pub rings: u32,
    /// Grid rows and columns.
    pub rows: u32,
    /// Grid columns.
    pub columns: u32,
    /// Grid jitter, as a fraction of the spacing (0..=0.5).
    pub jitter: f64,
    /// Grid: every other row runs backwards (the order drops fall in).
    pub serpentine: bool,
    /// Side of the scatter square; 4σ of the Gaussian.
    pub spread: f64,
}

/// The centres of the drops clicked at `at`, in order; `along` is the unit direction of
/// lines and grid rows (the drag, or +x for a plain click).
pub fn centers(shape: &PatternShape, at: Point, along: Vec2, seed: u64) -> Vec<Point> {
    let mut rng = SplitMix64(seed ^ 0x5eed_d0d5);
    let across = Vec2::new(-along.y, along.x);
    let sp = shape.spacing.max(0.1);
    let mut out = Vec::new();
    match shape.pattern {
        DropPattern::Single => out.push(at),
        DropPattern::Line => {
            let n = shape.count.max(1);
            let half = f64::from(n - 1) / 2.0;
            out.extend((0..n).map(|i| at + along * ((f64::from(i) - half) * sp)));
        }
        DropPattern::Ring => {
            out.push(at);
            for k in 1..=shape.rings {
                let r = f64::from(k) * sp;
                let n = (TAU * f64::from(k)).ceil() as u32;
                out.extend(
                    (0..n).map(|i| at + Vec2::from_angle(TAU * f64::from(i) / f64::from(n)) * r),
                );
            }
        }
        DropPattern::Grid => {
            let (rows, cols) = (shape.rows.max(1), shape.columns.max(1));
            let (hr, hc) = (f64::from(rows - 1) / 2.0, f64::from(cols - 1) / 2.0);
            for r in 0..rows {
                for c in 0..cols {
                    let c = if shape.serpentine && r % 2 == 1 {
                        cols - 1 - c
                    } else {
                        c
                    };
                    let j = shape.jitter.clamp(0.0, 0.5) * sp;
                    let dx = rng.range(-j, j);
                    let dy = rng.range(-j, j);
                    out.push(
                        at + along * ((f64::from(c) - hc) * sp + dx)
                            + across * ((f64::from(r) - hr) * sp + dy),
                    );
                }
            }
        }
        DropPattern::Coil => {
            // r = b·θ with b = spacing/2π; steps of arc length ≈ spacing.
            let b = sp / TAU;
            let mut theta: f64 = 0.0;
            for _ in 0..shape.count.max(1) {
                out.push(at + Vec2::from_angle(theta) * (b * theta));
                let r = (b * theta).max(sp / 2.0);
                theta += sp / r.hypot(b);
            }
        }
        DropPattern::Scatter => {
            let h = shape.spread / 2.0;
            out.extend(
                (0..shape.count.max(1)).map(|_| at + Vec2::new(rng.range(-h, h), rng.range(-h, h))),
            );
        }
        DropPattern::Gaussian => {
            let sigma = shape.spread / 4.0;
            out.extend((0..shape.count.max(1)).map(|_| {
                // Box–Muller.
                let (u1, u2) = (rng.unit().max(1e-12), rng.unit());
                let r = sigma * (-2.0 * u1.ln()).sqrt();
                at + Vec2::from_angle(TAU * u2) * r
            }));
        }
    }
    out.truncate(MAX_PATTERN_DROPS);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(pattern: DropPattern) -> PatternShape {
        PatternShape {
            pattern,
            count: 5,
            spacing: 10.0,
            rings: 2,
            rows: 2,
            columns: 3,
            jitter: 0.0,
            serpentine: true,
            spread: 100.0,
        }
    }

    #[test]
    fn each_pattern_lays_its_drops_where_it_says() {
        let at = Point::new(100.0, 50.0);
        let x = Vec2::new(1.0, 0.0);
        let line = centers(&shape(DropPattern::Line), at, x, 1);
        assert_eq!(line.first(), Some(&Point::new(80.0, 50.0)));
        assert_eq!(line.len(), 5);
        let rings = centers(&shape(DropPattern::Ring), at, x, 1);
        // Centre, 7 drops at radius 10, 13 at radius 20.
        assert_eq!(rings.len(), 1 + 7 + 13);
        assert!(((rings[20] - at).hypot() - 20.0).abs() < 1e-9);
        let grid = centers(&shape(DropPattern::Grid), at, x, 1);
        // Serpentine: the second row runs right to left.
        assert_eq!(
            grid,
            [
                Point::new(90.0, 45.0),
                Point::new(100.0, 45.0),
                Point::new(110.0, 45.0),
                Point::new(110.0, 55.0),
                Point::new(100.0, 55.0),
                Point::new(90.0, 55.0)
            ]
        );
        let coil = centers(&shape(DropPattern::Coil), at, x, 1);
        let radii: Vec<f64> = coil.iter().map(|p| (*p - at).hypot()).collect();
        assert!(radii.windows(2).all(|w| w[1] > w[0]), "{radii:?}");
        for p in centers(&shape(DropPattern::Scatter), at, x, 3) {
            assert!((p.x - at.x).abs() <= 50.0 && (p.y - at.y).abs() <= 50.0);
        }
        // Seeded: the ghosts before the click are the drops of the click.
        assert_eq!(
            centers(&shape(DropPattern::Gaussian), at, x, 9),
            centers(&shape(DropPattern::Gaussian), at, x, 9)
        );
        assert_ne!(
            centers(&shape(DropPattern::Gaussian), at, x, 9),
            centers(&shape(DropPattern::Gaussian), at, x, 10)
        );
    }
}
