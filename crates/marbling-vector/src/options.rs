//! Options of forward tracing.

use crate::VectorError;

/// How finely to trace a design. Lengths are output pixels (design pixels × `scale`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceOptions {
    /// Tolerance T, output pixels (> 0): refined segments span at most T, their mapped
    /// midpoints lie within `deviation`·T of the chord, simplification moves outlines by
    /// at most `epsilon`·T, and the lossy step drops pieces thinner than `thin`·T on
    /// average. Default 1.
    pub tolerance: f64,
    /// Output pixels per design pixel (> 0). Default 1 (SVG user units = design pixels).
    pub scale: f64,
    /// Simplify the refined outlines (default true). Without it every refined vertex is
    /// kept; off-canvas collapse and culling are part of simplification.
    pub simplify: bool,
    /// Most bisections of one initial segment (default 30).
    pub max_depth: u32,
    /// Furthest a segment's mapped midpoint may lie from its chord, as a fraction of T
    /// (default 0.04).
    pub deviation: f64,
    /// Longest chord of a refined segment on the canvas, in units of T (default 4):
    /// with `deviation` the chord limit only matters on nearly straight parts.
    pub chord: f64,
    /// Simplification distance ε, as a fraction of T (default 0.04).
    pub epsilon: f64,
    /// Re-anchor outlines every this many ops (default 32; 0: never, every point is an
    /// exact forward image of the original rim). Re-anchoring replaces each segment's
    /// source by the quadratic through its three exact samples, so a point inserted
    /// later is carried through at most this many ops instead of all since its ink was
    /// laid; the quadratic stands in for the true outline within about `deviation`·T.
    pub anchor: u32,
    /// Width w of the lossy step, as a fraction of T (default 1/16; 0 turns it off):
    /// after every op that grew a region by a quarter, parts of a ring closer than w
    /// are cut apart and pieces of mean width (2·area/perimeter) below w are dropped.
    pub thin: f64,
    /// Vertex budget of forward tracing at T ≥ 1, divided by T below (default 60 000:
    /// 240 000 at T = 0.25): whenever more vertices than that are held after an op, the
    /// regions holding the most are handed to the contour method until at most half the
    /// budget is held. Within the last 16 ops the budget is multiplied by 16 / (ops
    /// left), since finishing costs the vertices held times the ops left.
    pub max_live: usize,
    /// Sample spacing of the contour method's label raster, as a fraction of T
    /// (default ¼: at T = 1 the 4×4 grid of the reference's `grid4` antialiasing).
    /// Contour rings are simplified within one spacing where they show.
    pub contour_step: f64,
    /// Largest estimated cost of the contour method's label raster (op-samples: grid
    /// points times the ops a walk passes, measured on probes) at which every region is
    /// contoured rather than traced forward (default 4·10⁹: 1–10 s on two cores;
    /// 0: never). The contour method is the more faithful where inks abut (see the crate
    /// docs).
    pub contour_all: f64,
    /// How far a contour region grows under newer ink, output pixels (default 1.5: more
    /// than an antialiased edge plus the simplification of the ink painted over it).
    pub contour_reach: f64,
    /// Most refined vertices in the whole design before it is refused (default 50 M).
    pub max_vertices: usize,
}

impl Default for TraceOptions {
    fn default() -> Self {
        Self {
            tolerance: 1.0,
            scale: 1.0,
            simplify: true,
            max_depth: 30,
            deviation: 0.04,
            chord: 4.0,
            epsilon: 0.04,
            thin: 0.0,
            anchor: 32,
            max_vertices: 50_000_000,
            max_live: 60_000,
            contour_step: 0.25,
            contour_all: 4e9,
            contour_reach: 1.5,
        }
    }
}

impl TraceOptions {
    /// Checks tolerance and scale.
    pub fn validate(&self) -> Result<(), VectorError> {
        if !(self.tolerance.is_finite() && self.tolerance > 0.0) {
            return Err(VectorError::BadTolerance(self.tolerance));
        }
        if !(self.scale.is_finite() && self.scale > 0.0) {
            return Err(VectorError::BadScale(self.scale));
        }
        for (name, v) in [("deviation", self.deviation), ("epsilon", self.epsilon)] {
            if !(v.is_finite() && v > 0.0 && v <= 1.0) {
                return Err(VectorError::BadFraction(name, v));
            }
        }
        if !(self.chord.is_finite() && self.chord >= 1.0) {
            return Err(VectorError::BadFraction("chord", self.chord));
        }
        if !(self.thin.is_finite() && (0.0..=1.0).contains(&self.thin)) {
            return Err(VectorError::BadFraction("thin", self.thin));
        }
        if !(self.contour_step.is_finite() && self.contour_step > 0.0 && self.contour_step <= 1.0) {
            return Err(VectorError::BadFraction("contour_step", self.contour_step));
        }
        if !(self.contour_reach.is_finite() && (0.0..=8.0).contains(&self.contour_reach)) {
            return Err(VectorError::BadFraction(
                "contour_reach",
                self.contour_reach,
            ));
        }
        Ok(())
    }

    /// The refinement spacing T in design pixels.
    pub fn spacing(&self) -> f64 {
        self.tolerance / self.scale
    }
}
