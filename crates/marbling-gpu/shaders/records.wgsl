// The walk over a design's op records, newest → oldest (prepended after common.wgsl
// to the exact renderer and the per-op test). Ops of one record are walked with
// common.wgsl's `op_back`; finite combs and styli, which span several records, with
// `several_back` of several.wgsl, or of several_off.wgsl (`SEVERAL_ENABLED` false) in
// the variant for designs that have none, which so compiles none of their code (a
// software GPU runs every branch). The including module defines
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
        if SEVERAL_ENABLED && (kind == KIND_TINES || kind == KIND_STYLUS) {
            let s = several_back(at, r, p);
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
