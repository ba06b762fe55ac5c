//! Noise specs: the JSON documents `marbling noise` reads, parsed with errors that name
//! the JSON path of every problem (`frequency: must be > 0, got -3`).
//!
//! Every spec is an object with a `type` and type-specific fields (see the crate
//! README), plus optional `tile` (repeat every output size, or every N pixels),
//! `transfer`, `layers`, `palette` and `blend`. Lengths are in output pixels, frequencies in cycles per output pixel,
//! angles in radians from +x towards +y (x right, y down).

use crate::curve::Curve;
use crate::data::DataRef;
use crate::fbm::FbmParams;
use crate::fibers::FiberParams;
use crate::gabor::{Drive, GaborKind, GaborParams};
use crate::layer::Layer;
use crate::phasor::PhasorProfile;
use crate::ramp::{ColorRamp, Rgb};
use crate::ranges;
use crate::spec_reader::read_spec;
use crate::transfer::Threshold;
use crate::{CurlComponent, Metric, WorleyFeature};
pub use marbling_json::FieldError;
use serde_json::Value;

/// Names accepted in `type`.
pub const NOISE_TYPES: &[&str] = &[
    "gabor", "phasor", "perlin", "value", "worley", "white", "curl", "paper", "canvas", "product",
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

impl SpecError {
    /// Parses JSON text, a syntax error as [`SpecError::Syntax`].
    pub(crate) fn parse(text: &str) -> Result<Value, SpecError> {
        marbling_json::parse(text).map_err(|e| SpecError::Syntax {
            line: e.line,
            column: e.column,
            message: e.message,
        })
    }
}

/// How a Gabor parameter is driven by another field.
#[derive(Clone, Debug, PartialEq)]
pub struct DriveSpec {
    /// The driving field.
    pub by: DriveSource,
    /// Radians (orientation) or octaves (frequency) per unit of the field.
    pub amount: f32,
}

/// What drives a Gabor parameter.
#[derive(Clone, Debug, PartialEq)]
pub enum DriveSource {
    /// A noise (no transfer, palette or blend), unit variance: `{"noise": SPEC}`.
    Noise(Box<NoiseSpec>),
    /// A data channel in [0, 1]: `{"data": NAME, "channel": K}` (Khlebnikov et al. 2013).
    Data(DataRef),
}

/// Whether and how a spec repeats.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Tile {
    /// No repetition.
    #[default]
    Off,
    /// Every output size (`"tile": true`).
    Output,
    /// Every N output pixels (`"tile": N`).
    Period(u32),
}

impl Tile {
    /// The period in pixels for an output of `size`, `None` when not tiling.
    #[must_use]
    pub fn period(self, size: u32) -> Option<u32> {
        match self {
            Tile::Off => None,
            Tile::Output => Some(size),
            Tile::Period(p) => Some(p),
        }
    }

    /// Whether the spec repeats.
    #[must_use]
    pub fn is_on(self) -> bool {
        self != Tile::Off
    }

    /// This tiling, or `outer`'s when this one is off (inputs inherit their spec's).
    #[must_use]
    pub fn or(self, outer: Tile) -> Tile {
        if self.is_on() { self } else { outer }
    }
}

/// The noise a spec evaluates.
#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    /// Sparse Gabor noise, or phasor noise from the same kernels ([`crate::Gabor`]).
    Gabor(GaborSpec),
    /// fBm of Perlin or value noise ([`crate::Fbm`]); `period` is filled in at build time.
    Fbm(FbmParams),
    /// Worley noise.
    Worley(WorleySpec),
    /// White noise per pixel.
    White(WhiteSpec),
    /// Curl noise of an fBm potential.
    Curl(CurlSpec),
    /// Paper or canvas fibers.
    Fibers(FiberParams),
    /// Product of the intensities of several specs (cross-hatching).
    Product(Vec<NoiseSpec>),
}

/// A sparse Gabor noise's parameters (ranges: [`crate::ranges`]).
#[derive(Clone, Debug, PartialEq)]
pub struct GaborSpec {
    /// Kind.
    pub kind: GaborKind,
    /// F₀, cycles per pixel.
    pub frequency: f32,
    /// ω₀, radians.
    pub orientation: f32,
    /// a, 1/pixels.
    pub bandwidth: f32,
    /// Mean kernels per point.
    pub impulses: f32,
    /// Seed.
    pub seed: u32,
    /// Field driving the orientation.
    pub orientation_field: Option<DriveSpec>,
    /// Field driving the frequency.
    pub frequency_field: Option<DriveSpec>,
    /// `Some`: phasor noise (`"type": "phasor"`), the phase of the kernels' complex sum
    /// through this profile ([`PhasorProfile`]); `None`: Gabor noise.
    pub profile: Option<PhasorProfile>,
}

impl GaborSpec {
    /// The noise's parameters for a `period`-pixel tiling (`None`: none), with the
    /// fields driving its orientation and frequency as built by the caller.
    pub fn params(
        &self,
        period: Option<u32>,
        orientation_drive: Option<Drive>,
        frequency_drive: Option<Drive>,
    ) -> GaborParams {
        GaborParams {
            kind: self.kind,
            frequency: self.frequency,
            orientation: self.orientation,
            bandwidth: self.bandwidth,
            impulses: self.impulses,
            seed: self.seed,
            period,
            orientation_drive,
            frequency_drive,
            profile: self.profile,
        }
    }
}

/// A Worley noise's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct WorleySpec {
    /// Feature points per pixel along each axis (cells per pixel).
    pub frequency: f32,
    /// Returned distance.
    pub feature: WorleyFeature,
    /// Distance function.
    pub metric: Metric,
    /// Seed.
    pub seed: u32,
}

/// White noise's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct WhiteSpec {
    /// Seed.
    pub seed: u32,
}

/// A curl noise's parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct CurlSpec {
    /// The potential (Perlin basis).
    pub potential: FbmParams,
    /// The shown scalar.
    pub component: CurlComponent,
}

/// Intensity transfer of a spec.
#[derive(Clone, Debug, PartialEq)]
pub enum Transfer {
    /// Smoothstep threshold.
    Threshold(Threshold),
    /// Khlebnikov et al. (2013)'s spline decay with mean intensity `value`.
    SplineDecay(DecayValue),
    /// A monotone cubic remap of the default intensity through control points.
    Curve(Curve),
}

/// The value v a spline decay tracks.
#[derive(Clone, Debug, PartialEq)]
pub enum DecayValue {
    /// The same v everywhere.
    Constant(f32),
    /// v rising from 0 at the left edge to 1 at the right edge (a legend strip).
    RampX,
    /// v read from a data channel (Khlebnikov et al. 2013: the attribute shown by the frequency).
    Data(DataRef),
}

/// Khlebnikov et al. (2013)'s HSV value blend of the intensity into a base colour.
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
    /// A ramp sampled at a data channel's value (Khlebnikov et al. (2013)'s colour-coded attribute).
    Data {
        /// The colours.
        ramp: ColorRamp,
        /// The channel.
        value: DataRef,
    },
}

/// A parsed noise spec.
#[derive(Clone, Debug, PartialEq)]
pub struct NoiseSpec {
    /// What is evaluated.
    pub source: Source,
    /// Whether and how the result repeats.
    pub tile: Tile,
    /// Noise → intensity; default 0.5 + n/6 clamped.
    pub transfer: Option<Transfer>,
    /// More noises combined with this one's intensity, bottom to top.
    pub layers: Vec<Layer>,
    /// Intensity → colour.
    pub palette: Option<ColorRamp>,
    /// Intensity blended into a base colour's HSV value.
    pub blend: Option<Blend>,
}

impl NoiseSpec {
    /// `source` alone: untiled, the default transfer, no layers, palette or blend.
    #[must_use]
    pub fn from_source(source: Source) -> Self {
        Self {
            source,
            tile: Tile::Off,
            transfer: None,
            layers: Vec::new(),
            palette: None,
            blend: None,
        }
    }

    /// Whether the spec is its source alone ([`NoiseSpec::from_source`]).
    #[must_use]
    pub fn is_plain(&self) -> bool {
        self.tile == Tile::Off
            && self.transfer.is_none()
            && self.layers.is_empty()
            && self.palette.is_none()
            && self.blend.is_none()
    }

    /// Parses and checks a spec; every problem is reported with its path.
    pub fn from_json(text: &str) -> Result<Self, SpecError> {
        Self::from_value(&SpecError::parse(text)?)
    }

    /// Parses and checks a spec given as a JSON value.
    pub fn from_value(value: &Value) -> Result<Self, SpecError> {
        read_spec(value).map_err(SpecError::Invalid)
    }

    /// Every data reference of the spec (drives, transfers, blend, layers), to attach
    /// their grids.
    pub fn data_refs_mut(&mut self) -> Vec<&mut DataRef> {
        let mut out = Vec::new();
        collect_refs(self, &mut out);
        out
    }

    /// Attaches every data grid the spec names and has not attached yet, from `load`
    /// (given the name); the first failure as a problem at its path.
    pub fn attach_data(
        &mut self,
        load: &mut dyn FnMut(&str) -> Result<std::sync::Arc<crate::DataGrid>, String>,
    ) -> Result<(), FieldError> {
        for r in self.data_refs_mut() {
            if r.grid.is_none() {
                let grid = load(&r.name).map_err(|message| FieldError {
                    path: "data".into(),
                    message: format!("'{}': {message}", r.name),
                })?;
                r.grid = Some(grid);
            }
            let n = r.grid.as_ref().map_or(0, |g| g.channels.len());
            if r.channel > n {
                return Err(FieldError {
                    path: "channel".into(),
                    message: format!("'{}' has {n} channels, got channel {}", r.name, r.channel),
                });
            }
        }
        Ok(())
    }

    /// Whether the output is coloured (palette or blend) rather than greyscale.
    #[must_use]
    pub fn is_colored(&self) -> bool {
        self.palette.is_some() || self.blend.is_some()
    }
}

fn collect_refs<'a>(spec: &'a mut NoiseSpec, out: &mut Vec<&'a mut DataRef>) {
    match &mut spec.source {
        Source::Gabor(GaborSpec {
            orientation_field,
            frequency_field,
            ..
        }) => {
            for d in [orientation_field, frequency_field].into_iter().flatten() {
                match &mut d.by {
                    DriveSource::Data(r) => out.push(r),
                    DriveSource::Noise(n) => collect_refs(n, out),
                }
            }
        }
        Source::Product(inputs) => {
            for i in inputs {
                collect_refs(i, out);
            }
        }
        _ => {}
    }
    if let Some(Transfer::SplineDecay(DecayValue::Data(r))) = &mut spec.transfer {
        out.push(r);
    }
    if let Some(Blend {
        base: BlendBase::Data { value, .. },
        ..
    }) = &mut spec.blend
    {
        out.push(value);
    }
    for l in &mut spec.layers {
        collect_refs(&mut l.noise, out);
        if let Some(m) = &mut l.mask {
            collect_refs(m, out);
        }
    }
}
