//! The scalar-field abstraction every noise implements: a value at a point given in
//! output pixels (x right, y down).

/// A scalar field over the plane, sampled at output-pixel coordinates. Noises return
/// values at zero mean and unit variance.
pub trait Field: Send + Sync {
    /// The value at (x, y), output pixels.
    fn sample(&self, x: f32, y: f32) -> f32;

    /// `out[i] = self.sample(xs[i], y)` for each point of a row, bit for bit; fields
    /// with row kernels ([`crate::rows`]) are several times faster this way.
    fn sample_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        for (o, &x) in out.iter_mut().zip(xs) {
            *o = self.sample(x, y);
        }
    }
}
