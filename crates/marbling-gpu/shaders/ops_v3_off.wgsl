// Stand-in for ops_v3.wgsl in the exact renderer's variants for designs without schema
// v3 ops: `v3_back` is never called there, so none of their code is compiled.

const V3_ENABLED: bool = false;

fn v3_back(at: u32, r: OpRecord, p: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(p, 1.0);
}
