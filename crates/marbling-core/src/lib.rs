//! Mathematical marbling (Lu, Jaffer, Jin, Zhao & Mao 2012): the fourteen operations of
//! design schemas v1 and v3 with their exact forward and inverse maps, design documents
//! (JSON, validated with path-named errors; schema v2 adds noise backgrounds and grain
//! overlays, see [`surface`]), the traditional patterns and the exact CPU reference
//! renderer.
//!
//! Conventions: design pixels, origin top-left, x right, y down, angles in radians,
//! colours sRGB `"#rrggbb"`; all geometry in f64.

pub mod caption;
pub mod color;
pub mod compare;
mod compiled;
pub mod deep;
mod design;
pub mod explain;
mod gestures;
mod image;
pub mod image_background;
pub mod ink_palette;
mod json;
pub mod making;
mod op_kind;
mod ops;
pub mod patterns;
pub mod point_color;
pub mod print;
mod recipe;
mod render;
pub mod sampling;
mod share;
pub mod share_qr;
pub mod surface;
pub mod synth;
pub mod turbulence;
mod validate;
pub mod view3d;
pub mod view_spec;
mod walk;

pub use color::Rgb8;
pub use compiled::{CombKernel, CompiledOp, JiggleKernel, RigidKernel, SwirlKernel, WaveKernel};
pub use design::{CURRENT_VERSION, Design, MAX_OPS, MAX_SIDE, SUPPORTED_VERSIONS};
pub use gestures::GestureSpan;
pub use image::{PngError, RgbaImage};
pub use image_background::{ImageBackground, ImageError, ImageFit};
pub use json::DesignError;
pub use kurbo::{Point, Vec2};
pub use op_kind::OpKind;
// Every public op type and limit: a new op's file needs no line here.
pub use ops::*;
pub use recipe::{MAX_CAPTION, MAX_RECIPE_HISTORY, MAX_RECIPE_NAME, Recipe};
pub use render::{
    MAX_OUTPUT_PIXELS, MAX_OUTPUT_SIDE, RenderError, RenderOptions, Window, output_size, render,
    render_window, render_window_rows, render_with_progress,
};
pub use sampling::Antialias;
pub use share::{
    MAX_LINK_CHARS, MAX_LINK_JSON_BYTES, MAX_PICTURE_LINK_CHARS, ShareError, decode_noise_share,
    decode_share, encode_share_payload, encode_share_payload_fast, noise_fragment, share_fragment,
    with_link_sized_picture,
};
pub use surface::{
    GrainKind, MAX_PALETTE_STOPS, NoiseBackground, NoiseLayer, OVERLAY_TYPES, Overlay, Palette,
    PaletteError,
};
pub use validate::{FieldError, ValidationErrors};
pub use view_spec::{ViewSpec, ViewSpecError};
pub use walk::{Batch, Traced, Walker, set_wide_kernels, vector_width};
