// The exact renderer as a compute pass (appended to render.wgsl's module): one
// invocation per target pixel runs the same `shade` as the fragment entry and stores the
// result. Used where compute shaders exist (native, WebGPU): some GPUs run fragment work
// on a small part of the chip (an NVIDIA H100 has graphics on 4 of its 132 SMs).

// The target, `Rgba8Unorm`: the shader encodes sRGB itself (params.encode_srgb == 1).
@group(1) @binding(0) var target_texture: texture_storage_2d<rgba8unorm, write>;

@compute @workgroup_size(8, 8)
fn cs_main(@builtin(global_invocation_id) id: vec3<u32>) {
    let size = textureDimensions(target_texture);
    if id.x >= size.x || id.y >= size.y {
        return;
    }
    textureStore(target_texture, vec2<i32>(id.xy), shade(vec2<f32>(id.xy)));
}
