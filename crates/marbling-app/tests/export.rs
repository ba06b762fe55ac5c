//! Export PNG on a headless device (lavapipe here): the asynchronous tile-by-tile export
//! equals the GPU renderer's own render, at every offered size.

use marbling_app::export::{ExportSize, ExportStep, PngExport, export_file_name};
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, RenderOptions};
use marbling_gpu::{GpuContext, GpuRenderer};

/// A device, or a loud failure unless `MARBLING_SKIP_GPU=1` (`marbling_testkit`).
fn context() -> Option<GpuContext> {
    marbling_testkit::gpu_or_skip(GpuContext::new_headless())
}

#[test]
fn tiled_async_export_equals_the_gpu_render() {
    let Some(ctx) = context() else { return };
    let design = random_design(7, 230, 170, 300, Mix::Mixed);
    let size = ExportSize::Width(700);
    let scale = size.scale(&design);
    let export = PngExport::start(&ctx.device, &ctx.queue, &design, scale, Antialias::Rgss)
        .expect("start")
        .with_tile_side(256);
    assert_eq!(export.size(), (700, 517));
    let mut export = export;
    let mut steps = Vec::new();
    let image = loop {
        match export.step(&ctx.device, &ctx.queue).expect("step") {
            ExportStep::Working { done, total } => steps.push((done, total)),
            ExportStep::Finished(image) => break image,
        }
        // The app steps once per frame; here, every 2 ms for at most two minutes.
        assert!(steps.len() < 60_000, "the export never finished");
        std::thread::sleep(std::time::Duration::from_millis(2));
    };
    // 3 × 3 tiles, each reported done once it was read back, each drawn in parts
    // within the frame budget (its first parts are small: the budget starts low).
    assert_eq!(steps.last().map(|s| s.1), Some(9));
    assert!(
        export.parts() > 9,
        "{} parts: tiles drawn whole",
        export.parts()
    );
    assert!(steps.windows(2).all(|w| w[0].0 <= w[1].0));
    let gpu = GpuRenderer::new(ctx);
    let whole = gpu
        .render(
            &design,
            &RenderOptions {
                scale,
                antialias: Antialias::Rgss,
            },
        )
        .expect("render");
    assert_eq!((whole.width, whole.height), (image.width, image.height));
    let differing = whole
        .pixels
        .chunks(4)
        .zip(image.pixels.chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differing, 0, "the export differs from the GPU render");
    assert!(image.to_png().expect("png").starts_with(b"\x89PNG"));
}

#[test]
fn export_sizes_follow_the_design() {
    let design = random_design(1, 1024, 768, 3, Mix::Mixed);
    let sizes: Vec<f64> = ExportSize::CHOICES
        .iter()
        .map(|s| s.scale(&design))
        .collect();
    assert_eq!(sizes, vec![1.0, 2.0, 4.0, 8.0]);
    let (w, h) =
        marbling_core::output_size(&design, ExportSize::Width(8192).scale(&design)).expect("size");
    assert_eq!((w, h), (8192, 6144));
    assert_eq!(
        export_file_name(&design, (w, h), "png"),
        "marbling-3ops-8192x6144.png"
    );
}

#[test]
fn too_large_exports_are_refused_before_rendering() {
    let Some(ctx) = context() else { return };
    let design = random_design(1, 1000, 1000, 3, Mix::Mixed);
    let err = PngExport::start(&ctx.device, &ctx.queue, &design, 100.0, Antialias::None)
        .err()
        .expect("a 100,000 px export must be refused");
    assert!(err.contains("100000"), "{err}");
}
