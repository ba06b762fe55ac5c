//! Curl noise (Bridson et al. 2007; Kung 2019 ch. 5): v = (∂ψ/∂y, −∂ψ/∂x) of an fBm
//! potential ψ, divergence free by construction, from analytic Perlin derivatives.
//! Keep in sync with `curl` in `shaders/curl.wgsl`.

use crate::fbm::Fbm;

/// Mean of a Rayleigh variable of unit scale, √(π/2).
const RAYLEIGH_MEAN: f32 = 1.253_314_1;
/// Standard deviation of a Rayleigh variable of unit scale, √((4 − π)/2).
const RAYLEIGH_STD: f32 = 0.655_136_4;

/// Which scalar of the velocity field an image shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurlComponent {
    /// vₓ = ∂ψ/∂y, normalised to unit variance.
    X,
    /// v_y = −∂ψ/∂x, normalised to unit variance.
    Y,
    /// |v|, normalised as a Rayleigh variable (zero mean, unit variance if the
    /// components were Gaussian).
    Magnitude,
}

/// Curl noise of an fBm potential (Perlin basis).
#[derive(Clone, Debug)]
pub struct Curl {
    potential: Fbm,
    inv_component_std: f32,
}

impl Curl {
    /// Curl noise of the potential `potential` (normalised fBm, unit variance).
    #[must_use]
    pub fn new(potential: Fbm) -> Self {
        let inv_component_std = 1.0 / potential.derivative_variance().sqrt();
        Self {
            potential,
            inv_component_std,
        }
    }

    /// The potential ψ.
    #[must_use]
    pub fn potential(&self) -> &Fbm {
        &self.potential
    }

    /// The velocity (∂ψ/∂y, −∂ψ/∂x) at (x, y), output pixels; units of ψ per pixel.
    #[inline]
    #[must_use]
    pub fn velocity(&self, x: f32, y: f32) -> [f32; 2] {
        let [_, dx, dy] = self.potential.eval_with_gradient(x, y);
        [dy, -dx]
    }

    /// One scalar of the velocity, normalised to zero mean and unit variance.
    #[must_use]
    pub fn component(&self, x: f32, y: f32, which: CurlComponent) -> f32 {
        let [vx, vy] = self.velocity(x, y);
        match which {
            CurlComponent::X => vx * self.inv_component_std,
            CurlComponent::Y => vy * self.inv_component_std,
            CurlComponent::Magnitude => {
                ((vx * vx + vy * vy).sqrt() * self.inv_component_std - RAYLEIGH_MEAN) / RAYLEIGH_STD
            }
        }
    }
}
