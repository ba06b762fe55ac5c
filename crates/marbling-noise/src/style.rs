//! Styles of the 3D view: the marks a moving object is drawn with, one spec for the
//! playground's Style section and `marbling render-3d --style`.
//!
//! - **Marks** (Bénard, Lagae, Vangorp, Lefebvre, Drettakis & Thollot 2010): Gabor noise
//!   whose frequency F₀, bandwidth a, orientation ω₀ and density are in **screen pixels**
//!   while the kernel centres sit on the surface, thresholded into hatching, stipples,
//!   cross-hatching or graphite.
//! - **Fibres** (Kaplan & Cohen 2005, §4): paper or canvas fibres of a constant length and
//!   width on screen, anchored on the surface at a constant density per screen pixel.
//! - **Media** that work the render's own colour with the same marks: watercolor
//!   (pigment and paper noise in overlay blend), felt (strokes multiplied into the
//!   colour) and painterly (large strokes and brush fibres as a relief, bump-shaded).
//!
//! The renderer is `marbling_core::view3d::style`; this module holds the parameters, their
//! ranges and presets, and reads and writes the JSON (grammar in the crate README).

use crate::ramp::Rgb;
use crate::ranges::{self, Range};
use crate::spec::SpecError;
use serde_json::{Value, json};

/// The styles, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum StyleKind {
    /// Thresholded anisotropic noise: parallel strokes.
    Hatching,
    /// Thresholded isotropic noise: dots.
    Stipple,
    /// The product of two thresholded anisotropic noises a right angle apart.
    Crosshatch,
    /// Hatching whose strokes are broken by a fine isotropic grain (a pencil on paper).
    Graphite,
    /// Paper fibres at every angle.
    Paper,
    /// Canvas threads at 0° and 90° only.
    Canvas,
    /// Low-frequency pigment and fine paper noise in overlay blend with the colour.
    Watercolor,
    /// Soft broad strokes whose ink multiplies the colour, with a felt grain.
    Felt,
    /// Large strokes with brush fibres along them, lit as a relief over the colour.
    Painterly,
}

/// Style names as `--style` and the JSON's `style` take them (`none` is no style).
pub const STYLE_KINDS: [(&str, StyleKind); 9] = [
    ("hatching", StyleKind::Hatching),
    ("stipple", StyleKind::Stipple),
    ("crosshatch", StyleKind::Crosshatch),
    ("graphite", StyleKind::Graphite),
    ("watercolor", StyleKind::Watercolor),
    ("felt", StyleKind::Felt),
    ("painterly", StyleKind::Painterly),
    ("paper", StyleKind::Paper),
    ("canvas", StyleKind::Canvas),
];

/// How a style's overlay meets the render's colour (sRGB, channels in [0, 1]; c the
/// coverage, g the overlay grey, ink the spec's colour).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StyleBlend {
    /// base + (ink − base)·c: ink laid over the colour.
    Ink,
    /// base·(1 − c + c·ink): transparent ink that darkens the colour it crosses.
    Multiply,
    /// overlay(base, g) = 2·base·g where base < ½, else 1 − 2(1 − base)(1 − g); g = ½
    /// leaves the colour as it is.
    Overlay,
}

impl StyleKind {
    /// The style's name.
    pub fn name(self) -> &'static str {
        STYLE_KINDS
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("hatching", |(n, _)| n)
    }

    /// The style named `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        STYLE_KINDS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, k)| k)
    }

    /// True for the fibre styles (paper, canvas), false for the Gabor marks.
    pub fn is_fibres(self) -> bool {
        matches!(self, Self::Paper | Self::Canvas)
    }

    /// How the style's overlay meets the render's colour.
    pub fn blend(self) -> StyleBlend {
        match self {
            Self::Watercolor | Self::Painterly => StyleBlend::Overlay,
            Self::Felt => StyleBlend::Multiply,
            _ => StyleBlend::Ink,
        }
    }
}

/// Where the kernel centres of the marks live (the comparison of Bénard et al.'s fig. 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchoring {
    /// On the surface, parameters in screen pixels (the paper's dynamic noise): flat and
    /// moving with the object.
    Surface,
    /// On the screen ("shower door", 2D noise): flat, but the object slides under it.
    Screen,
    /// In texture space (texture mapping): moves with the object, but marks shrink and
    /// grow with its distance.
    Texture,
}

/// [`Anchoring`] names.
pub const ANCHORINGS: [(&str, Anchoring); 3] = [
    ("surface", Anchoring::Surface),
    ("screen", Anchoring::Screen),
    ("texture", Anchoring::Texture),
];

impl Anchoring {
    /// The anchoring's name in [`ANCHORINGS`].
    pub fn name(self) -> &'static str {
        name(&ANCHORINGS, self)
    }
}

/// How a kernel's mark is kept from showing on a part of the object its centre is not
/// on (a hidden kernel is never drawn).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthTest {
    /// Every pixel of the object receives every visible kernel.
    Off,
    /// A pixel receives a kernel only where its depth is within the kernel's tolerance.
    Hard,
    /// As `Hard`, but fading out over the tolerance's second half (no popping at folds).
    Fuzzy,
}

/// [`DepthTest`] names.
pub const DEPTH_TESTS: [(&str, DepthTest); 3] = [
    ("off", DepthTest::Off),
    ("hard", DepthTest::Hard),
    ("fuzzy", DepthTest::Fuzzy),
];

/// Which way the strokes of hatching run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Follow {
    /// At `orientation` on the screen.
    Screen,
    /// Along the surface's principal direction around the object (the parallels of the
    /// sphere, cylinder and vase; the sheet's rows on the plane and book), turned by
    /// `orientation`.
    Curvature,
    /// Along the marbled design's local stretch: the direction in which the ops drew the
    /// ink out (from the Jacobian of the inverse walk at the kernel's design point),
    /// turned by `orientation`; where the ink is not stretched, as `curvature`.
    Stretch,
}

/// [`Follow`] names.
pub const FOLLOWS: [(&str, Follow); 3] = [
    ("screen", Follow::Screen),
    ("curvature", Follow::Curvature),
    ("stretch", Follow::Stretch),
];

impl Follow {
    /// The direction's name in [`FOLLOWS`].
    pub fn name(self) -> &'static str {
        name(&FOLLOWS, self)
    }
}

/// Kernel frequency F₀, cycles per screen pixel.
pub const MARK_FREQUENCY: Range = ranges::GABOR_FREQUENCY;
/// Kernel bandwidth a, 1/pixels.
pub const MARK_BANDWIDTH: Range = Range::within(0.02, 0.5);
/// N₀, the mean number of kernels over a point (16–128 in Bénard et al.).
pub const MARK_IMPULSES: Range = Range::within(1.0, 128.0);
/// Threshold of the marks, noise standard deviations (lower: less ink).
pub const MARK_TONE: Range = Range::within(-4.0, 4.0);
/// Width of the threshold's smoothstep, noise standard deviations.
pub const MARK_SOFTNESS: Range = Range::within(0.01, 4.0);
/// How far the threshold moves per unit of darkness (0: the light has no say).
pub const MARK_SHADING: Range = Range::within(0.0, 4.0);
/// How much darkness raises a kernel's frequency: F = F₀·(1 + k·(d − ½)), d = 1 − the
/// headlight's cosine at the kernel's centre (darker, denser marks; 0: fixed F₀).
pub const MARK_FREQUENCY_SHADING: Range = Range::within(0.0, 1.8);
/// Fibres per screen pixel (Kaplan & Cohen's FibersPerPixel).
pub const FIBERS_PER_PIXEL: Range = Range::above(0.0, 0.5);
/// Fibre length on screen, pixels (Kaplan & Cohen: 20–40).
pub const FIBER_LENGTH: Range = Range::within(2.0, 120.0);
/// Fibre width on screen, pixels (Kaplan & Cohen: 1–3).
pub const FIBER_WIDTH: Range = Range::within(0.5, 8.0);
/// Opacity of the ink (marks) or of one fibre.
pub const OPACITY: Range = Range::within(0.0, 1.0);

/// The Gabor marks' parameters (screen pixels).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Marks {
    /// F₀, cycles per pixel.
    pub frequency: f32,
    /// a, 1/pixels.
    pub bandwidth: f32,
    /// N₀, mean kernels over a point.
    pub impulses: f32,
    /// ω₀, degrees (screen: from +x towards +y; curvature: from the principal direction).
    pub orientation: f32,
    /// Which way ω₀ is measured from.
    pub follow: Follow,
    /// Threshold, noise standard deviations: ink where the noise is below it.
    pub tone: f32,
    /// Smoothstep width, noise standard deviations.
    pub softness: f32,
    /// Threshold shift per unit of darkness (1 − the headlight's cosine): darker, more ink.
    pub shading: f32,
    /// k of [`MARK_FREQUENCY_SHADING`]: darker, denser marks.
    pub frequency_shading: f32,
}

/// The fibres' parameters (screen pixels).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fibres {
    /// Fibres per screen pixel.
    pub per_pixel: f32,
    /// Shortest and longest fibre, pixels.
    pub length: [f32; 2],
    /// Narrowest and widest fibre, pixels.
    pub width: [f32; 2],
    /// Canvas only: relative weights of horizontal and vertical threads.
    pub weave: [f32; 2],
}

/// A style: what is drawn, in which ink, and how the marks are anchored.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StyleSpec {
    /// Which style.
    pub kind: StyleKind,
    /// The marks (hatching, stipple, crosshatch, graphite).
    pub marks: Marks,
    /// The fibres (paper, canvas).
    pub fibres: Fibres,
    /// Ink (marks) or fibre colour, sRGB in [0, 1] (Kaplan & Cohen's κ for fibres).
    pub ink: Rgb,
    /// Opacity of full ink, or of one fibre.
    pub opacity: f32,
    /// Where kernel centres live (marks only).
    pub anchoring: Anchoring,
    /// The depth test between a kernel and the pixels it reaches (marks only).
    pub depth_test: DepthTest,
    /// Seed of every patch's random stream.
    pub seed: u32,
}

impl StyleSpec {
    /// The preset of `kind`.
    pub fn preset(kind: StyleKind) -> Self {
        let marks = |frequency, bandwidth, impulses, orientation, tone, softness| Marks {
            frequency,
            bandwidth,
            impulses,
            orientation,
            follow: Follow::Curvature,
            tone,
            softness,
            shading: 1.0,
            frequency_shading: 0.0,
        };
        let hatch = marks(0.14, 0.05, 32.0, 30.0, -0.2, 0.5);
        let (marks, ink, opacity) = match kind {
            StyleKind::Hatching | StyleKind::Paper | StyleKind::Canvas => {
                (hatch, [0.10, 0.09, 0.12], 0.85)
            }
            StyleKind::Stipple => (
                marks(0.07, 0.07, 24.0, 0.0, -1.1, 0.35),
                [0.08, 0.07, 0.10],
                0.9,
            ),
            StyleKind::Crosshatch => (
                marks(0.12, 0.05, 32.0, 45.0, -0.6, 0.5),
                [0.10, 0.09, 0.12],
                0.8,
            ),
            StyleKind::Graphite => (
                marks(0.2, 0.06, 32.0, 60.0, 0.4, 0.7),
                [0.18, 0.18, 0.21],
                0.85,
            ),
            // Pigment blotches some 25 px across; the paper grain is a layer at 3.5×.
            StyleKind::Watercolor => (marks(0.02, 0.04, 16.0, 0.0, 0.0, 1.0), [0.5, 0.5, 0.5], 0.8),
            // Broad soft strokes (low bandwidth: long), a blue-black felt ink.
            StyleKind::Felt => (
                marks(0.07, 0.03, 24.0, 20.0, -0.1, 0.9),
                [0.30, 0.36, 0.62],
                0.75,
            ),
            // Brush strokes some 14 px wide with fibres along them.
            StyleKind::Painterly => (
                marks(0.035, 0.025, 24.0, 35.0, 0.0, 1.0),
                [0.5, 0.5, 0.5],
                0.9,
            ),
        };
        let paper = Fibres {
            per_pixel: 0.05,
            length: [20.0, 40.0],
            width: [1.0, 3.0],
            weave: [1.0, 1.0],
        };
        let (fibres, ink, opacity) = match kind {
            StyleKind::Paper => (paper, [0.35, 0.32, 0.24], 0.12),
            StyleKind::Canvas => (
                Fibres {
                    per_pixel: 0.06,
                    width: [2.0, 3.0],
                    ..paper
                },
                [0.30, 0.27, 0.20],
                0.12,
            ),
            _ => (paper, ink, opacity),
        };
        Self {
            kind,
            marks,
            fibres,
            ink,
            opacity,
            anchoring: Anchoring::Surface,
            depth_test: DepthTest::Fuzzy,
            seed: 1,
        }
    }

    /// Reads a style spec from JSON text (grammar in the crate README): `style` names
    /// the preset, every other field overrides it.
    pub fn from_json(text: &str) -> Result<Self, SpecError> {
        crate::style_reader::read_style(&SpecError::parse(text)?).map_err(SpecError::Invalid)
    }

    /// The spec as JSON, every field written (reads back to the same spec).
    pub fn to_json(&self) -> Value {
        let hex = |c: Rgb| {
            let b = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
            format!("#{:02x}{:02x}{:02x}", b(c[0]), b(c[1]), b(c[2]))
        };
        let m = &self.marks;
        let f = &self.fibres;
        json!({
            "style": self.kind.name(),
            "frequency": m.frequency,
            "bandwidth": m.bandwidth,
            "impulses": m.impulses,
            "orientation": m.orientation,
            "follow": m.follow.name(),
            "tone": m.tone,
            "softness": m.softness,
            "shading": m.shading,
            "frequency_shading": m.frequency_shading,
            "fibers_per_pixel": f.per_pixel,
            "length": f.length,
            "width": f.width,
            "weave": f.weave,
            "ink": hex(self.ink),
            "opacity": self.opacity,
            "anchoring": self.anchoring.name(),
            "depth_test": name(&DEPTH_TESTS, self.depth_test),
            "seed": self.seed,
        })
    }
}

/// The name of `v` in a name table.
fn name<T: PartialEq>(table: &[(&'static str, T)], v: T) -> &'static str {
    table.iter().find(|(_, k)| *k == v).map_or("", |(n, _)| *n)
}

/// α(N) of Bénard et al. 2010, eqs. 2–4: for N ≥ 1 expected kernels, draw 2M points,
/// M = 2^⌊log₂ N⌋, the first M weighted 1 and the next M weighted
/// α = √(N/M − 1), so (1 + α²)·M = N keeps the noise's variance and spectrum, and α
/// grows from 0 as N passes a power of two (no kernel pops in or out). Returns (M, α);
/// N < 1 gives (1, N): one point weighted N, as the paper states.
pub fn lod_weights(n: f64) -> (u32, f64) {
    if n.is_nan() || n < 1.0 {
        return (1, n.max(0.0));
    }
    let m = 2f64.powi(n.log2().floor() as i32);
    // log2 may round a power of two down; keep N/M in [1, 2).
    let m = if n / m >= 2.0 { m * 2.0 } else { m };
    (m as u32, (n / m - 1.0).max(0.0).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lod_weights_keep_the_variance_from_1_to_10000() {
        let mut n = 1.0f64;
        while n <= 1e4 {
            let (m, alpha) = lod_weights(n);
            let m = f64::from(m);
            assert!((1.0 + alpha * alpha) * m / n - 1.0 < 1e-12, "N = {n}");
            assert!(
                ((1.0 + alpha * alpha) * m / n - 1.0).abs() < 1e-12,
                "N = {n}"
            );
            assert!(m <= n && n < 2.0 * m, "N = {n}, M = {m}");
            n *= 1.0137;
        }
        // Continuity at a power of two: α → 1 from below, 0 at it.
        let (m_lo, a_lo) = lod_weights(64.0 - 1e-9);
        let (m_hi, a_hi) = lod_weights(64.0);
        assert_eq!((m_lo, m_hi), (32, 64));
        assert!((a_lo - 1.0).abs() < 1e-6 && a_hi == 0.0);
        assert_eq!(lod_weights(0.25), (1, 0.25));
    }

    #[test]
    fn every_preset_round_trips_through_json() {
        for (name, kind) in STYLE_KINDS {
            let spec = StyleSpec::preset(kind);
            let text = spec.to_json().to_string();
            let back = StyleSpec::from_json(&text).expect(name);
            assert_eq!(back.to_json(), spec.to_json(), "{name}");
            assert_eq!(back.kind, kind);
        }
    }
}
