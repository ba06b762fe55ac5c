//! A uniform grid over an outline's vertices that tells whether replacing a chain of
//! the outline by its chord would sweep over another part of the same outline.

use crate::cellhash::CellMap;
use kurbo::Point;

/// Vertex buckets of one closed outline on square cells of side `cell`.
pub struct Guard<'a> {
    points: &'a [Point],
    cell: f64,
    buckets: CellMap<Vec<u32>>,
}

impl<'a> Guard<'a> {
    /// Buckets `points` on cells of side `cell` (> 0, design pixels); the chords it is
    /// asked about should deviate from their chains by at most `cell / 2`.
    pub fn new(points: &'a [Point], cell: f64) -> Self {
        let mut buckets: CellMap<Vec<u32>> = CellMap::default();
        let mut guard = Self {
            points,
            cell,
            buckets: CellMap::default(),
        };
        for (i, &p) in points.iter().enumerate() {
            buckets.entry(guard.key(p)).or_default().push(i as u32);
        }
        guard.buckets = buckets;
        guard
    }

    fn key(&self, p: Point) -> (i64, i64) {
        (
            (p.x / self.cell).floor() as i64,
            (p.y / self.cell).floor() as i64,
        )
    }

    /// Whether replacing the chain of vertices `a..=b` (indices mod n, `a < b ≤ n`) by
    /// the chord from `a` to `b` keeps clear of the rest of the outline: no other vertex
    /// lies inside the loop formed by the chain and the chord, and no other edge crosses
    /// the chord. Assumes the chain lies within `cell / 2` of the chord.
    pub fn chord_is_clear(&self, a: usize, b: usize) -> bool {
        let n = self.points.len();
        let (pa, pb) = (self.points[a], self.points[b % n]);
        let in_chain = |i: usize| (a <= i && i <= b) || (b == n && i == 0);
        // Cells within one cell of the chord cover every point within cell/2 of it.
        let len = (pb - pa).hypot();
        let steps = (2.0 * len / self.cell).ceil() as usize + 1;
        let mut keys = Vec::with_capacity(9 * (steps + 1));
        for s in 0..=steps {
            let (kx, ky) = self.key(pa.lerp(pb, s as f64 / steps as f64));
            for dx in -1..=1 {
                for dy in -1..=1 {
                    keys.push((kx + dx, ky + dy));
                }
            }
        }
        keys.sort_unstable();
        keys.dedup();
        for key in keys {
            let Some(bucket) = self.buckets.get(&key) else {
                continue;
            };
            for &i in bucket {
                let i = i as usize;
                if in_chain(i) {
                    continue;
                }
                let v = self.points[i];
                if self.winds(v, a, b) {
                    return false;
                }
                for j in [(i + n - 1) % n, (i + 1) % n] {
                    let w = self.points[j];
                    let shares_end = v == pa || v == pb || w == pa || w == pb;
                    if !shares_end && crosses(v, w, pa, pb) {
                        return false;
                    }
                }
            }
        }
        true
    }

    /// Nonzero winding of the loop (chain `a..=b`, then back to `a`) around `p`.
    fn winds(&self, p: Point, a: usize, b: usize) -> bool {
        let n = self.points.len();
        let mut winding = 0i32;
        let mut prev = self.points[a];
        for k in a + 1..=b + 1 {
            let cur = if k == b + 1 {
                self.points[a]
            } else {
                self.points[k % n]
            };
            let cross = (cur - prev).cross(p - prev);
            if prev.y <= p.y {
                if cur.y > p.y && cross > 0.0 {
                    winding += 1;
                }
            } else if cur.y <= p.y && cross < 0.0 {
                winding -= 1;
            }
            prev = cur;
        }
        winding != 0
    }
}

/// Whether segments p–q and r–s cross at a point interior to both.
fn crosses(p: Point, q: Point, r: Point, s: Point) -> bool {
    let d1 = (s - r).cross(p - r);
    let d2 = (s - r).cross(q - r);
    let d3 = (q - p).cross(r - p);
    let d4 = (q - p).cross(s - p);
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_chords_across_a_thin_filament() {
        // A hairpin 0.2 wide: along y = 0 with a bump, back along y = 0.2.
        let mut pts: Vec<Point> = (0..=10)
            .map(|i| Point::new(f64::from(i), if i == 5 { 0.3 } else { 0.0 }))
            .collect();
        pts.extend((0..=10).rev().map(|i| Point::new(f64::from(i), 0.2)));
        let guard = Guard::new(&pts, 1.0);
        // The bump's chord 4..6 passes below the other side: clear. The chain 0..10
        // folds over the other side's vertex near (5, 0.2): blocked.
        assert!(guard.chord_is_clear(0, 3));
        assert!(!guard.chord_is_clear(3, 7));
    }
}
