//! The WGSL sources, compiled into the crate. WGSL has no includes, so each module is
//! assembled from files: `common.wgsl` (op inverse, sRGB transfer, full-screen
//! triangle), then for the exact renderer marbling-noise's `noise` module and
//! `surface.wgsl` (schema v2 noise backgrounds and grain overlays), then its own file.

use crate::preview_kind::PreviewKind;

/// `shaders/common.wgsl`.
pub const COMMON: &str = include_str!("../shaders/common.wgsl");
/// `shaders/records.wgsl`: the walk over op records and the several-record ops.
pub const RECORDS: &str = include_str!("../shaders/records.wgsl");
/// `shaders/surface.wgsl`: noise background, pigment and paper grain.
pub const SURFACE: &str = include_str!("../shaders/surface.wgsl");
/// `shaders/surface_off.wgsl`: stand-ins for `surface.wgsl` in the plain variant.
pub const SURFACE_OFF: &str = include_str!("../shaders/surface_off.wgsl");
/// `shaders/render.wgsl`: the exact renderer's entry points.
pub const RENDER: &str = include_str!("../shaders/render.wgsl");

/// The exact renderer for designs with a plain background and no overlays (every v1
/// design): `common.wgsl`, `records.wgsl`, `surface_off.wgsl`, `render.wgsl` — no noise
/// code, so it is as small and fast as before schema v2.
pub const RENDER_PLAIN_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/records.wgsl"),
    "\n",
    include_str!("../shaders/surface_off.wgsl"),
    "\n",
    include_str!("../shaders/render.wgsl")
);

/// `shaders/render_compute.wgsl`: the exact renderer's compute entry point (appended to a
/// render module).
pub const RENDER_COMPUTE: &str = include_str!("../shaders/render_compute.wgsl");

/// [`RENDER_PLAIN_WGSL`] with the compute entry point.
pub fn render_plain_compute_wgsl() -> String {
    [RENDER_PLAIN_WGSL, RENDER_COMPUTE].join("\n")
}

/// [`render_wgsl`] with the compute entry point.
pub fn render_compute_wgsl() -> String {
    [render_wgsl(), RENDER_COMPUTE.to_owned()].join("\n")
}

/// The live preview (cache + one pending op) without its `pending_back`:
/// `shaders/common.wgsl` + `shaders/preview.wgsl`. See [`preview_wgsl`].
pub const PREVIEW_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/preview.wgsl")
);

/// The live-preview module for pending ops of `kind` drawing into a `…UnormSrgb` target
/// (`srgb_target`) or a `…Unorm` one: [`PREVIEW_WGSL`] + that kind's `pending_back` +
/// `encoded_to_target`, which converts the cache's sRGB-encoded colours for the target
/// (not at all for `…Unorm` targets, so the one-sample preview does no conversion there).
pub fn preview_wgsl(kind: PreviewKind, srgb_target: bool) -> String {
    let to_target = if srgb_target {
        "srgb_to_linear(c)"
    } else {
        "c"
    };
    let encoded_to_target = format!(
        "fn encoded_to_target(c: vec3<f32>) -> vec3<f32> {{\n    return {to_target};\n}}\n"
    );
    [PREVIEW_WGSL, &kind.pending_back(), &encoded_to_target].join("\n")
}

/// Untextured coloured triangles (the app's tool overlay): `shaders/common.wgsl` +
/// `shaders/flat_mesh.wgsl`.
pub const FLAT_MESH_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/flat_mesh.wgsl")
);

/// Showing a rendered texture 1:1 in a pass: `shaders/common.wgsl` + `shaders/present.wgsl`.
pub const PRESENT_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/present.wgsl")
);

/// The exact renderer: `common.wgsl`, `records.wgsl`, marbling-noise's noise module,
/// `surface.wgsl`, `render.wgsl`.
pub fn render_wgsl() -> String {
    let noise = marbling_noise::wgsl::module("noise").unwrap_or_else(|| {
        unreachable!("marbling-noise always provides its noise module");
    });
    [COMMON, RECORDS, &noise, SURFACE, RENDER].join("\n")
}

/// Every render-pipeline module (vertex + fragment; WebGPU and WebGL2) as (name,
/// source), for validation: the exact renderers, each live-preview variant, present.
pub fn all() -> Vec<(String, String)> {
    let mut out = vec![
        ("render".to_owned(), render_wgsl()),
        ("render-plain".to_owned(), RENDER_PLAIN_WGSL.to_owned()),
    ];
    for kind in PreviewKind::ALL {
        for (srgb_target, target) in [(false, "unorm"), (true, "srgb")] {
            out.push((
                format!("preview-{}-{target}", kind.name()),
                preview_wgsl(kind, srgb_target),
            ));
        }
    }
    out.push(("present".to_owned(), PRESENT_WGSL.to_owned()));
    out.push(("flat_mesh".to_owned(), FLAT_MESH_WGSL.to_owned()));
    out
}

/// The modules with the exact renderer's compute entry point (native and WebGPU only),
/// as (name, source), for validation.
pub fn compute_modules() -> [(&'static str, String); 2] {
    [
        ("render-compute", render_compute_wgsl()),
        ("render-plain-compute", render_plain_compute_wgsl()),
    ]
}
