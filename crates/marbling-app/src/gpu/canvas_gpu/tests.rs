use super::*;
use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{RenderOptions, RgbaImage, render};
use marbling_gpu::{GpuContext, copy_to_buffer, read_buffer};

/// The texture's pixels `[x, y, w, h]`.
fn read(g: &GpuContext, target: &RenderTarget, [x, y, w, h]: PixelRect) -> RgbaImage {
    let mut encoder = g
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    let (buffer, padded) = copy_to_buffer(&g.device, &mut encoder, target);
    g.queue.submit([encoder.finish()]);
    let mut image = RgbaImage::filled(w, h, [0, 0, 0, 255]);
    let row = (w * 4) as usize;
    read_buffer(
        g,
        &buffer,
        padded,
        target.width,
        target.height,
        |yy, bytes| {
            if (y..y + h).contains(&yy) {
                let start = ((yy - y) as usize) * row;
                image.pixels[start..start + row]
                    .copy_from_slice(&bytes[(x * 4) as usize..((x + w) * 4) as usize]);
            }
        },
    )
    .expect("readback");
    image
}

/// Frame after frame as the app draws them (one tile each, the GPU polled between
/// frames as a browser's event loop would): the exact frame arrives in several tiles
/// with rising progress, is reported drawn only after the last, and equals the CPU
/// render; the preview cache follows in tiles; an edit then shows the stand-in.
#[test]
fn the_exact_frame_is_drawn_in_tiles_then_the_cache() {
    let Some(g) = crate::gpu::test_window::gpu_or_skip() else {
        return;
    };
    let design = Arc::new(random_design(9, 100, 80, 200, Mix::Mixed));
    let mut gpu = CanvasGpu::new(&g.device, CANVAS_FORMAT);
    let request = FrameRequest {
        design_key: 1,
        size: [120, 90],
        scale: 1.0,
        // Texture pixel i samples design x = i − 10 + 0.5: the sheet is pixels 10..110.
        origin: [-10.0, -5.0],
        antialias: Antialias::Rgss,
        pending: None,
        stand_in: None,
        transient: false,
        live: None,
        stream: None,
    };
    assert_eq!(sheet_region(&design, &request), [10, 5, 100, 80]);
    let mut callback = CanvasCallback {
        shown: Shown::all(design.clone()),
        request,
        placement: CanvasPlacement {
            canvas_px: [0.0, 0.0],
            sheet_px: [10.0, 5.0, 110.0, 85.0],
        },
        status: Arc::default(),
        ctx: egui::Context::default(),
        active: true,
    };
    let frame = |gpu: &mut CanvasGpu, callback: &CanvasCallback| {
        let mut status = callback.status.lock().expect("status");
        callback.advance(gpu, &mut status, &g.device, &g.queue);
        drop(status);
        g.device
            .poll(wgpu::PollType::wait_indefinitely())
            .expect("poll");
    };
    let mut progress = Vec::new();
    for _ in 0..1000 {
        frame(&mut gpu, &callback);
        let st = callback.status.lock().expect("status");
        if st.drawn.is_some() {
            break;
        }
        progress.extend(st.progress);
    }
    let st = callback.status.lock().expect("status");
    assert!(st.error.is_none(), "{:?}", st.error);
    assert!(st.drawn.is_some(), "the exact frame was never done");
    assert!(st.work.tiles >= 2, "one tile: {:?}", st.work);
    assert_eq!(st.work.tiles as usize, progress.len() + 1);
    assert!(progress.windows(2).all(|w| w[0] < w[1]) && progress.iter().all(|p| *p < 1.0));
    assert_eq!(st.work.exact, 1);
    assert_eq!(
        st.exact_done.load(Ordering::SeqCst),
        1,
        "the GPU's finish not heard"
    );
    assert_eq!(st.progress, None);
    assert_eq!(
        st.cache_ready, None,
        "the cache is drawn after the exact frame"
    );
    let tiles = st.work.tiles;
    drop(st);
    assert_eq!(gpu.show, Show::Exact);
    let (target, _) = gpu.target.as_ref().expect("texture");
    let shown = read(&g, target, [10, 5, 100, 80]);
    let cpu = render(
        &design,
        &RenderOptions {
            scale: 1.0,
            antialias: Antialias::Rgss,
        },
    )
    .expect("render");
    let diff = compare(&cpu, &shown, 24).expect("size");
    assert!(diff.fraction() < 0.01, "tiled frame vs CPU: {diff:?}");

    // Then the preview cache, in tiles of its own.
    for _ in 0..1000 {
        frame(&mut gpu, &callback);
        if callback
            .status
            .lock()
            .expect("status")
            .cache_ready
            .is_some()
        {
            break;
        }
    }
    let st = callback.status.lock().expect("status");
    assert_eq!(st.cache_ready, Some(1));
    assert_eq!(st.cache_done.load(Ordering::SeqCst), 1);
    assert_eq!(st.work.caches, 1);
    assert!(st.work.tiles > tiles);
    let tiles = st.work.tiles;
    drop(st);
    // Idle: nothing more is drawn.
    frame(&mut gpu, &callback);
    assert_eq!(callback.status.lock().expect("status").work.tiles, tiles);

    // An edit: the design before it stands in at once, with the new op over it.
    let op = design.ops[0].clone();
    let mut edited = (*design).clone();
    edited.ops.push(op.clone());
    callback.shown = Shown::all(Arc::new(edited));
    callback.request.design_key = 2;
    callback.request.stand_in = Some(StandIn {
        key: Some(1),
        op: Some(op),
        paper: false,
    });
    // (A frame that may draw no tile, as when earlier tiles are still in flight.)
    gpu.in_flight.store(MAX_IN_FLIGHT, Ordering::SeqCst);
    frame(&mut gpu, &callback);
    assert_eq!(gpu.show, Show::Refining);
    let (_, prepared) = gpu.prepared.as_ref().expect("uploaded");
    assert_eq!(
        (prepared.op_count(), prepared.ops_written()),
        (201, 201),
        "the edit wrote its one op, not the design again"
    );
    assert!(callback.status.lock().expect("status").drawn.is_none());

    // The edit's exact frame and cache are drawn; the cache of the design before it is kept.
    gpu.in_flight.store(0, Ordering::SeqCst);
    for _ in 0..2000 {
        frame(&mut gpu, &callback);
        if callback.status.lock().expect("status").cache_ready == Some(2) {
            break;
        }
    }
    assert_eq!(callback.status.lock().expect("status").cache_ready, Some(2));
    assert_eq!(gpu.previous.as_ref().map(|(k, _)| *k), Some(1));

    // Undo: the state before the edit (a new key) shows that state's own cache at once,
    // never the edited frame under the first tiles.
    callback.shown = Shown::all(design.clone());
    callback.request.design_key = 3;
    callback.request.stand_in = Some(StandIn::other_state(Some(1)));
    gpu.in_flight.store(MAX_IN_FLIGHT, Ordering::SeqCst);
    frame(&mut gpu, &callback);
    assert_eq!(gpu.show, Show::Refining);
    assert_eq!(gpu.cache.as_ref().map(|(k, _)| *k), Some(1));
    assert_eq!(gpu.previous.as_ref().map(|(k, _)| *k), Some(2));

    // Another state with no cache held: bare paper under the tiles, not the last frame.
    let mut other = (*design).clone();
    other.ops.truncate(100);
    callback.shown = Shown::all(Arc::new(other));
    callback.request.design_key = 4;
    callback.request.stand_in = Some(StandIn::other_state(Some(77)));
    frame(&mut gpu, &callback);
    assert_eq!(gpu.show, Show::Exact);
    let (target, _) = gpu.target.as_ref().expect("texture");
    let bare = read(&g, target, [10, 5, 100, 80]);
    let c = design.background;
    let paper = RgbaImage::filled(100, 80, [c.r, c.g, c.b, 255]);
    let diff = compare(&paper, &bare, 2).expect("size");
    assert_eq!(
        diff.fraction(),
        0.0,
        "the last frame under the tiles: {diff:?}"
    );
    // (The comparator sees the design: the exact frame is not bare paper.)
    let inked = compare(&paper, &shown, 2).expect("size").fraction();
    assert!(inked > 0.05, "{inked}");
}

fn rect(x0: f32, y0: f32, x1: f32, y1: f32) -> Rect {
    Rect::from_min_max(Pos2::new(x0, y0), Pos2::new(x1, y1))
}

#[test]
fn the_canvas_corner_is_rounded_and_the_sheet_moves_with_it() {
    // At 1.5 physical pixels per point the canvas corner lands on 100.5 px → 101
    // (as egui rounds its viewport); the sheet keeps its place relative to it.
    let p = CanvasPlacement::new(
        rect(67.0, 10.0, 400.0, 300.0),
        [77.0, 20.0, 177.0, 80.0],
        1.5,
    );
    assert_eq!(p.canvas_px, [101.0, 15.0]);
    assert_eq!(p.sheet_px, [116.0, 30.0, 266.0, 120.0]);
}

#[test]
fn sheet_pixels_are_those_whose_centres_lie_inside_the_sheet() {
    let p = CanvasPlacement {
        canvas_px: [0.0, 0.0],
        sheet_px: [10.4, 10.6, 20.5, 20.6],
    };
    // x: centres 10.5 … 19.5 are inside [10.4, 20.5); y: 11.5 … 20.5 inside [10.6, 20.6).
    assert_eq!(p.sheet_pixels(), rect(10.0, 11.0, 20.0, 21.0));
}
