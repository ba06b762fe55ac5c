//! The exact renderer as a compute pass (shaders/render_compute.wgsl): the same
//! per-pixel `shade` as the fragment pipeline, one invocation per target pixel, stored
//! into an `Rgba8Unorm` storage texture. Headless renders use it wherever the device has
//! compute shaders and storage textures (every native backend and WebGPU; not WebGL2):
//! some GPUs run fragment work on a small part of the chip only (an NVIDIA H100 has
//! graphics on 4 of its 132 SMs), while compute runs on all of it. Same bytes as the
//! fragment path (tests/it/compute.rs).

use crate::exact::{ExactRenderer, PreparedDesign};
use crate::shaders::ExactVariant;
use crate::target::RenderTarget;
use crate::variants::Variants;

/// Workgroup side of `cs_main` (8 × 8 invocations).
const WORKGROUP: u32 = 8;

/// The compute variant of [`ExactRenderer`]'s pipelines (plain, the other
/// [`ExactVariant`]s on first use), sharing its bind group 0; group 1 is the target.
#[derive(Debug)]
pub struct ComputeExact {
    target_layout: wgpu::BindGroupLayout,
    pipeline_layout: wgpu::PipelineLayout,
    pipelines: Variants<wgpu::ComputePipeline>,
}

impl ComputeExact {
    /// Whether `device` can run it: compute shaders with at least 64 invocations per
    /// workgroup and a storage texture per stage (WebGL2 has neither).
    pub fn supported(device: &wgpu::Device) -> bool {
        let l = device.limits();
        l.max_storage_textures_per_shader_stage >= 1
            && l.max_compute_invocations_per_workgroup >= WORKGROUP * WORKGROUP
            && l.max_compute_workgroup_size_x >= WORKGROUP
            && l.max_compute_workgroup_size_y >= WORKGROUP
    }

    /// Builds the plain pipeline next to `exact` (whose bind group layout it shares).
    pub fn new(device: &wgpu::Device, exact: &ExactRenderer) -> Self {
        let target_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("marbling render target (compute)"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::StorageTexture {
                    access: wgpu::StorageTextureAccess::WriteOnly,
                    format: wgpu::TextureFormat::Rgba8Unorm,
                    view_dimension: wgpu::TextureViewDimension::D2,
                },
                count: None,
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("marbling render (compute)"),
            bind_group_layouts: &[Some(exact.bind_group_layout()), Some(&target_layout)],
            immediate_size: 0,
        });
        let pipeline = build(
            device,
            &pipeline_layout,
            "marbling render (compute, plain)",
            &ExactVariant::PLAIN.compute_wgsl(),
        );
        let pipelines = Variants::default();
        pipelines.get_or_init(ExactVariant::PLAIN, || pipeline);
        Self {
            target_layout,
            pipeline_layout,
            pipelines,
        }
    }

    /// Records the exact render of `design` (its view set with
    /// [`PreparedDesign::set_view`]) into all of `target`, which must be `Rgba8Unorm` with
    /// `STORAGE_BINDING` usage.
    pub fn dispatch(
        &self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        design: &PreparedDesign,
        target: &RenderTarget,
    ) {
        let variant = design.variant();
        let pipeline = self.pipelines.get_or_init(variant, || {
            build(
                device,
                &self.pipeline_layout,
                &format!("marbling render (compute, {})", variant.name()),
                &variant.compute_wgsl(),
            )
        });
        let target_group = crate::bindings::bind_group(
            device,
            "marbling render target (compute)",
            &self.target_layout,
            &[wgpu::BindingResource::TextureView(&target.view)],
        );
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("marbling render (compute)"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, design.bind_group(), &[]);
        pass.set_bind_group(1, &target_group, &[]);
        pass.dispatch_workgroups(
            target.width.div_ceil(WORKGROUP),
            target.height.div_ceil(WORKGROUP),
            1,
        );
    }
}

fn build(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    label: &str,
    source: &str,
) -> wgpu::ComputePipeline {
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: Some(layout),
        module: &module,
        entry_point: Some("cs_main"),
        compilation_options: Default::default(),
        cache: None,
    })
}
