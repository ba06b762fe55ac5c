//! Packing a design's ops into the f32 texels the shaders read: two `vec4<f32>` per op
//! (keep in sync with the encoding described at the top of `shaders/common.wgsl`).
//!
//! Everything the CPU walker precomputes (unit direction and normal, αλ, r²,
//! 2π/wavelength) is computed here in f64 and rounded once to f32, so the shader does
//! as little f32 arithmetic as possible.

use marbling_core::{Op, Rgb8, Vec2};
use std::f64::consts::TAU;

/// Kind code of a drop (deforming disc of ink).
pub const KIND_DROP: f32 = 0.0;
/// Kind code of a spray (disc of ink, no deformation).
pub const KIND_SPRAY: f32 = 1.0;
/// Kind code of a tine or rake (spacing 0 = tine).
pub const KIND_COMB: f32 = 2.0;
/// Kind code of a wavy comb.
pub const KIND_WAVE: f32 = 3.0;
/// Kind code of a circular comb.
pub const KIND_CIRCULAR: f32 = 4.0;
/// Kind code of a vortex.
pub const KIND_VORTEX: f32 = 5.0;

/// Texels (RGBA f32) per op in the op texture.
pub const TEXELS_PER_OP: u32 = 2;

/// An encoded op: texels `a` and `b`.
pub type EncodedOp = [[f32; 4]; 2];

/// The sRGB bytes as one exact f32: r·65536 + g·256 + b (< 2²⁴).
pub fn pack_srgb(c: Rgb8) -> f32 {
    (u32::from(c.r) << 16 | u32::from(c.g) << 8 | u32::from(c.b)) as f32
}

/// A colour as (linear r, g, b, packed sRGB), the form the shaders return for inks.
pub fn color_texel(c: Rgb8) -> [f32; 4] {
    let [r, g, b] = c.to_linear();
    [r, g, b, pack_srgb(c)]
}

fn comb(
    origin: marbling_core::Point,
    dir: Vec2,
    alpha: f64,
    lambda: f64,
    spacing: f64,
) -> EncodedOp {
    let m = dir.normalize();
    [
        [KIND_COMB, origin.x as f32, origin.y as f32, m.x as f32],
        [
            m.y as f32,
            (alpha * lambda) as f32,
            lambda as f32,
            spacing as f32,
        ],
    ]
}

/// Encodes one op for the shaders.
pub fn encode_op(op: &Op) -> EncodedOp {
    match *op {
        Op::Drop(d) => [
            [
                KIND_DROP,
                d.center.x as f32,
                d.center.y as f32,
                (d.radius * d.radius) as f32,
            ],
            color_texel(d.color),
        ],
        Op::Spray(s) => [
            [
                KIND_SPRAY,
                s.center.x as f32,
                s.center.y as f32,
                (s.radius * s.radius) as f32,
            ],
            color_texel(s.color),
        ],
        Op::Tine(t) => comb(t.origin, t.direction, t.alpha, t.lambda, 0.0),
        Op::Rake(r) => comb(r.origin, r.direction, r.alpha, r.lambda, r.spacing),
        Op::Wavy(w) => {
            let (s, c) = w.angle.sin_cos();
            [
                [KIND_WAVE, c as f32, s as f32, w.amplitude as f32],
                [
                    (TAU / w.wavelength) as f32,
                    w.phase.rem_euclid(TAU) as f32,
                    0.0,
                    0.0,
                ],
            ]
        }
        Op::Circular(c) => [
            [
                KIND_CIRCULAR,
                c.center.x as f32,
                c.center.y as f32,
                c.radius as f32,
            ],
            [(c.alpha * c.lambda) as f32, c.lambda as f32, 0.0, 0.0],
        ],
        Op::Vortex(v) => [
            [KIND_VORTEX, v.center.x as f32, v.center.y as f32, 0.0],
            [(v.alpha * v.lambda) as f32, v.lambda as f32, 0.0, 0.0],
        ],
    }
}

/// Where ops sit in an op texture: op k at texels (2·(k mod ops_per_row),
/// k div ops_per_row) and the one to its right.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OpLayout {
    /// Texture width, texels (even, ≥ 2).
    pub width: u32,
    /// Texture height, texels (≥ 1).
    pub height: u32,
    /// Ops per texture row (`width / 2`).
    pub ops_per_row: u32,
}

impl OpLayout {
    /// The smallest layout with room for `capacity` ops in a texture at most `max_side`
    /// texels wide and high (`max_side` ≥ 2; WebGL2 guarantees 2048). `None` when they
    /// do not fit.
    pub fn for_capacity(capacity: usize, max_side: u32) -> Option<Self> {
        let max_side = max_side.max(2);
        let max_per_row = max_side / TEXELS_PER_OP;
        let n = u32::try_from(capacity).ok()?;
        let ops_per_row = n.clamp(1, max_per_row);
        let height = n.div_ceil(ops_per_row).max(1);
        (height <= max_side).then_some(Self {
            width: ops_per_row * TEXELS_PER_OP,
            height,
            ops_per_row,
        })
    }

    /// Ops the texture has room for.
    pub fn capacity(&self) -> usize {
        self.ops_per_row as usize * self.height as usize
    }

    /// Ops `range` (within the capacity) as runs along texture rows: (row, index of
    /// the run's first op within its row, ops in the run).
    pub fn runs(&self, range: std::ops::Range<usize>) -> impl Iterator<Item = (u32, u32, u32)> {
        let per_row = self.ops_per_row as usize;
        let mut at = range.start;
        std::iter::from_fn(move || {
            (at < range.end).then(|| {
                let (row, col) = (at / per_row, at % per_row);
                let count = (per_row - col).min(range.end - at);
                at += count;
                (row as u32, col as u32, count as u32)
            })
        })
    }
}

/// A design's ops laid out as an RGBA f32 texture (see [`OpLayout`]).
#[derive(Clone, Debug, PartialEq)]
pub struct OpTexels {
    /// Texture width, texels (even, ≥ 2).
    pub width: u32,
    /// Texture height, texels (≥ 1).
    pub height: u32,
    /// Ops per texture row (`width / 2`).
    pub ops_per_row: u32,
    /// Number of ops encoded.
    pub op_count: u32,
    /// `width × height` texels, row-major; unused texels are zero.
    pub texels: Vec<[f32; 4]>,
}

/// Lays out `ops` (oldest first) in a texture at most `max_side` texels wide and high
/// (`max_side` ≥ 2; WebGL2 guarantees 2048). `None` when they do not fit.
pub fn layout_ops(ops: &[Op], max_side: u32) -> Option<OpTexels> {
    let layout = OpLayout::for_capacity(ops.len(), max_side)?;
    let mut texels = vec![[0.0f32; 4]; layout.width as usize * layout.height as usize];
    for (k, op) in ops.iter().enumerate() {
        let [a, b] = encode_op(op);
        let i = k * TEXELS_PER_OP as usize;
        texels[i] = a;
        texels[i + 1] = b;
    }
    Some(OpTexels {
        width: layout.width,
        height: layout.height,
        ops_per_row: layout.ops_per_row,
        op_count: ops.len() as u32,
        texels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use marbling_core::synth::{Mix, random_design};

    #[test]
    fn packed_srgb_is_exact() {
        let c = Rgb8::new(255, 254, 253);
        let p = pack_srgb(c) as u32;
        assert_eq!((p >> 16, (p >> 8) & 255, p & 255), (255, 254, 253));
    }

    #[test]
    fn layout_places_op_k_at_its_texel() {
        let d = random_design(3, 100, 100, 2500, Mix::Mixed);
        let t = layout_ops(&d.ops, 2048).expect("fits");
        assert_eq!((t.width, t.ops_per_row, t.height), (2048, 1024, 3));
        for k in [0usize, 1023, 1024, 2499] {
            let (col, row) = (2 * (k as u32 % t.ops_per_row), k as u32 / t.ops_per_row);
            let i = (row * t.width + col) as usize;
            assert_eq!([t.texels[i], t.texels[i + 1]], encode_op(&d.ops[k]));
        }
        assert!(layout_ops(&d.ops, 4).is_none());
        let empty = layout_ops(&[], 2048).expect("fits");
        assert_eq!((empty.width, empty.height, empty.op_count), (2, 1, 0));
    }

    #[test]
    fn runs_cut_a_range_at_row_ends() {
        let l = OpLayout::for_capacity(10, 8).expect("fits");
        assert_eq!(
            (l.width, l.height, l.ops_per_row, l.capacity()),
            (8, 3, 4, 12)
        );
        assert_eq!(
            l.runs(3..10).collect::<Vec<_>>(),
            [(0, 3, 1), (1, 0, 4), (2, 0, 2)]
        );
        assert_eq!(l.runs(5..6).collect::<Vec<_>>(), [(1, 1, 1)]);
        assert_eq!(l.runs(4..4).count(), 0);
        assert!(OpLayout::for_capacity(9, 4).is_none());
    }

    #[test]
    fn max_ops_fit_webgl2() {
        let d = random_design(1, 64, 64, marbling_core::MAX_OPS, Mix::Mixed);
        let t = layout_ops(&d.ops, 2048).expect("100,000 ops fit in 2048²");
        assert_eq!(t.height, 98);
    }
}
