//! Worley (cellular) noise: one jittered feature point per lattice cell; F1, F2 or
//! F2 − F1 under the Euclidean, Manhattan or Chebyshev metric; periodic variant.
//! Distances in lattice cells. Keep in sync with `shaders/worley.wgsl`.

use crate::hash::{CellRng, floor_i32, wrap_cell};

/// Which distance(s) the noise returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WorleyFeature {
    /// Distance to the nearest feature point.
    F1,
    /// Distance to the second nearest feature point.
    F2,
    /// F2 − F1 (bright cell borders).
    F2MinusF1,
}

/// The distance function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Metric {
    /// √(dx² + dy²).
    Euclidean,
    /// |dx| + |dy|.
    Manhattan,
    /// max(|dx|, |dy|).
    Chebyshev,
}

impl Metric {
    /// Index used by the WGSL (`0`, `1`, `2`).
    #[must_use]
    pub fn index(self) -> u32 {
        self as u32
    }

    #[inline(always)]
    fn distance(self, dx: f32, dy: f32) -> f32 {
        match self {
            Metric::Euclidean => (dx * dx + dy * dy).sqrt(),
            Metric::Manhattan => dx.abs() + dy.abs(),
            Metric::Chebyshev => dx.abs().max(dy.abs()),
        }
    }
}

impl WorleyFeature {
    /// Index used by the WGSL (`0`, `1`, `2`).
    #[must_use]
    pub fn index(self) -> u32 {
        self as u32
    }
}

/// `[F1, F2]` at (x, y) in lattice units: the two smallest distances to the feature
/// points of the 3×3 cells around the point (exact for F1 up to rare misses of far
/// points in distant cells; the usual trade-off). `period` > 0 wraps that axis.
#[must_use]
pub fn worley2(x: f32, y: f32, seed: u32, metric: Metric, period: [i32; 2]) -> [f32; 2] {
    let ix = floor_i32(x);
    let iy = floor_i32(y);
    let fx = x - ix as f32;
    let fy = y - iy as f32;
    let (mut f1, mut f2) = (f32::MAX, f32::MAX);
    for dj in -1..=1 {
        for di in -1..=1 {
            let mut rng = CellRng::new(
                wrap_cell(ix + di, period[0]),
                wrap_cell(iy + dj, period[1]),
                seed,
            );
            let px = di as f32 + rng.next_f32();
            let py = dj as f32 + rng.next_f32();
            let d = metric.distance(px - fx, py - fy);
            if d < f1 {
                f2 = f1;
                f1 = d;
            } else if d < f2 {
                f2 = d;
            }
        }
    }
    [f1, f2]
}

/// Mean and standard deviation of each feature (rows F1, F2, F2 − F1) under each metric
/// (columns Euclidean, Manhattan, Chebyshev), measured over 4·10⁶ points and checked by a
/// test; used to normalise to zero mean and unit variance.
pub const WORLEY_MOMENTS: [[[f32; 2]; 3]; 3] = [
    [[0.4299, 0.1900], [0.5411, 0.2414], [0.3819, 0.1695]],
    [[0.6991, 0.1765], [0.8771, 0.2244], [0.6215, 0.1597]],
    [[0.2692, 0.2009], [0.3359, 0.2513], [0.2395, 0.1799]],
];

/// The chosen feature of [`worley2`], normalised by [`WORLEY_MOMENTS`].
#[must_use]
pub fn worley_normalised(
    x: f32,
    y: f32,
    seed: u32,
    feature: WorleyFeature,
    metric: Metric,
    period: [i32; 2],
) -> f32 {
    normalise(worley2(x, y, seed, metric, period), feature, metric)
}

/// The chosen feature of `[F1, F2]` under `metric`, normalised by [`WORLEY_MOMENTS`].
#[inline]
#[must_use]
pub fn normalise([f1, f2]: [f32; 2], feature: WorleyFeature, metric: Metric) -> f32 {
    let d = match feature {
        WorleyFeature::F1 => f1,
        WorleyFeature::F2 => f2,
        WorleyFeature::F2MinusF1 => f2 - f1,
    };
    let [mean, std] = WORLEY_MOMENTS[feature as usize][metric as usize];
    (d - mean) / std
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moments_table() {
        let features = [
            WorleyFeature::F1,
            WorleyFeature::F2,
            WorleyFeature::F2MinusF1,
        ];
        let metrics = [Metric::Euclidean, Metric::Manhattan, Metric::Chebyshev];
        let mut report = String::new();
        let mut ok = true;
        for f in features {
            for m in metrics {
                let (mut s, mut s2) = (0.0_f64, 0.0_f64);
                let n = 600;
                for j in 0..n {
                    for i in 0..n {
                        let v = f64::from(worley_normalised(
                            i as f32 * 0.1373,
                            j as f32 * 0.1291,
                            5,
                            f,
                            m,
                            [0, 0],
                        ));
                        s += v;
                        s2 += v * v;
                    }
                }
                let c = f64::from(n * n);
                let mean = s / c;
                let var = s2 / c - mean * mean;
                report.push_str(&format!("{f:?} {m:?}: mean {mean:.4} var {var:.4}\n"));
                ok &= mean.abs() < 0.03 && (var - 1.0).abs() < 0.06;
            }
        }
        assert!(ok, "{report}");
    }

    #[test]
    fn f1_below_f2_and_metric_order() {
        for k in 0..200 {
            let (x, y) = (k as f32 * 0.731, k as f32 * 0.377);
            let [e1, e2] = worley2(x, y, 1, Metric::Euclidean, [0, 0]);
            let [m1, _] = worley2(x, y, 1, Metric::Manhattan, [0, 0]);
            let [c1, _] = worley2(x, y, 1, Metric::Chebyshev, [0, 0]);
            assert!(e1 <= e2);
            assert!(c1 <= e1 + 1e-6 && e1 <= m1 + 1e-6);
        }
    }
}
