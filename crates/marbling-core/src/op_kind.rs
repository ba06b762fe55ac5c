//! The kinds of compiled op, by the code each carries to the GPU: one list for the CPU
//! walk, the GPU record (marbling-gpu's `GpuOp`), the shaders' `KIND_…` constants (a
//! test checks them against this list) and the live preview's pipeline variants.

/// Which formula a compiled op applies. The discriminant is the code the GPU record
/// carries (as an exact small f32) and the shaders compare with.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OpKind {
    /// An ink drop pushing older ink outwards.
    Drop = 0,
    /// A spray droplet (ink without deformation).
    Spray = 1,
    /// A tine or a rake (a comb of parallel tine lines).
    Comb = 2,
    /// A wavy comb.
    Wave = 3,
    /// A circular comb.
    Circular = 4,
    /// A vortex.
    Vortex = 5,
    /// A shift or a turn (a rigid motion of the tank).
    Rigid = 6,
    /// A finite comb of tines at listed offsets.
    Tines = 7,
    /// A jiggle.
    Jiggle = 8,
    /// A stylus stroke.
    Stylus = 9,
    /// A flow along a curl noise.
    Flow = 10,
}

impl OpKind {
    /// Every kind, in code order.
    pub const ALL: [OpKind; 11] = [
        OpKind::Drop,
        OpKind::Spray,
        OpKind::Comb,
        OpKind::Wave,
        OpKind::Circular,
        OpKind::Vortex,
        OpKind::Rigid,
        OpKind::Tines,
        OpKind::Jiggle,
        OpKind::Stylus,
        OpKind::Flow,
    ];

    /// The code carried to the GPU.
    pub fn code(self) -> u32 {
        self as u32
    }

    /// The kind of a code, if any.
    pub fn from_code(code: u32) -> Option<Self> {
        Self::ALL.get(code as usize).copied()
    }

    /// The name of the shaders' constant for this kind (`KIND_DROP`, …).
    pub fn wgsl_name(self) -> &'static str {
        match self {
            OpKind::Drop => "KIND_DROP",
            OpKind::Spray => "KIND_SPRAY",
            OpKind::Comb => "KIND_COMB",
            OpKind::Wave => "KIND_WAVE",
            OpKind::Circular => "KIND_CIRCULAR",
            OpKind::Vortex => "KIND_VORTEX",
            OpKind::Rigid => "KIND_RIGID",
            OpKind::Tines => "KIND_TINES",
            OpKind::Jiggle => "KIND_JIGGLE",
            OpKind::Stylus => "KIND_STYLUS",
            OpKind::Flow => "KIND_FLOW",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_positions_and_round_trip() {
        for (i, k) in OpKind::ALL.into_iter().enumerate() {
            assert_eq!(k.code() as usize, i);
            assert_eq!(OpKind::from_code(k.code()), Some(k));
        }
        assert_eq!(OpKind::from_code(11), None);
    }
}
