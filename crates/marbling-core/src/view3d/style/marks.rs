//! Dynamic Gabor noise on the surface (Bénard et al. 2010, §3): kernels whose frequency,
//! bandwidth, orientation and density are in screen pixels, centred on surface points
//! drawn per patch, so the noise looks flat yet moves with the object.
//!
//! Per patch, N = λ·A (λ = N₀/(πR²) kernels per pixel², A its screen area), and the patch's
//! stream draws 2M points with M = 2^⌊log₂N⌋, the first M weighted 1 and the next M
//! weighted α = √(N/M − 1) ([`marbling_noise::lod_weights`]); N < 1 draws one point
//! weighted N. The stream is prefix-stable (point k always comes from the same draws), so
//! as the object nears, the points only gain weight and company — nothing pops. A kernel
//! is drawn only if its centre is what the frame shows at its pixel; it reaches the pixels
//! of the object within its radius whose depth passes the [`DepthTest`]. The sum is
//! divided by the analytic standard deviation ([`GaborParams::variance`]), so the noise
//! has unit variance whatever the zoom.
//!
//! With frequency shading, each kernel's frequency follows the darkness at its centre
//! (darker, denser); the sum is still divided by the deviation at F₀ (the Gabor
//! variance depends on F only through its factor 1 + exp(−2πF²/a²)).
//!
//! The two naive answers of the paper's figure 1 are [`Anchoring::Screen`] (a 2D Gabor
//! noise on the screen: the object slides under it) and [`Anchoring::Texture`] (the same
//! noise in the surface's texture space, sized for zoom 1: the marks shrink as the object
//! recedes).

use super::scene::{Face, Patch, Scene, base_patches, face_point, map_range, uv_extent};
use super::stretch;
use kurbo::Point;
use marbling_noise::{
    Anchoring, CellRng, DepthTest, Follow, Gabor, GaborKind, GaborParams, Marks, lod_weights,
    style::MARK_FREQUENCY,
};
use std::f64::consts::PI;

/// How many kernel radii (in object units at the kernel's distance) a pixel's depth may
/// differ from its kernel's and still receive it.
pub const DEPTH_TOLERANCE_RADII: f64 = 1.0;

/// A kernel placed on the screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kernel {
    /// Screen position, pixels.
    pub x: f64,
    /// Screen position, pixels.
    pub y: f64,
    /// Distance of its surface point from the camera.
    pub depth: f64,
    /// Weight: uniform in [−1, 1] times its level-of-detail weight (1, α or N).
    pub weight: f64,
    /// Direction of its frequency vector on the screen, radians from +x towards +y.
    pub omega: f64,
    /// Its frequency, cycles per pixel: F₀, or F₀·(1 + k·(d − ½)) with frequency
    /// shading k and d = 1 − the headlight's cosine at its pixel.
    pub frequency: f64,
}

/// One noise layer of a style.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    /// Anisotropic (strokes) or isotropic (dots).
    pub kind: GaborKind,
    /// The marks' screen parameters.
    pub marks: Marks,
    /// Stroke direction offset, radians (crosshatch's second layer: π/2).
    pub turn: f64,
    /// Seed of the layer's streams.
    pub seed: u32,
}

impl Layer {
    fn params(&self) -> GaborParams {
        GaborParams {
            kind: self.kind,
            frequency: self.marks.frequency,
            orientation: (f64::from(self.marks.orientation).to_radians() + self.turn + PI / 2.0)
                as f32,
            bandwidth: self.marks.bandwidth,
            impulses: self.marks.impulses,
            seed: self.seed,
            period: None,
            orientation_drive: None,
            frequency_drive: None,
            profile: None,
        }
    }
}

/// The layer's noise at every pixel (unit variance; NaN where the object does not show),
/// and the number of kernels drawn (0 for the naive anchorings).
pub(super) fn noise(
    scene: &Scene,
    layer: &Layer,
    anchoring: Anchoring,
    depth_test: DepthTest,
) -> (Vec<f32>, usize) {
    match anchoring {
        Anchoring::Surface => {
            let kernels = kernels(scene, layer);
            (splat(scene, layer, &kernels, depth_test), kernels.len())
        }
        Anchoring::Screen => (naive(scene, layer, |x, y, _| Some((x, y))), 0),
        Anchoring::Texture => {
            let (ex, ey) = uv_extent(scene.object.shape, scene.object.aspect);
            let k = scene.reference_scale;
            (
                naive(scene, layer, |_, _, uv: [f32; 2]| {
                    (!uv[0].is_nan())
                        .then(|| (f64::from(uv[0]) * ex * k, f64::from(uv[1]) * ey * k))
                }),
                0,
            )
        }
    }
}

/// A 2D Gabor noise evaluated where `at` places each object pixel.
fn naive(
    scene: &Scene,
    layer: &Layer,
    at: impl Fn(f64, f64, [f32; 2]) -> Option<(f64, f64)> + Sync,
) -> Vec<f32> {
    let gabor = Gabor::new(layer.params());
    let w = scene.width as usize;
    map_range(scene.depth.len(), |i| {
        if !scene.depth[i].is_finite() {
            return f32::NAN;
        }
        let (x, y) = ((i % w) as f64 + 0.5, (i / w) as f64 + 0.5);
        at(x, y, scene.uv[i]).map_or(f32::NAN, |(x, y)| gabor.eval(x as f32, y as f32))
    })
}

/// The visible kernels of every patch facing the camera.
pub(super) fn kernels(scene: &Scene, layer: &Layer) -> Vec<Kernel> {
    let params = layer.params();
    let r = f64::from(params.radius());
    let lambda = f64::from(layer.marks.impulses) / (PI * r * r);
    let patches = base_patches(&scene.object);
    map_range(patches.len(), |i| {
        patch_kernels(scene, layer, &patches[i], lambda)
    })
    .into_iter()
    .flatten()
    .collect()
}

fn patch_kernels(scene: &Scene, layer: &Layer, patch: &Patch, lambda: f64) -> Vec<Kernel> {
    let projected = patch.project(scene);
    if projected.area <= 0.0 || !projected.on_screen {
        return Vec::new();
    }
    let n = lambda * projected.area;
    let (m, alpha) = lod_weights(n);
    let count = if n < 1.0 { 1 } else { 2 * m };
    let mut rng = CellRng::new(patch.id as i32, patch.face as i32, layer.seed);
    let shape = scene.object.shape;
    let mut out = Vec::new();
    for k in 0..count {
        // Four draws per point, always, so point k's draws never depend on N.
        let (s, t, w, a) = (
            rng.next_f32(),
            rng.next_f32(),
            rng.next_f32(),
            rng.next_f32(),
        );
        let level = if n < 1.0 {
            n
        } else if k < m {
            1.0
        } else {
            alpha
        };
        let (u, v) = patch.at(shape, f64::from(s), f64::from(t));
        let (p, _) = face_point(&scene.object, patch.face, u, v);
        let Some((x, y, depth)) = scene.project(p) else {
            continue;
        };
        let tolerance = 0.5 * scene.world_per_pixel(depth) + 2e-3 * depth;
        if !scene.shows(x, y, depth, tolerance) {
            continue;
        }
        let omega = match layer.kind {
            GaborKind::Isotropic => f64::from(a) * 2.0 * PI,
            _ => orientation(scene, layer, patch.face, (u, v), (x, y)),
        };
        let dark = scene
            .pixel(x, y)
            .map_or(0.5, |i| 1.0 - f64::from(scene.light[i]));
        let shaded = 1.0 + f64::from(layer.marks.frequency_shading) * (dark - 0.5);
        out.push(Kernel {
            x,
            y,
            depth,
            weight: (2.0 * f64::from(w) - 1.0) * level,
            omega,
            frequency: (f64::from(layer.marks.frequency) * shaded).clamp(1e-3, MARK_FREQUENCY.hi),
        });
    }
    out
}

/// The frequency vector's screen direction of an anisotropic kernel at (u, v).
fn orientation(scene: &Scene, layer: &Layer, face: Face, uv: (f64, f64), at: (f64, f64)) -> f64 {
    let stroke = f64::from(layer.marks.orientation).to_radians() + layer.turn;
    // The screen direction of a step (du, dv) in texture space from the kernel.
    let towards = |du: f64, dv: f64| {
        let q = face_point(&scene.object, face, uv.0 + du, uv.1 + dv).0;
        match scene.project(q) {
            Some((x, y, _)) if (x - at.0).hypot(y - at.1) > 1e-9 => {
                Some((y - at.1).atan2(x - at.0))
            }
            _ => None,
        }
    };
    let curvature = || towards(1e-3, 0.0).unwrap_or(0.0);
    let base = match layer.marks.follow {
        Follow::Screen => 0.0,
        Follow::Curvature => curvature(),
        Follow::Stretch => {
            let (dw, dh) = scene.design_size;
            scene
                .walker
                .as_ref()
                .and_then(|w| stretch::direction(w, Point::new(uv.0 * dw, uv.1 * dh)))
                .and_then(|(dx, dy)| {
                    let (du, dv) = (dx / dw, dy / dh);
                    let k = 1e-3 / du.hypot(dv);
                    towards(du * k, dv * k)
                })
                .unwrap_or_else(curvature)
        }
    };
    base + stroke + PI / 2.0
}

/// Sums the kernels into the pixels they reach, divided by the noise's deviation.
fn splat(scene: &Scene, layer: &Layer, kernels: &[Kernel], depth_test: DepthTest) -> Vec<f32> {
    let params = layer.params();
    let r = f64::from(params.radius());
    let a = f64::from(params.bandwidth);
    let scale = 1.0 / f64::from(params.variance()).sqrt();
    let (w, h) = (scene.width as usize, scene.height as usize);
    // Bucket kernels by row band so rows can be summed in parallel.
    let band = (r.ceil() as usize).max(1);
    let mut buckets: Vec<Vec<usize>> = vec![Vec::new(); h / band + 2];
    for (i, k) in kernels.iter().enumerate() {
        let b = (k.y.max(0.0) as usize / band).min(buckets.len() - 1);
        buckets[b].push(i);
    }
    let rows = map_range(h, |y| {
        let py = y as f64 + 0.5;
        let b = y / band;
        let near = b.saturating_sub(1)..=(b + 1).min(buckets.len() - 1);
        let mut acc = vec![0.0f64; w];
        for &ki in near.flat_map(|b| buckets[b].iter()) {
            let k = &kernels[ki];
            let dy = py - k.y;
            if dy.abs() > r {
                continue;
            }
            let half = (r * r - dy * dy).sqrt();
            let x0 = ((k.x - half - 0.5).ceil().max(0.0)) as usize;
            let x1 = ((k.x + half - 0.5).floor().min(w as f64 - 1.0)).max(-1.0);
            if x1 < 0.0 {
                continue;
            }
            let (c, s) = (k.omega.cos(), k.omega.sin());
            let tolerance = DEPTH_TOLERANCE_RADII * r * scene.world_per_pixel(k.depth);
            // Along the row the kernel is stepped, not evaluated: with dx₀ the first
            // pixel's offset, the envelope e = exp(−πa²(dx² + dy²)) gains the factor
            // h = exp(−πa²(2dx + 1)) per pixel and h the factor exp(−2πa²); the wave is
            // the real part of z = exp(i·2πF(dx·c + dy·s)), turned by exp(i·2πF·c).
            let pa2 = PI * a * a;
            let dx0 = x0 as f64 + 0.5 - k.x;
            let mut envelope = (-pa2 * (dx0 * dx0 + dy * dy)).exp();
            let mut h = (-pa2 * (2.0 * dx0 + 1.0)).exp();
            let q = (-2.0 * pa2).exp();
            let (mut zr, mut zi) = {
                let phase = 2.0 * PI * k.frequency * (dx0 * c + dy * s);
                (phase.cos(), phase.sin())
            };
            let turn = 2.0 * PI * k.frequency * c;
            let (ur, ui) = (turn.cos(), turn.sin());
            for (x, cell) in acc.iter_mut().enumerate().take(x1 as usize + 1).skip(x0) {
                let (e, wave) = (envelope, zr);
                envelope *= h;
                h *= q;
                (zr, zi) = (zr * ur - zi * ui, zr * ui + zi * ur);
                let depth = f64::from(scene.depth[y * w + x]);
                if !depth.is_finite() {
                    continue;
                }
                let keep = match depth_test {
                    DepthTest::Off => 1.0,
                    DepthTest::Hard => f64::from(u8::from((depth - k.depth).abs() <= tolerance)),
                    DepthTest::Fuzzy => {
                        let e = (depth - k.depth).abs() / tolerance;
                        1.0 - f64::from(marbling_noise::smoothstep(0.5, 1.0, e as f32))
                    }
                };
                *cell += keep * k.weight * e * wave;
            }
        }
        (0..w)
            .map(|x| {
                if scene.depth[y * w + x].is_finite() {
                    (acc[x] * scale) as f32
                } else {
                    f32::NAN
                }
            })
            .collect::<Vec<f32>>()
    });
    rows.into_iter().flatten().collect()
}
