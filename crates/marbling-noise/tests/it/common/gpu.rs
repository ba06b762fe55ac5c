//! A minimal wgpu compute harness: evaluates `sample_noise` (noise.wgsl) or a layer
//! stack's `stack_intensity` (layers.wgsl) at every pixel centre of an N×N grid and
//! reads the values back. Used by the CPU≡WGSL tests and the GPU benchmark.

#![allow(dead_code)]

use marbling_noise::noise_gpu::NoiseGpu;
use marbling_noise::stack_gpu::NoiseStackGpu;
use marbling_noise::wgsl;
use std::time::{Duration, Instant};

/// A compute entry point writing `eval` (an expression of `p`, the pixel centre, and
/// `u`, a uniform of type `uniform`) for every pixel of a dims.x² grid.
fn entry(uniform: &str, eval: &str) -> String {
    format!(
        r"
@group(0) @binding(0) var<uniform> u: {uniform};
@group(0) @binding(1) var<storage, read_write> out: array<f32>;
@group(0) @binding(2) var<uniform> dims: vec4<u32>;

@compute @workgroup_size(8, 8)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {{
    if id.x >= dims.x || id.y >= dims.x {{
        return;
    }}
    let p = vec2<f32>(f32(id.x) + 0.5, f32(id.y) + 0.5);
    out[id.y * dims.x + id.x] = {eval};
}}
"
    )
}

fn pipeline(
    device: &wgpu::Device,
    name: &str,
    entry: &str,
) -> Result<wgpu::ComputePipeline, String> {
    let mut src = wgsl::module(name).ok_or("no such module")?;
    src.push_str(entry);
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(name),
        source: wgpu::ShaderSource::Wgsl(src.into()),
    });
    Ok(
        device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(name),
            layout: None,
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        }),
    )
}

/// A device with the noise pipeline.
pub struct GpuNoise {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipeline: wgpu::ComputePipeline,
    stack: wgpu::ComputePipeline,
    /// Adapter name and backend.
    pub adapter: String,
}

impl GpuNoise {
    /// Opens the adapter chosen by `WGPU_BACKEND` etc.; `Err` when there is none.
    pub fn new() -> Result<Self, String> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|e| format!("no GPU adapter: {e}"))?;
        let info = adapter.get_info();
        let (device, queue) =
            pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default()))
                .map_err(|e| format!("no device: {e}"))?;
        let pipeline = pipeline(
            &device,
            "noise",
            &entry("NoiseUniform", "sample_noise(p, u)"),
        )?;
        let stack = self::pipeline(
            &device,
            "layers",
            &entry("NoiseStack", "stack_intensity(p, u)"),
        )?;
        Ok(Self {
            device,
            queue,
            pipeline,
            stack,
            adapter: format!("{} ({:?})", info.name, info.backend),
        })
    }

    /// The noise of `u` at the N×N pixel centres, row-major, and the GPU time (submit to
    /// completion, excluding readback copy mapping).
    pub fn run(&self, u: &NoiseGpu, size: u32) -> (Vec<f32>, Duration) {
        self.dispatch(&self.pipeline, bytemuck::bytes_of(u), size)
    }

    /// The stack's intensity at the N×N pixel centres, row-major, and the GPU time.
    pub fn run_stack(&self, u: &NoiseStackGpu, size: u32) -> (Vec<f32>, Duration) {
        self.dispatch(&self.stack, bytemuck::bytes_of(u), size)
    }

    fn dispatch(
        &self,
        pipeline: &wgpu::ComputePipeline,
        uniform: &[u8],
        size: u32,
    ) -> (Vec<f32>, Duration) {
        use wgpu::util::DeviceExt;
        let d = &self.device;
        let uniform = d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("uniform"),
            contents: uniform,
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let dims = d.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("dims"),
            contents: bytemuck::cast_slice(&[size, 0, 0, 0]),
            usage: wgpu::BufferUsages::UNIFORM,
        });
        let bytes = u64::from(size) * u64::from(size) * 4;
        let out = d.create_buffer(&wgpu::BufferDescriptor {
            label: Some("out"),
            size: bytes,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let read = d.create_buffer(&wgpu::BufferDescriptor {
            label: Some("read"),
            size: bytes,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = d.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: uniform.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: out.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: dims.as_entire_binding(),
                },
            ],
        });
        let mut enc = d.create_command_encoder(&Default::default());
        {
            let mut pass = enc.begin_compute_pass(&Default::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(size.div_ceil(8), size.div_ceil(8), 1);
        }
        enc.copy_buffer_to_buffer(&out, 0, &read, 0, bytes);
        let start = Instant::now();
        self.queue.submit([enc.finish()]);
        let _ = d.poll(wgpu::PollType::wait_indefinitely());
        let elapsed = start.elapsed();
        read.map_async(wgpu::MapMode::Read, .., |r| {
            r.expect("map readback buffer");
        });
        let _ = d.poll(wgpu::PollType::wait_indefinitely());
        let values = {
            let view = read.get_mapped_range(..).expect("mapped readback buffer");
            bytemuck::pod_collect_to_vec::<u8, f32>(&view)
        };
        read.unmap();
        (values, elapsed)
    }
}
