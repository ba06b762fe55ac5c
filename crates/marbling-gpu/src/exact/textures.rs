//! The exact renderer's textures: the op records (`Rgba32Float`, [`TEXELS_PER_OP`]
//! texels per op, rows of [`OpLayout`]) and the background image, created empty and
//! written in place.

use super::PreparedDesign;
use crate::bindings::written_texture;
use crate::encode::{GpuOp, OpLayout, TEXELS_PER_OP};

/// An empty op texture of `layout`'s size.
pub(super) fn op_texture(device: &wgpu::Device, layout: OpLayout) -> wgpu::Texture {
    written_texture(
        device,
        "marbling ops",
        layout.width,
        layout.height,
        wgpu::TextureFormat::Rgba32Float,
    )
}

/// An image-background texture of `w`×`h` sRGB pixels.
pub(super) fn image_texture(device: &wgpu::Device, w: u32, h: u32) -> wgpu::Texture {
    written_texture(
        device,
        "marbling background image",
        w,
        h,
        wgpu::TextureFormat::Rgba8UnormSrgb,
    )
}

/// Writes `prepared.records[range]` into its texture, one write per texture row.
pub(super) fn write_records(
    queue: &wgpu::Queue,
    prepared: &mut PreparedDesign,
    range: std::ops::Range<usize>,
) {
    write_rows(
        queue,
        &prepared.ops_texture,
        prepared.layout,
        &prepared.records,
        range.clone(),
    );
    prepared.written += range.len() as u64;
}

/// Writes `records[range]` into `texture` laid out as `layout`, one write per row.
pub(super) fn write_rows(
    queue: &wgpu::Queue,
    texture: &wgpu::Texture,
    layout: OpLayout,
    records: &[GpuOp],
    range: std::ops::Range<usize>,
) {
    for (row, col, count) in layout.runs(range) {
        let first = row as usize * layout.ops_per_row as usize + col as usize;
        let texels: Vec<[f32; 4]> = records[first..first + count as usize]
            .iter()
            .flat_map(GpuOp::texels)
            .collect();
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d {
                    x: col * TEXELS_PER_OP,
                    y: row,
                    z: 0,
                },
                aspect: wgpu::TextureAspect::All,
            },
            bytemuck::cast_slice(&texels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(count * TEXELS_PER_OP * 16),
                rows_per_image: Some(1),
            },
            wgpu::Extent3d {
                width: count * TEXELS_PER_OP,
                height: 1,
                depth_or_array_layers: 1,
            },
        );
    }
}
