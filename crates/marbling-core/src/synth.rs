//! Deterministic random designs for tests and benchmarks (no external RNG: the same
//! seed gives the same design on every platform).

use crate::{
    Circular, Comb, Design, Drop, DropSet, Jiggle, Op, Radii, Rake, Rgb8, Shift, Spray, Stylus,
    Tine, Turn, Vortex, Wavy,
};
use kurbo::{Point, Vec2};
use std::sync::Arc;

/// SplitMix64: a tiny, well-distributed 64-bit generator.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform integer in 0..n (n > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
}

/// What a synthetic design is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mix {
    /// About 80 % drops and sprays, the rest combs and swirls.
    DropHeavy,
    /// A few drops first, then about 90 % tines, rakes and wavy combs.
    CombHeavy,
    /// All seven op types of schema v1 in roughly equal parts.
    Mixed,
    /// All fourteen op types (schema v1 and v3) in roughly equal parts.
    AllTypes,
    /// A few drop patterns first, then free-hand styli (one tip or several).
    Stylus,
    /// One drop first, then only ops of generator kind `k` (`0..KINDS`; the op's
    /// `type_name` says which): a per-kind cost profile.
    Only(u8),
}

/// How many op kinds the generator makes ([`Mix::Only`]'s range).
pub const KINDS: u8 = 14;

const PALETTE: [Rgb8; 6] = [
    Rgb8::new(0x1d, 0x35, 0x57),
    Rgb8::new(0xe6, 0x39, 0x46),
    Rgb8::new(0xf1, 0xfa, 0xee),
    Rgb8::new(0xa8, 0xda, 0xdc),
    Rgb8::new(0x45, 0x7b, 0x9d),
    Rgb8::new(0xe9, 0xc4, 0x6a),
];

/// A valid random design of `n_ops` ops on a `width × height` canvas.
pub fn random_design(seed: u64, width: u32, height: u32, n_ops: usize, mix: Mix) -> Design {
    let mut rng = SplitMix64(seed);
    let (w, h) = (f64::from(width), f64::from(height));
    let size = w.min(h);
    let mut design = Design::new(width, height, Rgb8::new(0xf3, 0xea, 0xd7));
    for i in 0..n_ops {
        let kind = match mix {
            Mix::DropHeavy => [0, 0, 0, 0, 0, 0, 1, 1, 2, 3, 4, 5][rng.below(12) as usize],
            Mix::CombHeavy if i < n_ops / 20 + 1 => 0,
            Mix::CombHeavy => [0, 2, 2, 2, 3, 3, 3, 4, 4, 5][rng.below(10) as usize],
            Mix::Mixed => rng.below(7) as usize,
            Mix::AllTypes => rng.below(14) as usize,
            Mix::Stylus if i < n_ops / 10 + 1 => 10,
            Mix::Stylus => 13,
            Mix::Only(_) if i == 0 => 0,
            Mix::Only(k) => usize::from(k.min(KINDS - 1)),
        };
        let center = Point::new(rng.range(0.0, w), rng.range(0.0, h));
        let color = PALETTE[rng.below(PALETTE.len() as u64) as usize];
        let angle = rng.range(0.0, std::f64::consts::TAU);
        let direction = Vec2::from_angle(angle);
        let alpha = rng.range(-0.15, 0.15) * size;
        let lambda = rng.range(0.01, 0.2) * size;
        let op = match kind {
            0 => Op::Drop(Drop {
                center,
                radius: rng.range(0.01, 0.08) * size,
                color,
            }),
            1 => Op::Spray(Spray {
                center,
                radius: rng.range(0.003, 0.02) * size,
                color,
            }),
            2 => Op::Tine(Tine {
                origin: center,
                direction,
                alpha,
                lambda,
            }),
            3 => Op::Rake(Rake {
                origin: center,
                direction,
                spacing: rng.range(0.04, 0.25) * size,
                alpha,
                lambda,
            }),
            4 => Op::Wavy(Wavy {
                angle,
                amplitude: rng.range(-0.05, 0.05) * size,
                wavelength: rng.range(0.1, 1.0) * size,
                phase: rng.range(0.0, std::f64::consts::TAU),
            }),
            5 => Op::Circular(Circular {
                center,
                radius: rng.range(0.05, 0.4) * size,
                alpha,
                lambda,
            }),
            6 => Op::Vortex(Vortex {
                center,
                alpha: alpha * 0.5,
                lambda,
            }),
            7 => Op::Shift(Shift {
                offset: direction * rng.range(0.0, 0.1 * size),
            }),
            8 => Op::Turn(Turn { center, angle }),
            9 => Op::Comb(Comb {
                origin: center,
                direction,
                tines: (0..1 + rng.below(12))
                    .map(|_| rng.range(-0.5, 0.5) * size)
                    .collect(),
                alpha,
                lambda,
            }),
            10 | 11 => {
                let n = 1 + rng.below(12) as usize;
                let centers: Arc<[Point]> = (0..n)
                    .map(|_| Point::new(rng.range(0.0, w), rng.range(0.0, h)))
                    .collect();
                let radii = if rng.below(2) == 0 {
                    Radii::One(rng.range(0.005, 0.05) * size)
                } else {
                    Radii::Each((0..n).map(|_| rng.range(0.005, 0.05) * size).collect())
                };
                let colors = (0..1 + rng.below(3))
                    .map(|_| PALETTE[rng.below(PALETTE.len() as u64) as usize])
                    .collect();
                let set = DropSet {
                    centers,
                    radii,
                    colors,
                };
                if kind == 10 {
                    Op::Drops(set)
                } else {
                    Op::Sprays(set)
                }
            }
            12 => {
                let wavelength = rng.range(0.1, 1.0) * size;
                Op::Jiggle(Jiggle {
                    angle,
                    wavelength,
                    // |kA| ≤ 0.8.
                    along: rng.range(-0.8, 0.8) * wavelength / std::f64::consts::TAU,
                    across: rng.range(-0.05, 0.05) * size,
                    phase: rng.range(0.0, std::f64::consts::TAU),
                })
            }
            _ => {
                let wake = rng.range(0.01, 0.04) * size;
                let mut at = center;
                let mut heading = angle;
                let path: Arc<[Point]> = (0..2 + rng.below(8))
                    .map(|k| {
                        if k > 0 {
                            heading += rng.range(-1.0, 1.0);
                            at += Vec2::from_angle(heading) * rng.range(0.02, 0.12) * size;
                        }
                        at
                    })
                    .collect();
                let tips = (rng.below(2) == 0).then(|| {
                    let spacing = rng.range(1.0, 4.0) * wake;
                    (0..2 + rng.below(3))
                        .map(|i| i as f64 * spacing)
                        .collect::<Arc<[f64]>>()
                });
                Op::Stylus(Stylus { path, wake, tips })
            }
        };
        design.ops.push(op);
    }
    design
}

/// A photo-like test picture of `width`×`height` pixels: smooth colour gradients, a few
/// soft discs and a fine checker band, deterministic for `seed` (image-background tests
/// and benchmarks; PNG-encode it with [`crate::RgbaImage::to_png`]).
pub fn test_photo(seed: u64, width: u32, height: u32) -> crate::RgbaImage {
    let mut rng = SplitMix64(seed);
    let discs: Vec<(f64, f64, f64, [f64; 3])> = (0..5)
        .map(|_| {
            (
                rng.unit(),
                rng.unit(),
                rng.range(0.08, 0.25),
                [rng.unit(), rng.unit(), rng.unit()],
            )
        })
        .collect();
    let mut img = crate::RgbaImage::filled(width, height, [0, 0, 0, 255]);
    for y in 0..height {
        for x in 0..width {
            let (u, v) = (
                (f64::from(x) + 0.5) / f64::from(width),
                (f64::from(y) + 0.5) / f64::from(height),
            );
            let mut c = [u, 0.5 * (1.0 - v) + 0.25 * u, v];
            for &(cx, cy, r, col) in &discs {
                let d = ((u - cx).powi(2) + (v - cy).powi(2)).sqrt() / r;
                let w = (1.0 - d).clamp(0.0, 1.0);
                for k in 0..3 {
                    c[k] += (col[k] - c[k]) * w;
                }
            }
            if (0.45..0.55).contains(&v) && (x / 4 + y / 4) % 2 == 0 {
                c = c.map(|ch| 1.0 - ch);
            }
            let b = c.map(|ch| (ch.clamp(0.0, 1.0) * 255.0).round() as u8);
            img.set_pixel(x, y, [b[0], b[1], b[2], 255]);
        }
    }
    img
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_makes_one_op_type_and_the_kinds_differ() {
        let mut names = Vec::new();
        for k in 0..KINDS {
            let d = random_design(3, 200, 100, 12, Mix::Only(k));
            assert_eq!(d.ops[0].type_name(), "drop", "kind {k} starts with a drop");
            let name = d.ops[1].type_name();
            assert!(
                d.ops[1..].iter().all(|op| op.type_name() == name),
                "kind {k}: {:?}",
                d.ops.iter().map(Op::type_name).collect::<Vec<_>>()
            );
            names.push(name);
        }
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), usize::from(KINDS), "{names:?}");
    }
}
