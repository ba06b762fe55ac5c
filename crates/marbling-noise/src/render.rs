//! Evaluating a [`NoiseSpec`] over an N×N image: pixel (i, j) samples the point
//! (i + 0.5, j + 0.5) in output pixels; noise n (zero mean, unit variance) becomes the
//! intensity 0.5 + n/6 clamped to [0, 1], or the spec's transfer of n; a palette or blend
//! turns intensity into colour.

use crate::curl::{Curl, CurlComponent};
use crate::data::DataRef;
use crate::fbm::Fbm;
use crate::fibers::Fibers;
use crate::field::Field;
use crate::gabor::{Drive, Gabor};
use crate::layer::Combine;
use crate::spec::{BlendBase, DecayValue, DriveSource, NoiseSpec, Source, Transfer};
use crate::spec::{CurlSpec, WhiteSpec, WorleySpec};
use crate::transfer::{SplineDecayTable, hsv_value_blend};
use crate::white::white2;
use crate::worley::{Metric, WorleyFeature, worley_normalised};
use std::sync::Arc;

/// Largest output side accepted by [`Renderer::new`].
pub const MAX_SIZE: u32 = 16384;

/// Bits per PNG sample of an export.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Depth {
    /// 256 levels.
    Eight,
    /// 65,536 levels (height maps).
    Sixteen,
}

impl Depth {
    /// Bytes per sample.
    #[must_use]
    pub fn bytes(self) -> usize {
        match self {
            Depth::Eight => 1,
            Depth::Sixteen => 2,
        }
    }
}

/// Why a spec could not be rendered.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum RenderError {
    /// The requested size is 0 or above [`MAX_SIZE`].
    #[error("size must be in 1..={MAX_SIZE}, got {0}")]
    Size(u32),
    /// A data set the spec names was not attached ([`NoiseSpec::attach_data`]).
    #[error("data '{0}' is not loaded")]
    Data(String),
}

/// The default noise-to-intensity map: 0.5 + n/6 clamped (±3σ spans black to white).
#[inline]
#[must_use]
pub fn noise_to_grey(n: f32) -> f32 {
    (0.5 + n / 6.0).clamp(0.0, 1.0)
}

struct Worley {
    frequency: f32,
    seed: u32,
    feature: WorleyFeature,
    metric: Metric,
    period: i32,
}

impl Field for Worley {
    fn sample(&self, x: f32, y: f32) -> f32 {
        worley_normalised(
            x * self.frequency,
            y * self.frequency,
            self.seed,
            self.feature,
            self.metric,
            [self.period, self.period],
        )
    }

    fn sample_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        let f = self.frequency;
        let scaled: Vec<f32> = xs.iter().map(|&x| x * f).collect();
        let mut f2 = vec![0.0; xs.len()];
        let p = [self.period, self.period];
        crate::rows::worley2_row(&scaled, y * f, self.seed, self.metric, p, out, &mut f2);
        for (o, b) in out.iter_mut().zip(f2).take(xs.len()) {
            *o = crate::worley::normalise([*o, b], self.feature, self.metric);
        }
    }
}

struct White {
    seed: u32,
    period: i32,
}

impl Field for White {
    fn sample(&self, x: f32, y: f32) -> f32 {
        white2(x, y, self.seed, [self.period, self.period])
    }
}

impl Field for Fbm {
    fn sample(&self, x: f32, y: f32) -> f32 {
        self.eval(x, y)
    }

    fn sample_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        self.eval_row(xs, y, out);
    }
}

struct CurlField {
    curl: Curl,
    component: CurlComponent,
}

impl Field for CurlField {
    fn sample(&self, x: f32, y: f32) -> f32 {
        self.curl.component(x, y, self.component)
    }
}

/// A data channel as a field: its value in [0, 1] over the frame it is stretched on.
struct DataField {
    data: DataRef,
    frame: [f32; 2],
}

impl Field for DataField {
    fn sample(&self, x: f32, y: f32) -> f32 {
        self.data.sample(x, y, self.frame)
    }
}

/// The unit-variance field of a non-product spec at output size `size` (the size sets the
/// tile period when the spec tiles `true`; data drives are stretched over the size²
/// square). Products have no single noise field: `None`.
#[must_use]
pub fn noise_field(spec: &NoiseSpec, size: u32) -> Option<Arc<dyn Field>> {
    field_in(spec, size, [size as f32; 2])
}

/// [`noise_field`] with data drives stretched over `frame` (width, height) pixels.
fn field_in(spec: &NoiseSpec, size: u32, frame: [f32; 2]) -> Option<Arc<dyn Field>> {
    let period = spec.tile.period(size);
    let field: Arc<dyn Field> = match &spec.source {
        Source::Gabor(g) => {
            let drive = |d: &Option<crate::spec::DriveSpec>| -> Option<Drive> {
                let d = d.as_ref()?;
                let field: Arc<dyn Field> = match &d.by {
                    DriveSource::Noise(n) => {
                        // A tiling Gabor tiles its driving fields too.
                        let noise = NoiseSpec {
                            tile: spec.tile,
                            ..(**n).clone()
                        };
                        field_in(&noise, size, frame)?
                    }
                    DriveSource::Data(r) => Arc::new(DataField {
                        data: r.clone(),
                        frame,
                    }),
                };
                Some(Drive {
                    field,
                    amount: d.amount,
                })
            };
            Arc::new(Gabor::new(g.params(
                period,
                drive(&g.orientation_field),
                drive(&g.frequency_field),
            )))
        }
        Source::Fbm(p) => Arc::new(Fbm::new(crate::FbmParams { period, ..*p })),
        Source::Worley(WorleySpec {
            frequency,
            feature,
            metric,
            seed,
        }) => {
            let (frequency, cells) = lattice_for_period(*frequency, period);
            Arc::new(Worley {
                frequency,
                seed: *seed,
                feature: *feature,
                metric: *metric,
                period: cells,
            })
        }
        Source::White(WhiteSpec { seed }) => Arc::new(White {
            seed: *seed,
            period: period.map_or(0, |p| p as i32),
        }),
        Source::Curl(CurlSpec {
            potential,
            component,
        }) => Arc::new(CurlField {
            curl: Curl::new(Fbm::new(crate::FbmParams {
                period,
                ..*potential
            })),
            component: *component,
        }),
        Source::Fibers(p) => Arc::new(Fibers::new(crate::FiberParams { period, ..*p })),
        Source::Product(_) => return None,
    };
    Some(field)
}

/// A frequency rounded so a whole number of cells fits the period, and that number (0
/// when not tiling).
pub(crate) fn lattice_for_period(frequency: f32, period: Option<u32>) -> (f32, i32) {
    match period {
        Some(p) if p > 0 => {
            let cells = (frequency * p as f32 + 0.5).floor().max(1.0);
            (cells / p as f32, cells as i32)
        }
        _ => (frequency, 0),
    }
}

enum Node {
    Noise {
        field: Arc<dyn Field>,
        transfer: Option<Transfer>,
    },
    Product(Vec<Node>),
    /// A node with layers stacked on it.
    Layered {
        base: Box<Node>,
        layers: Vec<LayerNode>,
    },
}

struct LayerNode {
    node: Node,
    combine: Combine,
    weight: f32,
    mask: Option<Node>,
}

/// A spec prepared for one output size: evaluates intensity and colour per point.
pub struct Renderer {
    root: Node,
    size: u32,
    /// Width and height, output pixels, that data grids, `"x"` values and blend ramps
    /// span.
    frame: [f32; 2],
    decay: Option<SplineDecayTable>,
    spec: NoiseSpec,
}

/// An 8-bit image produced by [`Renderer::render`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NoiseImage {
    /// Side, pixels.
    pub size: u32,
    /// Whether the spec has no palette or blend (then r = g = b).
    pub greyscale: bool,
    /// Row-major sRGB pixels.
    pub pixels: Vec<[u8; 3]>,
}

impl NoiseImage {
    /// The grey level of each pixel (the red channel), row-major.
    #[must_use]
    pub fn grey(&self) -> Vec<u8> {
        self.pixels.iter().map(|p| p[0]).collect()
    }
}

fn build(spec: &NoiseSpec, size: u32, frame: [f32; 2]) -> Node {
    // Inputs, layers and masks of a tiling spec tile too.
    let inherit = |s: &NoiseSpec| NoiseSpec {
        tile: s.tile.or(spec.tile),
        ..s.clone()
    };
    let base = match &spec.source {
        Source::Product(inputs) => Node::Product(
            inputs
                .iter()
                .map(|s| build(&inherit(s), size, frame))
                .collect(),
        ),
        _ => match field_in(spec, size, frame) {
            Some(field) => Node::Noise {
                field,
                transfer: spec.transfer.clone(),
            },
            None => Node::Product(Vec::new()),
        },
    };
    if spec.layers.is_empty() {
        return base;
    }
    Node::Layered {
        base: Box::new(base),
        layers: spec
            .layers
            .iter()
            .map(|l| LayerNode {
                node: build(&inherit(&l.noise), size, frame),
                combine: l.combine,
                weight: l.weight,
                mask: l.mask.as_ref().map(|m| build(&inherit(m), size, frame)),
            })
            .collect(),
    }
}

fn uses_decay(spec: &NoiseSpec) -> bool {
    matches!(spec.transfer, Some(Transfer::SplineDecay(_)))
        || matches!(&spec.source, Source::Product(v) if v.iter().any(uses_decay))
        || spec
            .layers
            .iter()
            .any(|l| uses_decay(&l.noise) || l.mask.as_ref().is_some_and(uses_decay))
}

impl Renderer {
    /// Prepares `spec` for an output of `size`×`size` pixels.
    pub fn new(spec: &NoiseSpec, size: u32) -> Result<Self, RenderError> {
        Self::with_frame(spec, size, [size as f32; 2])
    }

    /// Prepares `spec` for points in a `frame` (width, height, output pixels) that data
    /// grids, `"x"` values and blend ramps span; `size` is the output size a `"tile":
    /// true` repeats over.
    pub fn with_frame(spec: &NoiseSpec, size: u32, frame: [f32; 2]) -> Result<Self, RenderError> {
        if size == 0 || size > MAX_SIZE {
            return Err(RenderError::Size(size));
        }
        let mut unattached = spec.clone();
        if let Some(r) = unattached
            .data_refs_mut()
            .into_iter()
            .find(|r| r.grid.is_none())
        {
            return Err(RenderError::Data(r.name.clone()));
        }
        Ok(Self {
            root: build(spec, size, frame),
            size,
            frame,
            decay: uses_decay(spec).then(SplineDecayTable::new),
            spec: spec.clone(),
        })
    }

    /// Noise n at (x, y) through a node's transfer (or the default grey map).
    fn transfer(&self, transfer: Option<&Transfer>, n: f32, x: f32, y: f32) -> f32 {
        match transfer {
            None => noise_to_grey(n),
            Some(Transfer::Threshold(t)) => t.apply(n),
            Some(Transfer::SplineDecay(v)) => {
                let v = match v {
                    DecayValue::Constant(v) => *v,
                    DecayValue::RampX => x / self.frame[0],
                    DecayValue::Data(r) => r.sample(x, y, self.frame),
                };
                self.decay.as_ref().map_or(0.0, |t| t.decay(v).apply(n))
            }
            Some(Transfer::Curve(c)) => c.apply(n),
        }
    }

    fn node_intensity(&self, node: &Node, x: f32, y: f32) -> f32 {
        match node {
            Node::Noise { field, transfer } => {
                self.transfer(transfer.as_ref(), field.sample(x, y), x, y)
            }
            Node::Product(nodes) => nodes.iter().map(|n| self.node_intensity(n, x, y)).product(),
            Node::Layered { base, layers } => {
                layers.iter().fold(self.node_intensity(base, x, y), |c, l| {
                    let b = self.node_intensity(&l.node, x, y);
                    let m = l
                        .mask
                        .as_ref()
                        .map_or(0.0, |m| self.node_intensity(m, x, y));
                    l.combine.apply(c, b, m, l.weight)
                })
            }
        }
    }

    /// [`Renderer::node_intensity`] at each point of a row (`out[i]` at (xs[i], y)),
    /// bit for bit, through the fields' row kernels.
    fn node_intensity_row(&self, node: &Node, xs: &[f32], y: f32, out: &mut [f32]) {
        match node {
            Node::Noise { field, transfer } => {
                field.sample_row(xs, y, out);
                for (o, &x) in out.iter_mut().zip(xs) {
                    *o = self.transfer(transfer.as_ref(), *o, x, y);
                }
            }
            Node::Product(nodes) => {
                out.fill(1.0);
                let mut v = vec![0.0; xs.len()];
                for n in nodes {
                    self.node_intensity_row(n, xs, y, &mut v);
                    for (o, v) in out.iter_mut().zip(&v) {
                        *o *= v;
                    }
                }
            }
            Node::Layered { base, layers } => {
                self.node_intensity_row(base, xs, y, out);
                let (mut b, mut m) = (vec![0.0; xs.len()], vec![0.0; xs.len()]);
                for l in layers {
                    self.node_intensity_row(&l.node, xs, y, &mut b);
                    match &l.mask {
                        Some(mask) => self.node_intensity_row(mask, xs, y, &mut m),
                        None => m.fill(0.0),
                    }
                    for ((c, b), m) in out.iter_mut().zip(&b).zip(&m) {
                        *c = l.combine.apply(*c, *b, *m, l.weight);
                    }
                }
            }
        }
    }

    /// Intensity in [0, 1] at (x, y), output pixels.
    #[must_use]
    pub fn intensity(&self, x: f32, y: f32) -> f32 {
        self.node_intensity(&self.root, x, y)
    }

    /// [`Renderer::intensity`] at each point of a row: `out[i]` at (xs[i], y), bit for
    /// bit, several times faster for Perlin fBm and Worley.
    pub fn intensity_row(&self, xs: &[f32], y: f32, out: &mut [f32]) {
        self.node_intensity_row(&self.root, xs, y, &mut out[..xs.len()]);
    }

    /// The sRGB colour (components in [0, 1]) at (x, y).
    #[must_use]
    pub fn color(&self, x: f32, y: f32) -> [f32; 3] {
        self.color_of(self.intensity(x, y), x, y)
    }

    /// [`Renderer::color`] at each point of a row, bit for bit.
    #[must_use]
    pub fn color_row(&self, xs: &[f32], y: f32) -> Vec<[f32; 3]> {
        let mut t = vec![0.0; xs.len()];
        self.intensity_row(xs, y, &mut t);
        self.colors_of(xs, y, &t)
    }

    /// The colours of a row whose [`Renderer::intensity_row`] is `t` (for callers that
    /// keep the intensities too).
    #[must_use]
    pub fn colors_of(&self, xs: &[f32], y: f32, t: &[f32]) -> Vec<[f32; 3]> {
        t.iter()
            .zip(xs)
            .map(|(&t, &x)| self.color_of(t, x, y))
            .collect()
    }

    /// The colour of intensity `t` at (x, y): the blend, the palette or grey.
    fn color_of(&self, t: f32, x: f32, y: f32) -> [f32; 3] {
        if let Some(b) = &self.spec.blend {
            let base = match &b.base {
                BlendBase::Color(c) => *c,
                BlendBase::Ramp(r) => r.sample(x / self.frame[0]),
                BlendBase::Data { ramp, value } => ramp.sample(value.sample(x, y, self.frame)),
            };
            hsv_value_blend(base, t, b.beta)
        } else if let Some(p) = &self.spec.palette {
            p.sample(t)
        } else {
            [t, t, t]
        }
    }

    /// The x of each pixel centre of a row: i + 0.5.
    fn centres(&self) -> Vec<f32> {
        (0..self.size).map(|i| i as f32 + 0.5).collect()
    }

    /// Pixels of rows `rows` (row-major), 8-bit sRGB.
    #[must_use]
    pub fn render_rows(&self, rows: std::ops::Range<u32>) -> Vec<[u8; 3]> {
        let mut out = Vec::with_capacity(rows.len() * self.size as usize);
        let xs = self.centres();
        for j in rows {
            for c in self.color_row(&xs, j as f32 + 0.5) {
                out.push(c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8));
            }
        }
        out
    }

    /// The whole image (single thread; split [`Renderer::render_rows`] across threads
    /// for speed).
    #[must_use]
    pub fn render(&self) -> NoiseImage {
        NoiseImage {
            size: self.size,
            greyscale: !self.spec.is_colored(),
            pixels: self.render_rows(0..self.size),
        }
    }

    /// Row `j` as PNG sample bytes: one grey sample per pixel when the output is
    /// greyscale, else RGB; each sample 8-bit, or 16-bit big-endian (`round(v · 65535)`
    /// of the intensity or colour component v).
    #[must_use]
    pub fn png_row(&self, j: u32, depth: Depth) -> Vec<u8> {
        let grey = self.greyscale();
        let channels = if grey { 1 } else { 3 };
        let mut out = Vec::with_capacity(self.size as usize * channels * depth.bytes());
        let (xs, y) = (self.centres(), j as f32 + 0.5);
        let colors = if grey {
            let mut t = vec![0.0; xs.len()];
            self.intensity_row(&xs, y, &mut t);
            t.into_iter().map(|t| [t; 3]).collect()
        } else {
            self.color_row(&xs, y)
        };
        for c in colors {
            for &v in &c[..channels] {
                let v = v.clamp(0.0, 1.0);
                match depth {
                    Depth::Eight => out.push((v * 255.0).round() as u8),
                    Depth::Sixteen => {
                        out.extend_from_slice(&((v * 65535.0).round() as u16).to_be_bytes());
                    }
                }
            }
        }
        out
    }

    /// Side of the output, pixels.
    #[must_use]
    pub fn size(&self) -> u32 {
        self.size
    }

    /// Whether the output is greyscale.
    #[must_use]
    pub fn greyscale(&self) -> bool {
        !self.spec.is_colored()
    }

    /// A PNG encoder for this output at `depth`: size² pixels, grey or RGB as
    /// [`Renderer::png_row`] writes them (feed it those rows).
    pub fn png_encoder<W: std::io::Write>(&self, out: W, depth: Depth) -> png::Encoder<'static, W> {
        let mut enc = png::Encoder::new(out, self.size, self.size);
        enc.set_color(if self.greyscale() {
            png::ColorType::Grayscale
        } else {
            png::ColorType::Rgb
        });
        enc.set_depth(match depth {
            Depth::Eight => png::BitDepth::Eight,
            Depth::Sixteen => png::BitDepth::Sixteen,
        });
        enc
    }
}

/// Samples the unit-variance noise of `spec` (no transfer) over `size`×`size` pixel
/// centres, row-major; `None` for products.
#[must_use]
pub fn sample_grid(spec: &NoiseSpec, size: u32) -> Option<Vec<f32>> {
    let f = noise_field(spec, size)?;
    let n = size as usize;
    if n == 0 {
        return Some(Vec::new());
    }
    let xs: Vec<f32> = (0..size).map(|i| i as f32 + 0.5).collect();
    let mut out = vec![0.0; n * n];
    for (j, row) in out.chunks_exact_mut(n).enumerate() {
        f.sample_row(&xs, j as f32 + 0.5, row);
    }
    Some(out)
}
