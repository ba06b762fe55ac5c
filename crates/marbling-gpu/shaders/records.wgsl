// The walk over a design's op records, newest → oldest (prepended after common.wgsl
// to the exact renderer and the per-op test). Schema v1's ops are walked with
// common.wgsl's `op_back`; schema v3's (shift, turn, jiggle, and the finite comb and
// stylus, which span several records) with `v3_back` of ops_v3.wgsl, or of
// ops_v3_off.wgsl (`V3_ENABLED` false) in the variant for designs that have none,
// which so compiles none of their code. The including module defines
// `fn op_record(i: u32) -> OpRecord`: record i of the stream (render.wgsl reads the op
// texture).

struct OpRecord {
    a: vec4<f32>,
    b: vec4<f32>,
}

// Where a walk ended: the point, whether ink covered it there and that ink's colour
// (linear r, g, b, packed sRGB).
struct WalkEnd {
    p: vec2<f32>,
    covered: bool,
    ink: vec4<f32>,
}

// Walks `p0` back through records [first, end).
fn walk_records(first: u32, end: u32, p0: vec2<f32>) -> WalkEnd {
    var p = p0;
    // One past the next record to walk.
    var i = end;
    var covered = false;
    var ink = vec4<f32>(0.0);
    while i > first && !covered {
        let at = i - 1u;
        let r = op_record(at);
        let kind = u32(r.a.x);
        // Records this op spans (header and data).
        var span = 1u;
        if V3_ENABLED && kind >= KIND_RIGID {
            let s = v3_back(at, r, p);
            p = s.xy;
            span = u32(s.z);
        } else {
            let s = op_back(r.a, r.b, p);
            if s.z > 0.0 {
                covered = true;
                ink = r.b;
            } else {
                p = s.xy;
            }
        }
        i -= span;
    }
    return WalkEnd(p, covered, ink);
}
