//! Keeps the page canvas's backing store at its CSS size × `devicePixelRatio`, so one
//! egui point is one CSS pixel and the sheet is drawn at the screen's resolution.
//!
//! eframe sizes the backing store from the `devicePixelContentBoxSize` a
//! `ResizeObserver` reports. Chromium's device emulation (and so every headless test at a
//! ratio above 1) reports CSS pixels there while `devicePixelRatio` says 2: the store
//! stayed 1440 px wide on a 1440-CSS-px canvas at ratio 2, egui laid the UI out in
//! 720 points, and everything was drawn twice as large at half the resolution. Where the
//! two disagree by more than rounding, the ratio wins; where they agree (real browsers,
//! including fractional zooms whose device sizes snap by a pixel), eframe's size stays.

/// Backing-store sizes within this many device pixels of CSS size × ratio are left
/// alone: browsers snap device-pixel boxes to whole pixels.
#[cfg(any(target_arch = "wasm32", test))]
pub const SNAP_TOLERANCE_PX: u32 = 2;

/// The backing-store size, device pixels, for a canvas of `css` CSS pixels at `ratio`.
#[cfg(any(target_arch = "wasm32", test))]
pub fn wanted_size(css: [f64; 2], ratio: f64) -> [u32; 2] {
    css.map(|v| (v * ratio).round().max(1.0) as u32)
}

/// True when the backing store `have` is off `want` by more than browser snapping.
#[cfg(any(target_arch = "wasm32", test))]
pub fn needs_fix(have: [u32; 2], want: [u32; 2]) -> bool {
    have.iter()
        .zip(want)
        .any(|(&h, w)| h.abs_diff(w) > SNAP_TOLERANCE_PX)
}

/// Resizes the page canvas's backing store when it is off its CSS size × ratio; true
/// when it did (the caller repaints: this frame was laid out at the old size).
#[cfg(target_arch = "wasm32")]
pub fn fit_backing_store() -> bool {
    use wasm_bindgen::JsCast;
    let Some(window) = web_sys::window() else {
        return false;
    };
    let Some(canvas) = window
        .document()
        .and_then(|d| d.get_element_by_id(crate::platform::CANVAS_ID))
        .and_then(|e| e.dyn_into::<web_sys::HtmlCanvasElement>().ok())
    else {
        return false;
    };
    let rect = canvas.get_bounding_client_rect();
    let want = wanted_size([rect.width(), rect.height()], window.device_pixel_ratio());
    if !needs_fix([canvas.width(), canvas.height()], want) {
        return false;
    }
    canvas.set_width(want[0]);
    canvas.set_height(want[1]);
    true
}

/// A desktop window's surface follows the window; nothing to fix.
#[cfg(not(target_arch = "wasm32"))]
pub fn fit_backing_store() -> bool {
    false
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ratio_multiplies_the_css_size() {
        assert_eq!(wanted_size([1440.0, 900.0], 2.0), [2880, 1800]);
        assert_eq!(wanted_size([390.0, 844.0], 3.0), [1170, 2532]);
        assert_eq!(wanted_size([1300.5, 820.0], 1.25), [1626, 1025]);
    }

    #[test]
    fn only_more_than_snapping_is_fixed() {
        // The emulated ratio-2 store of the issue: CSS pixels, not device pixels.
        assert!(needs_fix([1440, 900], [2880, 1800]));
        // A device-pixel box snapped by a pixel at a fractional zoom stays.
        assert!(!needs_fix([1625, 1026], [1626, 1025]));
        assert!(!needs_fix([2880, 1800], [2880, 1800]));
        assert!(needs_fix([2880, 1797], [2880, 1800]));
    }
}
