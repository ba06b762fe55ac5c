// gabor_drive.wgsl — the driving fBms of a Gabor noise at an impulse (see gabor.wgsl):
// (orientation fBm, frequency fBm), 0 where not driven. Needs fbm.wgsl.

// Both drives go through one call site of `fbm`: a software GPU's compiler inlines each
// call, with Perlin and value noise inside each octave loop.
fn gabor_drive(ip: vec2<f32>, g: GaborParams, orientation_drive: FbmParams, frequency_drive: FbmParams) -> vec2<f32> {
    var drive = vec2<f32>(0.0, 0.0);
    for (var d = 0u; d < 2u; d = d + 1u) {
        if (g.drives & (1u << d)) != 0u && !(d == 0u && g.kind == 1u) {
            var fp = orientation_drive;
            if d == 1u {
                fp = frequency_drive;
            }
            drive[d] = fbm(ip, fp);
        }
    }
    return drive;
}
