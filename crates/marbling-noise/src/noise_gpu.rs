//! The host side of the WGSL noises: the uniform `sample_noise` in `noise.wgsl` reads
//! ([`NoiseGpu`], with its parts mirrored field for field from the shaders), built from
//! a spec, and which specs have a WGSL form at all ([`wgsl_form`]).

use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams, Fibers};
use crate::gabor::Gabor;
use crate::render::lattice_for_period;
use crate::spec::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use crate::spec::{DriveSource, DriveSpec, NoiseSpec, Source};
use crate::wgsl::NoiseKind;
use bytemuck::{Pod, Zeroable};

/// Host mirror of WGSL `FbmParams` (fbm.wgsl). Keep in sync.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct FbmGpu {
    /// First-octave frequency, cycles per pixel.
    pub frequency: f32,
    /// Frequency ratio per octave.
    pub lacunarity: f32,
    /// Amplitude ratio per octave.
    pub persistence: f32,
    /// Octave count.
    pub octaves: u32,
    /// Seed.
    pub seed: u32,
    /// 0 Perlin, 1 value.
    pub basis: u32,
    /// Tile period in pixels, 0 = none.
    pub period: u32,
    /// Padding.
    pub _pad: u32,
}

impl From<&FbmParams> for FbmGpu {
    fn from(p: &FbmParams) -> Self {
        Self {
            frequency: p.frequency,
            lacunarity: p.lacunarity,
            persistence: p.persistence,
            octaves: p.octaves,
            seed: p.seed,
            basis: match p.basis {
                Basis::Perlin => 0,
                Basis::Value => 1,
            },
            period: p.period.unwrap_or(0),
            _pad: 0,
        }
    }
}

/// Host mirror of WGSL `GaborParams` (gabor.wgsl). Keep in sync. Its driving fBms are
/// [`NoiseGpu::gabor_orientation_drive`] and [`NoiseGpu::gabor_frequency_drive`].
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct GaborGpu {
    /// 0 anisotropic, 1 isotropic, 2 random phase.
    pub kind: u32,
    /// Seed.
    pub seed: u32,
    /// Cells per tile, 0 = none.
    pub period_cells: i32,
    /// Bit 0 orientation driven, bit 1 frequency driven.
    pub drives: u32,
    /// F₀, cycles per pixel.
    pub frequency: f32,
    /// ω₀, radians.
    pub orientation: f32,
    /// Impulse cell side, pixels.
    pub cell: f32,
    /// Truncation radius², pixels².
    pub radius2: f32,
    /// π·a².
    pub pi_a2: f32,
    /// e^(−mean impulses per cell / parts).
    pub exp_neg_part: f32,
    /// 1 / analytical standard deviation.
    pub inv_std: f32,
    /// Radians per unit of the orientation drive.
    pub orientation_amount: f32,
    /// Octaves per unit of the frequency drive.
    pub frequency_amount: f32,
    /// Parts of the Poisson draw.
    pub poisson_parts: u32,
    /// Cells searched each way.
    pub reach_cells: i32,
    /// 0 Gabor; a phasor noise's [`crate::PhasorProfile::index`].
    pub profile: u32,
}

/// Host mirror of WGSL `FiberGrid` (fibers.wgsl). Keep in sync.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct FiberGridGpu {
    /// Cell side, pixels.
    pub cell: f32,
    /// Cells searched on each side.
    pub reach_cells: i32,
    /// Cells per tile, 0 = none.
    pub period_cells: i32,
    /// e^(−mean points per cell / parts).
    pub exp_neg_part: f32,
    /// Parts of the Poisson draw.
    pub poisson_parts: u32,
    /// Padding.
    pub _pad: [u32; 3],
}

/// Host mirror of WGSL `FiberParams` (fibers.wgsl). Keep in sync. Its grids are
/// [`NoiseGpu::fiber_grid`] and [`NoiseGpu::speck_grid`].
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct FibersGpu {
    /// 0 paper, 1 canvas.
    pub fiber_layout: u32,
    /// Seed.
    pub seed: u32,
    /// Whether specks are drawn.
    pub has_impurities: u32,
    /// Padding.
    pub _pad0: u32,
    /// Fiber length, pixels.
    pub length: f32,
    /// Fiber width, pixels.
    pub width: f32,
    /// Probability of a horizontal canvas thread.
    pub horizontal_probability: f32,
    /// Mean height.
    pub mean: f32,
    /// 1 / height standard deviation.
    pub inv_std: f32,
    /// Speck radius, pixels.
    pub speck_radius: f32,
    /// Speck depth, standard deviations.
    pub speck_strength: f32,
    /// Padding.
    pub _pad1: f32,
}

/// Host mirror of WGSL `NoiseUniform` (noise.wgsl), the uniform read by `sample_noise`.
/// Keep in sync. Structs nest at most 2 deep in it (the Gabor drives and fiber grids sit
/// here, not inside their parameters), so a uniform that holds it stays within WebGL2's
/// nesting limit.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub struct NoiseGpu {
    /// The [`NoiseKind`] (0 Gabor, 1 fBm, 2 Worley, 3 white, 4 curl, 5 fibers, 6 Gabor
    /// with drives).
    pub noise_type: u32,
    /// Seed (Worley, white).
    pub seed: u32,
    /// Worley feature or curl component.
    pub feature: u32,
    /// Worley metric.
    pub metric: u32,
    /// Worley cells / white pixels per tile, 0 = none.
    pub period: [i32; 2],
    /// Worley cells per pixel.
    pub frequency: f32,
    /// Padding.
    pub _pad: u32,
    /// fBm or curl potential.
    pub fbm: FbmGpu,
    /// Gabor parameters.
    pub gabor: GaborGpu,
    /// The fBm driving the Gabor orientation (read when `gabor.drives` bit 0 is set).
    pub gabor_orientation_drive: FbmGpu,
    /// The fBm driving the Gabor frequency (read when `gabor.drives` bit 1 is set).
    pub gabor_frequency_drive: FbmGpu,
    /// Fiber parameters.
    pub fibers: FibersGpu,
    /// Fiber grid.
    pub fiber_grid: FiberGridGpu,
    /// Impurity speck grid.
    pub speck_grid: FiberGridGpu,
}

/// Why a spec has no GPU form.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum GpuUnsupported {
    /// Products combine intensities; evaluate their inputs separately.
    #[error("a product has no single noise uniform; evaluate its inputs")]
    Product,
    /// The WGSL Gabor drives orientation/frequency with fBm only (no other noise, no
    /// data).
    #[error("{0}: the WGSL Gabor accepts only a perlin or value fBm as driving field")]
    Drive(&'static str),
}

/// Whether `spec`'s noise has a WGSL form (one [`NoiseGpu`] uniform), without building
/// it: a product has none, and the WGSL Gabor takes only an fBm as a driving field.
pub fn wgsl_form(spec: &NoiseSpec) -> Result<(), GpuUnsupported> {
    let drive = |d: &Option<DriveSpec>, what: &'static str| match d {
        Some(d) if !matches!(&d.by, DriveSource::Noise(n) if matches!(n.source, Source::Fbm(_))) => {
            Err(GpuUnsupported::Drive(what))
        }
        _ => Ok(()),
    };
    match &spec.source {
        Source::Product(_) => Err(GpuUnsupported::Product),
        Source::Gabor(GaborSpec {
            orientation_field,
            frequency_field,
            ..
        }) => {
            drive(orientation_field, "orientation_field")?;
            drive(frequency_field, "frequency_field")
        }
        _ => Ok(()),
    }
}

fn drive_fbm(
    d: &Option<DriveSpec>,
    what: &'static str,
    period: Option<u32>,
) -> Result<(FbmGpu, f32, bool), GpuUnsupported> {
    match d {
        None => Ok((FbmGpu::default(), 0.0, false)),
        Some(d) => match &d.by {
            DriveSource::Noise(n) => match &n.source {
                Source::Fbm(p) => Ok((FbmGpu::from(&FbmParams { period, ..*p }), d.amount, true)),
                _ => Err(GpuUnsupported::Drive(what)),
            },
            DriveSource::Data(_) => Err(GpuUnsupported::Drive(what)),
        },
    }
}

impl GaborGpu {
    /// The uniform of a CPU Gabor, with the amounts of the orientation and frequency
    /// drives when they are on (the driving fBms go in [`NoiseGpu`]).
    #[must_use]
    pub fn new(g: &Gabor, orientation: Option<f32>, frequency: Option<f32>) -> Self {
        let p = g.params();
        let oa = orientation.unwrap_or_default();
        let fa = frequency.unwrap_or_default();
        Self {
            kind: p.kind.index(),
            seed: p.seed,
            period_cells: g.period_cells,
            drives: u32::from(orientation.is_some()) | (u32::from(frequency.is_some()) << 1),
            frequency: p.frequency,
            orientation: p.orientation,
            cell: g.cell,
            radius2: g.radius2,
            pi_a2: g.pi_a2,
            exp_neg_part: g.exp_neg_part,
            inv_std: g.inv_std,
            orientation_amount: oa,
            frequency_amount: fa,
            poisson_parts: g.poisson_parts,
            reach_cells: g.reach_cells,
            profile: p.profile.map_or(0, crate::PhasorProfile::index),
        }
    }
}

/// The uniform of one of a [`Fibers`]' generation grids.
fn grid_gpu(g: &crate::fibers::Grid) -> FiberGridGpu {
    FiberGridGpu {
        cell: g.cell,
        reach_cells: g.reach_cells,
        period_cells: g.period_cells,
        exp_neg_part: g.exp_neg_part,
        poisson_parts: g.poisson_parts,
        _pad: [0; 3],
    }
}

impl From<&Fibers> for FibersGpu {
    fn from(f: &Fibers) -> Self {
        let p = f.params();
        let imp = p.impurities;
        Self {
            fiber_layout: match p.layout {
                FiberLayout::Paper => 0,
                FiberLayout::Canvas { .. } => 1,
            },
            seed: p.seed,
            has_impurities: u32::from(imp.is_some()),
            _pad0: 0,
            length: p.length,
            width: p.width,
            horizontal_probability: f.horizontal_probability,
            mean: f.mean,
            inv_std: f.inv_std,
            speck_radius: imp.map_or(0.0, |i| i.radius),
            speck_strength: imp.map_or(0.0, |i| i.strength),
            _pad1: 0.0,
        }
    }
}

impl NoiseGpu {
    /// The uniform for the noise of `spec` at output size `size` (transfer, palette and
    /// blend are applied separately).
    pub fn from_spec(spec: &NoiseSpec, size: u32) -> Result<Self, GpuUnsupported> {
        let period = spec.tile.period(size);
        let mut u = Self::default();
        match &spec.source {
            Source::Gabor(spec) => {
                let (od, oa, o_on) =
                    drive_fbm(&spec.orientation_field, "orientation_field", period)?;
                let (fd, fa, f_on) = drive_fbm(&spec.frequency_field, "frequency_field", period)?;
                let g = Gabor::new(spec.params(period, None, None));
                u.noise_type = if o_on || f_on {
                    NoiseKind::DrivenGabor
                } else {
                    NoiseKind::Gabor
                } as u32;
                u.gabor = GaborGpu::new(&g, o_on.then_some(oa), f_on.then_some(fa));
                u.gabor_orientation_drive = od;
                u.gabor_frequency_drive = fd;
            }
            Source::Fbm(p) => {
                u.noise_type = NoiseKind::Fbm as u32;
                u.fbm = FbmGpu::from(&FbmParams { period, ..*p });
            }
            Source::Worley(WorleySpec {
                frequency,
                feature,
                metric,
                seed,
            }) => {
                let (f, cells) = lattice_for_period(*frequency, period);
                u.noise_type = NoiseKind::Worley as u32;
                u.seed = *seed;
                u.feature = feature.index();
                u.metric = metric.index();
                u.period = [cells, cells];
                u.frequency = f;
            }
            Source::White(WhiteSpec { seed }) => {
                let p = period.map_or(0, |p| p as i32);
                u.noise_type = NoiseKind::White as u32;
                u.seed = *seed;
                u.period = [p, p];
            }
            Source::Curl(CurlSpec {
                potential,
                component,
            }) => {
                u.noise_type = NoiseKind::Curl as u32;
                u.fbm = FbmGpu::from(&FbmParams {
                    period,
                    ..*potential
                });
                u.feature = *component as u32;
            }
            Source::Fibers(p) => {
                u.noise_type = NoiseKind::Fibers as u32;
                let f = Fibers::new(FiberParams { period, ..*p });
                u.fibers = FibersGpu::from(&f);
                u.fiber_grid = grid_gpu(&f.fibers);
                u.speck_grid = f.specks.as_ref().map(grid_gpu).unwrap_or_default();
            }
            Source::Product(_) => return Err(GpuUnsupported::Product),
        }
        Ok(u)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plain check says yes exactly where a uniform can be built.
    #[test]
    fn wgsl_form_agrees_with_building_the_uniform() {
        let specs = [
            r#"{"type":"perlin","frequency":0.05,"octaves":3,"seed":1}"#,
            r#"{"type":"worley","frequency":0.05,"seed":1}"#,
            r#"{"type":"gabor","frequency":0.1,"bandwidth":0.04,"seed":2,"orientation_field":{"noise":{"type":"perlin","frequency":0.008,"seed":9},"amount":1.5}}"#,
            r#"{"type":"gabor","frequency":0.1,"bandwidth":0.04,"seed":2,"frequency_field":{"noise":{"type":"worley","frequency":0.01,"seed":9},"amount":0.5}}"#,
            r#"{"type":"product","inputs":[{"type":"perlin","frequency":0.05,"seed":1},{"type":"value","frequency":0.05,"seed":2}]}"#,
        ];
        let mut refused = 0;
        for text in specs {
            let spec = NoiseSpec::from_json(text).expect("valid spec");
            let plain = wgsl_form(&spec).map_err(|e| e.to_string());
            let built = NoiseGpu::from_spec(&spec, 64)
                .map(|_| ())
                .map_err(|e| e.to_string());
            assert_eq!(plain, built, "{text}");
            refused += usize::from(plain.is_err());
        }
        assert_eq!(
            refused, 2,
            "the worley drive and the product have no WGSL form"
        );
    }
}
