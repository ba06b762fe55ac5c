//! The canvas that moves with the scene (Kaplan & Cohen 2005, §4): paper or canvas fibres
//! of a constant length and width **on screen**, anchored at points of the surface, drawn
//! at a constant density per screen pixel.
//!
//! - Each design face is cut into patches ([`super::scene::base_patches`]); a patch facing
//!   the camera wants n = FibersPerPixel × its screen area fibres. One that wants more than
//!   [`FIBRE_LIST`] splits 1→4 at its midpoints (up to [`MAX_SPLITS`] times), so the
//!   density holds from far away to close up. Kaplan & Cohen draw ⌊n⌋ or ⌈n⌉; we draw ⌈n⌉
//!   with the last fading in with opacity n − ⌊n⌋, so a fibre appears gradually as its
//!   patch grows (a split still redraws the patch's fibres, as in the paper).
//! - Anchors: the paper keeps one list of uniform barycentric points (Turk's method; naive
//!   sampling clumps) and starts each triangle at a random index. We take the R2
//!   low-discrepancy sequence (Roberts 2018) from a random start per patch: as even, and
//!   endless.
//! - A fibre starts at its anchor's screen point and runs `length` pixels in its screen
//!   direction; it is drawn only where the anchor is what the frame shows (the paper's id
//!   buffer test); fibres are not clipped at the silhouette (the paper's halo).
//! - Directions: the paper prints normalize(rand, rand), which clusters its fibres in
//!   0–90° around 45° (likely unintended); paper fibres here are uniform over [0°, 180°),
//!   canvas threads 0° or 90° with the weave's weights.
//! - The backdrop is a sheet of the same paper, fixed to the screen (cells of
//!   [`BACKDROP_CELL`] pixels).

use super::scene::{Patch, Scene, base_patches, face_point};
use marbling_noise::{CellRng, StyleKind, StyleSpec};
use std::f64::consts::PI;

/// Fibres one patch draws before it splits 1→4.
pub const FIBRE_LIST: f64 = 64.0;
/// Most times a base patch splits.
pub const MAX_SPLITS: u32 = 8;
/// Side of the backdrop's screen cells, pixels.
pub const BACKDROP_CELL: u32 = 32;

/// R2 sequence steps: 1/g and 1/g², g the plastic number.
const R2: [f64; 2] = [0.754_877_666_246_692_7, 0.569_840_290_998_053_2];

/// A fibre placed on the screen.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fibre {
    /// Start (its anchor), screen pixels.
    pub start: [f64; 2],
    /// Unit direction on the screen.
    pub dir: [f64; 2],
    /// Length, pixels.
    pub length: f64,
    /// Width, pixels.
    pub width: f64,
    /// Share of full opacity: 1, or the fading-in fraction of a patch's last fibre.
    pub weight: f64,
    /// True when anchored on the object (false: on the backdrop).
    pub on_object: bool,
}

/// Every fibre of the frame: the object's, then the backdrop's.
pub(super) fn fibres(scene: &Scene, spec: &StyleSpec) -> Vec<Fibre> {
    let mut out = Vec::new();
    let mut stack: Vec<(Patch, u32)> = base_patches(&scene.object)
        .into_iter()
        .map(|p| (p, 0))
        .collect();
    let per_pixel = f64::from(spec.fibres.per_pixel);
    while let Some((patch, depth)) = stack.pop() {
        let projected = patch.project(scene);
        if projected.area <= 0.0 || !projected.on_screen {
            continue;
        }
        let n = per_pixel * projected.area;
        if n > FIBRE_LIST && depth < MAX_SPLITS {
            stack.extend(patch.split().map(|c| (c, depth + 1)));
            continue;
        }
        patch_fibres(scene, spec, &patch, n, &mut out);
    }
    backdrop(scene, spec, &mut out);
    out
}

fn patch_fibres(scene: &Scene, spec: &StyleSpec, patch: &Patch, n: f64, out: &mut Vec<Fibre>) {
    let mut rng = CellRng::new(patch.id as i32, patch.face as i32, spec.seed);
    let start = f64::from(rng.next_f32()) * 1e4;
    for k in 0..n.ceil() as u32 {
        let i = start + f64::from(k);
        let (s, t) = ((0.5 + i * R2[0]).fract(), (0.5 + i * R2[1]).fract());
        let (u, v) = patch.at(scene.object.shape, s, t);
        let (p, _) = face_point(&scene.object, patch.face, u, v);
        let look = fibre_look(spec, &mut rng);
        let Some((x, y, depth)) = scene.project(p) else {
            continue;
        };
        if !scene.shows(x, y, depth, anchor_tolerance(scene, depth)) {
            continue;
        }
        let weight = (n - f64::from(k)).min(1.0);
        out.push(Fibre {
            start: [x, y],
            weight,
            on_object: true,
            ..look
        });
    }
}

/// How far an anchor's depth may be from its pixel's (a pixel's depth is its centre's,
/// and a slanted surface's depth changes across it).
pub(super) fn anchor_tolerance(scene: &Scene, depth: f64) -> f64 {
    4.0 * scene.world_per_pixel(depth) + 1e-3 * depth
}

/// Direction, length and width of the next fibre of a stream (three draws, always).
fn fibre_look(spec: &StyleSpec, rng: &mut CellRng) -> Fibre {
    let (a, l, w) = (rng.next_f32(), rng.next_f32(), rng.next_f32());
    let f = &spec.fibres;
    let angle = if spec.kind == StyleKind::Canvas {
        let horizontal = f.weave[0] / (f.weave[0] + f.weave[1]);
        if a < horizontal { 0.0 } else { PI / 2.0 }
    } else {
        f64::from(a) * PI
    };
    let lerp = |r: [f32; 2], t: f32| f64::from(r[0] + t * (r[1] - r[0]));
    Fibre {
        start: [0.0; 2],
        dir: [angle.cos(), angle.sin()],
        length: lerp(f.length, l),
        width: lerp(f.width, w),
        weight: 1.0,
        on_object: false,
    }
}

/// The backdrop's fibres, where the backdrop shows at their anchors.
fn backdrop(scene: &Scene, spec: &StyleSpec, out: &mut Vec<Fibre>) {
    let cell = f64::from(BACKDROP_CELL);
    let n = f64::from(spec.fibres.per_pixel) * cell * cell;
    for cy in 0..scene.height.div_ceil(BACKDROP_CELL) {
        for cx in 0..scene.width.div_ceil(BACKDROP_CELL) {
            let mut rng = CellRng::new(cx as i32, cy as i32, spec.seed ^ 0xBAC0_0000);
            let start = f64::from(rng.next_f32()) * 1e4;
            for k in 0..n.ceil() as u32 {
                let i = start + f64::from(k);
                let x = (f64::from(cx) + (0.5 + i * R2[0]).fract()) * cell;
                let y = (f64::from(cy) + (0.5 + i * R2[1]).fract()) * cell;
                let look = fibre_look(spec, &mut rng);
                let backdrop_shows = scene
                    .pixel(x, y)
                    .is_some_and(|p| !scene.depth[p].is_finite());
                if backdrop_shows {
                    out.push(Fibre {
                        start: [x, y],
                        weight: (n - f64::from(k)).min(1.0),
                        ..look
                    });
                }
            }
        }
    }
}

/// Draws `fibres` into a coverage buffer: each adds opacity × weight × its antialiased
/// coverage (one pixel wide ramps at its sides and ends) by alpha compositing,
/// a ← a + (1 − a)·α.
pub(super) fn draw(fibres: &[Fibre], opacity: f64, width: u32, height: u32) -> Vec<f32> {
    let (w, h) = (width as usize, height as usize);
    let mut alpha = vec![0.0f32; w * h];
    for f in fibres {
        let [sx, sy] = f.start;
        let [dx, dy] = f.dir;
        let (ex, ey) = (sx + dx * f.length, sy + dy * f.length);
        let pad = 0.5 * f.width + 1.0;
        let x0 = (sx.min(ex) - pad).floor().max(0.0) as usize;
        let y0 = (sy.min(ey) - pad).floor().max(0.0) as usize;
        let x1 = ((sx.max(ex) + pad).ceil().max(0.0) as usize).min(w);
        let y1 = ((sy.max(ey) + pad).ceil().max(0.0) as usize).min(h);
        let strength = opacity * f.weight;
        for y in y0..y1 {
            for x in x0..x1 {
                let (px, py) = (x as f64 + 0.5 - sx, y as f64 + 0.5 - sy);
                let along = px * dx + py * dy;
                let across = (px * dy - py * dx).abs();
                let side = (0.5 * f.width + 0.5 - across).clamp(0.0, 1.0);
                let end = (along.min(f.length - along) + 0.5).clamp(0.0, 1.0);
                let a = (strength * side * end) as f32;
                if a > 0.0 {
                    let cell = &mut alpha[y * w + x];
                    *cell += (1.0 - *cell) * a;
                }
            }
        }
    }
    alpha
}
