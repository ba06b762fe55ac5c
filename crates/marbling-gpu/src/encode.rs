//! Packing a design's ops into the f32 texels the shaders read: records, [`GpuOp`], of
//! two `vec4<f32>` each (keep in sync with the encoding described at the top of
//! `shaders/common.wgsl` and `shaders/records.wgsl`).
//!
//! Records are made from the op's one compiled form, [`CompiledOp`] (unit direction and
//! normal, αλ, r², 2π/wavelength computed once in f64), rounded once to f32, so the
//! shader does as little f32 arithmetic as possible and the CPU and GPU cannot derive
//! the constants differently. Most ops are one record whose first value is the
//! [`OpKind`] code; a drop pattern is one record per drop, a finite comb and a stylus
//! are a header record (newest) with data records before it ([`records`]).

use marbling_core::{
    CombKernel, CompiledOp, JiggleKernel, Op, OpKind, Rgb8, RigidKernel, SwirlKernel, WaveKernel,
};
use std::f64::consts::TAU;

/// Texels (RGBA f32) per record in the op texture.
pub const TEXELS_PER_OP: u32 = 2;

/// Offsets (tines, tips) per data record.
const OFFSETS_PER_RECORD: usize = 8;

/// The sRGB bytes as one exact f32: r·65536 + g·256 + b (< 2²⁴).
pub fn pack_srgb(c: Rgb8) -> f32 {
    (u32::from(c.r) << 16 | u32::from(c.g) << 8 | u32::from(c.b)) as f32
}

/// A colour as (linear r, g, b, packed sRGB), the form the shaders return for inks.
pub fn color_texel(c: Rgb8) -> [f32; 4] {
    let [r, g, b] = c.to_linear();
    [r, g, b, pack_srgb(c)]
}

/// One op as the shaders read it: texels `a` and `b`; `a[0]` is its [`OpKind`] code.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct GpuOp {
    /// The first texel.
    pub a: [f32; 4],
    /// The second texel.
    pub b: [f32; 4],
}

impl GpuOp {
    /// The kind this record was made for (`None` for a record of no known kind).
    pub fn kind(&self) -> Option<OpKind> {
        let code = self.a[0];
        (code >= 0.0 && code.fract() == 0.0)
            .then(|| OpKind::from_code(code as u32))
            .flatten()
    }

    /// Its two texels, in texture order.
    pub fn texels(&self) -> [[f32; 4]; 2] {
        [self.a, self.b]
    }
}

impl GpuOp {
    /// The one record of an op of a one-record kind (every kind but [`OpKind::Tines`],
    /// [`OpKind::Stylus`] and [`OpKind::Flow`]); `None` for those three.
    pub fn single(op: &CompiledOp) -> Option<Self> {
        let kind = op.kind().code() as f32;
        let f = |v: f64| v as f32;
        let (a, b) = match *op {
            CompiledOp::Disc {
                cx, cy, r2, color, ..
            } => ([kind, f(cx), f(cy), f(r2)], color_texel(color)),
            CompiledOp::Comb(CombKernel {
                ax,
                ay,
                mx,
                my,
                al,
                lambda,
                spacing,
                ..
            }) => (
                [kind, f(ax), f(ay), f(mx)],
                [f(my), f(al), f(lambda), f(spacing)],
            ),
            CompiledOp::Wave(WaveKernel {
                mx,
                my,
                amp,
                k,
                phase,
                ..
            }) => (
                [kind, f(mx), f(my), f(amp)],
                // The phase reduced to [0, 2π) keeps f32 precision in the sine.
                [f(k), f(phase.rem_euclid(TAU)), 0.0, 0.0],
            ),
            CompiledOp::Swirl(SwirlKernel {
                cx,
                cy,
                r,
                al,
                lambda,
                ..
            }) => ([kind, f(cx), f(cy), f(r)], [f(al), f(lambda), 0.0, 0.0]),
            CompiledOp::Rigid(RigidKernel {
                cx,
                cy,
                sin,
                cos,
                ox,
                oy,
            }) => ([kind, f(cx), f(cy), f(sin)], [f(cos), f(ox), f(oy), 0.0]),
            CompiledOp::Jiggle(JiggleKernel {
                ux,
                uy,
                k,
                along,
                across,
                phase,
            }) => (
                [kind, f(ux), f(uy), f(k)],
                [f(along), f(across), f(phase.rem_euclid(TAU)), 0.0],
            ),
            CompiledOp::Tines { .. } | CompiledOp::Stylus { .. } | CompiledOp::Flow { .. } => {
                return None;
            }
        };
        Some(Self { a, b })
    }
}

/// Data records holding `offsets`, 8 per record, the last padded with the first offset
/// (which changes no minimum).
fn offset_records(offsets: &[f64], out: &mut Vec<GpuOp>) {
    for chunk in offsets.chunks(OFFSETS_PER_RECORD) {
        let mut v = [offsets[0] as f32; 8];
        for (slot, &o) in v.iter_mut().zip(chunk) {
            *slot = o as f32;
        }
        out.push(GpuOp {
            a: [v[0], v[1], v[2], v[3]],
            b: [v[4], v[5], v[6], v[7]],
        });
    }
}

/// Appends the records of one compiled op, oldest first (the header, read first by the
/// backward walk, last):
/// - [`OpKind::Tines`]: ⌈T/8⌉ records of tine offsets, then the header.
/// - [`OpKind::Stylus`]: for more than one tip, ⌈T/8⌉ records of tip offsets; then per
///   segment two records, `H2` and the header `H1` (see `shaders/records.wgsl`).
/// - [`OpKind::Flow`]: ⌈octaves/4⌉ records of (frequency, amplitude/σ) per octave,
///   then the header a = (kind, U/(2πf), Δt, N), b = (octaves, basis: 0 Perlin and
///   1 value, the first octave's seed's high and low 16 bits).
/// - every other kind: its one record ([`GpuOp::single`]).
pub fn compiled_records(op: &CompiledOp, out: &mut Vec<GpuOp>) {
    let f = |v: f64| v as f32;
    match op {
        CompiledOp::Tines {
            ax,
            ay,
            mx,
            my,
            al,
            lambda,
            offsets,
        } => {
            offset_records(offsets, out);
            let kind = OpKind::Tines.code() as f32;
            out.push(GpuOp {
                a: [kind, f(*ax), f(*ay), f(*mx)],
                b: [f(*my), f(*al), f(*lambda), offsets.len() as f32],
            });
        }
        CompiledOp::Stylus { segments } => {
            let Some(first) = segments.first() else {
                return;
            };
            let tips = &first.tips;
            let tips_start = out.len();
            if tips.len() > 1 {
                offset_records(tips, out);
            }
            let tip_records = out.len() - tips_start;
            let kind = OpKind::Stylus.code() as f32;
            for (k, s) in segments.iter().enumerate() {
                let h1 = out.len() + 1;
                let skip = if k == 0 { 2 + tip_records } else { 2 };
                out.push(GpuOp {
                    a: [
                        tips.len() as f32,
                        f(s.tip_range.0),
                        f(s.tip_range.1),
                        (h1 - tips_start) as f32,
                    ],
                    b: [skip as f32, f(s.length), 0.0, 0.0],
                });
                out.push(GpuOp {
                    a: [kind, f(s.start.x), f(s.start.y), f(s.n.x)],
                    b: [f(s.n.y), f(s.delta), s.steps as f32, f(s.wake)],
                });
            }
        }
        CompiledOp::Flow { field } => {
            let octaves = field.octaves();
            let pairs: Vec<f64> = octaves.iter().flat_map(|&(f, a, _)| [f, a]).collect();
            offset_records(&pairs, out);
            let seed = octaves.first().map_or(0, |o| o.2);
            let basis = match field.basis() {
                marbling_noise::Basis::Perlin => 0.0,
                marbling_noise::Basis::Value => 1.0,
            };
            out.push(GpuOp {
                a: [
                    OpKind::Flow.code() as f32,
                    f(field.factor),
                    f(field.dt),
                    field.steps as f32,
                ],
                b: [
                    octaves.len() as f32,
                    basis,
                    (seed >> 16) as f32,
                    (seed & 0xffff) as f32,
                ],
            });
        }
        single => out.extend(GpuOp::single(single)),
    }
}

/// Appends the records of `op` (of each drop of a drop pattern), oldest first.
pub fn records(op: &Op, out: &mut Vec<GpuOp>) {
    for c in CompiledOp::of(op) {
        compiled_records(&c, out);
    }
}

/// The one record of an op the live preview can walk (one record; `None` for a drop
/// pattern, a finite comb or a stylus).
pub fn encode_op(op: &Op) -> Option<GpuOp> {
    match CompiledOp::of(op).as_slice() {
        [c] => GpuOp::single(c),
        _ => None,
    }
}

/// Where records sit in an op texture: record k at texels (2·(k mod ops_per_row),
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
    /// Room for one record (a texture of 2×1 texels).
    pub const SMALLEST: OpLayout = OpLayout {
        width: TEXELS_PER_OP,
        height: 1,
        ops_per_row: 1,
    };

    /// The smallest layout with room for `capacity` ops in a texture at most `max_side`
    /// texels wide and high (`max_side` ≥ 2; WebGL2 guarantees 2048). `None` when they
    /// do not fit.
    /// Records per row are a power of two, so the shaders find a record's texel with a
    /// mask and a shift (an integer division made the walk 20 % slower on lavapipe).
    pub fn for_capacity(capacity: usize, max_side: u32) -> Option<Self> {
        let max_side = max_side.max(2);
        let max_per_row = 1 << (max_side / TEXELS_PER_OP).ilog2();
        let n = u32::try_from(capacity).ok()?;
        let ops_per_row = n.max(1).checked_next_power_of_two()?.min(max_per_row);
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
    /// Number of records encoded.
    pub op_count: u32,
    /// `width × height` texels, row-major; unused texels are zero.
    pub texels: Vec<[f32; 4]>,
}

/// Lays out the records of `ops` (oldest first) in a texture at most `max_side` texels
/// wide and high (`max_side` ≥ 2; WebGL2 guarantees 2048). `None` when they do not fit.
pub fn layout_ops(ops: &[Op], max_side: u32) -> Option<OpTexels> {
    let mut recs = Vec::with_capacity(ops.len());
    for op in ops {
        records(op, &mut recs);
    }
    let layout = OpLayout::for_capacity(recs.len(), max_side)?;
    let mut texels = vec![[0.0f32; 4]; layout.width as usize * layout.height as usize];
    for (k, r) in recs.iter().enumerate() {
        let i = k * TEXELS_PER_OP as usize;
        texels[i..i + 2].copy_from_slice(&r.texels());
    }
    Some(OpTexels {
        width: layout.width,
        height: layout.height,
        ops_per_row: layout.ops_per_row,
        op_count: recs.len() as u32,
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
            assert_eq!(
                [t.texels[i], t.texels[i + 1]],
                encode_op(&d.ops[k]).expect("one record").texels()
            );
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
