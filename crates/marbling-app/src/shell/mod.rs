//! The playground's frame around the features: layouts (side panel, bottom sheet, rail),
//! the gallery landing, the mode switch, fonts, style and keyboard access.

pub(crate) mod accessibility;
pub(crate) mod bottom_sheet;
pub(crate) mod fonts;
pub mod gallery;
pub(crate) mod landing;
pub(crate) mod layout;
pub(crate) mod message;
pub(crate) mod mode;
pub(crate) mod sections;
pub(crate) mod shortcuts;
pub(crate) mod status_bar;
pub(crate) mod style;
pub(crate) mod tool_rail;
