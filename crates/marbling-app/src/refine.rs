//! Progressive rendering: a render too big for one frame is drawn in tiles over
//! successive frames, each tile sized so its estimated GPU time fits a per-frame budget.
//! The estimate adapts to the measured completion time of earlier tiles.
//!
//! Work is counted in *op-samples*: pixels × samples per pixel × ops walked (plus a
//! small per-sample constant), the unit the exact shader's cost grows with.

/// GPU time one refinement tile may take, ms (one submission each; a frame draws one
/// to three, see `canvas_gpu::TILES_WHILE_IDLE`). It keeps the page's frames coming
/// (≈ 20 per second on a software GPU, whose frames cost ~20 ms besides, while the user
/// acts) and any one submission far from a driver's watchdog (about 2 s).
pub const FRAME_BUDGET_MS: f64 = 30.0;

/// What the first tile assumes before anything was measured: op-samples per ms
/// (a software GPU does about 4e4; a laptop GPU 1e6 and more).
const PRIOR_RATE: f64 = 1.0e5;

/// A tile never grows past this many times the largest tile measured so far, so a
/// wrong estimate costs at most one slow frame.
const MAX_GROWTH: f64 = 4.0;

/// Samples' fixed cost, in ops walked (loading params, averaging, writing the pixel).
const SAMPLE_OVERHEAD_OPS: u64 = 4;

/// Tiles submitted but not yet heard of beyond which no new tile is submitted (the
/// queue never holds much more than a frame's worth of refinement).
pub const MAX_IN_FLIGHT: usize = 4;

/// Op-samples of one pixel of a render of `ops` ops with `samples` samples per pixel.
pub fn per_pixel(ops: usize, samples: usize) -> u64 {
    (ops as u64 + SAMPLE_OVERHEAD_OPS) * samples.max(1) as u64
}

/// The adaptive estimate of the GPU's speed, in op-samples per ms.
#[derive(Clone, Debug)]
pub struct TileBudget {
    /// Smoothed measured rate (`None` until a tile was measured).
    rate: Option<f64>,
    /// The largest tile measured so far, op-samples.
    largest: u64,
    /// When the last measured tile finished, ms (a tile queued behind it starts then).
    last_done_ms: f64,
}

impl Default for TileBudget {
    fn default() -> Self {
        Self {
            rate: None,
            largest: 0,
            last_done_ms: f64::NEG_INFINITY,
        }
    }
}

impl TileBudget {
    /// The op-samples the next tile may have to take about `budget_ms` of GPU time.
    pub fn units(&self, budget_ms: f64) -> u64 {
        let rate = self.rate.unwrap_or(PRIOR_RATE);
        let mut units = rate * budget_ms;
        let cap = if self.largest == 0 {
            PRIOR_RATE * budget_ms
        } else {
            MAX_GROWTH * self.largest as f64
        };
        units = units.min(cap);
        units.max(1.0) as u64
    }

    /// Records a tile of `units` op-samples submitted at `submitted_ms` and finished at
    /// `done_ms` (the queue is serial: its work started when both it was submitted and
    /// the tile before it was done).
    pub fn record(&mut self, units: u64, submitted_ms: f64, done_ms: f64) {
        let start = submitted_ms.max(self.last_done_ms);
        self.last_done_ms = self.last_done_ms.max(done_ms);
        // A clock with 1 ms steps: a tile finished within one step took at most 1 ms.
        let ms = (done_ms - start).max(1.0);
        let rate = units as f64 / ms;
        // Smoothed towards the new value, faster when it is slower (a heavy region
        // must shrink the next tile at once).
        self.rate = Some(match self.rate {
            None => rate,
            Some(old) if rate < old => 0.3 * old + 0.7 * rate,
            Some(old) => 0.7 * old + 0.3 * rate,
        });
        self.largest = self.largest.max(units);
    }

    /// The measured rate, op-samples per ms (`None` before the first measurement).
    pub fn rate(&self) -> Option<f64> {
        self.rate
    }
}

/// A rectangle of pixels: x, y, width, height.
pub type PixelRect = [u32; 4];

/// The tiles of one render: horizontal bands, top to bottom, each cut left to right
/// into tiles as wide as the budget allows. What is done is always the bands above the
/// current one plus the part of the current band left of the cursor.
#[derive(Clone, Debug, PartialEq)]
pub struct Refinement {
    /// The region to draw (x, y, width, height).
    region: PixelRect,
    /// The next tile's top-left corner.
    x: u32,
    y: u32,
    /// The current band's height (chosen at its first tile).
    band: u32,
}

impl Refinement {
    /// A refinement of `region` with nothing drawn yet.
    pub fn new(region: PixelRect) -> Self {
        Self {
            region,
            x: region[0],
            y: region[1],
            band: 0,
        }
    }

    /// True once every pixel of the region was handed out.
    pub fn is_done(&self) -> bool {
        self.region[2] == 0 || self.y >= self.region[1] + self.region[3]
    }

    /// The fraction of the region's pixels handed out, 0..=1.
    pub fn progress(&self) -> f64 {
        let [x0, y0, w, h] = self.region;
        let total = u64::from(w) * u64::from(h);
        if total == 0 || self.is_done() {
            return 1.0;
        }
        let done =
            u64::from(self.y - y0) * u64::from(w) + u64::from(self.x - x0) * u64::from(self.band);
        done as f64 / total as f64
    }

    /// The next tile, with at most about `pixels` pixels (at least one), or `None` when
    /// the region is done. A band's height is the square root of the first tile's
    /// pixels, so tiles stay roughly square while the budget holds still.
    pub fn next_tile(&mut self, pixels: u64) -> Option<PixelRect> {
        if self.is_done() {
            return None;
        }
        let [x0, y0, w, h] = self.region;
        let (x1, y1) = (x0 + w, y0 + h);
        let pixels = pixels.max(1);
        if self.x == x0 {
            let side = (pixels as f64).sqrt().floor() as u64;
            // A band that covers the whole width when the budget allows more than one row.
            let rows = if pixels >= u64::from(w) {
                pixels / u64::from(w)
            } else {
                side
            };
            self.band = rows.clamp(1, u64::from(y1 - self.y)) as u32;
        }
        let cols = (pixels / u64::from(self.band)).clamp(1, u64::from(x1 - self.x)) as u32;
        let tile = [self.x, self.y, cols, self.band];
        self.x += cols;
        if self.x >= x1 {
            self.x = x0;
            self.y += self.band;
        }
        Some(tile)
    }

    /// The drawn part as at most two rectangles (the full bands, the current band's
    /// finished part); empty rectangles are left out.
    pub fn done_rects(&self) -> Vec<PixelRect> {
        let [x0, y0, w, h] = self.region;
        if self.is_done() {
            return if w > 0 && h > 0 {
                vec![self.region]
            } else {
                Vec::new()
            };
        }
        [
            [x0, y0, w, self.y - y0],
            [x0, self.y, self.x - x0, self.band],
        ]
        .into_iter()
        .filter(|r| r[2] > 0 && r[3] > 0)
        .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cover(mut r: Refinement, pixels: impl Fn(u64) -> u64) -> Vec<PixelRect> {
        let mut tiles = Vec::new();
        while let Some(t) = r.next_tile(pixels(tiles.len() as u64)) {
            tiles.push(t);
            assert!(tiles.len() < 100_000, "does not end");
        }
        tiles
    }

    #[test]
    fn tiles_cover_the_region_once_whatever_the_budget_does() {
        let region = [3, 5, 37, 23];
        for budget in [
            &(|_| 1u64) as &dyn Fn(u64) -> u64,
            &|_| 7,
            &|_| 100,
            &|_| 10_000,
            &|k| [5, 300, 17, 2, 90][k as usize % 5],
        ] {
            let tiles = cover(Refinement::new(region), budget);
            let mut seen = vec![0u8; 37 * 23];
            for [x, y, w, h] in tiles {
                for yy in y..y + h {
                    for xx in x..x + w {
                        assert!((3..40).contains(&xx) && (5..28).contains(&yy));
                        seen[((yy - 5) * 37 + xx - 3) as usize] += 1;
                    }
                }
            }
            assert!(seen.iter().all(|&n| n == 1), "a pixel drawn twice or never");
        }
    }

    #[test]
    fn tiles_keep_to_the_budget_and_progress_is_what_is_done() {
        let mut r = Refinement::new([0, 0, 100, 50]);
        assert_eq!(r.progress(), 0.0);
        let t = r.next_tile(64).unwrap();
        // 64 pixels: an 8-row band, 8 columns.
        assert_eq!(t, [0, 0, 8, 8]);
        assert!((r.progress() - 64.0 / 5000.0).abs() < 1e-12);
        assert_eq!(r.done_rects(), vec![[0, 0, 8, 8]]);
        // The band keeps its height; width follows the budget.
        assert_eq!(r.next_tile(160).unwrap(), [8, 0, 20, 8]);
        // More than a row: whole-width bands.
        let mut r = Refinement::new([0, 0, 100, 50]);
        assert_eq!(r.next_tile(1000).unwrap(), [0, 0, 100, 10]);
        assert_eq!(r.done_rects(), vec![[0, 0, 100, 10]]);
        assert_eq!(r.next_tile(100_000).unwrap(), [0, 10, 100, 40]);
        assert!(r.is_done());
        assert_eq!(r.progress(), 1.0);
        assert_eq!(r.next_tile(5), None);
        assert_eq!(r.done_rects(), vec![[0, 0, 100, 50]]);
    }

    #[test]
    fn the_budget_follows_measurements_and_grows_by_steps() {
        let mut b = TileBudget::default();
        let first = b.units(FRAME_BUDGET_MS);
        assert_eq!(first, (PRIOR_RATE * FRAME_BUDGET_MS) as u64);
        // A fast GPU: the tile took 1 ms; the next may be at most 4× as large.
        b.record(first, 0.0, 1.0);
        assert_eq!(b.units(FRAME_BUDGET_MS), 4 * first);
        // A slow one: 300 ms for the same work; the next tile is cut to about a tenth.
        let mut b = TileBudget::default();
        b.record(first, 0.0, 300.0);
        let next = b.units(FRAME_BUDGET_MS);
        assert!(next * 9 < first && next * 11 > first, "{next} vs {first}");
        // A tile queued behind another starts when that one is done.
        let mut b = TileBudget::default();
        b.record(1000, 0.0, 100.0);
        b.record(1000, 0.0, 110.0);
        // (counted from its submission it would seem to take 110 ms: rate ≈ 9)
        assert!(b.rate().unwrap() > 30.0, "{:?}", b.rate());
    }

    #[test]
    fn an_empty_region_is_done_at_once() {
        let mut r = Refinement::new([0, 0, 0, 10]);
        assert!(r.is_done());
        assert_eq!(r.next_tile(10), None);
        assert_eq!(r.progress(), 1.0);
        assert!(r.done_rects().is_empty());
    }
}
