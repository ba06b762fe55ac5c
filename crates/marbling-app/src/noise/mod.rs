//! The noise playground: the typed noise spec its sliders edit, its panel and controls,
//! the data sets of data-driven Gabor, its preview and its PNG export.

pub(crate) mod controls;
pub(crate) mod data;
pub(crate) mod export;
pub(crate) mod panel;
pub(crate) mod preview;
pub(crate) mod settings;
