//! The WGSL sources, compiled into the crate. Each shader module is `common.wgsl`
//! (op inverse, sRGB transfer, full-screen triangle) followed by its own file.

/// The exact renderer: `shaders/common.wgsl` + `shaders/render.wgsl`.
pub const RENDER_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/render.wgsl")
);

/// The live preview (cache + one pending op): `shaders/common.wgsl` + `shaders/preview.wgsl`.
pub const PREVIEW_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/preview.wgsl")
);

/// Every shader module as (name, source), for validation.
pub const ALL: [(&str, &str); 2] = [("render", RENDER_WGSL), ("preview", PREVIEW_WGSL)];
