//! How many samples per pixel the live preview takes, chosen from how fast preview
//! frames are drawn. While a device keeps up, the preview uses the user's antialiasing.
//! Once a drag's frames come slower than 30 per second (a software GPU such as
//! SwiftShader, a weak integrated GPU), it takes one sample per pixel for the rest of the
//! session: the cache is rendered at 2× the view's resolution and sampled bilinearly, so
//! the committed design stays smooth; only the edges the pending op itself draws are not
//! antialiased, and only until the release renders the design exactly.

use marbling_core::Antialias;

/// Preview frames measured before deciding.
pub const FRAMES_TO_DECIDE: usize = 10;
/// Median frame interval (seconds) above which the preview drops to one sample.
pub const SLOW_INTERVAL_S: f64 = 1.0 / 30.0;

/// The live preview's sampling decision.
#[derive(Debug, Default)]
pub struct PreviewQuality {
    /// Intervals of the preview frames of the current drag, seconds.
    intervals: Vec<f64>,
    reduced: bool,
}

impl PreviewQuality {
    /// Records the interval (seconds) ending at a preview frame with `samples` samples
    /// per pixel. One-sample previews cannot get cheaper, so they are not measured.
    pub fn record(&mut self, interval_s: f64, samples: usize) {
        if self.reduced || samples <= 1 || !interval_s.is_finite() {
            return;
        }
        self.intervals.push(interval_s);
        if self.intervals.len() >= FRAMES_TO_DECIDE {
            let mut sorted = self.intervals.clone();
            sorted.sort_by(f64::total_cmp);
            self.reduced = sorted[sorted.len() / 2] > SLOW_INTERVAL_S;
            self.intervals.clear();
        }
    }

    /// A drag ended: the next one is measured afresh (unless already reduced).
    pub fn end_drag(&mut self) {
        self.intervals.clear();
    }

    /// The preview's antialiasing for the user's choice `chosen`.
    pub fn antialias(&self, chosen: Antialias) -> Antialias {
        if self.reduced {
            Antialias::None
        } else {
            chosen
        }
    }

    /// True once the preview has dropped to one sample per pixel.
    pub fn reduced(&self) -> bool {
        self.reduced
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn drag(q: &mut PreviewQuality, interval_s: f64, frames: usize) {
        for _ in 0..frames {
            q.record(interval_s, 4);
        }
    }

    #[test]
    fn a_fast_device_keeps_the_chosen_antialiasing() {
        let mut q = PreviewQuality::default();
        drag(&mut q, 1.0 / 60.0, 100);
        assert!(!q.reduced());
        assert_eq!(q.antialias(Antialias::Rgss), Antialias::Rgss);
    }

    #[test]
    fn a_slow_device_drops_to_one_sample_after_ten_frames_and_stays_there() {
        let mut q = PreviewQuality::default();
        drag(&mut q, 0.05, FRAMES_TO_DECIDE - 1);
        assert!(!q.reduced(), "decided before {FRAMES_TO_DECIDE} frames");
        q.record(0.05, 4);
        assert!(q.reduced());
        assert_eq!(q.antialias(Antialias::Rgss), Antialias::None);
        q.end_drag();
        drag(&mut q, 1.0 / 60.0, 100);
        assert!(q.reduced(), "a reduced preview came back");
    }

    #[test]
    fn the_median_ignores_a_few_slow_frames() {
        let mut q = PreviewQuality::default();
        // The first frame of a drag and an occasional hitch are slow; the rest keep up.
        q.record(0.5, 4);
        q.record(0.2, 4);
        drag(&mut q, 1.0 / 60.0, FRAMES_TO_DECIDE - 2);
        assert!(!q.reduced());
    }

    #[test]
    fn one_sample_previews_and_nonsense_intervals_are_not_measured() {
        let mut q = PreviewQuality::default();
        for _ in 0..50 {
            q.record(0.1, 1);
            q.record(f64::NAN, 4);
            q.record(f64::INFINITY, 4);
        }
        assert!(!q.reduced());
    }

    #[test]
    fn a_drag_cut_short_is_not_judged_with_the_next() {
        let mut q = PreviewQuality::default();
        drag(&mut q, 0.05, FRAMES_TO_DECIDE - 1);
        q.end_drag();
        drag(&mut q, 1.0 / 60.0, FRAMES_TO_DECIDE);
        assert!(!q.reduced());
    }
}
