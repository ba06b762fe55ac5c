//! The canvas rectangle, enlarged by a margin, and the four open half-planes beyond it.

use kurbo::Point;

/// Margin around the canvas, output pixels, inside which outlines keep full accuracy.
pub const MARGIN_PX: f64 = 2.0;

/// The canvas `0..width × 0..height` grown by a margin on every side (design pixels).
/// Beyond it lie four half-planes: left (x < x0), right (x > x1), above (y < y0),
/// below (y > y1), numbered 0..4 in that order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Canvas {
    /// Left edge of the enlarged canvas.
    pub x0: f64,
    /// Top edge.
    pub y0: f64,
    /// Right edge.
    pub x1: f64,
    /// Bottom edge.
    pub y1: f64,
}

impl Canvas {
    /// The canvas of a `width × height` design grown by `margin` design pixels.
    pub fn new(width: f64, height: f64, margin: f64) -> Self {
        Self {
            x0: -margin,
            y0: -margin,
            x1: width + margin,
            y1: height + margin,
        }
    }

    /// How far `p` lies beyond each edge (positive: in that half-plane).
    pub fn beyond(&self, p: Point) -> [f64; 4] {
        [self.x0 - p.x, p.x - self.x1, self.y0 - p.y, p.y - self.y1]
    }

    /// Bit h set when `p` lies strictly in half-plane h.
    pub fn outside_mask(&self, p: Point) -> u8 {
        let b = self.beyond(p);
        (0..4).filter(|&h| b[h] > 0.0).fold(0, |m, h| m | 1 << h)
    }

    /// The largest distance d such that every point of `pts` lies at least d deep in one
    /// common half-plane; ≤ 0 when they share none.
    pub fn common_depth(&self, pts: &[Point]) -> f64 {
        let mut best = f64::NEG_INFINITY;
        for h in 0..4 {
            let depth = pts
                .iter()
                .map(|&p| self.beyond(p)[h])
                .fold(f64::INFINITY, f64::min);
            best = best.max(depth);
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_planes() {
        let c = Canvas::new(100.0, 50.0, 2.0);
        assert_eq!(c.outside_mask(Point::new(50.0, 25.0)), 0);
        assert_eq!(c.outside_mask(Point::new(-5.0, 25.0)), 1);
        assert_eq!(c.outside_mask(Point::new(105.0, 60.0)), 2 | 8);
        let d = c.common_depth(&[Point::new(-12.0, 0.0), Point::new(-7.0, 500.0)]);
        assert!((d - 5.0).abs() < 1e-12);
        assert!(c.common_depth(&[Point::new(-12.0, 0.0), Point::new(120.0, 0.0)]) <= 0.0);
    }
}
