//! `--backend`: which renderer draws the exact image (the CPU reference or the GPU).

use crate::render::LazyProgress;
use anyhow::{Context, Result};
use clap::ValueEnum;
use marbling_core::{Design, RenderOptions, RgbaImage, render_with_progress};
use marbling_gpu::{GpuContext, GpuRenderer};

/// A renderer to draw with.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Backend {
    /// The exact f64 CPU reference (all cores).
    Cpu,
    /// The WGSL renderer through wgpu, on any adapter (f32; tiles beyond the texture limit).
    Gpu,
}

impl Backend {
    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Cpu => "cpu",
            Backend::Gpu => "gpu",
        }
    }
}

/// Opens a GPU renderer on the best adapter, naming the fix when there is none.
pub fn gpu_renderer() -> Result<GpuRenderer> {
    let ctx = GpuContext::new_headless().context("cannot use --backend gpu")?;
    Ok(GpuRenderer::new(ctx))
}

/// Renders `design` exactly with `backend`, reporting progress (bands or tiles).
pub fn render_image(
    backend: Backend,
    design: &Design,
    opts: &RenderOptions,
    progress: &LazyProgress,
) -> Result<RgbaImage> {
    Ok(match backend {
        Backend::Cpu => render_with_progress(design, opts, &|d, t| progress.update(d, t))?,
        Backend::Gpu => {
            let gpu = gpu_renderer()?;
            eprintln!("gpu adapter: {}", gpu.context().describe());
            gpu.render_with_progress(design, opts, &|d, t| progress.update(d, t))?
        }
    })
}
