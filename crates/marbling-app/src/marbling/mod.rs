//! The marbling editor: the tools and their gestures, the history of operations, the canvas
//! (view, pan and zoom, footprints), the step player and the ink sets.

pub(crate) mod canvas;
pub(crate) mod colour_words;
pub(crate) mod drop_patterns;
pub(crate) mod editor;
pub(crate) mod explain_geometry;
pub(crate) mod fingers;
pub(crate) mod footprint;
pub(crate) mod history;
pub(crate) mod ink_panel;
pub(crate) mod ink_sets;
pub(crate) mod labels;
pub(crate) mod playback;
pub(crate) mod player;
pub(crate) mod player_drawing;
pub(crate) mod shown;
pub(crate) mod stream;
pub(crate) mod stroke;
pub(crate) mod tool_panel;
pub(crate) mod tools;
pub(crate) mod view;
pub(crate) mod zoom_to;
