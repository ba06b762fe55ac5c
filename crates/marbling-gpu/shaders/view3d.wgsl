// The 3D view (appended to a render module, see src/view3d.rs): each sample's ray meets
// the object, its texture coordinates give a design point, and `trace` walks that point
// back through every op — never a baked texture, unless `lens.w` asks for one, for
// comparison. Keep in sync with marbling-core's view3d module (conventions there).

// Keep in sync with `View3dParams` in src/view3d.rs (checked by tests/layout.rs).
struct View3dParams {
    // Camera position, unit forward, right and up (w unused).
    origin: vec4<f32>,
    forward: vec4<f32>,
    right: vec4<f32>,
    up: vec4<f32>,
    // tan(fov/2), design aspect W/H, shape code, source (0: exact walk, 1: the baked
    // texture holds linear light, 2: it holds sRGB-encoded values).
    lens: vec4<f32>,
    // Frame width and height (output pixels), design width and height (design pixels).
    frame: vec4<f32>,
    // Linear paper, pages and backdrop (top, bottom) colours.
    paper: vec4<f32>,
    pages: vec4<f32>,
    backdrop_top: vec4<f32>,
    backdrop_bottom: vec4<f32>,
    // Ambient share, spine shade, inside shade, book half-depth.
    shading: vec4<f32>,
    // Vase bound radius, march steps, bisection steps, cylinder half-height.
    shape: vec4<f32>,
    // Displacement: amplitude s (0: none), frequency f, octaves, lacunarity.
    displace: vec4<f32>,
    // Persistence, offset o (x, y, z).
    displace_fbm: vec4<f32>,
    // What the march's bounding volume adds to the object's extent (s·bound + margin),
    // march steps, bisection steps, the normal's finite-difference step.
    displace_march: vec4<f32>,
    // The style's blend (0: none, 1: ink, 2: multiply, 3: overlay), the rest unused.
    style: vec4<f32>,
    // The style's ink, sRGB in [0, 1].
    style_ink: vec4<f32>,
}

@group(1) @binding(0) var<uniform> view3d: View3dParams;
// The design baked into a raster (lens.w > 0); 1×1 otherwise.
@group(1) @binding(1) var baked: texture_2d<f32>;
// The style field (style.x > 0): coverage, the overlay grey's byte/255, 0, 1 per pixel.
@group(1) @binding(2) var style_field: texture_2d<f32>;

const PI: f32 = 3.14159265358979;
const MAT_DESIGN: u32 = 0u;
const MAT_PAPER: u32 = 1u;
const MAT_PAGES: u32 = 2u;
const MAT_SPINE: u32 = 3u;
const MAT_INSIDE: u32 = 4u;
// Seed of the displacement noise and the margin of its march's bounding volume
// (marbling-core's view3d::displace::SEED and BOUND_MARGIN).
const DISPLACE_SEED: u32 = 3u;
const DISPLACE_MARGIN: f32 = 1e-3;

// A ray's hit: t < 0 for none.
struct Hit3 {
    t: f32,
    normal: vec3<f32>,
    uv: vec2<f32>,
    material: u32,
}

fn no_hit() -> Hit3 {
    return Hit3(-1.0, vec3<f32>(0.0), vec2<f32>(0.0), 0u);
}

fn nearer(a: Hit3, b: Hit3) -> Hit3 {
    if a.t < 0.0 || (b.t >= 0.0 && b.t < a.t) {
        return b;
    }
    return a;
}

fn around(p: vec3<f32>) -> f32 {
    return 0.5 + atan2(p.x, p.z) / (2.0 * PI);
}

fn vase_radius(y: f32) -> f32 {
    let belly = exp(-pow((y + 0.25) / 0.42, 2.0));
    let t = clamp((y - 0.55) / 0.45, 0.0, 1.0);
    return 0.30 + 0.30 * belly + 0.10 * t * t * (3.0 - 2.0 * t);
}

fn cap(o: vec3<f32>, d: vec3<f32>, y: f32, radius: f32, material: u32) -> Hit3 {
    if d.y == 0.0 {
        return no_hit();
    }
    let t = (y - o.y) / d.y;
    let p = o + d * t;
    if t > 0.0 && dot(p.xz, p.xz) <= radius * radius {
        return Hit3(t, vec3<f32>(0.0, sign(y), 0.0), vec2<f32>(0.0), material);
    }
    return no_hit();
}

fn hit_plane(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let a = view3d.lens.y;
    if d.z == 0.0 {
        return no_hit();
    }
    let t = -o.z / d.z;
    let p = o + d * t;
    if t > 0.0 && abs(p.x) <= a && abs(p.y) <= 1.0 {
        return Hit3(t, vec3<f32>(0.0, 0.0, 1.0), vec2<f32>((p.x + a) / (2.0 * a), (1.0 - p.y) / 2.0), MAT_DESIGN);
    }
    return no_hit();
}

fn hit_sphere(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let b = dot(o, d);
    let disc = b * b - (dot(o, o) - 1.0);
    if disc < 0.0 {
        return no_hit();
    }
    var t = -b - sqrt(disc);
    if t <= 0.0 {
        t = -b + sqrt(disc);
    }
    if t <= 0.0 {
        return no_hit();
    }
    let p = o + d * t;
    return Hit3(t, p, vec2<f32>(around(p), acos(clamp(p.y, -1.0, 1.0)) / PI), MAT_DESIGN);
}

fn hit_cylinder(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let h = view3d.shape.w;
    var best = no_hit();
    let a = dot(d.xz, d.xz);
    let b = dot(o.xz, d.xz);
    let c = dot(o.xz, o.xz) - 1.0;
    let disc = b * b - a * c;
    if a > 0.0 && disc >= 0.0 {
        for (var k = 0; k < 2; k++) {
            let t = (-b + (f32(k) * 2.0 - 1.0) * sqrt(disc)) / a;
            let p = o + d * t;
            if t > 0.0 && abs(p.y) <= h {
                best = Hit3(t, vec3<f32>(p.x, 0.0, p.z), vec2<f32>(around(p), (h - p.y) / (2.0 * h)), MAT_DESIGN);
                break;
            }
        }
    }
    best = nearer(best, cap(o, d, h, 1.0, MAT_PAPER));
    return nearer(best, cap(o, d, -h, 1.0, MAT_PAPER));
}

fn vase_gap(p: vec3<f32>) -> f32 {
    return length(p.xz) - vase_radius(p.y);
}

fn hit_vase(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let bound = view3d.shape.x;
    let a = dot(d.xz, d.xz);
    let b = dot(o.xz, d.xz);
    let c = dot(o.xz, o.xz) - bound * bound;
    let disc = b * b - a * c;
    if a <= 0.0 || disc < 0.0 {
        return no_hit();
    }
    var t0 = (-b - sqrt(disc)) / a;
    var t1 = (-b + sqrt(disc)) / a;
    if d.y != 0.0 {
        let s0 = (-1.0 - o.y) / d.y;
        let s1 = (1.0 - o.y) / d.y;
        t0 = max(t0, min(s0, s1));
        t1 = min(t1, max(s0, s1));
    } else if abs(o.y) > 1.0 {
        return no_hit();
    }
    t0 = max(t0, 0.0);
    var side = no_hit();
    if t0 < t1 {
        let steps = u32(view3d.shape.y);
        let step = (t1 - t0) / f32(steps);
        var prev = t0;
        var outside = vase_gap(o + d * t0) > 0.0;
        for (var i = 1u; i <= steps; i++) {
            let t = t0 + step * f32(i);
            let now = vase_gap(o + d * t) > 0.0;
            if outside && !now {
                var lo = prev;
                var hi = t;
                for (var k = 0u; k < u32(view3d.shape.z); k++) {
                    let mid = 0.5 * (lo + hi);
                    if vase_gap(o + d * mid) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let p = o + d * hi;
                let slope = (vase_radius(p.y + 1e-3) - vase_radius(p.y - 1e-3)) / 2e-3;
                let rho = max(length(p.xz), 1e-12);
                let n = normalize(vec3<f32>(p.x / rho, -slope, p.z / rho));
                side = Hit3(hi, n, vec2<f32>(around(p), (1.0 - p.y) / 2.0), MAT_DESIGN);
                break;
            }
            prev = t;
            outside = now;
        }
    }
    let top = cap(o, d, 1.0, vase_radius(1.0), MAT_INSIDE);
    let base = cap(o, d, -1.0, vase_radius(-1.0), MAT_PAPER);
    return nearer(nearer(side, top), base);
}

fn hit_book(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let a = view3d.lens.y;
    let half = vec3<f32>(a, 1.0, view3d.shading.w);
    var near = -3.0e38;
    var far = 3.0e38;
    var axis = 0;
    for (var k = 0; k < 3; k++) {
        if d[k] == 0.0 {
            if abs(o[k]) > half[k] {
                return no_hit();
            }
            continue;
        }
        let ta = (-half[k] - o[k]) / d[k];
        let tb = (half[k] - o[k]) / d[k];
        let lo = min(ta, tb);
        if lo > near {
            near = lo;
            axis = k;
        }
        far = min(far, max(ta, tb));
    }
    if near > far || near <= 0.0 {
        return no_hit();
    }
    let p = o + d * near;
    if axis == 2 && p.z > 0.0 {
        return Hit3(near, vec3<f32>(0.0, 0.0, 1.0), vec2<f32>((p.x + a) / (2.0 * a), (1.0 - p.y) / 2.0), MAT_DESIGN);
    }
    if axis == 2 {
        return Hit3(near, vec3<f32>(0.0, 0.0, -1.0), vec2<f32>((a - p.x) / (2.0 * a), (1.0 - p.y) / 2.0), MAT_DESIGN);
    }
    if axis == 0 && p.x < 0.0 {
        return Hit3(near, vec3<f32>(-1.0, 0.0, 0.0), vec2<f32>(0.0), MAT_SPINE);
    }
    if axis == 0 {
        return Hit3(near, vec3<f32>(1.0, 0.0, 0.0), vec2<f32>(0.0), MAT_PAGES);
    }
    return Hit3(near, vec3<f32>(0.0, sign(p.y), 0.0), vec2<f32>(0.0), MAT_PAGES);
}

// The height s·fbm((p + o)·f) of surface point p.
fn displace_height(p: vec3<f32>) -> f32 {
    let q = (p + view3d.displace_fbm.yzw) * view3d.displace.y;
    return view3d.displace.x * fbm3(q, u32(view3d.displace.z), view3d.displace.w, view3d.displace_fbm.x, DISPLACE_SEED);
}

// The displaced surface's normal at foot p (undisplaced normal n): displace p, p + ε·t
// and p + ε·b the same way and cross (Kung 2019). One call of the noise, in a loop.
fn displaced_normal(p: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    var t = cross(n, vec3<f32>(0.0, 1.0, 0.0));
    if length(t) < 1e-6 {
        t = vec3<f32>(1.0, 0.0, 0.0);
    } else {
        t = normalize(t);
    }
    let b = cross(n, t);
    let e = view3d.displace_march.w;
    var moved: array<vec3<f32>, 3>;
    for (var k = 0u; k < 3u; k++) {
        var q = p;
        if k == 1u {
            q = p + t * e;
        } else if k == 2u {
            q = p + b * e;
        }
        moved[k] = q + n * displace_height(q);
    }
    let m = normalize(cross(moved[1] - moved[0], moved[2] - moved[0]));
    if dot(m, n) < 0.0 {
        return -m;
    }
    return m;
}

// A displaced object's gap at a point (≤ 0 inside; the plane's: z − h, 3e38 off its
// rectangle) and the face nearest there: a design face (foot point, normal, uv) or a
// flat one (material, normal).
struct Gap {
    g: f32,
    material: u32,
    foot: vec3<f32>,
    normal: vec3<f32>,
    uv: vec2<f32>,
}

fn outer(a: Gap, b: Gap) -> Gap {
    if b.g > a.g {
        return b;
    }
    return a;
}

fn flat_gap(g: f32, material: u32, normal: vec3<f32>) -> Gap {
    return Gap(g, material, vec3<f32>(0.0), normal, vec2<f32>(0.0));
}

// The design face before the displacement, intersected with `flat` below.
fn displaced_gap(x: vec3<f32>) -> Gap {
    let shape = u32(view3d.lens.z);
    let a = view3d.lens.y;
    var side = Gap(0.0, MAT_DESIGN, vec3<f32>(x.x, x.y, 0.0), vec3<f32>(0.0, 0.0, 1.0), vec2<f32>((x.x + a) / (2.0 * a), (1.0 - x.y) / 2.0));
    var flat = flat_gap(-3.0e38, MAT_PAPER, vec3<f32>(0.0));
    if shape == 0u {
        let r = max(length(x), 1e-12);
        let foot = x / r;
        side = Gap(r - 1.0, MAT_DESIGN, foot, foot, vec2<f32>(around(foot), acos(clamp(foot.y, -1.0, 1.0)) / PI));
    } else if shape == 1u || shape == 2u {
        var radius = 1.0;
        var slope = 0.0;
        var v = 0.0;
        let y = clamp(x.y, -1.0, 1.0);
        if shape == 1u {
            radius = vase_radius(y);
            slope = (vase_radius(y + 1e-3) - vase_radius(y - 1e-3)) / 2e-3;
            v = (1.0 - y) / 2.0;
            flat = flat_gap(abs(x.y) - 1.0, MAT_PAPER, vec3<f32>(0.0, -1.0, 0.0));
            if x.y > 0.0 {
                flat = flat_gap(abs(x.y) - 1.0, MAT_INSIDE, vec3<f32>(0.0, 1.0, 0.0));
            }
        } else {
            let h = view3d.shape.w;
            v = (h - x.y) / (2.0 * h);
            flat = flat_gap(abs(x.y) - h, MAT_PAPER, vec3<f32>(0.0, sign(x.y), 0.0));
        }
        let rho = length(x.xz);
        var s = vec2<f32>(0.0, 1.0);
        if rho > 1e-12 {
            s = x.xz / rho;
        }
        let foot = vec3<f32>(radius * s.x, x.y, radius * s.y);
        let normal = normalize(vec3<f32>(s.x, -slope, s.y));
        side = Gap((rho - radius) / sqrt(1.0 + slope * slope), MAT_DESIGN, foot, normal, vec2<f32>(around(foot), v));
    } else if shape == 3u {
        let depth = view3d.shading.w;
        var face = 1.0;
        if x.z < 0.0 {
            face = -1.0;
        }
        // The back cover shows the design mirrored (a wrap-around cover).
        side = Gap(face * x.z - depth, MAT_DESIGN, vec3<f32>(x.x, x.y, face * depth), vec3<f32>(0.0, 0.0, face), vec2<f32>((face * x.x + a) / (2.0 * a), (1.0 - x.y) / 2.0));
        var edge = MAT_PAGES;
        if x.x < 0.0 {
            edge = MAT_SPINE;
        }
        flat = outer(
            flat_gap(abs(x.x) - a, edge, vec3<f32>(sign(x.x), 0.0, 0.0)),
            flat_gap(abs(x.y) - 1.0, MAT_PAGES, vec3<f32>(0.0, sign(x.y), 0.0)),
        );
    } else {
        if abs(x.x) > a || abs(x.y) > 1.0 {
            return flat_gap(3.0e38, MAT_DESIGN, vec3<f32>(0.0));
        }
        side.g = x.z;
    }
    side.g -= displace_height(side.foot);
    return outer(side, flat);
}

// The first hit on the displaced object (see marbling-core's view3d::displace): the
// first sign change of the gap along the march, refined by bisection, in one loop with
// one call of `displaced_gap`.
// The ray's span inside the box or upright cylinder holding the displaced object (its
// extent grown by the reach and a margin); x > y when it misses.
fn march_span(o: vec3<f32>, d: vec3<f32>) -> vec2<f32> {
    let shape = u32(view3d.lens.z);
    let grow = view3d.displace_march.x;
    let margin = DISPLACE_MARGIN;
    var lo = vec3<f32>(-3.0e38);
    var hi = vec3<f32>(3.0e38);
    var span = vec2<f32>(0.0, 3.0e38);
    if shape == 0u {
        let r = 1.0 + grow;
        let b = dot(o, d);
        let disc = b * b - (dot(o, o) - r * r);
        if disc < 0.0 {
            return vec2<f32>(1.0, 0.0);
        }
        span = vec2<f32>(max(-b - sqrt(disc), 0.0), -b + sqrt(disc));
    } else if shape == 1u || shape == 2u {
        var r = 1.0 + grow;
        var h = view3d.shape.w;
        if shape == 1u {
            r = view3d.shape.x + grow;
            h = 1.0;
        }
        let a = dot(d.xz, d.xz);
        let b = dot(o.xz, d.xz);
        let disc = b * b - a * (dot(o.xz, o.xz) - r * r);
        if a > 0.0 {
            if disc < 0.0 {
                return vec2<f32>(1.0, 0.0);
            }
            span = vec2<f32>(max((-b - sqrt(disc)) / a, 0.0), (-b + sqrt(disc)) / a);
        } else if dot(o.xz, o.xz) > r * r {
            return vec2<f32>(1.0, 0.0);
        }
        lo = vec3<f32>(-3.0e38, -h - margin, -3.0e38);
        hi = -lo;
    } else {
        var depth = grow;
        if shape == 3u {
            depth = view3d.shading.w + grow;
        }
        hi = vec3<f32>(view3d.lens.y + margin, 1.0 + margin, depth);
        lo = -hi;
    }
    for (var k = 0; k < 3; k++) {
        if hi[k] > 1.0e38 {
            continue;
        }
        if d[k] == 0.0 {
            if o[k] < lo[k] || o[k] > hi[k] {
                return vec2<f32>(1.0, 0.0);
            }
            continue;
        }
        let ta = (lo[k] - o[k]) / d[k];
        let tb = (hi[k] - o[k]) / d[k];
        span = vec2<f32>(max(span.x, min(ta, tb)), min(span.y, max(ta, tb)));
    }
    return span;
}

// The first hit on the displaced object (see marbling-core's view3d::displace): the
// first sign change of the gap along the march, refined by bisection, in one loop with
// one call of `displaced_gap`.
fn hit_displaced(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let span = march_span(o, d);
    let t0 = span.x;
    let t1 = span.y;
    if t1 <= t0 {
        return no_hit();
    }
    let steps = u32(view3d.displace_march.y);
    let bisections = u32(view3d.displace_march.z);
    let step = (t1 - t0) / f32(steps);
    var prev = 0.0;
    var found = false;
    var lo = t0;
    var hi = t0;
    var at_hi = flat_gap(0.0, MAT_PAPER, vec3<f32>(0.0));
    var halvings = 0u;
    for (var i = 0u; i <= steps + bisections; i++) {
        var t = t0 + step * f32(i);
        if found {
            t = 0.5 * (lo + hi);
        }
        let g = displaced_gap(o + d * t);
        if found {
            if g.g < 1.0e38 && (g.g > 0.0) == (prev > 0.0) {
                lo = t;
            } else {
                hi = t;
                at_hi = g;
            }
            halvings++;
            if halvings == bisections {
                break;
            }
        } else if i > 0u && prev < 1.0e38 && g.g < 1.0e38 && (prev > 0.0) != (g.g > 0.0) {
            found = true;
            lo = t - step;
            hi = t;
            at_hi = g;
        } else {
            prev = g.g;
            if i == steps {
                return no_hit();
            }
        }
    }
    if at_hi.material == MAT_DESIGN {
        return Hit3(hi, displaced_normal(at_hi.foot, at_hi.normal), at_hi.uv, MAT_DESIGN);
    }
    return Hit3(hi, at_hi.normal, vec2<f32>(0.0), at_hi.material);
}

fn hit_object(o: vec3<f32>, d: vec3<f32>) -> Hit3 {
    let shape = u32(view3d.lens.z);
    var h: Hit3;
    if view3d.displace.x != 0.0 && view3d.displace.y != 0.0 {
        h = hit_displaced(o, d);
        if dot(h.normal, d) > 0.0 {
            h.normal = -h.normal;
        }
        return h;
    }
    switch shape {
        case 0u: { h = hit_sphere(o, d); }
        case 1u: { h = hit_vase(o, d); }
        case 2u: { h = hit_cylinder(o, d); }
        case 3u: { h = hit_book(o, d); }
        default: { h = hit_plane(o, d); }
    }
    if dot(h.normal, d) > 0.0 {
        h.normal = -h.normal;
    }
    return h;
}

// Texel i of the baked texture in linear light (decoded when stored sRGB-encoded).
fn baked_texel(i: vec2<i32>) -> vec3<f32> {
    let size = vec2<i32>(textureDimensions(baked));
    let rgb = textureLoad(baked, clamp(i, vec2<i32>(0), size - 1), 0).rgb;
    if view3d.lens.w > 1.5 {
        return srgb_to_linear(rgb);
    }
    return rgb;
}

// Linear colour of the baked texture at texture coordinates uv (bilinear in linear
// light between texel centres, clamped), as marbling-core's texture mode.
fn baked_color(uv: vec2<f32>) -> vec3<f32> {
    let f = uv * vec2<f32>(textureDimensions(baked)) - 0.5;
    let base = floor(f);
    let t = f - base;
    let i = vec2<i32>(base);
    let top = mix(baked_texel(i), baked_texel(i + vec2<i32>(1, 0)), t.x);
    let bottom = mix(baked_texel(i + vec2<i32>(0, 1)), baked_texel(i + vec2<i32>(1, 1)), t.x);
    return mix(top, bottom, t.y);
}

// Linear colour and source (the ink's packed colour, or a negative code for faces
// and the backdrop) of output point `pixel` (pixels from the frame's top-left).
fn sample3d(pixel: vec2<f32>) -> vec4<f32> {
    let w = view3d.frame.x;
    let h = view3d.frame.y;
    let k = view3d.lens.x;
    let sx = (pixel.x - 0.5 * w) / (0.5 * h) * k;
    let sy = (0.5 * h - pixel.y) / (0.5 * h) * k;
    let d = normalize(view3d.forward.xyz + view3d.right.xyz * sx + view3d.up.xyz * sy);
    let hit = hit_object(view3d.origin.xyz, d);
    if hit.t < 0.0 {
        let t = clamp(pixel.y / h, 0.0, 1.0);
        return vec4<f32>(mix(view3d.backdrop_top.rgb, view3d.backdrop_bottom.rgb, t), -1.0);
    }
    var c = vec4<f32>(view3d.paper.rgb, -2.0);
    switch hit.material {
        case 0u: {
            if view3d.lens.w > 0.5 {
                c = vec4<f32>(baked_color(hit.uv), -3.0);
            } else {
                c = trace(hit.uv * view3d.frame.zw);
            }
        }
        case 2u: { c = vec4<f32>(view3d.pages.rgb, -2.0); }
        case 3u: { c = vec4<f32>(view3d.paper.rgb * view3d.shading.y, -2.0); }
        case 4u: { c = vec4<f32>(view3d.paper.rgb * view3d.shading.z, -2.0); }
        default: {}
    }
    let ambient = view3d.shading.x;
    let light = ambient + (1.0 - ambient) * max(dot(hit.normal, -view3d.forward.xyz), 0.0);
    return vec4<f32>(c.rgb * light, c.w);
}

// Weighted average of samples[start .. start + count] of pixel `pixel` (top-left
// corner): (r, g, b, 1 when the samples came from different sources else 0).
fn average3d(pixel: vec2<f32>, start: u32, count: u32) -> vec4<f32> {
    var acc = vec3<f32>(0.0);
    var source = 0.0;
    var mixed = 0.0;
    for (var i = 0u; i < count; i++) {
        let s = params.samples[start + i];
        let c = sample3d(pixel + s.xy);
        acc += s.z * c.rgb;
        if i == 0u {
            source = c.w;
        } else if c.w != source {
            mixed = 1.0;
        }
    }
    return vec4<f32>(acc, mixed);
}

@fragment
fn fs_view3d(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let pixel = floor(position.xy);
    var r = average3d(pixel, 0u, params.first_count);
    if r.w > 0.5 && params.refine_count > 0u {
        r = average3d(pixel, params.first_count, params.refine_count);
    }
    if view3d.style.x > 0.5 {
        let field = textureLoad(style_field, vec2<i32>(pixel), 0);
        let s = clamp(styled(linear_to_srgb(r.rgb), field), vec3<f32>(0.0), vec3<f32>(1.0));
        if params.encode_srgb == 0u {
            return vec4<f32>(srgb_to_linear(s), 1.0);
        }
        return vec4<f32>(s, 1.0);
    }
    if params.encode_srgb == 0u {
        return vec4<f32>(r.rgb, 1.0);
    }
    return vec4<f32>(linear_to_srgb(r.rgb), 1.0);
}

// A pixel's sRGB colour under the style: marbling-core's view3d::style::blend_pixel, the
// grey decoded as byte_grey (½ + (b − 128)/254).
fn styled(base: vec3<f32>, field: vec4<f32>) -> vec3<f32> {
    let c = field.x;
    let g = 0.5 + (field.y * 255.0 - 128.0) / 254.0;
    let ink = view3d.style_ink.rgb;
    let blend = u32(view3d.style.x + 0.5);
    if blend == 1u {
        return base + (ink - base) * c;
    }
    if blend == 2u {
        return base * (1.0 - c + c * ink);
    }
    return select(1.0 - 2.0 * (1.0 - base) * (1.0 - g), 2.0 * base * g, base < vec3<f32>(0.5));
}
