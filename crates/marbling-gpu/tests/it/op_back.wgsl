// Test-only entry point (tests/compute.rs appends it to shaders/common.wgsl and
// shaders/records.wgsl): walks every point back through every op's records with
// `walk_records`, one invocation per (point, op).

@group(0) @binding(0) var<storage, read> records: array<OpRecord>;
// Op k's records are records[ranges[k].x .. ranges[k].y].
@group(0) @binding(1) var<storage, read> ranges: array<vec2<u32>>;
@group(0) @binding(2) var<storage, read> points: array<vec2<f32>>;
// out[op · point count + point] = (x, y, covered, 0)
@group(0) @binding(3) var<storage, read_write> out: array<vec4<f32>>;

fn op_record(i: u32) -> OpRecord {
    return records[i];
}

@compute @workgroup_size(64)
fn cs_op_back(@builtin(global_invocation_id) id: vec3<u32>) {
    let n = arrayLength(&points);
    if id.x >= n {
        return;
    }
    let range = ranges[id.y];
    let e = walk_records(range.x, range.y, points[id.x]);
    out[id.y * n + id.x] = vec4<f32>(e.p, select(0.0, 1.0, e.covered), 0.0);
}
