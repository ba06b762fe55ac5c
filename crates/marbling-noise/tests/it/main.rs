//! The integration tests of `marbling-noise`, in one test binary (one link instead of one per
//! file): each module is one area, named as its file.

mod common;
mod data_gabor;
mod gabor;
mod gpu;
mod noises;
mod phasor;
mod rows;
mod snapshots;
mod spec_errors;
mod wgsl;
