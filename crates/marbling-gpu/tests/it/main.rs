//! The integration tests of `marbling-gpu`, in one test binary (one link instead of one per
//! file): each module is one area, named as its file.

mod common;
mod compute;
mod deep_view;
mod gpu_vs_cpu;
mod gpu_vs_cpu_v2;
mod gpu_vs_cpu_v4;
mod image_background;
mod layout;
mod present;
mod preview;
mod shaders_validate;
mod snapshot;
mod tiles;
mod view3d;
mod webgl2_limits;
