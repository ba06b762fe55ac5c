// Test-only entry point (tests/compute.rs appends it to shaders/common.wgsl): walks
// every point back through every op with `op_back`, one invocation per (point, op).

struct OpRecord {
    a: vec4<f32>,
    b: vec4<f32>,
}

@group(0) @binding(0) var<storage, read> ops: array<OpRecord>;
@group(0) @binding(1) var<storage, read> points: array<vec2<f32>>;
// out[op · point count + point] = op_back(op, point)
@group(0) @binding(2) var<storage, read_write> out: array<vec4<f32>>;

@compute @workgroup_size(64)
fn cs_op_back(@builtin(global_invocation_id) id: vec3<u32>) {
    let n = arrayLength(&points);
    if id.x >= n {
        return;
    }
    let op = ops[id.y];
    out[id.y * n + id.x] = vec4<f32>(op_back(op.a, op.b, points[id.x]), 0.0);
}
