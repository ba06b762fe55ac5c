//! Traced ink regions and the vector form of a whole design.

use kurbo::{BezPath, Point};
use marbling_core::Rgb8;

/// One ink region: a drop or spray after all later ops, as closed rings filled together
/// with the nonzero rule (one ring until the lossy step pinches it apart).
#[derive(Clone, Debug, PartialEq)]
pub struct Outline {
    /// Index of the drop or spray in `Design::ops`.
    pub op_index: usize,
    /// Ink colour.
    pub color: Rgb8,
    /// Closed polygons (the last vertex of each joins its first), design pixels. The
    /// first ring runs in order of increasing angle on the original circle (clockwise
    /// on screen, y down); pieces of a pinched ring keep its direction, so a ring around
    /// a gap runs the other way.
    pub rings: Vec<Vec<Point>>,
}

impl Outline {
    /// The rings as one kurbo path of closed line subpaths (design pixels).
    pub fn to_bez_path(&self) -> BezPath {
        let mut path = BezPath::new();
        for ring in &self.rings {
            let mut it = ring.iter();
            if let Some(&first) = it.next() {
                path.move_to(first);
                for &p in it {
                    path.line_to(p);
                }
                path.close_path();
            }
        }
        path
    }

    /// Vertices of all rings.
    pub fn vertices(&self) -> usize {
        self.rings.iter().map(Vec::len).sum()
    }
}

/// Counts gathered while tracing a design.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TraceStats {
    /// Drops and sprays traced.
    pub regions: usize,
    /// Regions dropped because they lie wholly outside the canvas.
    pub culled: usize,
    /// Vertices of all initial n-gons.
    pub initial_vertices: usize,
    /// Vertices after the last op (refined, after the lossy step, before
    /// simplification).
    pub refined_vertices: usize,
    /// Most vertices held after any op (all regions together).
    pub peak_vertices: usize,
    /// Times the deviation, thin width and simplification distance were doubled
    /// because more than `TraceOptions::max_live` vertices were held (0: none).
    pub level: u32,
    /// Rings exported.
    pub rings: usize,
    /// Cuts the lossy step made (exact: they change no winding number).
    pub cuts: usize,
    /// Pieces the lossy step dropped.
    pub dropped_pieces: usize,
    /// Area of ink (or gap) the lossy step dropped, design px² (ops preserve area, so
    /// this is also its area in the final design, before later ink covers any of it).
    pub dropped_area: f64,
    /// Vertices exported (after simplification, or equal to `refined_vertices`).
    pub vertices: usize,
    /// Segments left longer than the tolerance because the depth cap was reached.
    pub capped: usize,
    /// Points mapped from their source curve through many ops (new vertices' probes).
    pub mapped_points: usize,
}

impl std::ops::AddAssign for TraceStats {
    fn add_assign(&mut self, o: Self) {
        self.regions += o.regions;
        self.culled += o.culled;
        self.initial_vertices += o.initial_vertices;
        self.refined_vertices += o.refined_vertices;
        self.peak_vertices = self.peak_vertices.max(o.peak_vertices);
        self.level = self.level.max(o.level);
        self.rings += o.rings;
        self.cuts += o.cuts;
        self.dropped_pieces += o.dropped_pieces;
        self.dropped_area += o.dropped_area;
        self.vertices += o.vertices;
        self.capped += o.capped;
        self.mapped_points += o.mapped_points;
    }
}

/// A design as filled polygons in painter's order: the background rectangle
/// `0..width × 0..height`, then `outlines` (later over earlier), nonzero fill rule.
#[derive(Clone, Debug, PartialEq)]
pub struct VectorDesign {
    /// Canvas width, design pixels.
    pub width: u32,
    /// Canvas height, design pixels.
    pub height: u32,
    /// Colour of the background rectangle.
    pub background: Rgb8,
    /// Ink regions, oldest first.
    pub outlines: Vec<Outline>,
    /// Tolerance T the outlines were traced at, output pixels.
    pub tolerance: f64,
    /// Output pixels per design pixel the tolerance refers to.
    pub scale: f64,
    /// What tracing did.
    pub stats: TraceStats,
}
