//! What outlives a frame: autosave, recent designs, preferences, and the files the app
//! writes (Export PNG, Export SVG, thumbnails).

pub(crate) mod autosave;
pub mod export;
pub(crate) mod prefs;
pub(crate) mod recent;
pub(crate) mod svg_export;
pub(crate) mod thumbnails;
