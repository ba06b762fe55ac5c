// gabor_drive_off.wgsl — stand-in for gabor_drive.wgsl in modules whose Gabor noises
// are not driven (`g.drives` is 0 there): no fBm is compiled.

fn gabor_drive(ip: vec2<f32>, g: GaborParams, orientation_drive: FbmParams, frequency_drive: FbmParams) -> vec2<f32> {
    return vec2<f32>(0.0, 0.0);
}
