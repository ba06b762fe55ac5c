//! Procedural noises for the marbling playground, each in two forms with the same
//! names: a CPU reference (this crate, f32, deterministic) and WGSL (`shaders/*.wgsl`,
//! see [`wgsl`]), sharing one u32 hash so both give the same pattern for a seed.
//!
//! Noises: sparse Gabor (anisotropic, isotropic, random phase; orientation and frequency
//! optionally driven by another field) and phasor noise from the same kernels (sine,
//! square, saw or triangle profile), Perlin fBm, value noise, Worley (F1, F2, F2 − F1
//! × Euclidean, Manhattan, Chebyshev), white noise, curl noise, paper and canvas fibers;
//! tileable variants; transfer functions (thresholds, Khlebnikov et al. (2013)'s spline decay, curves,
//! HSV value blend) and colour ramps; layers combined by add, multiply, max, min or mask;
//! Gabor parameters driven by data grids (Khlebnikov et al. 2013); JSON specs with path-named errors.
//!
//! Conventions: positions in output pixels, x right, y down; frequencies in cycles per
//! output pixel; angles in radians from +x towards +y. Every noise is normalised to zero
//! mean and unit variance (analytically where a formula exists, else by constants
//! measured once and checked by tests).

pub mod analysis;
mod cost;
mod curl;
mod curve;
mod data;
mod fbm;
mod fbm64;
mod fibers;
mod field;
mod gabor;
pub mod hash;
mod layer;
mod maps;
pub mod noise_gpu;
mod perlin;
mod perlin3;
mod phasor;
mod ramp;
pub mod ranges;
mod render;
pub mod rows;
mod spec;
mod spec_edit;
mod spec_reader;
mod spec_writer;
pub mod stack_gpu;
pub mod style;
mod style_reader;
mod transfer;
mod value;
pub mod wgsl;
mod white;
mod worley;

pub use curl::{Curl, CurlComponent};
pub use curve::{Curve, CurveError, MAX_CURVE_POINTS};
pub use data::{
    Channel, DataError, DataGrid, DataRef, MAX_DATA_SIDE, WEATHER, WEATHER_PRESSURE, WEATHER_SIZE,
    WEATHER_TEMPERATURE,
};
pub use fbm::{Basis, Fbm, FbmParams, MAX_OCTAVES, OCTAVE_SEED_STEP};
pub use fbm64::{Fbm64, Jet, VALUE_GRADIENT_BOUND};
pub use fibers::{
    FiberLayout, FiberParams, Fibers, IMPURITY_SEED, Impurities, MAX_FIBERS_PER_CELL,
};
pub use field::Field;
pub use gabor::{Drive, GABOR_TRUNCATION, Gabor, GaborKind, GaborParams};
pub use hash::CellRng;
pub use layer::{COMBINES, Combine, Layer, MAX_LAYERS};
pub use maps::{PngContent, SURFACE_MAPS, SurfaceMap, surface_normal};
pub use perlin::{
    GRADIENTS, PERLIN_DERIVATIVE_VARIANCE, PERLIN_GRADIENT_BOUND, PERLIN_VARIANCE, fade, perlin2,
    perlin2_periodic, perlin2_with_gradient,
};
pub use perlin3::{GRADIENTS3, PERLIN3_BOUND, PRIME_Z, fbm3, perlin3};
pub use phasor::PhasorProfile;
pub use ramp::{ColorRamp, PALETTES, Rgb, parse_hex};
pub use render::{
    Depth, MAX_SIZE, NoiseImage, RenderError, Renderer, noise_field, noise_to_grey, sample_grid,
};
pub use spec::{
    Blend, BlendBase, CurlSpec, DecayValue, DriveSource, DriveSpec, FieldError, GaborSpec,
    MAX_IMPULSES, NOISE_TYPES, NoiseSpec, Source, SpecError, Tile, Transfer, WhiteSpec, WorleySpec,
};
pub use spec_edit::{EDIT_FLOOR, FEATURE_PX};
pub use style::{
    ANCHORINGS, Anchoring, DEPTH_TESTS, DepthTest, FOLLOWS, Fibres, Follow, Marks, STYLE_KINDS,
    StyleBlend, StyleKind, StyleSpec, lod_weights,
};
pub use transfer::{
    SplineDecay, SplineDecayTable, Threshold, hsv_to_rgb, hsv_value_blend, rgb_to_hsv, smoothstep,
};
pub use value::{VALUE_VARIANCE, value2, value2_periodic};
pub use white::{WHITE_HALF_RANGE, white2};
pub use worley::{Metric, WORLEY_MOMENTS, WorleyFeature, worley_normalised, worley2};
