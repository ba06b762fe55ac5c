//! The compute path of headless renders draws the same bytes as the fragment pipeline
//! (the app's path): v1 designs with every antialiasing mode, tiled, and a schema v2
//! design with a noise background and both grains; and the comparison sees a change.

use marbling_core::synth::{Mix, random_design};
use marbling_core::{
    Antialias, Design, NoiseBackground, NoiseLayer, Overlay, Palette, RenderOptions, RgbaImage,
};
use marbling_gpu::{GpuContext, GpuRenderer};

/// (compute, fragment) renderers on one device of the best adapter.
fn renderers() -> Option<(GpuRenderer, GpuRenderer)> {
    let ctx = marbling_testkit::gpu_or_skip(GpuContext::new_headless())?;
    let compute = GpuRenderer::new(ctx.clone());
    let fragment = GpuRenderer::new(ctx).with_fragment_path();
    eprintln!("adapter: {}", compute.context().describe());
    assert_eq!(
        compute.path(),
        "compute",
        "the adapter has no compute path, so nothing would be compared"
    );
    assert_eq!(fragment.path(), "fragment");
    Some((compute, fragment))
}

/// Pixels whose bytes differ.
fn differing(a: &RgbaImage, b: &RgbaImage) -> usize {
    assert_eq!((a.width, a.height), (b.width, b.height));
    a.pixels
        .chunks_exact(4)
        .zip(b.pixels.chunks_exact(4))
        .filter(|(x, y)| x != y)
        .count()
}

fn v2_design() -> Design {
    let mut d = random_design(11, 160, 120, 60, Mix::Mixed);
    let layer = |json: &str| NoiseLayer::from_json(json).expect("valid test noise");
    d.background_noise = Some(NoiseBackground {
        noise: layer(r#"{"type":"perlin","frequency":0.03,"octaves":4,"seed":4}"#),
        palette: Palette::named("marble").expect("built-in palette"),
    });
    d.overlays = vec![
        Overlay::paper_grain(
            layer(r#"{"type":"value","frequency":0.2,"octaves":3,"seed":8}"#),
            0.3,
        ),
        Overlay::pigment_grain(
            layer(r#"{"type":"perlin","frequency":0.12,"octaves":2,"seed":3}"#),
            0.4,
        ),
    ];
    d
}

#[test]
fn compute_path_draws_the_fragment_path_bytes() {
    let Some((compute, fragment)) = renderers() else {
        return;
    };
    let compute = compute.with_tile_side(96);
    let fragment = fragment.with_tile_side(96);
    let v1 = random_design(5, 200, 150, 150, Mix::Mixed);
    for aa in [
        Antialias::None,
        Antialias::Rgss,
        Antialias::Adaptive,
        Antialias::Rooks8,
    ] {
        let opts = RenderOptions {
            scale: 1.3,
            antialias: aa,
        };
        let a = compute.render(&v1, &opts).expect("compute render");
        let b = fragment.render(&v1, &opts).expect("fragment render");
        assert_eq!(differing(&a, &b), 0, "v1, {aa:?}");
    }
    let v2 = v2_design();
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::Rgss,
    };
    let a = compute.render(&v2, &opts).expect("compute render");
    let b = fragment.render(&v2, &opts).expect("fragment render");
    assert_eq!(differing(&a, &b), 0, "v2 surface");
    // The comparison sees a one-op change.
    let mut changed = v1.clone();
    changed.ops.pop();
    let c = compute.render(&changed, &opts).expect("compute render");
    let d = fragment.render(&v1, &opts).expect("fragment render");
    assert!(differing(&c, &d) > 0, "dropping an op changed nothing");
}

/// `walk_records` of `shaders/records.wgsl` (with `op_back` of `common.wgsl`) over each
/// op's records at every point of `points`, through a compute pass: (x, y, covered)
/// per (op, point), op-major. `shaders` is common.wgsl then records.wgsl (tests pass
/// broken copies).
fn gpu_op_back(
    ctx: &GpuContext,
    shaders: &str,
    ops: &[marbling_core::Op],
    points: &[[f32; 2]],
) -> Vec<[f32; 4]> {
    use wgpu::util::DeviceExt;
    let device = &ctx.device;
    let source = [shaders, include_str!("op_back.wgsl")].join("\n");
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("op_back test"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("op_back test"),
        layout: None,
        module: &module,
        entry_point: Some("cs_op_back"),
        compilation_options: Default::default(),
        cache: None,
    });
    let mut records: Vec<marbling_gpu::encode::GpuOp> = Vec::new();
    let mut ranges: Vec<[u32; 2]> = Vec::new();
    for op in ops {
        let start = records.len() as u32;
        marbling_gpu::encode::records(op, &mut records);
        ranges.push([start, records.len() as u32]);
    }
    let storage = |label, contents: &[u8], usage| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents,
            usage,
        })
    };
    let op_buffer = storage(
        "ops",
        bytemuck::cast_slice(&records),
        wgpu::BufferUsages::STORAGE,
    );
    let range_buffer = storage(
        "ranges",
        bytemuck::cast_slice(&ranges),
        wgpu::BufferUsages::STORAGE,
    );
    let point_buffer = storage(
        "points",
        bytemuck::cast_slice(points),
        wgpu::BufferUsages::STORAGE,
    );
    let size = (ops.len() * points.len() * 16) as u64;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("out"),
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: op_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: range_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: point_buffer.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 3,
                resource: out.as_entire_binding(),
            },
        ],
    });
    let mut encoder =
        device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
    {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups((points.len() as u32).div_ceil(64), ops.len() as u32, 1);
    }
    encoder.copy_buffer_to_buffer(&out, 0, &readback, 0, size);
    ctx.queue.submit([encoder.finish()]);
    let mut result = Vec::new();
    marbling_gpu::read_buffer(
        ctx,
        &readback,
        size as u32,
        (size / 4) as u32,
        1,
        |_, bytes| {
            result = bytemuck::cast_slice::<u8, [f32; 4]>(bytes).to_vec();
        },
    )
    .expect("readback");
    result
}

/// Every op of `kind` in random designs, walked back on the GPU (f32, `walk_records`
/// of `shaders`) and the CPU (f64, [`marbling_core::CompiledOp::inverse`]) from random
/// points around the sheet: how many points got another covered/not-covered answer, and
/// the worst position error relative to the position's distance from the origin (at
/// least 1 design px). Points within 1e-4 of a disc's rim are skipped (f32 may put them
/// on either side).
fn inverse_errors(ctx: &GpuContext, shaders: &str, kind: marbling_core::OpKind) -> (usize, f64) {
    use marbling_core::{CompiledOp, Point};
    let mut ops = if kind == marbling_core::OpKind::Flow {
        flows()
    } else {
        Vec::new()
    };
    for (seed, mix) in [
        (1, Mix::Mixed),
        (2, Mix::DropHeavy),
        (3, Mix::CombHeavy),
        (4, Mix::AllTypes),
    ] {
        ops.extend(
            random_design(seed, 300, 200, 400, mix)
                .ops
                .into_iter()
                .filter(|op| matches!(CompiledOp::of(op).as_slice(), [c] if c.kind() == kind))
                .take(12),
        );
    }
    assert!(ops.len() >= 6, "{kind:?}: only {} ops to test", ops.len());
    let mut rng = marbling_core::synth::SplitMix64(kind.code() as u64 + 7);
    let points: Vec<[f32; 2]> = (0..256)
        .map(|_| {
            [
                rng.range(-50.0, 350.0) as f32,
                rng.range(-50.0, 250.0) as f32,
            ]
        })
        .collect();
    let gpu = gpu_op_back(ctx, shaders, &ops, &points);
    let (mut worst, mut compared, mut other_answer) = (0.0f64, 0, 0);
    for (i, op) in ops.iter().enumerate() {
        let [c] = CompiledOp::of(op).try_into().expect("one compiled op");
        for (j, p) in points.iter().enumerate() {
            let p64 = Point::new(f64::from(p[0]), f64::from(p[1]));
            if let CompiledOp::Disc { cx, cy, r2, .. } = c {
                let d2 = (p64.x - cx).powi(2) + (p64.y - cy).powi(2);
                if (d2 - r2).abs() <= 1e-4 * r2.max(1.0) {
                    continue;
                }
            }
            let [x, y, covered, _] = gpu[i * points.len() + j];
            match (c.inverse(p64), covered == 1.0) {
                (None, true) => {}
                (Some(q), false) => {
                    let err = (q - Point::new(f64::from(x), f64::from(y))).hypot()
                        / q.to_vec2().hypot().max(1.0);
                    worst = worst.max(err);
                    compared += 1;
                }
                _ => other_answer += 1,
            }
        }
    }
    eprintln!(
        "{kind:?}: {compared} points compared, worst relative error {worst:e}, {other_answer} other ink answers"
    );
    (other_answer, worst)
}

/// Six flows (random designs hold none): Perlin and value noise, one to four octaves,
/// times of either sign, 30 to 330 sub-steps.
fn flows() -> Vec<marbling_core::Op> {
    (0..6u32)
        .map(|k| {
            marbling_core::Op::Flow(marbling_core::Flow {
                noise: marbling_noise::FbmParams {
                    basis: if k.is_multiple_of(2) {
                        marbling_noise::Basis::Perlin
                    } else {
                        marbling_noise::Basis::Value
                    },
                    frequency: 1.0 / (30.0 + 25.0 * k as f32),
                    octaves: 1 + k % 4,
                    seed: 1000 * k + 7,
                    ..marbling_noise::FbmParams::default()
                },
                strength: 8.0 + 4.0 * f64::from(k),
                time: if k.is_multiple_of(3) { -1.0 } else { 1.3 },
            })
        })
        .collect()
}

/// The per-kind test: the same ink answers, positions within 1e-4 relative.
fn wgsl_inverse_matches_cpu(kind: marbling_core::OpKind) {
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    let shaders = marbling_gpu::shaders::walk_wgsl();
    let (other_answer, worst) = inverse_errors(&ctx, &shaders, kind);
    assert_eq!(
        other_answer, 0,
        "{kind:?}: the GPU put points in or out of ink wrongly"
    );
    assert!(worst <= 1e-4, "{kind:?}: relative error {worst:e} > 1e-4");
}

/// The comparison sees a mistake: a drop inverse with 0.1 % of r² missing, a wave whose
/// phase is off by 0.01 rad, a finite comb that skips its last tine record, a stylus
/// sub-step walked forward instead of back, a flow whose octaves draw the wrong seeds or
/// whose velocity is 1 % too fast.
#[test]
fn a_wrong_wgsl_inverse_is_caught() {
    let Some(ctx) = marbling_testkit::gpu_or_skip(GpuContext::new_headless()) else {
        return;
    };
    let shaders = marbling_gpu::shaders::walk_wgsl();
    for (kind, right, wrong) in [
        (
            marbling_core::OpKind::Drop,
            "sqrt(1.0 - a.w / d2)",
            "sqrt(1.0 - 0.999 * a.w / d2)",
        ),
        (
            marbling_core::OpKind::Wave,
            "dot(p, n) + b.y)",
            "dot(p, n) + b.y + 0.01)",
        ),
        (
            marbling_core::OpKind::Tines,
            "r < i; r++",
            "r + 1u < i; r++",
        ),
        (
            marbling_core::OpKind::Stylus,
            "stylus_sub_step(q, -0.5 * delta",
            "stylus_sub_step(q, 0.5 * delta",
        ),
        (
            marbling_core::OpKind::Flow,
            "seed0 + o * 0x9E3779B9u",
            "seed0 + o * 0x9E3779B1u",
        ),
        (
            marbling_core::OpKind::Flow,
            "c * vec2<f32>(g.y, -g.x)",
            "c * vec2<f32>(g.y, -g.x) * 1.01",
        ),
    ] {
        assert!(shaders.contains(right), "{right} is not in the shaders");
        let broken = shaders.replacen(right, wrong, 1);
        let (other, worst) = inverse_errors(&ctx, &broken, kind);
        assert!(
            worst > 1e-4 || other > 0,
            "{kind:?}: a wrong inverse passed ({worst:e})"
        );
    }
}

#[test]
fn wgsl_inverse_of_flow_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Flow);
}

#[test]
fn wgsl_inverse_of_drop_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Drop);
}

#[test]
fn wgsl_inverse_of_spray_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Spray);
}

#[test]
fn wgsl_inverse_of_comb_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Comb);
}

#[test]
fn wgsl_inverse_of_wave_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Wave);
}

#[test]
fn wgsl_inverse_of_circular_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Circular);
}

#[test]
fn wgsl_inverse_of_vortex_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Vortex);
}

#[test]
fn wgsl_inverse_of_rigid_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Rigid);
}

#[test]
fn wgsl_inverse_of_tines_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Tines);
}

#[test]
fn wgsl_inverse_of_jiggle_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Jiggle);
}

#[test]
fn wgsl_inverse_of_stylus_matches_cpu() {
    wgsl_inverse_matches_cpu(marbling_core::OpKind::Stylus);
}
