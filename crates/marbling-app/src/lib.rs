//! The marbling playground: an eframe app (native and wasm32, WebGPU or WebGL2) whose
//! canvas is drawn exactly by the WGSL renderer, with the editing model it drives: the
//! history of operations with undo/redo, the tools that turn pointer gestures into
//! operations, palettes, share links, autosave and the example gallery.

pub mod accessibility;
mod action;
mod app;
pub mod autosave;
mod bottom_sheet;
mod canvas;
pub mod canvas_gpu;
pub mod device_pixels;
pub mod drop_patterns;
pub mod export;
pub mod fast_paint;
pub mod fingers;
mod fonts;
mod footprint;
pub mod gallery;
pub mod gallery_atlas;
pub mod gallery_gpu;
pub mod gpu_errors;
pub mod history;
mod hooks;
mod image_input;
pub mod ink_sets;
mod labels;
pub mod landing;
pub mod layout;
mod memory;
pub mod mode;
mod noise_controls;
pub mod noise_data;
pub mod noise_export;
mod noise_panel;
pub mod noise_preview;
pub mod noise_settings;
mod panel;
pub mod panic_guard;
pub mod platform;
pub mod playback;
pub mod player;
pub mod player_drawing;
pub mod prefs;
pub mod recent;
pub mod recorder;
pub mod recovery;
mod refine;
pub mod shown;
mod state;
mod stroke;
pub mod style;
pub mod svg_export;
#[cfg(test)]
mod test_window;
pub mod thumbnails;
mod tool_panel;
mod tool_rail;
pub mod tools;
mod video;
mod video_panel;
pub mod view;
mod view3d_window;

pub use action::Action;
pub use app::{MarblingApp, Message};
pub use history::History;
pub use ink_sets::{INK_SETS, InkSet};
pub use tools::{Gesture, ToolKind, ToolSettings, ops_for};
