// transfer.wgsl — noise to intensity and colour: default grey map, smoothstep threshold,
// Khlebnikov et al. (2013)'s cubic spline decay and HSV value blend (keep in sync with
// crates/marbling-noise/src/transfer.rs and render.rs).

// 0.5 + n/6 clamped: +-3 sigma spans black to white.
fn noise_to_grey(n: f32) -> f32 {
    return clamp(0.5 + n / 6.0, 0.0, 1.0);
}

fn threshold_transfer(n: f32, threshold: f32, width: f32, invert: bool) -> f32 {
    let s = smoothstep(threshold - 0.5 * width, threshold + 0.5 * width, n);
    if invert {
        return 1.0 - s;
    }
    return s;
}

// D(t) = (2q/g^3)|t|^3 - (3q/g^2)t^2 + q on [-g, g], 0 outside.
fn spline_decay(t: f32, gamma: f32, q: f32) -> f32 {
    let a = abs(t);
    if a > gamma || gamma <= 0.0 {
        return 0.0;
    }
    return q * (2.0 * a * a * a / (gamma * gamma * gamma) - 3.0 * a * a / (gamma * gamma) + 1.0);
}

fn rgb_to_hsv(c: vec3<f32>) -> vec3<f32> {
    let mx = max(c.r, max(c.g, c.b));
    let mn = min(c.r, min(c.g, c.b));
    let d = mx - mn;
    var h = 0.0;
    if d > 0.0 {
        if mx == c.r {
            let x = (c.g - c.b) / d;
            h = (x - 6.0 * floor(x / 6.0)) / 6.0;
        } else if mx == c.g {
            h = ((c.b - c.r) / d + 2.0) / 6.0;
        } else {
            h = ((c.r - c.g) / d + 4.0) / 6.0;
        }
    }
    var s = 0.0;
    if mx > 0.0 {
        s = d / mx;
    }
    return vec3<f32>(h, s, mx);
}

fn hsv_to_rgb(hsv: vec3<f32>) -> vec3<f32> {
    let h6 = (hsv.x - floor(hsv.x)) * 6.0;
    let c = hsv.z * hsv.y;
    let x = c * (1.0 - abs(h6 - 2.0 * floor(h6 / 2.0) - 1.0));
    let sector = u32(h6);
    var rgb = vec3<f32>(c, 0.0, x);
    if sector == 0u {
        rgb = vec3<f32>(c, x, 0.0);
    } else if sector == 1u {
        rgb = vec3<f32>(x, c, 0.0);
    } else if sector == 2u {
        rgb = vec3<f32>(0.0, c, x);
    } else if sector == 3u {
        rgb = vec3<f32>(0.0, x, c);
    } else if sector == 4u {
        rgb = vec3<f32>(x, 0.0, c);
    }
    return rgb + vec3<f32>(hsv.z - c);
}

// Keeps hue and saturation; value = beta * C_v + (1 - beta) * intensity.
fn hsv_value_blend(color: vec3<f32>, intensity: f32, beta: f32) -> vec3<f32> {
    let hsv = rgb_to_hsv(color);
    return hsv_to_rgb(vec3<f32>(hsv.x, hsv.y, beta * hsv.z + (1.0 - beta) * clamp(intensity, 0.0, 1.0)));
}
