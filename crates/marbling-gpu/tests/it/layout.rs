//! The host mirrors of the WGSL uniform structs have the same member offsets and size
//! as naga computes for the shaders (keep src/params.rs and shaders/*.wgsl in sync).

use marbling_gpu::PreviewKind;
use marbling_gpu::params::{PresentParams, PreviewParams, RenderParams};
use marbling_gpu::shaders::{PRESENT_WGSL, preview_wgsl, render_wgsl};
use marbling_gpu::surface::{LayerParams, SurfaceParams};
use std::mem::{offset_of, size_of};

/// The host struct `host` mirrors WGSL uniform struct `name` of `source`, every member
/// (`marbling_testkit::wgsl`).
fn check(source: &str, name: &str, host: &[(&str, usize)], host_size: usize) {
    let module = marbling_testkit::wgsl::validate(name, source);
    marbling_testkit::wgsl::check_uniform(&module, name, host, host_size);
}

#[test]
fn render_params_match_wgsl() {
    check(
        &render_wgsl(),
        "RenderParams",
        &[
            ("background", offset_of!(RenderParams, background)),
            ("offset", offset_of!(RenderParams, offset)),
            ("inv_scale", offset_of!(RenderParams, inv_scale)),
            ("op_count", offset_of!(RenderParams, op_count)),
            ("ops_row_shift", offset_of!(RenderParams, ops_row_shift)),
            ("first_count", offset_of!(RenderParams, first_count)),
            ("refine_count", offset_of!(RenderParams, refine_count)),
            ("encode_srgb", offset_of!(RenderParams, encode_srgb)),
            ("layers", offset_of!(RenderParams, layers)),
            ("samples", offset_of!(RenderParams, samples)),
            ("deep", offset_of!(RenderParams, deep)),
        ],
        size_of::<RenderParams>(),
    );
}

#[test]
fn preview_params_match_wgsl() {
    check(
        &preview_wgsl(PreviewKind::Comb, false),
        "PreviewParams",
        &[
            ("pending_a", offset_of!(PreviewParams, pending_a)),
            ("pending_b", offset_of!(PreviewParams, pending_b)),
            ("view_origin", offset_of!(PreviewParams, view_origin)),
            ("view_inv_scale", offset_of!(PreviewParams, view_inv_scale)),
            ("has_pending", offset_of!(PreviewParams, has_pending)),
            ("design_size", offset_of!(PreviewParams, design_size)),
            ("sample_count", offset_of!(PreviewParams, sample_count)),
            ("encode_srgb", offset_of!(PreviewParams, encode_srgb)),
            ("samples", offset_of!(PreviewParams, samples)),
        ],
        size_of::<PreviewParams>(),
    );
}

#[test]
fn present_params_match_wgsl() {
    check(
        PRESENT_WGSL,
        "PresentParams",
        &[
            ("origin", offset_of!(PresentParams, origin)),
            ("_pad", offset_of!(PresentParams, _pad)),
        ],
        size_of::<PresentParams>(),
    );
}

#[test]
fn surface_params_match_wgsl() {
    let source = render_wgsl();
    check(
        &source,
        "SurfaceLayer",
        &[
            ("threshold", offset_of!(LayerParams, threshold)),
            ("width", offset_of!(LayerParams, width)),
            ("transfer", offset_of!(LayerParams, transfer)),
            ("strength", offset_of!(LayerParams, strength)),
        ],
        size_of::<LayerParams>(),
    );
    check(
        &source,
        "SurfaceParams",
        &[
            ("flags", offset_of!(SurfaceParams, flags)),
            ("stop_count", offset_of!(SurfaceParams, stop_count)),
            ("layer_count", offset_of!(SurfaceParams, layer_count)),
            ("_pad", offset_of!(SurfaceParams, _pad)),
            ("stops", offset_of!(SurfaceParams, stops)),
            ("noises", offset_of!(SurfaceParams, noises)),
            ("layers", offset_of!(SurfaceParams, layers)),
            ("image_map", offset_of!(SurfaceParams, image_map)),
            ("image_size", offset_of!(SurfaceParams, image_size)),
            ("paper", offset_of!(SurfaceParams, paper)),
        ],
        size_of::<SurfaceParams>(),
    );
}

/// How deeply struct `ty` nests structs (a struct of scalars is 1; arrays add nothing),
/// the way ANGLE counts for WebGL's limit.
fn struct_depth(module: &naga::Module, ty: naga::Handle<naga::Type>) -> u32 {
    match &module.types[ty].inner {
        naga::TypeInner::Struct { members, .. } => {
            1 + members
                .iter()
                .map(|m| struct_depth(module, m.ty))
                .max()
                .unwrap_or(0)
        }
        naga::TypeInner::Array { base, .. } | naga::TypeInner::BindingArray { base, .. } => {
            struct_depth(module, *base)
        }
        _ => 0,
    }
}

/// WebGL2 (GLSL ES through ANGLE) rejects structs nested more than 4 deep ("exceeds
/// maximum allowed nesting level of 4"), and counts a uniform block as one level: a
/// uniform's type may nest at most 3 deep. Every shader the app runs must stay within it.
#[test]
fn structs_nest_within_webgl2_limits() {
    let render = render_wgsl();
    let preview = preview_wgsl(PreviewKind::Swirl, false);
    for (name, source) in [
        ("render.wgsl (surface)", render.as_str()),
        (
            "render.wgsl (plain)",
            marbling_gpu::shaders::RENDER_PLAIN_WGSL,
        ),
        ("preview.wgsl", preview.as_str()),
        ("present.wgsl", PRESENT_WGSL),
    ] {
        let module = naga::front::wgsl::parse_str(source).expect("parses");
        for (handle, ty) in module.types.iter() {
            let depth = struct_depth(&module, handle);
            assert!(
                depth <= 4,
                "{name}: struct {:?} nests {depth} deep (WebGL2 allows 4)",
                ty.name
            );
        }
        for (_, var) in module.global_variables.iter() {
            if var.space != naga::AddressSpace::Uniform {
                continue;
            }
            let depth = struct_depth(&module, var.ty);
            assert!(
                depth <= 3,
                "{name}: uniform {:?} nests structs {depth} deep; with its block that is \
                 {} levels (WebGL2 allows 4)",
                var.name,
                depth + 1
            );
        }
    }
}

/// The depth measure itself: a 5-deep chain is caught.
#[test]
fn struct_depth_counts_nested_structs_through_arrays() {
    let source = "struct A { x: f32 } struct B { a: array<A, 2> } struct C { b: B } \
                  struct D { c: C } struct E { d: array<D, 3>, y: f32 }";
    let module = naga::front::wgsl::parse_str(source).expect("parses");
    let depth = |n: &str| {
        let (h, _) = module
            .types
            .iter()
            .find(|(_, t)| t.name.as_deref() == Some(n))
            .expect("declared");
        struct_depth(&module, h)
    };
    assert_eq!(depth("A"), 1);
    assert_eq!(depth("C"), 3);
    assert_eq!(depth("E"), 5);
}

#[test]
fn view3d_params_match_wgsl() {
    use marbling_gpu::View3dParams;
    let source = marbling_gpu::view3d::view3d_wgsl(marbling_gpu::shaders::ExactVariant::ALL[0]);
    check(
        &source,
        "View3dParams",
        &[
            ("origin", offset_of!(View3dParams, origin)),
            ("forward", offset_of!(View3dParams, forward)),
            ("right", offset_of!(View3dParams, right)),
            ("up", offset_of!(View3dParams, up)),
            ("lens", offset_of!(View3dParams, lens)),
            ("frame", offset_of!(View3dParams, frame)),
            ("paper", offset_of!(View3dParams, paper)),
            ("pages", offset_of!(View3dParams, pages)),
            ("backdrop_top", offset_of!(View3dParams, backdrop_top)),
            ("backdrop_bottom", offset_of!(View3dParams, backdrop_bottom)),
            ("shading", offset_of!(View3dParams, shading)),
            ("shape", offset_of!(View3dParams, shape)),
            ("displace", offset_of!(View3dParams, displace)),
            ("displace_fbm", offset_of!(View3dParams, displace_fbm)),
            ("displace_march", offset_of!(View3dParams, displace_march)),
            ("style", offset_of!(View3dParams, style)),
            ("style_ink", offset_of!(View3dParams, style_ink)),
        ],
        size_of::<View3dParams>(),
    );
}

#[test]
fn the_plain_variants_surface_head_reaches_the_image_fields() {
    // surface_off.wgsl skips the noise members to read the image background's fields
    // at the host's offsets (plain and v3 variants draw image backgrounds too).
    let image_map = offset_of!(SurfaceParams, image_map);
    check(
        marbling_gpu::shaders::RENDER_PLAIN_WGSL,
        "SurfaceParams",
        &[
            ("flags", offset_of!(SurfaceParams, flags)),
            ("stop_count", offset_of!(SurfaceParams, stop_count)),
            ("layer_count", offset_of!(SurfaceParams, layer_count)),
            ("_pad", offset_of!(SurfaceParams, _pad)),
            ("_noise", offset_of!(SurfaceParams, stops)),
            ("image_map", image_map),
            ("image_size", offset_of!(SurfaceParams, image_size)),
            ("paper", offset_of!(SurfaceParams, paper)),
        ],
        size_of::<SurfaceParams>(),
    );
    assert_eq!((image_map - 16) / 16, 68, "surface_off.wgsl skips 68 vec4s");
}
