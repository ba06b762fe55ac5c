//! Untextured coloured triangles drawn inside egui's render pass: the tool overlay
//! (lines and circles that egui tessellated), which egui would draw with its general
//! textured shader. On software GPUs (SwiftShader) that shader costs milliseconds a frame
//! even for a few thousand pixels, because every branch of it runs for every pixel;
//! `flat_mesh.wgsl` is straight-line code (docs/BENCHMARKS.md).

use marbling_gpu::bindings;
use std::ops::Range;

/// `marbling-gpu`'s shared WGSL functions (`srgb_to_linear`) + `flat_mesh.wgsl`.
pub fn flat_mesh_wgsl() -> String {
    [
        marbling_gpu::shaders::COMMON,
        include_str!("flat_mesh.wgsl"),
    ]
    .join("\n")
}

/// Parameters of the flat-mesh pass. Keep in sync with `struct FlatMeshParams` in
/// flat_mesh.wgsl (checked by a test below).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FlatMeshParams {
    /// The target's size in points.
    pub screen_size_points: [f32; 2],
    /// Padding to 16 bytes.
    pub _pad: [f32; 2],
}

/// One vertex, laid out as egui's `epaint::Vertex`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct FlatVertex {
    /// Position in points (egui's screen coordinates).
    pub position: [f32; 2],
    /// A texture coordinate, unused (egui's meshes carry one).
    pub uv: [f32; 2],
    /// Premultiplied sRGB-encoded RGBA bytes.
    pub color: [u8; 4],
}

/// The pipeline for one target format, and the buffers of the triangles it draws next.
#[derive(Debug)]
pub struct FlatMeshRenderer {
    pipeline: wgpu::RenderPipeline,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    vertices: Option<wgpu::Buffer>,
    indices: Option<wgpu::Buffer>,
}

impl FlatMeshRenderer {
    /// Builds the pipeline drawing into targets of `format`, blending with premultiplied
    /// alpha.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("marbling flat_mesh.wgsl"),
            source: wgpu::ShaderSource::Wgsl(flat_mesh_wgsl().into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling flat mesh"),
            entries: &[bindings::uniform::<FlatMeshParams>(
                0,
                wgpu::ShaderStages::VERTEX,
            )],
        });
        let pipeline_layout = bindings::pipeline_layout(device, "marbling flat mesh", &layout);
        let premultiplied = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::OneMinusSrcAlpha,
            operation: wgpu::BlendOperation::Add,
        };
        let pipeline = device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("marbling flat mesh"),
            layout: Some(&pipeline_layout),
            vertex: wgpu::VertexState {
                module: &module,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(wgpu::VertexBufferLayout {
                    array_stride: std::mem::size_of::<FlatVertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &wgpu::vertex_attr_array![
                        0 => Float32x2,
                        1 => Float32x2,
                        2 => Unorm8x4,
                    ],
                })],
            },
            primitive: wgpu::PrimitiveState::default(),
            depth_stencil: None,
            multisample: wgpu::MultisampleState::default(),
            fragment: Some(wgpu::FragmentState {
                module: &module,
                entry_point: Some(if format.is_srgb() {
                    "fs_linear"
                } else {
                    "fs_main"
                }),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format,
                    blend: Some(wgpu::BlendState {
                        color: premultiplied,
                        alpha: premultiplied,
                    }),
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        });
        let uniform = bindings::uniform_buffer::<FlatMeshParams>(device, "marbling flat mesh");
        let bind_group = marbling_gpu::bindings::bind_group(
            device,
            "marbling flat mesh",
            &layout,
            &[uniform.as_entire_binding()],
        );
        Self {
            pipeline,
            uniform,
            bind_group,
            vertices: None,
            indices: None,
        }
    }

    /// Uploads the triangles of the next draws: `indices` into `vertices`, on a target
    /// `screen_size_points` points large. The buffers grow as needed.
    pub fn upload(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        screen_size_points: [f32; 2],
        vertices: &[FlatVertex],
        indices: &[u32],
    ) {
        let params = FlatMeshParams {
            screen_size_points,
            _pad: [0.0; 2],
        };
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&params));
        write_growing(
            device,
            queue,
            &mut self.vertices,
            bytemuck::cast_slice(vertices),
            wgpu::BufferUsages::VERTEX,
        );
        write_growing(
            device,
            queue,
            &mut self.indices,
            bytemuck::cast_slice(indices),
            wgpu::BufferUsages::INDEX,
        );
    }

    /// Records a draw of the uploaded triangles `indices` (a range of the index list)
    /// into `pass`, within its viewport and scissor rectangle. The viewport must be the
    /// whole target. Does nothing before an upload.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>, indices: Range<u32>) {
        let (Some(vertices), Some(index_buffer)) = (&self.vertices, &self.indices) else {
            return;
        };
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_vertex_buffer(0, vertices.slice(..));
        pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(indices, 0, 0..1);
    }
}

/// Writes `bytes` to the start of `buffer`, first replacing it by a larger one (twice
/// the size needed) when it is too small.
fn write_growing(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    buffer: &mut Option<wgpu::Buffer>,
    bytes: &[u8],
    usage: wgpu::BufferUsages,
) {
    if bytes.is_empty() {
        return;
    }
    let size = (bytes.len() as u64).next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT);
    if buffer.as_ref().is_none_or(|b| b.size() < size) {
        *buffer = Some(device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("marbling flat mesh"),
            size: size * 2,
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        }));
    }
    if let Some(b) = buffer {
        queue.write_buffer(b, 0, bytes);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::{offset_of, size_of};

    #[test]
    fn the_shader_validates_and_its_uniform_matches_the_host_struct() {
        let module = marbling_testkit::wgsl::validate("flat_mesh", &flat_mesh_wgsl());
        let entry: Vec<&str> = module
            .entry_points
            .iter()
            .map(|e| e.name.as_str())
            .collect();
        assert_eq!(entry, ["vs_main", "fs_main", "fs_linear"]);
        marbling_testkit::wgsl::check_uniform(
            &module,
            "FlatMeshParams",
            &[
                (
                    "screen_size_points",
                    offset_of!(FlatMeshParams, screen_size_points),
                ),
                ("_pad", offset_of!(FlatMeshParams, _pad)),
            ],
            size_of::<FlatMeshParams>(),
        );
        assert_eq!(
            size_of::<FlatVertex>(),
            20,
            "egui's epaint::Vertex is 20 bytes"
        );
    }
}
