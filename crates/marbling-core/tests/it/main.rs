//! The integration tests of `marbling-core`, in one test binary (one link instead of one per
//! file): each module is one area, named as its file.

mod common;
mod deep_view;
mod design_json;
mod flow;
mod image_background;
mod ops_properties;
mod ops_v3;
mod patterns;
mod render_reference;
mod snapshots;
mod snapshots_v2;
mod snapshots_v3;
mod view3d;
mod view3d_displace;
mod view3d_style;
mod view3d_style_links;
