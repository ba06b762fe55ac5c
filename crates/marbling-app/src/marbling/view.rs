//! The canvas view: which part of the design is on screen and how large.

use marbling_core::{Design, Point};

/// Zoom limits, screen points per design pixel.
pub const MIN_ZOOM: f64 = 0.02;
/// Zoomed in far enough to inspect edges: every render is still exact.
pub const MAX_ZOOM: f64 = 400.0;

/// Screen mapping of the design: `zoom` points per design pixel, `origin` the design
/// point at the canvas's top-left corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewState {
    /// Screen points per design pixel.
    pub zoom: f64,
    /// Design point at the canvas's top-left corner.
    pub origin: Point,
}

impl Default for ViewState {
    fn default() -> Self {
        Self {
            zoom: 1.0,
            origin: Point::ZERO,
        }
    }
}

impl ViewState {
    /// The view that shows the whole design centred in a canvas of `size` points, with
    /// a small margin.
    pub fn fit(design: &Design, size: [f64; 2]) -> Self {
        let (w, h) = (f64::from(design.width), f64::from(design.height));
        let zoom = ((size[0] - 16.0) / w)
            .min((size[1] - 16.0) / h)
            .clamp(MIN_ZOOM, MAX_ZOOM);
        let origin = Point::new(
            w / 2.0 - size[0] / 2.0 / zoom,
            h / 2.0 - size[1] / 2.0 / zoom,
        );
        Self { zoom, origin }
    }

    /// Moves the origin by less than one physical pixel so that design pixel corners
    /// fall on physical pixel corners (`ppp` physical pixels per point): the canvas then
    /// samples exactly the points a CPU render at `zoom × ppp` samples.
    pub fn snapped(mut self, ppp: f64) -> Self {
        let scale = self.zoom * ppp;
        self.origin = Point::new(
            (self.origin.x * scale).round() / scale,
            (self.origin.y * scale).round() / scale,
        );
        self
    }

    /// The design point under canvas-relative screen position `p` (points).
    pub fn to_design(self, p: [f64; 2]) -> Point {
        Point::new(
            self.origin.x + p[0] / self.zoom,
            self.origin.y + p[1] / self.zoom,
        )
    }

    /// The canvas-relative screen position (points) of design point `d`.
    pub fn to_screen(self, d: Point) -> [f64; 2] {
        [
            (d.x - self.origin.x) * self.zoom,
            (d.y - self.origin.y) * self.zoom,
        ]
    }

    /// Zooms by `factor` keeping the design point under canvas position `at` fixed.
    pub fn zoom_about(&mut self, factor: f64, at: [f64; 2]) {
        let anchor = self.to_design(at);
        self.zoom = (self.zoom * factor).clamp(MIN_ZOOM, MAX_ZOOM);
        self.origin = Point::new(anchor.x - at[0] / self.zoom, anchor.y - at[1] / self.zoom);
    }

    /// Moves the view by a screen displacement (points): the design follows the pointer.
    pub fn pan(&mut self, delta: [f64; 2]) {
        self.origin.x -= delta[0] / self.zoom;
        self.origin.y -= delta[1] / self.zoom;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::Rgb8;

    #[test]
    fn screen_and_design_round_trip_and_zoom_keeps_the_anchor() {
        let d = Design::new(800, 600, Rgb8::new(0, 0, 0));
        let mut v = ViewState::fit(&d, [1000.0, 700.0]);
        let centre = v.to_design([500.0, 350.0]);
        assert!((centre - Point::new(400.0, 300.0)).hypot() < 1e-9);
        let at = [123.0, 456.0];
        let before = v.to_design(at);
        v.zoom_about(7.5, at);
        assert!((v.to_design(at) - before).hypot() < 1e-9);
        let s = v.to_screen(before);
        assert!((s[0] - at[0]).abs() < 1e-9 && (s[1] - at[1]).abs() < 1e-9);
        v.pan([10.0, -20.0]);
        let moved = v.to_screen(before);
        assert!((moved[0] - 133.0).abs() < 1e-9 && (moved[1] - 436.0).abs() < 1e-9);
    }
}
