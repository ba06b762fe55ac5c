//! Helpers shared by the integration tests: the crate's own spectrum analysis under
//! the names the tests use.

#![allow(dead_code)]

pub mod gpu;

pub use marbling_noise::analysis::{bin_frequency as freq, power_spectrum};
