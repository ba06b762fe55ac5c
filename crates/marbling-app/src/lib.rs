//! The marbling playground: an eframe app (native and wasm32, WebGPU or WebGL2) whose
//! canvas is drawn exactly by the WGSL renderer, with the editing model it drives: the
//! history of operations with undo/redo, the tools that turn pointer gestures into
//! operations, palettes, share links, autosave and the example gallery.

mod action;
mod app;
mod automation;
mod fast_paint;
mod frame;
mod gpu;
mod marbling;
mod media;
mod noise;
pub mod platform;
mod shell;
mod state;
mod store;

pub use action::Action;
pub use app::MarblingApp;
pub use automation::panic_guard;
pub use gpu::{canvas_gpu, gallery_atlas, recovery};
pub use marbling::history::History;
pub use marbling::ink_sets::{INK_SETS, InkSet};
pub use marbling::tools::{Gesture, ToolKind, ToolSettings, ops_for};
pub use shell::gallery;
pub use shell::message::Message;
pub use store::export;
