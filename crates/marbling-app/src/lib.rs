//! The marbling playground's editing model: the history of operations with undo/redo,
//! the tools that turn pointer gestures into operations, and the ink palettes. The
//! eframe user interface that drives them is built on top of this crate.

pub mod history;
pub mod palettes;
pub mod tools;

pub use history::History;
pub use palettes::{PALETTES, Palette};
pub use tools::{Gesture, ToolKind, ToolSettings, ops_for};
