//! Options of forward tracing.

use crate::VectorError;

/// How finely to trace a design. Lengths are output pixels (design pixels × `scale`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceOptions {
    /// Tolerance T, output pixels (> 0): refined segments span at most T, mapped arc
    /// midpoints lie within T/4 of their chord, simplification moves the outline by at
    /// most T/4. Default 1.
    pub tolerance: f64,
    /// Output pixels per design pixel (> 0). Default 1 (SVG user units = design pixels).
    pub scale: f64,
    /// Simplify the refined outlines (default true). Without it every refined vertex is
    /// kept; off-canvas collapse and culling are part of simplification.
    pub simplify: bool,
    /// Most bisections of one initial segment (default 30).
    pub max_depth: u32,
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
            max_vertices: 50_000_000,
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
        Ok(())
    }

    /// The refinement spacing T in design pixels.
    pub fn spacing(&self) -> f64 {
        self.tolerance / self.scale
    }
}
