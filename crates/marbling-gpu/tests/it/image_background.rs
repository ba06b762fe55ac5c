//! Image backgrounds on the GPU against the f64 CPU reference: a photo under random ops
//! in each fit (alone, drawn by the variants without noise, and with paper grain, by
//! the noise variant), and a wrong fit failing the same comparison.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design, test_photo};
use marbling_core::{Antialias, Design, ImageBackground, ImageFit, Op, RenderOptions, render};

/// A channel difference above this counts as a differing pixel (out of 255).
const THRESHOLD: u8 = 8;

/// A random design of `ops` ops (combs at 0.3 strength) on a `photo` (width, height)
/// picture laid by `fit`.
fn design(seed: u64, ops: usize, photo: (u32, u32), fit: ImageFit) -> Design {
    let mut d = random_design(seed, 160, 120, ops, Mix::Mixed);
    for op in &mut d.ops {
        match op {
            Op::Tine(t) => t.alpha *= 0.3,
            Op::Rake(r) => r.alpha *= 0.3,
            Op::Wavy(w) => w.amplitude *= 0.3,
            _ => {}
        }
    }
    let png = test_photo(seed, photo.0, photo.1).to_png().expect("png");
    d.set_background_image(Some(
        ImageBackground::from_file_bytes(&png, fit).expect("photo"),
    ));
    d
}

#[test]
fn image_backgrounds_match_the_cpu() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let fits = [ImageFit::Stretch, ImageFit::Cover, ImageFit::Contain];
    for (i, fit) in fits.into_iter().enumerate() {
        for (aa, budget) in [(Antialias::None, 0.005), (Antialias::Rgss, 0.01)] {
            let mut d = design(40 + i as u64, [0, 30, 120][i], (90, 70), fit);
            if fit == ImageFit::Contain {
                // With grain the picture is drawn by the noise variant (surface.wgsl),
                // without by the lean one (surface_off.wgsl): both are compared.
                let grain = marbling_core::NoiseLayer::from_json(
                    r#"{"type":"value","frequency":0.2,"octaves":2,"seed":8}"#,
                )
                .expect("grain");
                d.overlays = vec![marbling_core::Overlay::paper_grain(grain, 0.3)];
            }
            let opts = RenderOptions {
                scale: [1.0, 0.8, 1.25][i],
                antialias: aa,
            };
            let g = gpu.render(&d, &opts).expect("GPU render");
            let c = render(&d, &opts).expect("CPU render");
            let r = compare(&c, &g, THRESHOLD).expect("same size");
            println!("{fit:?} {} ops aa {}: {r:?}", d.ops.len(), aa.name());
            assert!(r.fraction() <= budget, "{fit:?} {}: {r:?}", aa.name());
        }
    }
}

#[test]
fn a_wrong_fit_fails_the_comparison() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    // A portrait picture: cover crops it top and bottom, stretch squashes it.
    let d = design(7, 20, (60, 90), ImageFit::Cover);
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::None,
    };
    let cpu = render(&d, &opts).expect("CPU render");
    let mut wrong = d.clone();
    let img = wrong.background_image.take().expect("image");
    wrong.set_background_image(Some(img.with_fit(ImageFit::Stretch)));
    let r = compare(&cpu, &gpu.render(&wrong, &opts).expect("GPU"), THRESHOLD).expect("size");
    println!("cover drawn as stretch: {r:?}");
    assert!(r.fraction() > 0.05, "{r:?}");
}
