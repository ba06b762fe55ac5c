//! The strips of a rectangle around an inner one (the canvas around the sheet).

use egui::{Pos2, Rect};

/// The parts of `outer` not covered by `inner`: up to four strips (above, below, left,
/// right of `inner`), none of them empty.
pub(crate) fn margins(outer: Rect, inner: Rect) -> Vec<Rect> {
    let inner = inner.intersect(outer);
    if !inner.is_positive() {
        return vec![outer];
    }
    [
        Rect::from_min_max(outer.min, Pos2::new(outer.max.x, inner.min.y)),
        Rect::from_min_max(Pos2::new(outer.min.x, inner.max.y), outer.max),
        Rect::from_min_max(
            Pos2::new(outer.min.x, inner.min.y),
            Pos2::new(inner.min.x, inner.max.y),
        ),
        Rect::from_min_max(
            Pos2::new(inner.max.x, inner.min.y),
            Pos2::new(outer.max.x, inner.max.y),
        ),
    ]
    .into_iter()
    .filter(|r| r.is_positive())
    .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(rects: &[Rect]) -> f32 {
        rects.iter().map(|r| r.area()).sum()
    }

    #[test]
    fn margins_cover_exactly_what_the_sheet_leaves() {
        let outer = Rect::from_min_max(Pos2::new(0.0, 0.0), Pos2::new(100.0, 80.0));
        let inner = Rect::from_min_max(Pos2::new(10.0, 20.0), Pos2::new(70.0, 50.0));
        let m = margins(outer, inner);
        assert_eq!(m.len(), 4);
        assert_eq!(area(&m), outer.area() - inner.area());
        for r in &m {
            assert!(
                !r.intersects(inner.shrink(0.001)),
                "{r:?} overlaps the sheet"
            );
            assert!(outer.contains_rect(*r));
        }
    }

    #[test]
    fn a_sheet_beyond_the_canvas_leaves_the_rest_or_nothing() {
        let outer = Rect::from_min_max(Pos2::new(0.0, 0.0), Pos2::new(100.0, 80.0));
        let wide = Rect::from_min_max(Pos2::new(-50.0, 10.0), Pos2::new(150.0, 60.0));
        let m = margins(outer, wide);
        assert_eq!(m.len(), 2, "{m:?}");
        assert_eq!(area(&m), 100.0 * 30.0);
        let covering = outer.expand(5.0);
        assert!(margins(outer, covering).is_empty());
        let away = Rect::from_min_max(Pos2::new(200.0, 0.0), Pos2::new(300.0, 80.0));
        assert_eq!(margins(outer, away), vec![outer]);
    }
}
