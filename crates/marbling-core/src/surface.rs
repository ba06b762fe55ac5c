//! Schema v2 surfaces: a procedural-noise background mapped to a palette ("start from
//! noise"), and grain overlays applied after marbling.
//!
//! # Conventions (keep in sync with `surface.wgsl` in marbling-gpu)
//! - Noise is evaluated at **design pixels** (x right, y down), the same coordinates as
//!   the ops, so a design looks the same at every output scale. Noise specs use the
//!   `marbling-noise` JSON format; their frequencies are therefore cycles per design pixel.
//! - Intensity of a noise value n (zero mean, unit variance): the spec's `threshold`
//!   transfer if it has one, else the default `0.5 + n/6` clamped to [0, 1].
//! - Background colour: the palette at that intensity (stops evenly spaced, interpolated
//!   linearly in sRGB as `marbling-noise` ramps are), then converted to linear light.
//!   The noise is sampled at the **back-traced** point, where the sample's walk leaves
//!   the oldest op without meeting ink: the background is marbled like ink.
//! - Overlays multiply the sample's colour **in linear light** by `1 − strength·g`,
//!   g the overlay's intensity (so they only darken; strength ∈ [0, 1]), per sample,
//!   before antialiasing averages samples (also in linear light). `paper-grain` samples
//!   its noise at the sample's **output design point** (fixed to the paper: it does not
//!   move when the ink is combed); `pigment-grain` at the point where the walk ended —
//!   the back-traced point for background samples, or the point inside the drop/spray
//!   disc that covered the sample — so it flows with the ink (Bénard et al. 2010: flatness vs
//!   coherent motion). Paper grain is applied after pigment grain (the order does not
//!   change the product).
//! - Inside a design a noise spec may not `tile`, stack `layers` or carry its own
//!   `palette`/`blend` (the palette sits beside it), its `transfer` must be a threshold, and it must have
//!   a WGSL form (no `product`; Gabor driving fields are perlin/value fBm), so the CPU
//!   and the GPU renderers draw the same picture.

use crate::Rgb8;
use crate::image_background::{ImageBackground, ImageMap};
use marbling_noise::GaborSpec;
use marbling_noise::noise_gpu::{GpuUnsupported, wgsl_form};
use marbling_noise::{
    ColorRamp, Field, FieldError, NoiseSpec, PALETTES, Source, Transfer, noise_field,
};
use serde_json::Value;
use std::fmt;
use std::sync::Arc;

/// Most stops a background palette may have (the GPU uniform holds this many).
pub const MAX_PALETTE_STOPS: usize = 8;
/// Names accepted as overlay `type`.
pub const OVERLAY_TYPES: &[&str] = &["paper-grain", "pigment-grain"];

/// A noise spec usable inside a design: the JSON as written (kept so the design writes
/// it back unchanged) and its evaluator.
#[derive(Clone)]
pub struct NoiseLayer {
    json: Value,
    spec: NoiseSpec,
    field: Arc<dyn Field>,
    threshold: Option<marbling_noise::Threshold>,
}

impl fmt::Debug for NoiseLayer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "NoiseLayer({})", self.json)
    }
}

impl PartialEq for NoiseLayer {
    fn eq(&self, other: &Self) -> bool {
        self.json == other.json
    }
}

impl NoiseLayer {
    /// Parses a noise spec (the `marbling-noise` JSON format) for use in a design; every
    /// problem is returned with its path inside the spec.
    pub fn from_value(json: &Value) -> Result<Self, Vec<FieldError>> {
        let spec = NoiseSpec::from_value(json).map_err(|e| match e {
            marbling_noise::SpecError::Invalid(list) => list,
            other => vec![FieldError {
                path: String::new(),
                message: other.to_string(),
            }],
        })?;
        Self::checked(json.clone(), spec)
    }

    /// A spec made in code, for use in a design: written ([`NoiseSpec::to_value`]) and
    /// read back, so every range of the spec grammar is checked as for a document (a
    /// typed spec can hold any number: the reader is where the ranges are enforced).
    pub fn from_spec(spec: &NoiseSpec) -> Result<Self, Vec<FieldError>> {
        Self::from_value(&spec.to_value())
    }

    /// `spec` (written as `json`) if a design may hold it: no tiling, palette, blend or
    /// spline decay, and a WGSL form.
    fn checked(json: Value, spec: NoiseSpec) -> Result<Self, Vec<FieldError>> {
        let mut problems = Vec::new();
        let mut no = |path: &str, message: &str| {
            problems.push(FieldError {
                path: path.to_owned(),
                message: message.to_owned(),
            })
        };
        if !spec.layers.is_empty() {
            no("layers", "not allowed in a design");
        }
        if spec.tile.is_on() {
            no("tile", "not allowed in a design (a design does not repeat)");
        }
        if spec.palette.is_some() {
            no(
                "palette",
                "not allowed inside the noise; put the palette beside \"noise\"",
            );
        }
        if spec.blend.is_some() {
            no("blend", "not allowed in a design");
        }
        if matches!(
            spec.transfer,
            Some(Transfer::SplineDecay(_) | Transfer::Curve(_))
        ) {
            no(
                "transfer",
                "only a threshold transfer is allowed in a design",
            );
        }
        let field = noise_field(&spec, 1);
        match (&field, wgsl_form(&spec)) {
            (None, _) | (_, Err(GpuUnsupported::Product)) => {
                no("type", "a product is not allowed in a design")
            }
            (_, Err(e)) => no("", &e.to_string()),
            _ => {}
        }
        let Some(field) = field else {
            return Err(problems);
        };
        if !problems.is_empty() {
            return Err(problems);
        }
        let threshold = match spec.transfer {
            Some(Transfer::Threshold(t)) => Some(t),
            _ => None,
        };
        Ok(Self {
            json,
            spec,
            field,
            threshold,
        })
    }

    /// Parses a noise spec given as JSON text; problems joined one per line.
    pub fn from_json(text: &str) -> Result<Self, String> {
        let v: Value = serde_json::from_str(text).map_err(|e| e.to_string())?;
        Self::from_value(&v).map_err(|list| {
            list.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        })
    }

    /// The spec as written in the document.
    pub fn json(&self) -> &Value {
        &self.json
    }

    /// The parsed spec.
    pub fn spec(&self) -> &NoiseSpec {
        &self.spec
    }

    /// The threshold transfer, if the spec has one (else the default grey map applies).
    pub fn threshold(&self) -> Option<marbling_noise::Threshold> {
        self.threshold
    }

    /// The noise value (zero mean, unit variance) at design point (x, y).
    #[inline]
    pub fn noise(&self, x: f64, y: f64) -> f32 {
        self.field.sample(x as f32, y as f32)
    }

    /// Intensity in [0, 1] at design point (x, y): the threshold transfer of the noise,
    /// or `0.5 + n/6` clamped.
    #[inline]
    pub fn intensity(&self, x: f64, y: f64) -> f32 {
        let n = self.noise(x, y);
        match self.threshold {
            Some(t) => t.apply(n),
            None => marbling_noise::noise_to_grey(n),
        }
    }

    /// The noise type name (`gabor`, `perlin`, …).
    pub fn type_name(&self) -> &str {
        self.json.get("type").and_then(Value::as_str).unwrap_or("?")
    }

    /// Whether the spec is a Gabor noise (for callers that pick budgets by cost).
    pub fn is_gabor(&self) -> bool {
        matches!(self.spec.source, Source::Gabor(GaborSpec { .. }))
    }
}

/// Colours a noise intensity maps to: a named `marbling-noise` palette or 2 to
/// [`MAX_PALETTE_STOPS`] sRGB stops, evenly spaced from intensity 0 to 1 and
/// interpolated linearly in sRGB.
#[derive(Clone, Debug, PartialEq)]
pub struct Palette {
    /// The built-in name it was given by, if any (written back as the name).
    pub name: Option<String>,
    /// The stops, intensity 0 first.
    pub stops: Vec<Rgb8>,
}

/// Why a palette cannot be made.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum PaletteError {
    /// Not a built-in name.
    #[error("unknown palette {0:?}; expected one of {names} or an array of \"#rrggbb\"", names = PALETTES.join(", "))]
    UnknownName(String),
    /// Too few or too many stops.
    #[error("must have 2 to {MAX_PALETTE_STOPS} colours, got {0}")]
    StopCount(usize),
}

fn to_byte(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

impl Palette {
    /// The built-in palette `name` (see `marbling_noise::PALETTES`).
    pub fn named(name: &str) -> Result<Self, PaletteError> {
        let ramp =
            ColorRamp::named(name).ok_or_else(|| PaletteError::UnknownName(name.to_owned()))?;
        Ok(Self {
            name: Some(name.to_owned()),
            stops: ramp
                .stops()
                .iter()
                .map(|c| Rgb8::new(to_byte(c[0]), to_byte(c[1]), to_byte(c[2])))
                .collect(),
        })
    }

    /// A palette through `stops` (2 to [`MAX_PALETTE_STOPS`]).
    pub fn from_stops(stops: Vec<Rgb8>) -> Result<Self, PaletteError> {
        if !(2..=MAX_PALETTE_STOPS).contains(&stops.len()) {
            return Err(PaletteError::StopCount(stops.len()));
        }
        Ok(Self { name: None, stops })
    }

    /// The stops as sRGB values in [0, 1].
    pub fn srgb_stops(&self) -> Vec<[f32; 3]> {
        self.stops
            .iter()
            .map(|c| [c.r, c.g, c.b].map(|v| f32::from(v) / 255.0))
            .collect()
    }
}

/// sRGB value in [0, 1] → linear light (IEC 61966-2-1), f32 as in the WGSL.
#[inline]
pub fn srgb_unit_to_linear(c: f32) -> f32 {
    if c <= 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// A background of noise mapped to a palette (schema v2 `background` object).
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseBackground {
    /// The noise, sampled at back-traced design points.
    pub noise: NoiseLayer,
    /// Intensity → colour.
    pub palette: Palette,
}

impl NoiseBackground {
    /// A background of `noise` coloured by `palette`.
    pub fn new(noise: NoiseLayer, palette: Palette) -> Self {
        Self { noise, palette }
    }

    /// The palette colour at intensity 0.5 as sRGB bytes: the plain colour that stands
    /// for this background where one colour is needed (`Design::background`).
    pub fn mid_color(&self) -> Rgb8 {
        let ramp = self.ramp();
        let c = ramp.sample(0.5);
        Rgb8::new(to_byte(c[0]), to_byte(c[1]), to_byte(c[2]))
    }

    fn ramp(&self) -> ColorRamp {
        // Palettes are checked to have at least two stops; a grey ramp is the fallback.
        ColorRamp::new(self.palette.srgb_stops())
            .or_else(|| ColorRamp::named("grey"))
            .unwrap_or_else(|| unreachable!("the grey palette exists"))
    }
}

/// Which way a grain overlay is attached.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GrainKind {
    /// Fixed to the paper: sampled at the output design point.
    Paper,
    /// Flows with the ink: sampled where the sample's walk ended.
    Pigment,
}

impl GrainKind {
    /// The overlay `type` in JSON.
    pub fn name(self) -> &'static str {
        match self {
            GrainKind::Paper => "paper-grain",
            GrainKind::Pigment => "pigment-grain",
        }
    }
}

/// A grain overlay (schema v2 `overlays[i]`): multiplies linear colour by
/// `1 − strength·intensity`.
#[derive(Clone, Debug, PartialEq)]
pub struct Overlay {
    /// Paper or pigment grain.
    pub kind: GrainKind,
    /// The grain noise.
    pub noise: NoiseLayer,
    /// Darkening at intensity 1, in [0, 1].
    pub strength: f64,
}

impl Overlay {
    /// Paper grain of `noise` at `strength` (0..=1).
    pub fn paper_grain(noise: NoiseLayer, strength: f64) -> Self {
        Self {
            kind: GrainKind::Paper,
            noise,
            strength,
        }
    }

    /// Pigment grain of `noise` at `strength` (0..=1).
    pub fn pigment_grain(noise: NoiseLayer, strength: f64) -> Self {
        Self {
            kind: GrainKind::Pigment,
            noise,
            strength,
        }
    }

    /// The factor on linear colour at design point (x, y): `1 − strength·g`.
    #[inline]
    pub fn factor(&self, x: f64, y: f64) -> f32 {
        1.0 - self.strength as f32 * self.noise.intensity(x, y)
    }
}

/// Everything that colours samples besides ink, prepared for the CPU renderer.
#[derive(Clone, Debug)]
pub(crate) struct Surface {
    background: Option<(NoiseLayer, ColorRamp)>,
    image: Option<(ImageBackground, ImageMap)>,
    plain: [f32; 3],
    paper: Vec<Overlay>,
    pigment: Vec<Overlay>,
}

impl Surface {
    /// `None` for a plain background without overlays (the fast palette path).
    pub(crate) fn new(design: &crate::Design) -> Option<Self> {
        if !design.uses_v2() {
            return None;
        }
        let pick = |k: GrainKind| {
            design
                .overlays
                .iter()
                .filter(|o| o.kind == k)
                .cloned()
                .collect::<Vec<_>>()
        };
        Some(Self {
            background: design
                .background_noise
                .as_ref()
                .map(|b| (b.noise.clone(), b.ramp())),
            image: design
                .background_image
                .as_ref()
                .map(|b| (b.clone(), b.map(design.width, design.height))),
            plain: design.background.to_linear(),
            paper: pick(GrainKind::Paper),
            pigment: pick(GrainKind::Pigment),
        })
    }

    /// Linear colour of the background at back-traced point (x, y).
    #[inline]
    pub(crate) fn background(&self, x: f64, y: f64) -> [f32; 3] {
        if let Some((image, map)) = &self.image {
            return map.sample(image.pixels(), x, y, self.plain);
        }
        match &self.background {
            Some((noise, ramp)) => ramp.sample(noise.intensity(x, y)).map(srgb_unit_to_linear),
            None => self.plain,
        }
    }

    /// Applies the overlays to linear colour `c` of a sample at output design point
    /// `out` whose walk ended at `end`.
    #[inline]
    pub(crate) fn overlay(&self, mut c: [f32; 3], out: (f64, f64), end: (f64, f64)) -> [f32; 3] {
        for o in &self.pigment {
            let f = o.factor(end.0, end.1);
            c = c.map(|v| v * f);
        }
        for o in &self.paper {
            let f = o.factor(out.0, out.1);
            c = c.map(|v| v * f);
        }
        c
    }
}
