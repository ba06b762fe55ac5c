// Stand-in for flow.wgsl in the exact renderer's variants for designs without a flow:
// `flow_back` is never called there, so no noise code is compiled, and render.wgsl's
// turbulence (which needs a flow) folds away with `FLOW_ENABLED`.

const FLOW_ENABLED: bool = false;

fn flow_back(i: u32, h: OpRecord, p: vec2<f32>) -> vec2<f32> {
    return p;
}
