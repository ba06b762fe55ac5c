//! The canvas view: which part of the design is on screen and how large.

use marbling_core::{Design, Point, ViewSpec};

/// Zoom limits, screen points per design pixel.
pub const MIN_ZOOM: f64 = 0.02;
/// A million screen points per design pixel: past f32's reach the canvas walks by
/// perturbation from f64 references (marbling-gpu's deep walk), so edges stay exact.
pub const MAX_ZOOM: f64 = 1e6;

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

    /// The view of `spec` (its centre in the middle of a canvas of `size` points, its
    /// scale the zoom, clamped to the zoom limits).
    pub fn centred(spec: ViewSpec, size: [f64; 2]) -> Self {
        let zoom = spec.scale.clamp(MIN_ZOOM, MAX_ZOOM);
        Self {
            zoom,
            origin: Point::new(
                spec.centre.x - size[0] / (2.0 * zoom),
                spec.centre.y - size[1] / (2.0 * zoom),
            ),
        }
    }

    /// This view as a centre and zoom, on a canvas of `size` points.
    pub fn spec(self, size: [f64; 2]) -> ViewSpec {
        ViewSpec {
            centre: self.to_design([size[0] / 2.0, size[1] / 2.0]),
            scale: self.zoom,
        }
    }

    /// How the status bar says the zoom: a percentage up to 10,000 %, then a factor.
    pub fn zoom_label(self) -> String {
        if self.zoom < 100.0 {
            format!("zoom {:.0} %", self.zoom * 100.0)
        } else {
            format!("zoom {:.0}×", self.zoom)
        }
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

    #[test]
    fn a_view_centred_on_a_spec_gives_that_spec_back_at_a_million_times() {
        let spec = ViewSpec {
            centre: Point::new(123.456_789_012, 98.765_432_1),
            scale: 1e6,
        };
        let size = [900.0, 640.0];
        let v = ViewState::centred(spec, size);
        let back = v.spec(size);
        assert!((back.centre - spec.centre).hypot() < 1e-10, "{back:?}");
        assert_eq!(back.scale, 1e6);
        assert_eq!(v.zoom_label(), "zoom 1000000×");
        let mut far = v;
        far.zoom_about(10.0, [1.0, 2.0]);
        assert_eq!(far.zoom, MAX_ZOOM, "zoom stops at the limit");
    }
}
