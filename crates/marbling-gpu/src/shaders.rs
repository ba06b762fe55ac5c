//! The WGSL sources, compiled into the crate. WGSL has no includes, so each module is
//! assembled from files: `common.wgsl` (op inverse, sRGB transfer, full-screen
//! triangle), then for the exact renderer `records.wgsl` (the walk over op records),
//! `ops_v3.wgsl` (the ops schema v3 added) or its stand-in, `image.wgsl` (image
//! backgrounds, in every variant), marbling-noise's `noise` module and `surface.wgsl`
//! (schema v2 noise backgrounds and grain overlays) or its stand-in, then its own file.
//! [`ExactVariant`] names an exact module: its noise types and whether it walks v3 ops.

use marbling_noise::wgsl::{NoiseKind, NoiseKinds, UniformAt};

use crate::preview_kind::PreviewKind;

/// `shaders/common.wgsl`.
pub const COMMON: &str = include_str!("../shaders/common.wgsl");
/// `shaders/records.wgsl`: the walk over op records.
pub const RECORDS: &str = include_str!("../shaders/records.wgsl");
/// `shaders/ops_v3.wgsl`: the exact walk of schema v3's ops (shift, turn, jiggle,
/// finite comb, stylus).
pub const OPS_V3: &str = include_str!("../shaders/ops_v3.wgsl");
/// `shaders/ops_v3_off.wgsl`: stand-in for `ops_v3.wgsl` in variants without v3 ops.
pub const OPS_V3_OFF: &str = include_str!("../shaders/ops_v3_off.wgsl");
/// `shaders/flow.wgsl`: the exact walk of schema v4's flow (needs the noise lattice).
pub const FLOW: &str = include_str!("../shaders/flow.wgsl");
/// `shaders/flow_off.wgsl`: stand-in for `flow.wgsl` in variants without a flow.
pub const FLOW_OFF: &str = include_str!("../shaders/flow_off.wgsl");
/// `shaders/deep.wgsl`: deep zoom's perturbed walk.
pub const DEEP: &str = include_str!("../shaders/deep.wgsl");
/// `shaders/deep_off.wgsl`: stand-in for `deep.wgsl` in variants for shallow views.
pub const DEEP_OFF: &str = include_str!("../shaders/deep_off.wgsl");
/// `shaders/image.wgsl`: the image background's sampling (every variant).
pub const IMAGE: &str = include_str!("../shaders/image.wgsl");
/// `shaders/surface.wgsl`: noise background, pigment and paper grain.
pub const SURFACE: &str = include_str!("../shaders/surface.wgsl");
/// `shaders/surface_off.wgsl`: stand-ins for `surface.wgsl` in the variants without
/// noise (they draw image backgrounds only).
pub const SURFACE_OFF: &str = include_str!("../shaders/surface_off.wgsl");
/// `shaders/render.wgsl`: the exact renderer's entry points.
pub const RENDER: &str = include_str!("../shaders/render.wgsl");

/// The exact renderer for designs with a plain or image background, no overlays and no
/// schema v3 op (every v1 design): `common.wgsl`, `records.wgsl`, `ops_v3_off.wgsl`,
/// `flow_off.wgsl`, `deep_off.wgsl`, `image.wgsl`, `surface_off.wgsl`, `render.wgsl` — no noise or stylus code, so it is
/// as small and fast as before schemas v2 and v3.
pub const RENDER_PLAIN_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/records.wgsl"),
    "\n",
    include_str!("../shaders/ops_v3_off.wgsl"),
    "\n",
    include_str!("../shaders/flow_off.wgsl"),
    "\n",
    include_str!("../shaders/deep_off.wgsl"),
    "\n",
    include_str!("../shaders/image.wgsl"),
    "\n",
    include_str!("../shaders/surface_off.wgsl"),
    "\n",
    include_str!("../shaders/render.wgsl")
);

/// `shaders/render_compute.wgsl`: the exact renderer's compute entry point (appended to a
/// render module).
pub const RENDER_COMPUTE: &str = include_str!("../shaders/render_compute.wgsl");

/// Where `surface.wgsl`'s `sample_noise(p, i)` reads layer `i`'s noise uniform.
const SURFACE_NOISES: UniformAt<'static> = UniformAt::Element("surface.noises");

/// Which exact-renderer module a design needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ExactVariant {
    /// The noise types of its schema v2 noise background or grain (`surface.wgsl` and
    /// the noise module, whose `sample_noise` draws only these); none without noise
    /// (image backgrounds alone need none).
    pub noises: NoiseKinds,
    /// With schema v3's ops (`ops_v3.wgsl`).
    pub v3: bool,
    /// With schema v4's flow (`flow.wgsl` and the noise lattice; only with `v3`).
    pub flow: bool,
    /// Walking by perturbation from per-tile references (`deep.wgsl`): views deeper
    /// than f32 can place samples in.
    pub deep: bool,
}

impl ExactVariant {
    /// The plain variant (no noise, no v3 ops): every v1 design.
    pub const PLAIN: ExactVariant = ExactVariant {
        noises: NoiseKinds::NONE,
        v3: false,
        flow: false,
        deep: false,
    };

    /// The eight kinds of module: plain, with every noise, with v3 ops, with both, the
    /// last two with the flow, and the first and the fullest walking deep views.
    pub const ALL: [ExactVariant; 8] = [
        ExactVariant::PLAIN,
        ExactVariant {
            noises: NoiseKinds::ALL,
            v3: false,
            flow: false,
            deep: false,
        },
        ExactVariant {
            noises: NoiseKinds::NONE,
            v3: true,
            flow: false,
            deep: false,
        },
        ExactVariant {
            noises: NoiseKinds::ALL,
            v3: true,
            flow: false,
            deep: false,
        },
        ExactVariant {
            noises: NoiseKinds::NONE,
            v3: true,
            flow: true,
            deep: false,
        },
        ExactVariant {
            noises: NoiseKinds::ALL,
            v3: true,
            flow: true,
            deep: false,
        },
        ExactVariant {
            noises: NoiseKinds::NONE,
            v3: false,
            flow: false,
            deep: true,
        },
        ExactVariant {
            noises: NoiseKinds::ALL,
            v3: true,
            flow: true,
            deep: true,
        },
    ];

    /// True when it holds noise code.
    pub fn surface(self) -> bool {
        !self.noises.is_empty()
    }

    /// Short name, for labels and test messages: `plain`, `v3`, `v3+flow`,
    /// `surface(gabor)`, …
    pub fn name(self) -> String {
        let ops = match (self.v3, self.flow) {
            (false, _) => "",
            (true, false) => "v3",
            (true, true) => "v3+flow",
        };
        let name = match (self.surface(), ops) {
            (false, "") => "plain".to_owned(),
            (false, ops) => ops.to_owned(),
            (true, "") => format!("surface({})", self.noises.name()),
            (true, ops) => format!("surface({})+{ops}", self.noises.name()),
        };
        if self.deep {
            format!("{name}+deep")
        } else {
            name
        }
    }

    /// True when [`ExactVariant::render_wgsl`] holds marbling-noise's lattice files
    /// (hash, perlin, value: the flow's or the surface's).
    pub fn has_noise_lattice(self) -> bool {
        self.surface() || (self.v3 && self.flow)
    }

    /// The render module (vertex and fragment entry points).
    pub fn render_wgsl(self) -> String {
        if !self.surface() && !self.v3 && !self.deep {
            return RENDER_PLAIN_WGSL.to_owned();
        }
        let deep = if self.deep { DEEP } else { DEEP_OFF };
        let v3 = if self.v3 { OPS_V3 } else { OPS_V3_OFF };
        let flow = match (self.v3 && self.flow, self.surface()) {
            (false, _) => FLOW_OFF.to_owned(),
            // The surface's noise module holds the lattice already.
            (true, true) => FLOW.to_owned(),
            (true, false) => [flow_lattice().as_str(), FLOW].join("\n"),
        };
        let surface = if self.surface() {
            let noise = marbling_noise::wgsl::module_for("noise", self.noises, SURFACE_NOISES)
                .unwrap_or_else(|| {
                    unreachable!("marbling-noise always provides its noise module");
                });
            [noise.as_str(), SURFACE].join("\n")
        } else {
            SURFACE_OFF.to_owned()
        };
        [COMMON, RECORDS, v3, &flow, deep, IMAGE, &surface, RENDER].join("\n")
    }

    /// The render module with the compute entry point.
    pub fn compute_wgsl(self) -> String {
        [self.render_wgsl(), RENDER_COMPUTE.to_owned()].join("\n")
    }
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

/// Showing a rendered texture 1:1 in a pass: `shaders/common.wgsl` + `shaders/present.wgsl`.
pub const PRESENT_WGSL: &str = concat!(
    include_str!("../shaders/common.wgsl"),
    "\n",
    include_str!("../shaders/present.wgsl")
);

/// The noise lattice `flow.wgsl` needs: marbling-noise's hash, Perlin and value files.
fn flow_lattice() -> String {
    marbling_noise::wgsl::module("value").unwrap_or_else(|| {
        unreachable!("marbling-noise always provides its value module");
    })
}

/// The walk over op records with every kind: `common.wgsl`, `records.wgsl`,
/// `ops_v3.wgsl`, the noise lattice and `flow.wgsl` (the per-op tests append their
/// entry point).
pub fn walk_wgsl() -> String {
    [COMMON, RECORDS, OPS_V3, &flow_lattice(), FLOW].join("\n")
}

/// The exact renderer with everything: schema v2 surfaces, schema v3 ops and the flow.
pub fn render_wgsl() -> String {
    ExactVariant::ALL[7].render_wgsl()
}

/// Every render-pipeline module (vertex + fragment; WebGPU and WebGL2) as (name,
/// source), for validation: the exact renderers, each live-preview variant, present.
pub fn all() -> Vec<(String, String)> {
    // The four kinds of module, and one with each noise type alone.
    let one_noise = NoiseKind::ALL.map(|k| ExactVariant {
        noises: NoiseKinds::NONE.with(k),
        v3: false,
        flow: false,
        deep: false,
    });
    let mut out: Vec<(String, String)> = ExactVariant::ALL
        .iter()
        .chain(&one_noise)
        .map(|v| (format!("render-{}", v.name()), v.render_wgsl()))
        .collect();
    for kind in PreviewKind::ALL {
        for (srgb_target, target) in [(false, "unorm"), (true, "srgb")] {
            out.push((
                format!("preview-{}-{target}", kind.name()),
                preview_wgsl(kind, srgb_target),
            ));
        }
    }
    out.push(("present".to_owned(), PRESENT_WGSL.to_owned()));
    // The 3D view draws its panes at the sheet's scale: never deep.
    for v in ExactVariant::ALL.into_iter().filter(|v| !v.deep) {
        out.push((
            format!("view3d-{}", v.name()),
            crate::view3d::view3d_wgsl(v),
        ));
    }
    out
}

/// The modules with the exact renderer's compute entry point (native and WebGPU only),
/// as (name, source), for validation.
pub fn compute_modules() -> Vec<(String, String)> {
    ExactVariant::ALL
        .iter()
        .map(|v| (format!("render-compute-{}", v.name()), v.compute_wgsl()))
        .collect()
}
