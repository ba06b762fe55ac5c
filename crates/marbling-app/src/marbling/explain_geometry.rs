//! What the explain view draws over the sheet, made readable at every step (Lu et al.
//! 2012's maps shown by what they do to a grid): the regular grid pushed forward as
//! curves fine enough that no drawn segment is longer than [`SEGMENT_PX`] screen points,
//! arrows from coarse grid nodes toward where they go (drawn at most one grid square
//! long; the true longest trip is reported), and the area probe before and after.
//!
//! A step of hundreds of drops moves every node far; the view then shows the step's
//! first [`FIRST_DROPS`] drops, which a reader can follow, and says so.

use marbling_core::{Op, Point, Vec2};

/// Longest drawn segment of a pushed curve, screen points.
pub const SEGMENT_PX: f64 = 6.0;
/// Most drops of one step the single-step view pushes the grid through.
pub const FIRST_DROPS: usize = 6;
/// Most point-through-op evaluations one geometry may cost (about 50 ms natively);
/// curves not resolved within it are left out where too coarse.
const WORK: f64 = 4.0e6;
/// Most halvings of one initial sample interval.
const MAX_ROUNDS: usize = 14;

/// The ops the explain view pushes through, and what was left out.
#[derive(Clone, Debug, PartialEq)]
pub struct Window {
    /// The ops, drop and spray sets expanded into single drops.
    pub ops: Vec<Op>,
    /// `(shown, of)`: only the first `shown` drops of the step's `of` are pushed.
    pub first_of: Option<(usize, usize)>,
}

impl Window {
    /// The single-step view of `step` (its ops in order): every op, but only the first
    /// [`FIRST_DROPS`] drops when it lays more.
    pub fn step(step: &[Op]) -> Self {
        let expanded = expand(step);
        let drops = expanded
            .iter()
            .filter(|op| matches!(op, Op::Drop(_) | Op::Spray(_)))
            .count();
        if drops <= FIRST_DROPS {
            return Self {
                ops: expanded,
                first_of: None,
            };
        }
        let mut seen = 0;
        let ops = expanded
            .into_iter()
            .filter(|op| {
                let drop = matches!(op, Op::Drop(_) | Op::Spray(_));
                seen += usize::from(drop);
                !drop || seen <= FIRST_DROPS
            })
            .collect();
        Self {
            ops,
            first_of: Some((FIRST_DROPS, drops)),
        }
    }

    /// Every op so far (the grid through every step), nothing left out.
    pub fn all(ops: &[Op]) -> Self {
        Self {
            ops: expand(ops),
            first_of: None,
        }
    }
}

/// `ops` with drop and spray sets as single drops (so a window can cut between them).
fn expand(ops: &[Op]) -> Vec<Op> {
    let mut out = Vec::with_capacity(ops.len());
    for op in ops {
        match op {
            Op::Drops(d) => out.extend(d.expand(false)),
            Op::Sprays(d) => out.extend(d.expand(true)),
            other => out.push(other.clone()),
        }
    }
    out
}

/// The explain view's geometry for one window at one zoom.
pub struct ExplainGeometry {
    /// The pushed grid as polylines, no segment longer than [`SEGMENT_PX`] at the zoom
    /// it was made for.
    pub grid: Vec<Vec<Point>>,
    /// Grid line spacing before the push, design px (also the arrows' longest drawn
    /// length).
    pub spacing: f64,
    /// Coarse grid nodes and where the ops send them (the true end, see [`arrow_tip`]).
    pub arrows: Vec<(Point, Point)>,
    /// The probe circle before (a 256-gon) and its pieces after the push (one closed
    /// ring unless a thread or a drop's centre parts it).
    pub probe: (Vec<Point>, Vec<Vec<Point>>),
    /// The probe's area before and after, design px² (`None` when the budget ran out).
    pub probe_areas: Option<(f64, f64)>,
    /// False when the work budget ran out before every curve was fine enough (parts
    /// of the grid or probe are then left out; a tear, where a line parts around a
    /// drop's centre, is not a part left out).
    pub complete: bool,
    /// The window's `first_of` (only the first drops of a step pushed).
    pub first_of: Option<(usize, usize)>,
    /// How much of the pushed grid lies on the sheet, as a share of the regular grid's
    /// length, and whether any of the probe after does (ink laid later can push nearly
    /// all of the older paper off it).
    pub on_sheet: (f64, bool),
}

impl ExplainGeometry {
    /// The geometry of `window` over a `size` sheet, fine enough for `zoom` screen
    /// points per design px, with the probe circle `probe` (centre, radius).
    pub fn new(window: &Window, size: (u32, u32), zoom: f64, probe: (Point, f64)) -> Self {
        let ops = &window.ops;
        let (w, h) = (f64::from(size.0), f64::from(size.1));
        let long = w.max(h);
        // Ops push a point in about the same time, but a flow walks thousands of
        // sub-steps: it counts its walk cost ([`Op::walk_cost`]).
        let cost = ops
            .iter()
            .map(|op| match op {
                Op::Flow(_) => op.walk_cost(),
                _ => 1,
            })
            .sum::<u64>()
            .max(1) as f64;
        // 16 lines along the longer side, fewer when the ops are many (the first
        // samples then take at most a quarter of the work).
        let mut spacing = long / 16.0;
        let first_samples = |s: f64| ((w + s) / s) * h * 8.0 / s + ((h + s) / s) * w * 8.0 / s;
        while first_samples(spacing) * cost > WORK / 4.0 && spacing < long {
            spacing *= 1.5;
        }
        let max_segment = SEGMENT_PX / zoom;
        let mut curves = Vec::new();
        let mut x = 0.0;
        while x <= w + 1e-9 {
            curves.push(Curve::line(
                Point::new(x, 0.0),
                Point::new(x, h),
                spacing / 8.0,
            ));
            x += spacing;
        }
        let mut y = 0.0;
        while y <= h + 1e-9 {
            curves.push(Curve::line(
                Point::new(0.0, y),
                Point::new(w, y),
                spacing / 8.0,
            ));
            y += spacing;
        }
        let (c, r) = probe;
        let ring = Curve::circle(c, r, 256);
        let before: Vec<Point> = ring.samples.iter().map(|&t| ring.source(t)).collect();
        curves.push(ring);
        let mut budget = (WORK / cost) as i64;
        let mut pushed: Vec<Vec<(f64, Point)>> = curves
            .iter()
            .map(|cv| {
                budget -= cv.samples.len() as i64;
                cv.samples
                    .iter()
                    .map(|&t| (t, push(ops, cv.source(t))))
                    .collect()
            })
            .collect();
        let sheet = [
            Point::new(-max_segment, -max_segment),
            Point::new(w + max_segment, h + max_segment),
        ];
        // Halve every too-long segment that may show on the sheet, a round at a time
        // over all curves, so the budget is spent evenly.
        for _ in 0..MAX_ROUNDS {
            let mut refined = false;
            for (cv, pts) in curves.iter().zip(pushed.iter_mut()) {
                let mut out = Vec::with_capacity(pts.len() * 2);
                for pair in pts.windows(2) {
                    let ((t0, a), (t1, b)) = (pair[0], pair[1]);
                    out.push((t0, a));
                    if budget > 0
                        && (b - a).hypot() > max_segment
                        && (!cv.clip || may_show(a, b, sheet))
                    {
                        let t = (t0 + t1) / 2.0;
                        out.push((t, push(ops, cv.source(t))));
                        budget -= 1;
                        refined = true;
                    }
                }
                out.extend(pts.last().copied());
                *pts = out;
            }
            if !refined || budget <= 0 {
                break;
            }
        }
        // Segments still too long after every round are tears (a line through a drop's
        // centre parts around it) unless the budget ran out first.
        let complete = budget > 0;
        let pieces = |pts: &[(f64, Point)]| -> Vec<Vec<Point>> {
            let mut out: Vec<Vec<Point>> = Vec::new();
            let mut piece: Vec<Point> = Vec::new();
            for pair in pts.windows(2) {
                let (a, b) = (pair[0].1, pair[1].1);
                if (b - a).hypot() <= max_segment {
                    if piece.is_empty() {
                        piece.push(a);
                    }
                    piece.push(b);
                } else {
                    if piece.len() > 1 {
                        out.push(std::mem::take(&mut piece));
                    }
                    piece.clear();
                }
            }
            if piece.len() > 1 {
                out.push(piece);
            }
            out
        };
        let ring: Vec<Point> = pushed
            .pop()
            .unwrap_or_default()
            .iter()
            .map(|s| s.1)
            .collect();
        // A part is a thread of no width (a point on a stylus's centre line is carried
        // the whole way): the ring's every point still bounds the area.
        let probe_areas = complete.then(|| (polygon_area(&before), polygon_area(&ring)));
        let after = pieces(&ring.iter().map(|p| (0.0, *p)).collect::<Vec<_>>());
        let grid: Vec<Vec<Point>> = pushed.iter().flat_map(|p| pieces(p)).collect();
        let mut arrows = Vec::new();
        let coarse = spacing * 2.0;
        let mut y = coarse / 2.0;
        while y < h {
            let mut x = coarse / 2.0;
            while x < w {
                let a = Point::new(x, y);
                arrows.push((a, push(ops, a)));
                x += coarse;
            }
            y += coarse;
        }
        let inside = |p: &Point| (0.0..=w).contains(&p.x) && (0.0..=h).contains(&p.y);
        let regular: f64 = curves[..curves.len() - 1]
            .iter()
            .map(|cv| match cv.kind {
                Source::Line(a, b) => (b - a).hypot(),
                Source::Circle(..) => 0.0,
            })
            .sum();
        let shown: f64 = grid
            .iter()
            .flat_map(|l| l.windows(2))
            .filter(|s| inside(&s[0]) && inside(&s[1]))
            .map(|s| (s[1] - s[0]).hypot())
            .sum();
        let on_sheet = (shown / regular, after.iter().flatten().any(inside));
        Self {
            on_sheet,
            grid,
            spacing,
            arrows,
            probe: (before, after),
            probe_areas,
            complete,
            first_of: window.first_of,
        }
    }

    /// The longest trip of an arrow's node, design px.
    pub fn longest_trip(&self) -> f64 {
        self.arrows
            .iter()
            .map(|(a, b)| (*b - *a).hypot())
            .fold(0.0, f64::max)
    }
}

/// Where an arrow from `from` toward `to` is drawn to: the whole way, or `cap` along it
/// when the trip is longer.
pub fn arrow_tip(from: Point, to: Point, cap: f64) -> Point {
    let d = to - from;
    let len = d.hypot();
    if len <= cap {
        to
    } else {
        from + d * (cap / len)
    }
}

/// A curve of the regular grid or the probe: a source parametrised by `t` in 0..=1,
/// sampled at `samples`.
struct Curve {
    kind: Source,
    samples: Vec<f64>,
    /// Refined only where it may show on the sheet (the probe is refined everywhere:
    /// its after ring is always drawn).
    clip: bool,
}

enum Source {
    Line(Point, Point),
    Circle(Point, f64),
}

impl Curve {
    fn line(from: Point, to: Point, sample: f64) -> Self {
        let n = ((to - from).hypot() / sample).ceil().max(1.0) as usize;
        Self {
            kind: Source::Line(from, to),
            samples: (0..=n).map(|i| i as f64 / n as f64).collect(),
            clip: true,
        }
    }

    /// A closed ring: the last sample is the first again.
    fn circle(c: Point, r: f64, n: usize) -> Self {
        Self {
            kind: Source::Circle(c, r),
            samples: (0..=n).map(|i| i as f64 / n as f64).collect(),
            clip: false,
        }
    }

    fn source(&self, t: f64) -> Point {
        match self.kind {
            Source::Line(a, b) => a.lerp(b, t),
            Source::Circle(c, r) => {
                let a = std::f64::consts::TAU * t;
                c + Vec2::new(a.cos(), a.sin()) * r
            }
        }
    }
}

/// Whether the pushed curve between `a` and `b` may cross `sheet` (min, max): the
/// box around them, grown by their distance, meets it.
fn may_show(a: Point, b: Point, sheet: [Point; 2]) -> bool {
    let grow = (b - a).hypot();
    a.x.min(b.x) - grow <= sheet[1].x
        && a.x.max(b.x) + grow >= sheet[0].x
        && a.y.min(b.y) - grow <= sheet[1].y
        && a.y.max(b.y) + grow >= sheet[0].y
}

/// Pushes `p` forward through `ops` in order.
pub fn push(ops: &[Op], p: Point) -> Point {
    ops.iter().fold(p, |p, op| op.forward(p))
}

/// The area enclosed by a closed polygon (shoelace formula), design px².
pub fn polygon_area(pts: &[Point]) -> f64 {
    let n = pts.len();
    (0..n)
        .map(|i| {
            let (a, b) = (pts[i], pts[(i + 1) % n]);
            a.x * b.y - b.x * a.y
        })
        .sum::<f64>()
        .abs()
        / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::marbling::view::ViewState;
    use marbling_core::{Drop, Jiggle, Rgb8, Tine};

    fn tine() -> Op {
        Op::Tine(Tine {
            origin: Point::new(0.0, 50.0),
            direction: Vec2::new(1.0, 0.0),
            alpha: 30.0,
            lambda: 6.0,
        })
    }

    /// The grid of a tine step: every node is where the tine's forward map sends the
    /// regular node (checked against the formula αλ/(d+λ), not the op's own code).
    #[test]
    fn a_tine_steps_grid_nodes_follow_the_forward_map() {
        let g = ExplainGeometry::new(
            &Window::all(&[tine()]),
            (200, 100),
            1.0,
            (Point::new(50.0, 50.0), 5.0),
        );
        assert_eq!(g.spacing, 12.5);
        assert!(g.complete);
        // Vertical line x = 50 (index 4), refined where the tine shears it.
        let line = &g.grid[4];
        // 65 first samples, more where the tine shears the line.
        assert!(line.len() > 65, "{}", line.len());
        for p in line {
            let d = (p.y - 50.0).abs();
            let shift = 30.0 * 6.0 / (d + 6.0);
            assert!((p.x - (50.0 + shift)).abs() < 1e-9, "{p:?}");
        }
        // The horizontal line on the tine slides along itself: its nodes stay on it.
        assert!(
            g.grid
                .iter()
                .any(|l| l.len() > 60 && l.iter().all(|p| (p.y - 50.0).abs() < 1e-9))
        );
    }

    #[test]
    fn the_probe_keeps_its_area_through_a_drop_and_a_jiggle_compresses_it() {
        let drop = Op::Drop(Drop {
            center: Point::new(40.0, 50.0),
            radius: 20.0,
            color: Rgb8::new(0, 0, 0),
        });
        let g = ExplainGeometry::new(
            &Window::all(&[drop, tine()]),
            (200, 100),
            4.0,
            (Point::new(70.0, 50.0), 10.0),
        );
        let (a0, a1) = g.probe_areas.expect("a whole ring");
        assert!((a0 - std::f64::consts::PI * 100.0).abs() < 0.1, "{a0}");
        assert!((a1 / a0 - 1.0).abs() < 2e-3, "area changed: {a0} → {a1}");
        let jiggle = Op::Jiggle(Jiggle {
            angle: 0.0,
            wavelength: 100.0,
            along: 12.0,
            across: 0.0,
            phase: 0.0,
        });
        // At φ = 0 the Jacobian is 1 + kA = 1.754: a small probe there grows by it.
        let g = ExplainGeometry::new(
            &Window::all(&[jiggle]),
            (200, 100),
            4.0,
            (Point::new(0.0, 50.0), 1.0),
        );
        let (b0, b1) = g.probe_areas.expect("a whole ring");
        let k = std::f64::consts::TAU / 100.0;
        assert!((b1 / b0 - (1.0 + k * 12.0)).abs() < 0.01, "{}", b1 / b0);
    }

    #[test]
    fn a_long_arrow_is_drawn_one_square_long_a_short_one_whole() {
        let a = Point::new(10.0, 10.0);
        assert_eq!(
            arrow_tip(a, Point::new(13.0, 14.0), 20.0),
            Point::new(13.0, 14.0)
        );
        let tip = arrow_tip(a, Point::new(310.0, 410.0), 20.0);
        assert!(((tip - a).hypot() - 20.0).abs() < 1e-9);
        assert!(((tip - a).normalize() - Vec2::new(0.6, 0.8)).hypot() < 1e-12);
    }

    #[test]
    fn a_step_of_many_drops_shows_its_first_few_and_says_so() {
        let drops: Vec<Op> = (0..40)
            .map(|i| {
                Op::Drop(Drop {
                    center: Point::new(10.0 * f64::from(i), 50.0),
                    radius: 8.0,
                    color: Rgb8::new(0, 0, 0),
                })
            })
            .chain([tine()])
            .collect();
        let w = Window::step(&drops);
        assert_eq!(w.first_of, Some((FIRST_DROPS, 40)));
        assert_eq!(w.ops.len(), FIRST_DROPS + 1);
        assert_eq!(w.ops[..FIRST_DROPS], drops[..FIRST_DROPS]);
        assert_eq!(w.ops[FIRST_DROPS], tine());
        let few = Window::step(&drops[..3]);
        assert_eq!((few.ops.len(), few.first_of), (3, None));
    }

    /// Chevron's 288 drops cover more than the sheet: through every step so far less
    /// than 1 % of the grid and none of the probe stay on it (and the view says so);
    /// its first step's first drops keep most of them on it.
    #[test]
    fn chevrons_drops_push_the_whole_grid_off_the_sheet() {
        let design = marbling_core::patterns::find("chevron")
            .and_then(|p| p.design(&Default::default()))
            .expect("chevron");
        let size = (design.width, design.height);
        let probe = (Point::new(320.0, 200.0), 40.0);
        let all = ExplainGeometry::new(&Window::all(&design.ops), size, 2.0, probe);
        assert!(
            all.on_sheet.0 < 0.01 && !all.on_sheet.1,
            "{:?}",
            all.on_sheet
        );
        let bounds = design.step_bounds();
        let first = Window::step(&design.ops[..bounds[1]]);
        let g = ExplainGeometry::new(&first, size, 2.0, probe);
        assert!(g.on_sheet.0 > 0.8 && g.on_sheet.1, "{:?}", g.on_sheet);
    }

    /// Every step of every pattern, alone and through every step so far, at the fitted
    /// view of a 1440×900 window's canvas (1124×678 points) and of a phone's (374×320):
    /// no drawn grid segment longer than 6 points, no arrow drawn longer than a grid
    /// square, the probe drawn before and after; a single step is drawn whole.
    #[test]
    fn explain_reads_at_every_step_of_every_pattern() {
        for pattern in marbling_core::patterns::all() {
            let design = pattern
                .design(&Default::default())
                .expect("a pattern's design");
            let bounds = design.step_bounds();
            let size = (design.width, design.height);
            let probe = (Point::new(320.0, 200.0), 40.0);
            for canvas in [[1124.0, 678.0], [374.0, 320.0]] {
                let zoom = ViewState::fit(&design, canvas).zoom;
                for k in 0..bounds.len() - 1 {
                    let step = &design.ops[bounds[k]..bounds[k + 1]];
                    let so_far = &design.ops[..bounds[k + 1]];
                    let what = format!("{} step {} at zoom {zoom:.2}", pattern.id, k + 1);
                    for (window, cumulative) in
                        [(Window::step(step), false), (Window::all(so_far), true)]
                    {
                        if cumulative && canvas[0] < 1000.0 {
                            continue;
                        }
                        let g = ExplainGeometry::new(&window, size, zoom, probe);
                        let longest = g
                            .grid
                            .iter()
                            .chain(&g.probe.1)
                            .flat_map(|l| l.windows(2))
                            .map(|s| (s[1] - s[0]).hypot() * zoom)
                            .fold(0.0, f64::max);
                        assert!(
                            longest <= SEGMENT_PX + 1e-9,
                            "{what}: a {longest:.1}-pt segment"
                        );
                        for (a, b) in &g.arrows {
                            let drawn = (arrow_tip(*a, *b, g.spacing) - *a).hypot();
                            assert!(drawn <= g.spacing + 1e-9, "{what}: arrow {drawn}");
                        }
                        assert_eq!(g.probe.0.len(), 257, "{what}");
                        assert!(!g.probe.1.is_empty(), "{what}: no probe after");
                        if !cumulative {
                            assert!(g.complete, "{what}: parts of one step left out");
                            assert!(g.probe_areas.is_some(), "{what}: no probe area");
                        }
                    }
                }
            }
        }
    }
}
