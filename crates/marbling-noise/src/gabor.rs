//! Sparse Gabor convolution noise (Lagae, Lefebvre, Drettakis & Dutré 2009; NPR use after
//! Bénard et al., Bénard et al. 2010; random phase and spatially varying parameters after seed
//! 004 / Lagae et al. 2011).
//!
//! n(x) = Σᵢ wᵢ·g(x − xᵢ) with the kernel
//! g(x, y) = K·exp(−πa²(x² + y²))·cos(2πF₀(x cos ω₀ + y sin ω₀) + φ), K = 1,
//! impulses xᵢ from a Poisson process of density λ = N/(πR²) (N: mean number of kernels
//! overlapping a point), weights wᵢ uniform in [−1, 1], the kernel truncated at radius
//! R = √(−ln t/π)/a where the Gaussian envelope falls to t = [`GABOR_TRUNCATION`].
//! Impulses are generated per grid cell of side R (the tile divided evenly in the tileable
//! variant, searching ⌈R/cell⌉ cells each way) from the
//! cell's seeded stream ([`crate::CellRng`]): a Poisson count, then four uniforms per
//! impulse (x, y, weight, angle-or-phase).
//!
//! Units: positions in output pixels, x right, y down; F₀ in cycles per output pixel;
//! ω₀ in radians from +x towards +y; a in 1/pixels. The result is divided by the
//! analytical standard deviation ([`GaborParams::variance`]), so it has zero mean and
//! unit variance. With a [`PhasorProfile`] the same kernels are summed as complex numbers
//! and the phase of the sum goes through the profile ([`crate::phasor`]). Keep in sync
//! with `shaders/gabor.wgsl`.

use crate::field::Field;
use crate::hash::{CellRng, floor_i32, poisson_split, wrap_cell};
use crate::phasor::PhasorProfile;
use std::f32::consts::{PI, TAU};
use std::sync::Arc;

/// Level t of the Gaussian envelope at which the kernel is cut off (as in Lagae et al.
/// 2009): the kernel radius is R = √(−ln t/π)/a.
pub const GABOR_TRUNCATION: f32 = 0.05;

/// How orientation and phase vary between impulses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GaborKind {
    /// Every kernel has orientation ω₀ and phase 0: oriented stripes.
    Anisotropic,
    /// Each impulse draws a uniform orientation in [0, 2π): a ring-shaped spectrum.
    Isotropic,
    /// Orientation ω₀ and a uniform random phase φ ∈ [0, 2π) per impulse (Khlebnikov et al. 2013);
    /// its variance has no oscillating term, so it is independent of F₀.
    RandomPhase,
}

impl GaborKind {
    /// Index used by the WGSL (`0`, `1`, `2`).
    #[must_use]
    pub fn index(self) -> u32 {
        self as u32
    }
}

/// A scalar field that drives a Gabor parameter over space, evaluated at each impulse
/// position: orientation ωᵢ = ω₀ + amount·n(xᵢ), frequency Fᵢ = F₀·2^(amount·n(xᵢ)).
#[derive(Clone)]
pub struct Drive {
    /// The driving field (usually unit-variance noise such as fBm).
    pub field: Arc<dyn Field>,
    /// Radians per unit of the field (orientation), octaves per unit (frequency).
    pub amount: f32,
}

impl std::fmt::Debug for Drive {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Drive")
            .field("amount", &self.amount)
            .finish_non_exhaustive()
    }
}

/// Parameters of a Gabor noise.
#[derive(Clone, Debug)]
pub struct GaborParams {
    /// Orientation/phase behaviour.
    pub kind: GaborKind,
    /// F₀, cycles per output pixel (> 0; below 0.5 to avoid aliasing).
    pub frequency: f32,
    /// ω₀, radians from +x towards +y (image coordinates, y down).
    pub orientation: f32,
    /// a, the Gaussian bandwidth in 1/pixels (> 0); the kernel radius is
    /// √(−ln t/π)/a pixels.
    pub bandwidth: f32,
    /// N, the mean number of kernels overlapping a point (Lagae's "impulses per
    /// kernel"; 16–128 typical).
    pub impulses: f32,
    /// Seed of the impulse process.
    pub seed: u32,
    /// Tile period in output pixels: impulse cells are sized to divide it and wrap.
    pub period: Option<u32>,
    /// Optional field driving the orientation (ignored by the isotropic kind).
    pub orientation_drive: Option<Drive>,
    /// Optional field driving the frequency.
    pub frequency_drive: Option<Drive>,
    /// `Some`: phasor noise, the phase of the complex sum through this profile.
    pub profile: Option<PhasorProfile>,
}

impl GaborParams {
    /// The kernel radius R = √(−ln t/π)/a, pixels.
    #[must_use]
    pub fn radius(&self) -> f32 {
        (-GABOR_TRUNCATION.ln() / PI).sqrt() / self.bandwidth
    }

    /// Analytical variance of the un-normalised sum:
    /// λ·E[w²]·∫g² = (N/(πR²))·(1/3)·(1 − t²)/(4a²)·(1 + e^(−2πF₀²/a²)),
    /// without the oscillating term for random phase; (1 − t²) accounts for the
    /// truncation of the envelope (exact for the non-oscillating term).
    #[must_use]
    pub fn variance(&self) -> f32 {
        let a2 = self.bandwidth * self.bandwidth;
        let r = self.radius();
        let lambda = self.impulses / (PI * r * r);
        let t2 = GABOR_TRUNCATION * GABOR_TRUNCATION;
        let oscillating = match self.kind {
            GaborKind::RandomPhase => 0.0,
            _ => (-2.0 * PI * self.frequency * self.frequency / a2).exp(),
        };
        lambda / 3.0 * (1.0 - t2) / (4.0 * a2) * (1.0 + oscillating)
    }
}

/// A ready-to-evaluate Gabor noise.
#[derive(Clone, Debug)]
pub struct Gabor {
    params: GaborParams,
    /// Side of an impulse cell, pixels.
    pub(crate) cell: f32,
    /// Cells per tile period, 0 when not tileable.
    pub(crate) period_cells: i32,
    /// Cells searched on each side: ⌈R / cell⌉ (1 unless a tile is smaller than R).
    pub(crate) reach_cells: i32,
    /// e^(−mean impulses per cell / parts), for the Poisson draw.
    pub(crate) exp_neg_part: f32,
    /// Parts the Poisson draw is split into ([`crate::hash::poisson_split`]).
    pub(crate) poisson_parts: u32,
    pub(crate) radius2: f32,
    pub(crate) pi_a2: f32,
    pub(crate) inv_std: f32,
}

impl Gabor {
    /// Precomputes cell size, Poisson threshold and normalisation.
    #[must_use]
    pub fn new(params: GaborParams) -> Self {
        let r = params.radius();
        let (cell, period_cells) = match params.period {
            Some(p) if p > 0 => {
                let cells = ((p as f32 / r).floor() as i32).max(1);
                (p as f32 / cells as f32, cells)
            }
            _ => (r, 0),
        };
        let lambda = params.impulses / (PI * r * r);
        let (exp_neg_part, poisson_parts) = poisson_split(lambda * cell * cell);
        Self {
            cell,
            period_cells,
            reach_cells: ((r / cell).ceil() as i32).max(1),
            exp_neg_part,
            poisson_parts,
            radius2: r * r,
            pi_a2: PI * params.bandwidth * params.bandwidth,
            inv_std: 1.0 / params.variance().sqrt(),
            params,
        }
    }

    /// The parameters.
    #[must_use]
    pub fn params(&self) -> &GaborParams {
        &self.params
    }

    /// Side of an impulse cell in pixels (the kernel radius unless tileable).
    #[must_use]
    pub fn cell_size(&self) -> f32 {
        self.cell
    }

    /// Mean impulse count per cell.
    #[must_use]
    pub fn impulses_per_cell(&self) -> f32 {
        -self.exp_neg_part.ln() * self.poisson_parts as f32
    }

    /// The noise at (x, y), output pixels, normalised to zero mean and unit variance: the
    /// Gabor sum, or the phasor profile of its phase.
    #[must_use]
    pub fn eval(&self, x: f32, y: f32) -> f32 {
        match self.params.profile {
            None => self.eval_raw(x, y) * self.inv_std,
            Some(profile) => {
                let (re, im) = self.sum::<true>(x, y);
                profile.apply(im.atan2(re))
            }
        }
    }

    /// The un-normalised sum Σ wᵢ g(x − xᵢ).
    #[must_use]
    pub fn eval_raw(&self, x: f32, y: f32) -> f32 {
        self.sum::<false>(x, y).0
    }

    /// (Σ wᵢ e^(−πa²r²) cos argᵢ, Σ wᵢ e^(−πa²r²) sin argᵢ); the imaginary part only
    /// when `COMPLEX`.
    #[inline]
    fn sum<const COMPLEX: bool>(&self, x: f32, y: f32) -> (f32, f32) {
        let p = &self.params;
        let u = x / self.cell;
        let v = y / self.cell;
        let ix = floor_i32(u);
        let iy = floor_i32(v);
        let fx = (u - ix as f32) * self.cell;
        let fy = (v - iy as f32) * self.cell;
        let (cos0, sin0) = (p.orientation.cos(), p.orientation.sin());
        let mut sum = 0.0_f32;
        let mut sum_im = 0.0_f32;
        let k = self.reach_cells;
        for dj in -k..=k {
            for di in -k..=k {
                // Skip cells whose every point is farther than R.
                let ex = (di as f32 * self.cell - fx).max(fx - (di + 1) as f32 * self.cell);
                let ey = (dj as f32 * self.cell - fy).max(fy - (dj + 1) as f32 * self.cell);
                let (ex, ey) = (ex.max(0.0), ey.max(0.0));
                if ex * ex + ey * ey >= self.radius2 {
                    continue;
                }
                let cx = ix + di;
                let cy = iy + dj;
                let mut rng = CellRng::new(
                    wrap_cell(cx, self.period_cells),
                    wrap_cell(cy, self.period_cells),
                    p.seed,
                );
                let count = rng.poisson_parts(self.exp_neg_part, self.poisson_parts);
                for _ in 0..count {
                    let ox = rng.next_f32();
                    let oy = rng.next_f32();
                    let w = rng.next_f32() * 2.0 - 1.0;
                    let extra = rng.next_f32();
                    // Offset from the impulse to (x, y), pixels.
                    let dx = fx - (di as f32 + ox) * self.cell;
                    let dy = fy - (dj as f32 + oy) * self.cell;
                    let r2 = dx * dx + dy * dy;
                    if r2 >= self.radius2 {
                        continue;
                    }
                    let px = (cx as f32 + ox) * self.cell;
                    let py = (cy as f32 + oy) * self.cell;
                    let (ci, si, phase) = self.impulse_frame(px, py, extra, (cos0, sin0));
                    let f = self.impulse_frequency(px, py);
                    let arg = TAU * f * (dx * ci + dy * si) + phase;
                    let e = w * (-self.pi_a2 * r2).exp();
                    if COMPLEX {
                        let (s, c) = arg.sin_cos();
                        sum += e * c;
                        sum_im += e * s;
                    } else {
                        sum += e * arg.cos();
                    }
                }
            }
        }
        (sum, sum_im)
    }

    /// (cos ωᵢ, sin ωᵢ, φᵢ) of an impulse at (px, py) with its fourth uniform `extra`.
    #[inline]
    fn impulse_frame(&self, px: f32, py: f32, extra: f32, base: (f32, f32)) -> (f32, f32, f32) {
        let p = &self.params;
        match p.kind {
            GaborKind::Isotropic => {
                let w = TAU * extra;
                (w.cos(), w.sin(), 0.0)
            }
            GaborKind::Anisotropic | GaborKind::RandomPhase => {
                let phase = if p.kind == GaborKind::RandomPhase {
                    TAU * extra
                } else {
                    0.0
                };
                match &p.orientation_drive {
                    Some(d) => {
                        let w = p.orientation + d.amount * d.field.sample(px, py);
                        (w.cos(), w.sin(), phase)
                    }
                    None => (base.0, base.1, phase),
                }
            }
        }
    }

    #[inline]
    fn impulse_frequency(&self, px: f32, py: f32) -> f32 {
        let p = &self.params;
        match &p.frequency_drive {
            Some(d) => p.frequency * (d.amount * d.field.sample(px, py)).exp2(),
            None => p.frequency,
        }
    }
}

impl Field for Gabor {
    fn sample(&self, x: f32, y: f32) -> f32 {
        self.eval(x, y)
    }
}
