//! The curve transfer: a remap of the default intensity t = 0.5 + n/6 (clamped to
//! [0, 1]) through control points, interpolated by a monotone cubic (Fritsch–Carlson:
//! it never overshoots between points, so a rising set of points gives a rising curve).
//! Left of the first point the curve holds the first y, right of the last the last y.

/// Most control points a curve may have.
pub const MAX_CURVE_POINTS: usize = 16;

/// Control points (x strictly increasing in [0, 1], y in [0, 1]) and their tangents.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    points: Vec<[f32; 2]>,
    tangents: Vec<f32>,
}

/// Why a list of points is not a curve.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CurveError {
    /// Fewer than 2 or more than [`MAX_CURVE_POINTS`].
    #[error("must have 2 to {MAX_CURVE_POINTS} points, got {0}")]
    Count(usize),
    /// A coordinate outside [0, 1].
    #[error("[{0}]: x and y must be in [0, 1]")]
    Range(usize),
    /// x not increasing.
    #[error("[{0}]: x must be greater than the previous point's")]
    Order(usize),
}

impl Curve {
    /// The curve through `points`.
    pub fn new(points: Vec<[f32; 2]>) -> Result<Self, CurveError> {
        if !(2..=MAX_CURVE_POINTS).contains(&points.len()) {
            return Err(CurveError::Count(points.len()));
        }
        for (i, p) in points.iter().enumerate() {
            if !p.iter().all(|v| (0.0..=1.0).contains(v)) {
                return Err(CurveError::Range(i));
            }
            if i > 0 && p[0] <= points[i - 1][0] {
                return Err(CurveError::Order(i));
            }
        }
        let n = points.len();
        let slope: Vec<f32> = points
            .windows(2)
            .map(|w| (w[1][1] - w[0][1]) / (w[1][0] - w[0][0]))
            .collect();
        let mut tangents = vec![0.0; n];
        tangents[0] = slope[0];
        tangents[n - 1] = slope[n - 2];
        for i in 1..n - 1 {
            tangents[i] = if slope[i - 1] * slope[i] <= 0.0 {
                0.0
            } else {
                (slope[i - 1] + slope[i]) / 2.0
            };
        }
        // Fritsch–Carlson: limit the tangents so each segment stays monotone.
        for (i, &d) in slope.iter().enumerate() {
            if d == 0.0 {
                tangents[i] = 0.0;
                tangents[i + 1] = 0.0;
                continue;
            }
            let (a, b) = (tangents[i] / d, tangents[i + 1] / d);
            let s = a * a + b * b;
            if s > 9.0 {
                let t = 3.0 / s.sqrt();
                tangents[i] = t * a * d;
                tangents[i + 1] = t * b * d;
            }
        }
        Ok(Self { points, tangents })
    }

    /// The straight line from (0, 0) to (1, 1): the default intensity unchanged.
    #[must_use]
    pub fn identity() -> Self {
        Self::new(vec![[0.0, 0.0], [1.0, 1.0]]).expect("valid")
    }

    /// The control points.
    #[must_use]
    pub fn points(&self) -> &[[f32; 2]] {
        &self.points
    }

    /// The curve at t ∈ [0, 1].
    #[must_use]
    pub fn eval(&self, t: f32) -> f32 {
        let p = &self.points;
        let last = p.len() - 1;
        if t <= p[0][0] {
            return p[0][1];
        }
        if t >= p[last][0] {
            return p[last][1];
        }
        let i = p.partition_point(|q| q[0] <= t) - 1;
        let h = p[i + 1][0] - p[i][0];
        let s = (t - p[i][0]) / h;
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        (h00 * p[i][1]
            + h10 * h * self.tangents[i]
            + h01 * p[i + 1][1]
            + h11 * h * self.tangents[i + 1])
            .clamp(0.0, 1.0)
    }

    /// The curve of the default intensity of noise value `n`.
    #[must_use]
    pub fn apply(&self, n: f32) -> f32 {
        self.eval(crate::noise_to_grey(n))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_curve_passes_its_points_and_stays_monotone() {
        let c = Curve::new(vec![[0.0, 0.0], [0.3, 0.1], [0.5, 0.8], [1.0, 1.0]]).expect("valid");
        for p in c.points() {
            assert!((c.eval(p[0]) - p[1]).abs() < 1e-6);
        }
        let mut last = -1.0;
        for i in 0..=1000 {
            let y = c.eval(i as f32 / 1000.0);
            assert!(y >= last - 1e-6, "falls at {i}");
            last = y;
        }
        let id = Curve::identity();
        assert!((id.eval(0.37) - 0.37).abs() < 1e-6);
        assert!((id.apply(0.0) - 0.5).abs() < 1e-6);
    }

    #[test]
    fn bad_points_are_named() {
        assert_eq!(Curve::new(vec![[0.0, 0.0]]), Err(CurveError::Count(1)));
        assert_eq!(
            Curve::new(vec![[0.0, 0.0], [0.0, 1.0]]),
            Err(CurveError::Order(1))
        );
        assert_eq!(
            Curve::new(vec![[0.0, 0.0], [1.0, 1.5]])
                .map(|_| ())
                .map_err(|e| e.to_string()),
            Err("[1]: x and y must be in [0, 1]".to_owned())
        );
    }
}
