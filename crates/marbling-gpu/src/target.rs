//! Offscreen render targets and reading their pixels back (the blocking read is
//! native only; [`PendingRead`] waits for the map between frames, everywhere).

#[cfg(not(target_arch = "wasm32"))]
use crate::GpuContext;
use crate::GpuError;

/// Bytes per row of a texture-to-buffer copy must be a multiple of this.
const ROW_ALIGN: u32 = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;

/// A texture to draw into, with its view.
#[derive(Debug)]
pub struct RenderTarget {
    /// The texture (usages: render attachment, copy source, texture binding).
    pub texture: wgpu::Texture,
    /// Its default view.
    pub view: wgpu::TextureView,
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
}

impl RenderTarget {
    /// A `width × height` target of `format`.
    pub fn new(
        device: &wgpu::Device,
        width: u32,
        height: u32,
        format: wgpu::TextureFormat,
    ) -> Self {
        Self::with_usage(device, width, height, format, wgpu::TextureUsages::empty())
    }

    /// [`RenderTarget::new`] with `extra` usages (e.g. `STORAGE_BINDING` for the compute
    /// path).
    pub fn with_usage(
        device: &wgpu::Device,
        width: u32,
        height: u32,
        format: wgpu::TextureFormat,
        extra: wgpu::TextureUsages,
    ) -> Self {
        let texture = crate::bindings::texture(
            device,
            "marbling target",
            [width, height],
            format,
            wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::COPY_SRC
                | wgpu::TextureUsages::TEXTURE_BINDING
                | extra,
        );
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        Self {
            texture,
            view,
            width,
            height,
        }
    }

    /// Begins a render pass that overwrites the whole target.
    pub fn begin_pass<'e>(&self, encoder: &'e mut wgpu::CommandEncoder) -> wgpu::RenderPass<'e> {
        self.begin_pass_with(encoder, wgpu::LoadOp::Clear(wgpu::Color::BLACK))
    }

    /// Begins a render pass that keeps the target's pixels (draws within a scissor
    /// rectangle change only those: tiles of a progressive render).
    pub fn begin_pass_keeping<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
    ) -> wgpu::RenderPass<'e> {
        self.begin_pass_with(encoder, wgpu::LoadOp::Load)
    }

    /// Begins a render pass that clears the target to `color` (linear RGBA for sRGB
    /// formats, the stored values otherwise).
    pub fn begin_pass_clearing<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        color: wgpu::Color,
    ) -> wgpu::RenderPass<'e> {
        self.begin_pass_with(encoder, wgpu::LoadOp::Clear(color))
    }

    fn begin_pass_with<'e>(
        &self,
        encoder: &'e mut wgpu::CommandEncoder,
        load: wgpu::LoadOp<wgpu::Color>,
    ) -> wgpu::RenderPass<'e> {
        encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("marbling pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load,
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: None,
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        })
    }
}

/// Copies an RGBA8 `target` into a padded buffer: the returned buffer and its padded
/// bytes per row. Record into `encoder`, submit, then [`read_buffer`].
pub fn copy_to_buffer(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    target: &RenderTarget,
) -> (wgpu::Buffer, u32) {
    let padded = (target.width * 4).div_ceil(ROW_ALIGN) * ROW_ALIGN;
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("marbling readback"),
        size: u64::from(padded) * u64::from(target.height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture: &target.texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded),
                rows_per_image: Some(target.height),
            },
        },
        wgpu::Extent3d {
            width: target.width,
            height: target.height,
            depth_or_array_layers: 1,
        },
    );
    (buffer, padded)
}

/// Maps a submitted readback buffer (native only: it blocks on the device) and hands each unpadded row (`width × 4` bytes,
/// top to bottom) to `row(y, bytes)`.
#[cfg(not(target_arch = "wasm32"))]
pub fn read_buffer(
    ctx: &GpuContext,
    buffer: &wgpu::Buffer,
    padded: u32,
    width: u32,
    height: u32,
    mut row: impl FnMut(u32, &[u8]),
) -> Result<(), GpuError> {
    let (tx, rx) = std::sync::mpsc::channel();
    buffer.map_async(wgpu::MapMode::Read, .., move |r| {
        // The receiver lives until this function returns; a failed send only means
        // nobody waits any more.
        let _ = tx.send(r);
    });
    ctx.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    rx.recv()
        .map_err(|e| GpuError::Readback(e.to_string()))?
        .map_err(|e| GpuError::Readback(e.to_string()))?;
    {
        let data = buffer
            .get_mapped_range(..)
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        for y in 0..height {
            let start = (y * padded) as usize;
            row(y, &data[start..start + (width * 4) as usize]);
        }
    }
    buffer.unmap();
    Ok(())
}

/// A target's pixels on their way back without blocking (the browser maps buffers
/// between frames): [`PendingRead::start`] copies and asks for the map; call
/// [`PendingRead::rows`] once per frame until it answers.
pub struct PendingRead {
    buffer: wgpu::Buffer,
    padded: u32,
    /// The target's size, pixels.
    size: (u32, u32),
    mapped: MapSlot,
}

/// Where a buffer's map callback leaves its outcome.
type MapSlot = std::sync::Arc<std::sync::Mutex<Option<Result<(), wgpu::BufferAsyncError>>>>;

impl PendingRead {
    /// Copies `target` (RGBA8) at the end of `encoder`, submits it and asks for the map.
    pub fn start(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mut encoder: wgpu::CommandEncoder,
        target: &RenderTarget,
    ) -> Self {
        let (buffer, padded) = copy_to_buffer(device, &mut encoder, target);
        queue.submit([encoder.finish()]);
        let mapped = MapSlot::default();
        let slot = std::sync::Arc::clone(&mapped);
        buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            if let Ok(mut s) = slot.lock() {
                *s = Some(r);
            }
        });
        Self {
            buffer,
            padded,
            size: (target.width, target.height),
            mapped,
        }
    }

    /// `None` while the map is pending; then hands each unpadded row (`width × 4`
    /// bytes, top to bottom) to `row(y, bytes)`, once. Native backends deliver the map
    /// from `device.poll`, which the caller runs.
    pub fn rows(&self, mut row: impl FnMut(u32, &[u8])) -> Option<Result<(), GpuError>> {
        let (width, height) = self.size;
        let outcome = self.mapped.lock().ok().and_then(|mut m| m.take())?;
        let read = || -> Result<(), GpuError> {
            outcome.map_err(|e| GpuError::Readback(e.to_string()))?;
            {
                let data = self
                    .buffer
                    .get_mapped_range(..)
                    .map_err(|e| GpuError::Readback(e.to_string()))?;
                for y in 0..height {
                    let start = (y * self.padded) as usize;
                    row(y, &data[start..start + (width * 4) as usize]);
                }
            }
            self.buffer.unmap();
            Ok(())
        };
        Some(read())
    }
}
