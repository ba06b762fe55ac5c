//! What outlives a frame: autosave, recent designs, preferences, and the files the app
//! writes (Export PNG, Export SVG, thumbnails), and the links the address bar holds.

pub(crate) mod address_bar;
pub(crate) mod autosave;
pub mod export;
pub(crate) mod export_panel;
pub(crate) mod file_panel;
pub(crate) mod link_qr;
pub(crate) mod links;
pub(crate) mod prefs;
pub(crate) mod print_panel;
pub(crate) mod recent;
pub(crate) mod recent_panel;
pub(crate) mod restore;
pub(crate) mod session;
pub(crate) mod svg_export;
pub(crate) mod thumbnails;
