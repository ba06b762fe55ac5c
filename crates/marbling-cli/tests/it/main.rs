//! The integration tests of `marbling-cli`, in one test binary (one link instead of one per
//! file): each module is one area, named as its file.

mod cli;
mod cli_gpu;
mod common;
mod flow_cli;
mod making_cli;
mod noise_cli;
mod palette_cli;
mod pictures_3d_cli;
mod print_cli;
mod svg_cli;
mod v2_cli;
