//! Noise specs: the JSON documents `marbling noise` reads, parsed with errors that name
//! the JSON path of every problem (`frequency: must be > 0, got -3`).
//!
//! Every spec is an object with a `type` and type-specific fields (see the crate
//! README), plus optional `tile` (repeat every output size), `transfer`, `palette` and
//! `blend`. Lengths are in output pixels, frequencies in cycles per output pixel,
//! angles in radians from +x towards +y (x right, y down).

use crate::fbm::FbmParams;
use crate::fibers::FiberParams;
use crate::gabor::GaborKind;
use crate::ramp::{ColorRamp, Rgb};
use crate::ranges;
use crate::spec_reader::read_spec;
use crate::transfer::Threshold;
use crate::{CurlComponent, Metric, WorleyFeature};
pub use marbling_json::FieldError;
use serde_json::Value;

/// Names accepted in `type`.
pub const NOISE_TYPES: &[&str] = &[
    "gabor", "perlin", "value", "worley", "white", "curl", "paper", "canvas", "product",
];

/// Most impulses per kernel a Gabor spec may ask for.
pub const MAX_IMPULSES: f64 = ranges::IMPULSES.hi;

/// Why a spec could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SpecError {
    /// Not JSON; line and column are 1-based.
    #[error("line {line}, column {column}: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What the parser expected.
        message: String,
    },
    /// Valid JSON that is not a valid spec; every problem is listed, one per line.
    #[error("{}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("\n"))]
    Invalid(Vec<FieldError>),
}

/// How a Gabor parameter is driven by another field.
#[derive(Clone, Debug, PartialEq)]
pub struct DriveSpec {
    /// The driving noise (no transfer, palette or blend).
    pub noise: Box<NoiseSpec>,
    /// Radians (orientation) or octaves (frequency) per unit of the noise.
    pub amount: f32,
}

/// The noise a spec evaluates.
#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    /// Sparse Gabor noise ([`crate::Gabor`]).
    Gabor {
        /// Kind.
        kind: GaborKind,
        /// F₀, cycles per pixel.
        frequency: f32,
        /// ω₀, radians.
        orientation: f32,
        /// a, 1/pixels.
        bandwidth: f32,
        /// Mean kernels per point.
        impulses: f32,
        /// Seed.
        seed: u32,
        /// Field driving the orientation.
        orientation_field: Option<DriveSpec>,
        /// Field driving the frequency.
        frequency_field: Option<DriveSpec>,
    },
    /// fBm of Perlin or value noise ([`crate::Fbm`]); `period` is filled in at build time.
    Fbm(FbmParams),
    /// Worley noise.
    Worley {
        /// Feature points per pixel along each axis (cells per pixel).
        frequency: f32,
        /// Returned distance.
        feature: WorleyFeature,
        /// Distance function.
        metric: Metric,
        /// Seed.
        seed: u32,
    },
    /// White noise per pixel.
    White {
        /// Seed.
        seed: u32,
    },
    /// Curl noise of an fBm potential.
    Curl {
        /// The potential (Perlin basis).
        potential: FbmParams,
        /// The shown scalar.
        component: CurlComponent,
    },
    /// Paper or canvas fibers.
    Fibers(FiberParams),
    /// Product of the intensities of several specs (cross-hatching).
    Product(Vec<NoiseSpec>),
}

/// Intensity transfer of a spec.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transfer {
    /// Smoothstep threshold.
    Threshold(Threshold),
    /// Seed 004's spline decay with mean intensity `value`.
    SplineDecay(DecayValue),
}

/// The value v a spline decay tracks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DecayValue {
    /// The same v everywhere.
    Constant(f32),
    /// v rising from 0 at the left edge to 1 at the right edge (a legend strip).
    RampX,
}

/// Seed 004's HSV value blend of the intensity into a base colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Blend {
    /// β, the share of the base colour's value kept (0.6 in the paper).
    pub beta: f32,
    /// The base colour: one colour, or a palette sampled from left (0) to right (1).
    pub base: BlendBase,
}

/// Base colour of a [`Blend`].
#[derive(Clone, Debug, PartialEq)]
pub enum BlendBase {
    /// One sRGB colour.
    Color(Rgb),
    /// A ramp across the image, left to right.
    Ramp(ColorRamp),
}

/// A parsed noise spec.
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseSpec {
    /// What is evaluated.
    pub source: Source,
    /// Whether the result tiles with period equal to the output size.
    pub tile: bool,
    /// Noise → intensity; default 0.5 + n/6 clamped.
    pub transfer: Option<Transfer>,
    /// Intensity → colour.
    pub palette: Option<ColorRamp>,
    /// Intensity blended into a base colour's HSV value.
    pub blend: Option<Blend>,
}

impl NoiseSpec {
    /// Parses and checks a spec; every problem is reported with its path.
    pub fn from_json(text: &str) -> Result<Self, SpecError> {
        let value = marbling_json::parse(text).map_err(|e| SpecError::Syntax {
            line: e.line,
            column: e.column,
            message: e.message,
        })?;
        Self::from_value(&value)
    }

    /// Parses and checks a spec given as a JSON value.
    pub fn from_value(value: &Value) -> Result<Self, SpecError> {
        read_spec(value).map_err(SpecError::Invalid)
    }

    /// Whether the output is coloured (palette or blend) rather than greyscale.
    #[must_use]
    pub fn is_colored(&self) -> bool {
        self.palette.is_some() || self.blend.is_some()
    }
}
