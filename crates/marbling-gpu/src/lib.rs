//! The WGSL renderer of marbling designs through wgpu: every sample walks back through
//! the whole op stack of a design in ONE fragment-shader pass, as the f64 CPU reference
//! (`marbling_core::render`) does, in f32.
//!
//! # How the ops reach the shader
//! The op list is an `Rgba32Float` texture read with `textureLoad` (no sampler, no
//! filtering): two texels (8 f32) per op, `ops_per_row` ops per row, rows at most the
//! device's texture side wide (2048 on WebGL2, so 1024 ops per row and the schema's
//! 100,000 ops in 98 rows). Why a texture:
//! - WebGL2 (wgpu's GL backend on the web) has no storage buffers and no compute, so a
//!   storage buffer would not run there; a float texture and `texelFetch` run everywhere.
//! - Uniform blocks are capped at 16 KiB on WebGL2 (≈ 500 ops): 100,000 ops would need
//!   hundreds of chunked draws, each re-walking from the previous chunk's output and so
//!   needing an intermediate position buffer; one texture keeps it one pass.
//! - Everything the CPU walker precomputes (unit vectors, αλ, r², 2π/wavelength, linear
//!   ink colours) is computed on the host in f64 and rounded once ([`encode`]).
//!
//! The app draws with vertex and fragment shaders only (a full-screen triangle), so the
//! same WGSL runs on Vulkan/Metal/DX12, WebGPU and WebGL2. Headless renders
//! ([`GpuRenderer`]) run the same per-pixel function as a compute pass where the device
//! has compute ([`ComputeExact`]): datacenter GPUs such as the H100 run fragment shaders
//! on a few SMs only, and the bytes are the same.
//!
//! # Colours and sampling
//! The same antialiasing patterns as the CPU ([`marbling_core::Antialias`]; positions
//! and weights are passed in the uniform block), averaged in linear light; a pixel whose
//! samples all show one colour keeps that colour's exact sRGB bytes. Into `…Unorm`
//! targets the shader encodes sRGB itself (as the CPU does); into `…UnormSrgb` targets it
//! writes linear light and lets the hardware encode.
//!
//! # Precision
//! Positions are f32 (design pixels), so renders agree with the f64 reference except
//! where the design itself is ill-conditioned: heavily combed designs stretch ink
//! exponentially, and beyond a few hundred strong combs a relative change of 1e-7 in
//! the parameters (what rounding them to f32 does) already moves visible ink. The tests
//! state both budgets (tests/it/gpu_vs_cpu.rs); docs/BENCHMARKS.md has the numbers.
//!
//! # Schema v2 surfaces
//! Noise backgrounds and grain overlays (see `marbling_core::surface`) use
//! marbling-noise's WGSL, composed into the exact renderer's module
//! ([`shaders::render_wgsl`]), with their parameters in a second uniform block
//! ([`surface::SurfaceParams`], about 1.1 KiB, well under WebGL2's 16 KiB). The live
//! preview shows them through its cache; while a tool is dragged the pending op moves
//! the cached paper grain too (part of the drag-only approximation).
//!
//! # Pieces
//! - [`GpuContext`]: a device (headless on any adapter, including Mesa lavapipe, or
//!   the app's own).
//! - [`ExactRenderer`] + [`PreparedDesign`] + [`View`]: the exact pipeline for any
//!   target format, for apps drawing into their own render passes.
//! - [`GpuRenderer`] (native): exact renders to an [`marbling_core::RgbaImage`], tiled
//!   beyond the device's texture limit, with progress.
//! - [`PreviewRenderer`] + [`PreviewCache`]: live-editing frames (a cached committed
//!   design plus one pending op), an approximation shown only while dragging; one
//!   pipeline per [`PreviewKind`] of pending op.
//! - [`View3dRenderer`]: the design on a 3D object (sphere, vase, cylinder, book,
//!   plane), every sample's design point walked exactly (`marbling_core::view3d`).
//! - [`Presenter`] + [`PresentSource`]: a rendered texture shown 1:1 within the scissor
//!   rectangle of another pass (the app's canvas and cached panels).

pub mod bindings;
mod compute;
mod context;
pub mod deep;
pub mod encode;
mod error;
mod exact;
mod fullscreen;
#[cfg(not(target_arch = "wasm32"))]
mod headless;
pub mod params;
mod prefix;
mod present;
mod preview;
mod preview_kind;
pub mod shaders;
pub mod surface;
mod target;
mod tiles;
mod variants;
pub mod view3d;

pub use compute::ComputeExact;
pub use context::GpuContext;
pub use error::GpuError;
pub use exact::{ExactRenderer, PreparedDesign, View};
#[cfg(not(target_arch = "wasm32"))]
pub use headless::{DEFAULT_TILE_SIDE, GpuRenderer, OUTPUT_FORMAT};
pub use prefix::DesignPrefix;
pub use present::{Placement, PresentSource, Presenter};
pub use preview::{CACHE_FACTOR, CACHE_FORMAT, PreviewCache, PreviewRenderer};
pub use preview_kind::PreviewKind;
#[cfg(not(target_arch = "wasm32"))]
pub use target::read_buffer;
pub use target::{PendingRead, RenderTarget, copy_to_buffer};
pub use tiles::tile_grid;
pub use view3d::{View3dParams, View3dRenderer};
/// The wgpu this crate is built on (so callers use the same version).
pub use wgpu;
