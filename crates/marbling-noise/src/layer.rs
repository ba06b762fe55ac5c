//! Noise layers: a spec's `layers` stack more noises on its own, bottom to top, each by
//! one combine mode on intensities in [0, 1] (after each layer's own transfer), faded in
//! by the layer's weight w: c ← clamp(lerp(c, combine(c, b), w), 0, 1). The WGSL twin is
//! `combine_layer` in `shaders/layers.wgsl`.

use crate::spec::NoiseSpec;

/// Most layers a spec may stack on its own noise.
pub const MAX_LAYERS: usize = 4;

/// How a layer's intensity b meets the intensity c below it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Combine {
    /// c + b − ½: adds the noises (0.5 + (n₁ + n₂)/6 while neither clamps).
    Add,
    /// c · b.
    Multiply,
    /// max(c, b).
    Max,
    /// min(c, b).
    Min,
    /// lerp(c, b, m), m the intensity of the layer's `mask` noise (libnoise's select;
    /// a threshold transfer on the mask gives a sharp edge).
    Mask,
}

/// The `combine` names, with their index in the WGSL (`COMBINE_*` in layers.wgsl).
pub const COMBINES: [(&str, Combine); 5] = [
    ("add", Combine::Add),
    ("multiply", Combine::Multiply),
    ("max", Combine::Max),
    ("min", Combine::Min),
    ("mask", Combine::Mask),
];

impl Combine {
    /// Index used by the WGSL.
    #[must_use]
    pub fn index(self) -> u32 {
        self as u32
    }

    /// The spec name.
    #[must_use]
    pub fn name(self) -> &'static str {
        COMBINES
            .iter()
            .find(|(_, c)| *c == self)
            .map_or("add", |(n, _)| n)
    }

    /// c combined with b (and mask intensity m, read by [`Combine::Mask`] only), faded
    /// in by `weight`, clamped to [0, 1].
    #[must_use]
    pub fn apply(self, c: f32, b: f32, m: f32, weight: f32) -> f32 {
        let mixed = match self {
            Combine::Add => c + b - 0.5,
            Combine::Multiply => c * b,
            Combine::Max => c.max(b),
            Combine::Min => c.min(b),
            Combine::Mask => c + (b - c) * m,
        };
        (c + (mixed - c) * weight).clamp(0.0, 1.0)
    }
}

/// One layer of a spec's stack.
#[derive(Clone, Debug, PartialEq)]
pub struct Layer {
    /// The layer's noise, with its own transfer (no tile, palette, blend or layers: the
    /// spec's tile applies to it).
    pub noise: NoiseSpec,
    /// How it meets the layers below.
    pub combine: Combine,
    /// Fade, [0, 1].
    pub weight: f32,
    /// The mask noise of [`Combine::Mask`] (with its own transfer).
    pub mask: Option<NoiseSpec>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_mode_follows_its_formula() {
        assert!((Combine::Add.apply(0.5, 0.7, 0.0, 1.0) - 0.7).abs() < 1e-6);
        assert_eq!(Combine::Add.apply(0.9, 0.9, 0.0, 1.0), 1.0);
        assert_eq!(Combine::Multiply.apply(0.5, 0.5, 0.0, 1.0), 0.25);
        assert_eq!(Combine::Max.apply(0.2, 0.6, 0.0, 1.0), 0.6);
        assert_eq!(Combine::Min.apply(0.2, 0.6, 0.0, 1.0), 0.2);
        assert_eq!(Combine::Mask.apply(0.2, 0.6, 0.0, 1.0), 0.2);
        assert_eq!(Combine::Mask.apply(0.2, 0.6, 1.0, 1.0), 0.6);
        assert!((Combine::Mask.apply(0.2, 0.6, 0.25, 1.0) - 0.3).abs() < 1e-6);
        // Half weight: halfway to the combined value.
        assert!((Combine::Multiply.apply(0.5, 0.5, 0.0, 0.5) - 0.375).abs() < 1e-6);
        for (name, c) in COMBINES {
            assert_eq!(c.name(), name);
            assert_eq!(c.apply(0.4, 0.9, 0.5, 0.0), 0.4, "{name} at weight 0");
        }
    }
}
