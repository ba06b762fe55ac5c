//! Traced ink regions and the vector form of a whole design.

use kurbo::{BezPath, Point};
use marbling_core::Rgb8;

/// One ink region: the closed outline of a drop or spray after all later ops.
#[derive(Clone, Debug, PartialEq)]
pub struct Outline {
    /// Index of the drop or spray in `Design::ops`.
    pub op_index: usize,
    /// Ink colour.
    pub color: Rgb8,
    /// Vertices of the closed polygon (the last joins the first), design pixels,
    /// in order of increasing angle on the original circle (clockwise on screen, y down).
    pub points: Vec<Point>,
}

impl Outline {
    /// The outline as a closed kurbo path of line segments (design pixels).
    pub fn to_bez_path(&self) -> BezPath {
        let mut path = BezPath::new();
        let mut it = self.points.iter();
        if let Some(&first) = it.next() {
            path.move_to(first);
            for &p in it {
                path.line_to(p);
            }
            path.close_path();
        }
        path
    }
}

/// Counts gathered while tracing a design.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TraceStats {
    /// Drops and sprays traced.
    pub regions: usize,
    /// Regions dropped because they lie wholly outside the canvas.
    pub culled: usize,
    /// Vertices of all initial n-gons.
    pub initial_vertices: usize,
    /// Vertices after adaptive refinement.
    pub refined_vertices: usize,
    /// Vertices exported (after simplification, or equal to `refined_vertices`).
    pub vertices: usize,
    /// Segments left longer than the tolerance because the depth cap was reached.
    pub capped: usize,
    /// Forward-mapped points (each through every later op).
    pub mapped_points: usize,
}

impl std::ops::AddAssign for TraceStats {
    fn add_assign(&mut self, o: Self) {
        self.regions += o.regions;
        self.culled += o.culled;
        self.initial_vertices += o.initial_vertices;
        self.refined_vertices += o.refined_vertices;
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
