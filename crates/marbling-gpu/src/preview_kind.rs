//! The live preview's pipeline variants: one per kind of pending op, each compiled with
//! only that kind's inverse (`pending_back` in `shaders/preview.wgsl`).
//!
//! Why: the exact renderer's `op_back` switches on the op kind per op. A GPU runs only
//! the case the pixels take, but a software GPU (SwiftShader, which is what Chromium
//! uses where there is no GPU) runs every case for every pixel, masked. The preview
//! walks one op whose kind is known when the frame is recorded, so it need not switch:
//! in headless Chromium on SwiftShader the specialised preview draws a tine drag frame
//! over 1024×768 about 13 ms faster (docs/BENCHMARKS.md).

use crate::encode::GpuOp;
use marbling_core::OpKind;

/// Which inverse a preview pipeline walks for its pending op.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PreviewKind {
    /// No pending op: the cache alone.
    Idle,
    /// Drops and spray droplets (`drop_back`).
    Drop,
    /// Tines and rakes (`comb_back`).
    Comb,
    /// Wavy combs (`wave_back`).
    Wave,
    /// Circular combs and vortices (`swirl_back`).
    Swirl,
    /// Shifts and turns (`rigid_back`).
    Rigid,
    /// Jiggles (`jiggle_back`).
    Jiggle,
}

impl PreviewKind {
    /// Every variant, in the order of [`PreviewKind::index`].
    pub const ALL: [PreviewKind; 7] = [
        PreviewKind::Idle,
        PreviewKind::Drop,
        PreviewKind::Comb,
        PreviewKind::Wave,
        PreviewKind::Swirl,
        PreviewKind::Rigid,
        PreviewKind::Jiggle,
    ];

    /// The variant that walks `pending` (by the kind its record carries).
    pub fn of(pending: Option<&GpuOp>) -> Self {
        match pending.and_then(GpuOp::kind) {
            Some(OpKind::Drop | OpKind::Spray) => PreviewKind::Drop,
            Some(OpKind::Comb) => PreviewKind::Comb,
            Some(OpKind::Wave) => PreviewKind::Wave,
            Some(OpKind::Circular | OpKind::Vortex) => PreviewKind::Swirl,
            Some(OpKind::Rigid) => PreviewKind::Rigid,
            Some(OpKind::Jiggle) => PreviewKind::Jiggle,
            // No pending op: the cache alone. Finite combs, styli and flows span several
            // records and are never a pending op ([`crate::encode::encode_op`] gives
            // none for them; the app draws them exactly), nor are records of unknown
            // kind made.
            Some(OpKind::Tines | OpKind::Stylus | OpKind::Flow) | None => PreviewKind::Idle,
        }
    }

    /// Position in [`PreviewKind::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// Short name, for pipeline labels and test messages.
    pub fn name(self) -> &'static str {
        match self {
            PreviewKind::Idle => "idle",
            PreviewKind::Drop => "drop",
            PreviewKind::Comb => "comb",
            PreviewKind::Wave => "wave",
            PreviewKind::Swirl => "swirl",
            PreviewKind::Rigid => "rigid",
            PreviewKind::Jiggle => "jiggle",
        }
    }

    /// The WGSL definition of `pending_back` for this variant (appended to preview.wgsl):
    /// a call of this kind's inverse from common.wgsl, or no move at all when idle.
    pub fn pending_back(self) -> String {
        let body = match self {
            PreviewKind::Idle => "vec3<f32>(p, 0.0)",
            PreviewKind::Drop => "drop_back(a, b, p)",
            PreviewKind::Comb => "comb_back(a, b, p)",
            PreviewKind::Wave => "wave_back(a, b, p)",
            PreviewKind::Swirl => "swirl_back(a, b, p)",
            PreviewKind::Rigid => "rigid_back(a, b, p)",
            PreviewKind::Jiggle => "jiggle_back(a, b, p)",
        };
        format!(
            "fn pending_back(a: vec4<f32>, b: vec4<f32>, p: vec2<f32>) -> vec3<f32> {{\n    return {body};\n}}\n"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::encode::encode_op;
    use marbling_core::Design;

    #[test]
    fn every_op_kind_gets_the_variant_with_its_inverse() {
        let json = r##"{"version":3,"width":100,"height":80,"background":"#ffffff","ops":[
            {"type":"drop","center":[50,40],"radius":10,"color":"#112233"},
            {"type":"spray","center":[20,30],"radius":3,"color":"#112233"},
            {"type":"tine","origin":[0,40],"direction":[1,0],"alpha":10,"lambda":8},
            {"type":"rake","origin":[0,40],"direction":[1,0],"alpha":10,"lambda":8,"spacing":20},
            {"type":"wavy","angle":0.5,"amplitude":5,"wavelength":30,"phase":0},
            {"type":"circular","center":[50,40],"radius":20,"alpha":10,"lambda":8},
            {"type":"vortex","center":[50,40],"alpha":10,"lambda":8},
            {"type":"shift","offset":[3,4]},
            {"type":"turn","center":[50,40],"angle":0.3},
            {"type":"jiggle","angle":0.2,"wavelength":40,"along":2,"across":5,"phase":0}
        ]}"##;
        let design = Design::from_json(json).expect("valid design");
        let kinds: Vec<PreviewKind> = design
            .ops
            .iter()
            .map(|op| PreviewKind::of(encode_op(op).as_ref()))
            .collect();
        use PreviewKind::*;
        assert_eq!(
            kinds,
            [
                Drop, Drop, Comb, Comb, Wave, Swirl, Swirl, Rigid, Rigid, Jiggle
            ]
        );
        assert_eq!(PreviewKind::of(None), Idle);
        assert_eq!(
            PreviewKind::of(Some(&GpuOp {
                a: [99.0, 0.0, 0.0, 0.0],
                b: [0.0; 4]
            })),
            Idle
        );
    }

    #[test]
    fn indices_follow_all() {
        for (i, k) in PreviewKind::ALL.into_iter().enumerate() {
            assert_eq!(k.index(), i, "{}", k.name());
        }
    }
}
