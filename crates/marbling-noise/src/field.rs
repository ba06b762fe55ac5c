//! The scalar-field abstraction every noise implements: a value at a point given in
//! output pixels (x right, y down).

/// A scalar field over the plane, sampled at output-pixel coordinates. Noises return
/// values at zero mean and unit variance.
pub trait Field: Send + Sync {
    /// The value at (x, y), output pixels.
    fn sample(&self, x: f32, y: f32) -> f32;
}
