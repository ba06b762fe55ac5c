//! Progressive rendering: a render too big for one frame is drawn in tiles over
//! successive frames. How much a frame draws adapts to how long frames take: the tiles'
//! GPU work delays the next frame (a browser holds back its animation frames, a native
//! swap chain its images, while the GPU is behind), so the interval between two frames
//! is the completion time of the tiles drawn in them plus everything else in a frame,
//! the thing a user feels.
//!
//! Work is counted in *op-samples*: pixels × samples per pixel × ops walked (plus a
//! small per-sample constant), the unit the exact shader's cost grows with.
//!
//! Why frame intervals and not each tile's own completion callback: browsers report
//! finished GPU work late and in batches (a tile of 5 ms can be heard of a frame later,
//! with its neighbours), so per-tile times mix the GPU's speed with the report's delay,
//! and a budget steered by them shrank to 1,457 tiles for a 5,000-op frame that took
//! 42 s (docs/BENCHMARKS.md). Tiles are squares where a row is too much: on SwiftShader
//! one-row tiles shade 4× slower per pixel (half of each 2 × 2 quad is wasted, and one
//! row runs on one thread).

/// Frame interval aimed at while the user acts (pointer moving or pressed, keys), ms:
/// input stays live at ≥ 30 frames per second wherever the page alone allows it.
pub const ACTIVE_FRAME_MS: f64 = 33.0;

/// Frame interval aimed at while the user does nothing, ms: most of a frame goes to the
/// exact frame, and the page still answers within a tenth of a second.
pub const IDLE_FRAME_MS: f64 = 100.0;

/// Where a page's frames are slower than [`IDLE_FRAME_MS`] on their own (a software or
/// weak GPU), an idle frame may take this many times the interval measured at the
/// floor's work ([`MIN_UNITS`]): refinement then gets about half of each frame instead
/// of the floor's sliver. Measured on SwiftShader (2 cores, the app at 1000×660): frames
/// of 76 ms on their own, 126 ms at the floor; the first exact frame of the Stone
/// pattern 22 → 11–16 s (WebGL2), 28 → 11–21 s (WebGPU) (`tests/browser/boot-bench.mjs`).
pub const IDLE_STRETCH: f64 = 2.0;

/// What is kept per frame of the interval measured at the floor once the work is above
/// it: a page that got faster is seen again (the aim falls back to the floor and is
/// measured anew) within a few hundred frames, long after a refinement ends.
const FLOOR_FADE: f64 = 0.998;

/// How the user is using the page, which sets the frame interval aimed at.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pace {
    /// Pointer moving or pressed, keys: [`ACTIVE_FRAME_MS`].
    Active,
    /// Nothing: [`IDLE_FRAME_MS`], stretched by [`IDLE_STRETCH`] on slow pages.
    Idle,
}

/// What the first frame draws before anything was measured, op-samples (about the
/// idle aim's worth on SwiftShader, the slowest GPU the app meets; a real GPU gets to
/// its own budget in a few frames of growth).
const PRIOR_UNITS: f64 = 4.0e6;

/// The largest change of a frame's work from one frame to the next (a factor).
pub const MAX_STEP: f64 = 1.4;

/// The smallest frame's work, op-samples (≈ 50 ms on SwiftShader, nothing on a real
/// GPU): where a page's frames are slower than the aim on their own (WebGL2 on
/// SwiftShader with a noise background, measured), shrinking the tiles cannot bring
/// the interval down, and a smaller floor made refinement crawl (9 pixels a frame).
const MIN_UNITS: f64 = 2.0e6;

/// Samples' fixed cost, in ops walked (loading params, averaging, writing the pixel).
const SAMPLE_OVERHEAD_OPS: u64 = 4;

/// Tiles submitted but not yet heard of beyond which no new tile is submitted (a guard
/// for a queue that does not hold frames back).
pub const MAX_IN_FLIGHT: usize = 12;

/// Op-samples of one pixel of a render of ops costing `cost` simple ops
/// ([`marbling_core::Op::walk_cost`]: a comb counts its tines, a stylus its segments)
/// with `samples` samples per pixel.
pub fn per_pixel(cost: u64, samples: usize) -> u64 {
    (cost + SAMPLE_OVERHEAD_OPS) * samples.max(1) as u64
}

/// How much refinement a frame draws, op-samples, steered by frame intervals.
#[derive(Clone, Debug)]
pub struct FrameBudget {
    units: f64,
    /// The frame interval last measured with the work at [`MIN_UNITS`], ms (faded by
    /// [`FLOOR_FADE`] a frame since); 0 before any.
    floor_ms: f64,
}

impl Default for FrameBudget {
    fn default() -> Self {
        Self {
            units: PRIOR_UNITS,
            floor_ms: 0.0,
        }
    }
}

impl FrameBudget {
    /// Op-samples the next frame's tiles may take together.
    pub fn units(&self) -> u64 {
        self.units as u64
    }

    /// The frame interval aimed at for `pace`, ms.
    pub fn aim_ms(&self, pace: Pace) -> f64 {
        match pace {
            Pace::Active => ACTIVE_FRAME_MS,
            Pace::Idle => IDLE_FRAME_MS.max(IDLE_STRETCH * self.floor_ms),
        }
    }

    /// A frame that drew tiles at `pace` was followed by the next one `interval_ms`
    /// later. The work grows or shrinks by the square root of the ratio of the aim to
    /// the interval, by at most [`MAX_STEP`] a frame: the measurement lags a frame or
    /// two behind the work, so bolder steps overshoot (measured: worst gaps of 600 ms
    /// with ×2 steps).
    pub fn record_frame(&mut self, interval_ms: f64, pace: Pace) {
        if interval_ms.is_nan() || interval_ms <= 0.0 {
            return;
        }
        if self.units <= MIN_UNITS {
            self.floor_ms = interval_ms;
        } else {
            self.floor_ms *= FLOOR_FADE;
        }
        let factor = (self.aim_ms(pace) / interval_ms)
            .sqrt()
            .clamp(1.0 / MAX_STEP, MAX_STEP);
        self.units = (self.units * factor).max(MIN_UNITS);
    }
}

/// One [`FrameBudget`] per [`Pace`]: when the user starts acting, the first frame draws
/// the active budget's work, not the (larger) idle one's.
#[derive(Clone, Debug, Default)]
pub struct PacedBudget {
    active: FrameBudget,
    idle: FrameBudget,
}

impl PacedBudget {
    /// The budget of `pace`.
    pub fn of(&self, pace: Pace) -> &FrameBudget {
        match pace {
            Pace::Active => &self.active,
            Pace::Idle => &self.idle,
        }
    }

    /// [`FrameBudget::record_frame`] on the budget of `pace`.
    pub fn record_frame(&mut self, interval_ms: f64, pace: Pace) {
        match pace {
            Pace::Active => &mut self.active,
            Pace::Idle => &mut self.idle,
        }
        .record_frame(interval_ms, pace);
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
        let t = r.next_tile(64).expect("a tile");
        // 64 pixels: an 8-row band, 8 columns.
        assert_eq!(t, [0, 0, 8, 8]);
        assert!((r.progress() - 64.0 / 5000.0).abs() < 1e-12);
        assert_eq!(r.done_rects(), vec![[0, 0, 8, 8]]);
        // The band keeps its height; width follows the budget.
        assert_eq!(r.next_tile(160).expect("a tile"), [8, 0, 20, 8]);
        // More than a row: whole-width bands.
        let mut r = Refinement::new([0, 0, 100, 50]);
        assert_eq!(r.next_tile(1000).expect("a tile"), [0, 0, 100, 10]);
        assert_eq!(r.done_rects(), vec![[0, 0, 100, 10]]);
        assert_eq!(r.next_tile(100_000).expect("a tile"), [0, 10, 100, 40]);
        assert!(r.is_done());
        assert_eq!(r.progress(), 1.0);
        assert_eq!(r.next_tile(5), None);
        assert_eq!(r.done_rects(), vec![[0, 0, 100, 50]]);
    }

    /// A model of a page: a frame takes `fixed` ms besides the tiles, and the GPU does
    /// `rate` op-samples per ms; the budget must settle where frames take the target.
    fn settle(fixed: f64, rate: f64, pace: Pace, frames: usize) -> (f64, f64) {
        let mut b = FrameBudget::default();
        let mut interval = 0.0;
        for _ in 0..frames {
            interval = fixed + b.units() as f64 / rate;
            b.record_frame(interval, pace);
        }
        (interval, b.units() as f64)
    }

    #[test]
    fn the_budget_settles_where_frames_take_the_aim() {
        // SwiftShader-like: 25 ms a frame besides, 5e4 op-samples per ms.
        let (interval, units) = settle(25.0, 5e4, Pace::Idle, 200);
        assert!((interval - IDLE_FRAME_MS).abs() < 1.0, "{interval}");
        assert!((units - 75.0 * 5e4).abs() < 5e4, "{units}");
        // A fast GPU at 60 frames per second: the tiles take the rest of 33 ms.
        let (interval, _) = settle(16.7, 5e7, Pace::Active, 200);
        assert!((interval - ACTIVE_FRAME_MS).abs() < 0.5, "{interval}");
        // A page slower than the aim on its own while the user acts: the work shrinks
        // to its floor but never stops.
        let (_, units) = settle(150.0, 5e4, Pace::Active, 200);
        assert_eq!(units, MIN_UNITS);
    }

    #[test]
    fn on_a_slow_page_an_idle_frame_stretches_to_twice_the_floors_interval() {
        // SwiftShader at 1000×660: 76 ms a frame on its own, 4e4 op-samples per ms.
        let (fixed, rate) = (76.0, 4e4);
        let floor = fixed + MIN_UNITS / rate;
        let frame =
            |b: &mut FrameBudget, pace| b.record_frame(fixed + b.units() as f64 / rate, pace);
        let mut b = FrameBudget::default();
        for _ in 0..40 {
            frame(&mut b, Pace::Idle);
        }
        let interval = fixed + b.units() as f64 / rate;
        // Within the fade of 40 frames (0.998^40 = 0.92).
        assert!(
            (interval / (IDLE_STRETCH * floor) - 1.0).abs() < 0.1,
            "{interval}"
        );
        // Refinement per ms of frame: 1.7 times the floor's.
        assert!(
            b.units() as f64 / interval > 1.6 * MIN_UNITS / floor,
            "{b:?}"
        );
        // The measure fades: a hundred frames later the aim has come down (0.998^100).
        let aim = b.aim_ms(Pace::Idle);
        for _ in 0..100 {
            frame(&mut b, Pace::Idle);
        }
        let faded = b.aim_ms(Pace::Idle) / aim;
        assert!((0.8..0.84).contains(&faded), "{faded}");
        // While the user acts, frames aim at the active interval (the floor, here).
        for _ in 0..10 {
            frame(&mut b, Pace::Active);
        }
        assert_eq!(b.units() as f64, MIN_UNITS);
    }

    #[test]
    fn the_budget_moves_by_bounded_steps() {
        let mut b = FrameBudget::default();
        b.record_frame(1.0, Pace::Idle);
        assert_eq!(b.units(), (PRIOR_UNITS * MAX_STEP) as u64);
        let mut b = FrameBudget::default();
        b.record_frame(10_000.0, Pace::Idle);
        let shrunk = (PRIOR_UNITS / MAX_STEP) as u64;
        assert_eq!(b.units(), shrunk);
        // No interval measured: nothing changes.
        b.record_frame(0.0, Pace::Idle);
        b.record_frame(f64::NAN, Pace::Idle);
        assert_eq!(b.units(), shrunk);
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
