// Stand-in for flow.wgsl in the exact renderer's variants for designs without a flow
// (render.wgsl's turbulence needs one): `flow_back` is never called there, so no noise
// code is compiled.

fn flow_back(i: u32, h: OpRecord, p: vec2<f32>) -> vec2<f32> {
    return p;
}
