//! The present pass shows texels 1:1 within the pass's scissor rectangle and touches
//! nothing outside it (the way the app draws its canvas and cached panels inside egui's
//! pass): sRGB-encoded texels reach a `…Unorm` target as they are and an `…UnormSrgb`
//! target decoded; a texture of the target's own format reaches it as it is.

use marbling_gpu::{GpuContext, Placement, Presenter, RenderTarget, copy_to_buffer, read_buffer};

const SRC: (u32, u32) = (37, 23);
const DST: (u32, u32) = (64, 48);
const ORIGIN: [u32; 2] = [9, 6];
/// The texture's placement in the target: x, y, width, height.
const TEXTURE_RECT: [u32; 4] = [ORIGIN[0], ORIGIN[1], SRC.0, SRC.1];
/// A scissor rectangle inside the texture's placement.
const WITHIN: [u32; 4] = [12, 8, 20, 11];

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

/// Presents the test pattern (its bytes written into a texture bound as `kind`) within
/// the viewport and scissor rectangle `rect` of a cleared-to-black `format` target and
/// reads it back.
fn present(ctx: &GpuContext, format: wgpu::TextureFormat, kind: Source, rect: [u32; 4]) -> Vec<u8> {
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
        presenter.draw(&mut pass, &bound);
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

/// What each target pixel must hold (RGB) after a draw within `rect`: the texel under
/// it inside, the clear colour (black) outside.
fn expected(x: u32, y: u32, rect: [u32; 4]) -> [u8; 3] {
    let [rx, ry, rw, rh] = rect;
    if x < rx || y < ry || x >= rx + rw || y >= ry + rh {
        return [0, 0, 0];
    }
    let (u, v) = (x - ORIGIN[0], y - ORIGIN[1]);
    [0, 1, 2].map(|c| source_byte(u, v, c))
}

/// Pixels whose RGB differs from [`expected`] by more than `tolerance`.
fn wrong_pixels(image: &[u8], tolerance: u8, rect: [u32; 4]) -> Vec<(u32, u32)> {
    let mut wrong = Vec::new();
    for y in 0..DST.1 {
        for x in 0..DST.0 {
            let i = ((y * DST.0 + x) * 4) as usize;
            let want = expected(x, y, rect);
            if (0..3).any(|c| image[i + c].abs_diff(want[c]) > tolerance) {
                wrong.push((x, y));
            }
        }
    }
    wrong
}

/// sRGB-encoded texels (the canvas's exact frame) reach a `…Unorm` target as they are;
/// an `…UnormSrgb` target gets them decoded and encoded again by the hardware, at most
/// one step of rounding off. Nothing outside the scissor is touched.
#[test]
fn encoded_texels_are_shown_unchanged_within_the_scissor() {
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    for (format, tolerance) in [
        (wgpu::TextureFormat::Rgba8Unorm, 0),
        (wgpu::TextureFormat::Rgba8UnormSrgb, 1),
    ] {
        for rect in [TEXTURE_RECT, WITHIN] {
            let image = present(&ctx, format, Source::Encoded, rect);
            assert_eq!(
                wrong_pixels(&image, tolerance, rect),
                Vec::<(u32, u32)>::new(),
                "{format:?} {rect:?}"
            );
        }
    }
}

/// The comparison can fail: one changed byte is found, and so is a copy one pixel off.
#[test]
fn the_comparison_sees_one_changed_byte_and_a_shifted_copy() {
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    let image = present(
        &ctx,
        wgpu::TextureFormat::Rgba8Unorm,
        Source::Encoded,
        TEXTURE_RECT,
    );
    let mut perturbed = image.clone();
    let i = ((10 * DST.0 + 12) * 4) as usize;
    perturbed[i] ^= 1;
    assert_eq!(wrong_pixels(&perturbed, 0, TEXTURE_RECT), vec![(12, 10)]);
    // The whole picture one pixel to the right.
    let row = DST.0 as usize * 4;
    let mut shifted = vec![0; image.len()];
    for (to, from) in shifted.chunks_mut(row).zip(image.chunks(row)) {
        to[4..].copy_from_slice(&from[..row - 4]);
    }
    assert!(wrong_pixels(&shifted, 0, TEXTURE_RECT).len() > 500);
}

/// A texture of the target's own format (the app's cached panels) reaches it as it is,
/// for `…Unorm` and `…UnormSrgb` targets alike, and only within the scissor.
#[test]
fn a_texture_in_the_target_format_is_copied_as_it_is() {
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    for format in [
        wgpu::TextureFormat::Rgba8Unorm,
        wgpu::TextureFormat::Rgba8UnormSrgb,
    ] {
        for rect in [TEXTURE_RECT, WITHIN] {
            let image = present(&ctx, format, Source::InTargetFormat, rect);
            assert_eq!(
                wrong_pixels(&image, 0, rect),
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
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    let format = wgpu::TextureFormat::Rgba8UnormSrgb;
    let image = present(&ctx, format, Source::TargetFormatAsEncoded, TEXTURE_RECT);
    assert!(wrong_pixels(&image, 1, TEXTURE_RECT).len() > 500);
}
