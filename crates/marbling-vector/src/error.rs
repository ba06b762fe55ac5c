//! Why a design cannot be exported as vectors.

/// Errors of tracing, export and preview.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VectorError {
    /// The tolerance is not a positive finite number of output pixels.
    #[error("tolerance must be a finite number of output pixels > 0, got {0}")]
    BadTolerance(f64),
    /// The output scale is not a positive finite number.
    #[error("scale must be a finite number > 0, got {0}")]
    BadScale(f64),
    /// A tracing option relative to the tolerance is out of range.
    #[error(
        "{0} = {1} is out of range (deviation, epsilon, contour_step: (0, 1] × T; thin: [0, 1] × T; chord: ≥ 1 × T; contour_reach: [0, 8] px)"
    )]
    BadFraction(&'static str, f64),
    /// The design has something that is not a union of traced ink outlines.
    #[error("design cannot be traced exactly as vectors: {0}")]
    Untraceable(String),
    /// Refinement needed more vertices than allowed.
    #[error(
        "design needs more than {limit} outline vertices at this tolerance; raise the tolerance or the vertex limit"
    )]
    TooComplex {
        /// The vertex limit that was exceeded.
        limit: usize,
    },
    /// The preview raster would be too large (or the scale is invalid).
    #[error(transparent)]
    Render(#[from] marbling_core::RenderError),
}
