//! `--backend`: which renderer draws the image (the exact CPU reference, the GPU, or the
//! forward-traced vector outlines).

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
    /// Ink outlines traced forward through later ops, rasterised with tiny-skia at the
    /// same sample positions.
    Vector,
}

impl Backend {
    /// The name used on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Backend::Cpu => "cpu",
            Backend::Gpu => "gpu",
            Backend::Vector => "vector",
        }
    }
}

/// Opens a GPU renderer on the best adapter, naming the fix when there is none.
pub fn gpu_renderer() -> Result<GpuRenderer> {
    let ctx = GpuContext::new_headless().context("cannot use --backend gpu")?;
    Ok(GpuRenderer::new(ctx))
}

/// Traces `design`'s outlines within `tolerance` output pixels and rasterises them.
pub fn render_vector(design: &Design, opts: &RenderOptions, tolerance: f64) -> Result<RgbaImage> {
    let trace_opts = marbling_vector::TraceOptions {
        tolerance,
        scale: opts.scale,
        ..marbling_vector::TraceOptions::default()
    };
    let progress = LazyProgress::new();
    let traced =
        marbling_vector::trace_with_progress(design, &trace_opts, &|d, t| progress.update(d, t));
    progress.finish();
    let blend = marbling_vector::Blend::Linear(opts.antialias);
    Ok(marbling_vector::rasterize(&traced?, opts.scale, blend)?)
}

/// Renders `design` with `backend` (vector at `tolerance`), reporting progress.
pub fn render_image(
    backend: Backend,
    design: &Design,
    opts: &RenderOptions,
    tolerance: f64,
    progress: &LazyProgress,
) -> Result<RgbaImage> {
    Ok(match backend {
        Backend::Vector => render_vector(design, opts, tolerance)?,
        Backend::Cpu => render_with_progress(design, opts, &|d, t| progress.update(d, t))?,
        Backend::Gpu => {
            let gpu = gpu_renderer()?;
            eprintln!("gpu adapter: {}", gpu.context().describe());
            gpu.render_with_progress(design, opts, &|d, t| progress.update(d, t))?
        }
    })
}
