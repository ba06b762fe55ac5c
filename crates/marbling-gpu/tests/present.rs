//! The present pass copies texels 1:1 inside the sheet, paints the background outside
//! it, and touches nothing outside the pass's viewport and scissor rectangle (the way
//! the app draws its canvas inside egui's pass). A texture of the target's own format
//! reaches it as it is.

mod common;

use marbling_gpu::{GpuContext, Placement, Presenter, RenderTarget, copy_to_buffer, read_buffer};

const SRC: (u32, u32) = (37, 23);
const DST: (u32, u32) = (64, 48);
/// The canvas rectangle (viewport and scissor): x, y, width, height.
const CANVAS: [u32; 4] = [5, 3, 55, 42];
const ORIGIN: [u32; 2] = [9, 6];
/// The sheet: min x, min y, max x, max y (smaller than the source). A pixel is inside
/// when its centre is: x in 9..38, y in 6..27.
const SHEET: [f32; 4] = [9.4, 6.5, 38.5, 26.6];
const BACKGROUND: [u8; 3] = [48, 50, 52];

fn source_byte(x: u32, y: u32, c: u32) -> u8 {
    ((x * 7 + y * 13 + c * 61) % 256) as u8
}

/// How the source texture is bound.
#[derive(Clone, Copy, PartialEq)]
enum Source {
    /// `Presenter::source`: an `Rgba8Unorm` texture of sRGB-encoded values.
    Encoded,
    /// `Presenter::source_in_target_format`: a texture of the target's format.
    InTargetFormat,
    /// A texture of the target's format bound with `Presenter::source` (a mistake: an
    /// sRGB target's texels would be decoded twice).
    TargetFormatAsEncoded,
}

/// Which of the presenter's draws a test makes.
#[derive(Clone, Copy, PartialEq)]
enum Draw {
    /// `Presenter::draw`: texels in the sheet, background around it.
    Full,
    /// `Presenter::draw_texels`: texels only, the scissor within the sheet.
    Texels,
}

/// The texture's placement in the target: x, y, width, height.
const TEXTURE_RECT: [u32; 4] = [ORIGIN[0], ORIGIN[1], SRC.0, SRC.1];

/// Presents the test pattern (its bytes written into a texture bound as `kind`) with
/// the sheet at `sheet`, within the viewport and scissor rectangle `rect`, into a
/// cleared-to-black `format` target and reads it back.
fn present(
    ctx: &GpuContext,
    format: wgpu::TextureFormat,
    sheet: [f32; 4],
    kind: Source,
    rect: [u32; 4],
    draw: Draw,
) -> Vec<u8> {
    let (device, queue) = (&ctx.device, &ctx.queue);
    let source_format = match kind {
        Source::Encoded => wgpu::TextureFormat::Rgba8Unorm,
        Source::InTargetFormat | Source::TargetFormatAsEncoded => format,
    };
    let source = RenderTarget::with_usage(
        device,
        SRC.0,
        SRC.1,
        source_format,
        wgpu::TextureUsages::COPY_DST,
    );
    let bytes: Vec<u8> = (0..SRC.1)
        .flat_map(|y| (0..SRC.0).flat_map(move |x| (0..4).map(move |c| source_byte(x, y, c))))
        .collect();
    queue.write_texture(
        source.texture.as_image_copy(),
        &bytes,
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(SRC.0 * 4),
            rows_per_image: None,
        },
        source.texture.size(),
    );
    let presenter = Presenter::new(device, format);
    let mut bound = match kind {
        Source::Encoded | Source::TargetFormatAsEncoded => presenter.source(device, &source.view),
        Source::InTargetFormat => presenter.source_in_target_format(device, &source.view),
    };
    bound.place(
        queue,
        &Placement {
            origin: ORIGIN.map(|v| v as f32),
            sheet,
            background: BACKGROUND,
        },
    );
    let target = RenderTarget::new(device, DST.0, DST.1, format);
    let mut encoder =
        device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    {
        let mut pass = target.begin_pass(&mut encoder);
        let [x, y, w, h] = rect;
        pass.set_viewport(x as f32, y as f32, w as f32, h as f32, 0.0, 1.0);
        pass.set_scissor_rect(x, y, w, h);
        match draw {
            Draw::Full => presenter.draw(&mut pass, &bound),
            Draw::Texels => presenter.draw_texels(&mut pass, &bound),
        }
    }
    let (buffer, padded) = copy_to_buffer(device, &mut encoder, &target);
    queue.submit([encoder.finish()]);
    let mut out = vec![0; (DST.0 * DST.1 * 4) as usize];
    let row = DST.0 as usize * 4;
    read_buffer(ctx, &buffer, padded, DST.0, DST.1, |y, b| {
        out[y as usize * row..(y as usize + 1) * row].copy_from_slice(b);
    })
    .expect("readback");
    out
}

/// What each target pixel must hold (RGB) with the sheet at `sheet`.
fn expected(x: u32, y: u32, sheet: [f32; 4]) -> [u8; 3] {
    let [cx, cy, cw, ch] = CANVAS;
    if x < cx || y < cy || x >= cx + cw || y >= cy + ch {
        return [0, 0, 0];
    }
    let [sx0, sy0, sx1, sy1] = sheet;
    let (px, py) = (x as f32 + 0.5, y as f32 + 0.5);
    if px < sx0 || py < sy0 || px >= sx1 || py >= sy1 {
        return BACKGROUND;
    }
    let (u, v) = (x - ORIGIN[0], y - ORIGIN[1]);
    [0, 1, 2].map(|c| source_byte(u, v, c))
}

/// Pixels whose RGB differs from [`expected`] by more than `tolerance`.
fn wrong_pixels(image: &[u8], tolerance: u8, sheet: [f32; 4]) -> Vec<(u32, u32)> {
    differing_from(image, tolerance, |x, y| expected(x, y, sheet))
}

/// Pixels whose RGB differs from `want(x, y)` by more than `tolerance`.
fn differing_from(
    image: &[u8],
    tolerance: u8,
    want: impl Fn(u32, u32) -> [u8; 3],
) -> Vec<(u32, u32)> {
    let mut wrong = Vec::new();
    for y in 0..DST.1 {
        for x in 0..DST.0 {
            let i = ((y * DST.0 + x) * 4) as usize;
            let want = want(x, y);
            if (0..3).any(|c| image[i + c].abs_diff(want[c]) > tolerance) {
                wrong.push((x, y));
            }
        }
    }
    wrong
}

#[test]
fn texels_inside_the_sheet_background_around_it_nothing_beyond_the_canvas() {
    let Some(ctx) = common::or_skip(GpuContext::new_headless()) else {
        return;
    };
    let image = present(
        &ctx,
        wgpu::TextureFormat::Rgba8Unorm,
        SHEET,
        Source::Encoded,
        CANVAS,
        Draw::Full,
    );
    assert_eq!(wrong_pixels(&image, 0, SHEET), Vec::<(u32, u32)>::new());
    // The comparison can fail: one changed byte is found.
    let mut perturbed = image.clone();
    let i = ((10 * DST.0 + 12) * 4) as usize;
    perturbed[i] ^= 1;
    assert_eq!(wrong_pixels(&perturbed, 0, SHEET), vec![(12, 10)]);
}

#[test]
fn srgb_targets_show_the_same_colours() {
    let Some(ctx) = common::or_skip(GpuContext::new_headless()) else {
        return;
    };
    // Decoded to linear light by the shader and encoded again by the hardware: at most
    // one step of rounding.
    let format = wgpu::TextureFormat::Rgba8UnormSrgb;
    let image = present(&ctx, format, SHEET, Source::Encoded, CANVAS, Draw::Full);
    assert_eq!(wrong_pixels(&image, 1, SHEET), Vec::<(u32, u32)>::new());
}

/// What each target pixel must hold (RGB) after a copy within `rect`.
fn expected_copy(x: u32, y: u32, rect: [u32; 4]) -> [u8; 3] {
    let [rx, ry, rw, rh] = rect;
    if x < rx || y < ry || x >= rx + rw || y >= ry + rh {
        return [0, 0, 0];
    }
    let (u, v) = (x - ORIGIN[0], y - ORIGIN[1]);
    [0, 1, 2].map(|c| source_byte(u, v, c))
}

/// Pixels whose RGB differs from [`expected_copy`] by more than `tolerance`.
fn wrong_copy_pixels(image: &[u8], tolerance: u8, rect: [u32; 4]) -> Vec<(u32, u32)> {
    differing_from(image, tolerance, |x, y| expected_copy(x, y, rect))
}

/// A texture of the target's own format (the app's cached side panel) reaches it as it
/// is, for `…Unorm` and `…UnormSrgb` targets alike, and only within the scissor.
#[test]
fn a_texture_in_the_target_format_is_copied_as_it_is() {
    let Some(ctx) = common::or_skip(GpuContext::new_headless()) else {
        return;
    };
    let within = [12, 8, 20, 11];
    for format in [
        wgpu::TextureFormat::Rgba8Unorm,
        wgpu::TextureFormat::Rgba8UnormSrgb,
    ] {
        for rect in [TEXTURE_RECT, within] {
            let image = present(
                &ctx,
                format,
                SHEET,
                Source::InTargetFormat,
                rect,
                Draw::Texels,
            );
            assert_eq!(
                wrong_copy_pixels(&image, 0, rect),
                Vec::<(u32, u32)>::new(),
                "{format:?} {rect:?}"
            );
        }
    }
}

/// The comparison sees a texture of an sRGB target's format bound as sRGB-encoded
/// values (its texels decoded twice).
#[test]
fn decoding_a_texture_in_the_target_format_again_is_caught() {
    let Some(ctx) = common::or_skip(GpuContext::new_headless()) else {
        return;
    };
    let format = wgpu::TextureFormat::Rgba8UnormSrgb;
    let whole = [0.0, 0.0, DST.0 as f32, DST.1 as f32];
    let image = present(
        &ctx,
        format,
        whole,
        Source::TargetFormatAsEncoded,
        TEXTURE_RECT,
        Draw::Texels,
    );
    assert!(wrong_copy_pixels(&image, 1, TEXTURE_RECT).len() > 500);
}

/// Only the texels, within a scissor inside the sheet: copied as they are on a `…Unorm`
/// target, decoded for an `…UnormSrgb` one (one step of rounding at most).
#[test]
fn texels_only_draws_show_the_sheet_unchanged() {
    let Some(ctx) = common::or_skip(GpuContext::new_headless()) else {
        return;
    };
    // Pixels 10..37 × 7..26 lie inside SHEET.
    let inside = [10, 7, 27, 19];
    for (format, tolerance) in [
        (wgpu::TextureFormat::Rgba8Unorm, 0),
        (wgpu::TextureFormat::Rgba8UnormSrgb, 1),
    ] {
        let image = present(&ctx, format, SHEET, Source::Encoded, inside, Draw::Texels);
        assert_eq!(
            wrong_copy_pixels(&image, tolerance, inside),
            Vec::<(u32, u32)>::new(),
            "{format:?}"
        );
    }
}
