//! The WGSL twins of the CPU noises (`shaders/*.wgsl`), with the helper that assembles a
//! module from its dependencies (WGSL has no includes).

/// `hash.wgsl`: pcg_hash, lattice_hash, cell_hash, unit_f32, the cell stream and Poisson.
pub const HASH: &str = include_str!("../shaders/hash.wgsl");
