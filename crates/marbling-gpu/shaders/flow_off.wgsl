// Stand-in for flow.wgsl in the exact renderer's v3 variants for designs without a
// flow: `flow_back` is never called there, so no noise code is compiled.

fn flow_back(i: u32, h: OpRecord, p: vec2<f32>) -> vec2<f32> {
    return p;
}
