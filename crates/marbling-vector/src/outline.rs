//! Traced ink regions and the vector form of a whole design.

use crate::surface_layers::RasterLayer;
use kurbo::{BezPath, Point};
use marbling_core::Rgb8;

/// How an outline was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Traced forward through every later op (resolution independent).
    Forward,
    /// Read off the exact label raster by marching squares (see [`crate::contour`]).
    Contour,
}

impl Method {
    /// The value of the SVG path's `data-method` attribute.
    pub fn name(self) -> &'static str {
        match self {
            Method::Forward => "forward",
            Method::Contour => "contour",
        }
    }
}

/// One ink region: a drop or spray after all later ops, as closed rings filled together
/// with the nonzero rule (one ring until the lossy step pinches it apart).
#[derive(Clone, Debug, PartialEq)]
pub struct Outline {
    /// Index of the drop or spray among the compiled ops (the same as in `Design::ops`
    /// for designs without drop patterns).
    pub op_index: usize,
    /// Ink colour.
    pub color: Rgb8,
    /// How the rings were found. Forward rings enclose the whole region as traced
    /// (newer ink is painted over what lies inside); contour rings enclose what shows,
    /// grown under newer ink, with holes where older ink shows through.
    pub method: Method,
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
    /// Regions handed to the contour method because more than
    /// `TraceOptions::max_live` vertices were held (0: every region traced forward).
    pub contour_regions: usize,
    /// Samples of the label raster walked back through the ops (0 without contours).
    pub contour_samples: usize,
    /// Spacing of the label raster, output pixels (0 without contours).
    pub contour_step: f64,
    /// Output pixels exported in the dense patch (see [`crate::dense`]).
    pub dense_pixels: usize,
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
        self.contour_regions += o.contour_regions;
        self.contour_samples += o.contour_samples;
        self.contour_step = self.contour_step.max(o.contour_step);
        self.dense_pixels += o.dense_pixels;
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
    /// A schema v2 noise background: the exact render of the design without its grain
    /// overlays, at the output size, drawn in place of the background rectangle (the
    /// outlines then paint the ink over it sharply).
    pub underlay: Option<RasterLayer>,
    /// Output pixels where three or more inks meet, as an RGBA patch over the outlines
    /// (see [`crate::dense`]); only designs that needed the contour method have one.
    pub dense: Option<RasterLayer>,
    /// Schema v2 grain overlays: the product of their factors on linear colour at each
    /// output pixel, sRGB-encoded grey, multiplied over everything else.
    pub grain: Option<RasterLayer>,
    /// Tolerance T the outlines were traced at, output pixels.
    pub tolerance: f64,
    /// Output pixels per design pixel the tolerance refers to.
    pub scale: f64,
    /// What tracing did.
    pub stats: TraceStats,
}
