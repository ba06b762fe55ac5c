//! Vector export of marbling designs: every ink drop and spray is traced *forward*
//! through all later operations as closed outlines, refined adaptively, thinned by a
//! bounded lossy step, simplified within a stated bound, and written as SVG or
//! rasterised with tiny-skia.
//!
//! This follows the "Vector Image Output" section of Lu, Jaffer, Jin, Zhao & Mao (2012)
//! and bounds the growth of vertex counts that the paper leaves open.
//!
//! # Pipeline (op by op)
//! 1. **Initial polygon.** A drop or spray of radius r starts as the regular n-gon
//!    inscribed in its circle, with n the smallest count whose sagitta
//!    r·s·(1 − cos(π/n)) is at most T/4 output pixels ([`initial_sides`]), at least 8.
//!    Every segment carries a *probe*: the point of its source curve at its parameter
//!    midpoint.
//! 2. **Carry and refine.** At each later op, every vertex and probe of every region is
//!    mapped through that op ([`marbling_core::CompiledOp::forward`], f64; regions in
//!    parallel with rayon). A segment is bisected at its probe while its chord is longer
//!    than `chord`·T or its probe lies further than `deviation`·T from the chord; the
//!    two new probes are the source curve's points at the quarter parameters, carried
//!    through every op since the curve was anchored. Off the canvas (enlarged by 2 output
//!    pixels) both limits relax to the distance from it. Every fourth op, two
//!    consecutive halves of one source interval that are well within half the limits
//!    merge back.
//! 3. **Re-anchoring (lossy, bounds the cost of a new point).** Every `anchor` ops
//!    (default 32) each segment's source becomes the quadratic through its start, probe
//!    and end, so a point inserted later is carried through at most `anchor` ops
//!    instead of all ops since its ink was laid.
//! 4. **The thin step (lossy, bounds the count).** Whenever a region has grown by half
//!    since the last time (and after the last op), each ring is *pinched*: where a
//!    vertex lies within w = `thin`·T of a segment of the same ring more than
//!    max(4w, 2·`chord`·T) of arc away, the ring is cut along the short chord into two
//!    rings. Cutting is exact (the chord is traversed once each way, so winding numbers
//!    add up to the original's everywhere). Pieces whose mean width 2·|area|/perimeter
//!    is below w are then dropped: filaments of ink, and thin gaps inside a region,
//!    narrower than w on average.
//! 5. **Vertex budget.** Whenever more than `max_live`/min(T, 1) vertices (default
//!    60 000, 240 000 at T = 0.25) are held after an op, `deviation`, `thin` and
//!    `epsilon` double for the rest of the design (at most 4 times: w ≤ T, deviation and ε ≤ 0.64·T), every region is
//!    thinned at once, and any two neighbouring segments within half the limits may
//!    merge (their source becomes the quadratic through their three points).
//!    [`TraceStats::level`] says how often this happened; 0 for every design of the
//!    agreement test.
//! 6. **Simplification** ([`simplify`]). Runs of vertices in one half-plane outside the
//!    canvas collapse to their end points; then Ramer–Douglas–Peucker removes every
//!    vertex within `epsilon`·T of the segment replacing it, unless the shortcut would
//!    sweep over another part of the same ring.
//! 7. **Painter's order.** The background rectangle first, then one filled path per
//!    drop or spray in op order (later inks over earlier), its rings as subpaths,
//!    nonzero rule. A later drop is drawn over the hole it pushes into older ink, so
//!    older outlines need no holes.
//!
//! # Tolerance contract (output pixels, `T` = [`TraceOptions::tolerance`])
//! Lengths are output pixels: design pixels × [`TraceOptions::scale`]. Defaults:
//! `deviation` = `epsilon` = 0.04, `chord` = 4, `thin` = 1/16, `anchor` = 32,
//! `max_live` = 60 000.
//!
//! **What T guarantees** (the exact mode: `thin = 0`, `anchor = 0`, `max_live` =
//! `usize::MAX`, `marbling svg --exact`): every vertex and probe is the forward image of
//! a point of the drop's rim, exact to f64 rounding. After the last op every segment on
//! the canvas is at most `chord`·T long and its probe lies within `deviation`·T of it;
//! simplification moves the outline by at most `epsilon`·T (Hausdorff distance between
//! refined and simplified polyline inside the canvas, exact); SVG coordinates are
//! rounded to a grid of at most T/50. Between probes the bound is sampled, not proved
//! (no sampling-based flattener of an arbitrary map can prove it; one probe per
//! segment, checked after every op). So a canvas point further than about
//! (`deviation` + `epsilon`)·T ≈ T/12 from every true outline gets the right ink.
//! Outside the canvas enlarged by 2 output pixels an outline is only guaranteed to stay
//! outside: collapsing a run in one half-plane changes the fill only inside it.
//!
//! **What the lossy steps give up** (defaults):
//! * *Thin pieces.* A dropped piece had mean width below w when it was dropped. Every op
//!   but the jiggle preserves area, so the ink (or gap) it takes away keeps its area
//!   ([`TraceStats::dropped_area`], design px²) through every later op, and later ops
//!   usually stretch it thinner still (a shear can widen a filament only by the factor
//!   by which it shortens it). The pixels that may differ are those such a piece
//!   crosses: a filament of width w < T/16 covers a sixteenth of each pixel it crosses at
//!   scale 1, so with a point-sampled reference only the pixels where one of its samples
//!   hits the filament change, by a quarter of the colour contrast (RGSS). Ink pushed off
//!   the canvas and ink later covered by newer drops count in `dropped_area` too, so it
//!   overstates the visible loss.
//! * *Re-anchoring and approximate merges.* Between three exact samples the true outline
//!   is replaced by a quadratic; on a segment within the limits the two differ by a
//!   fraction of `deviation`·T. Later ops carry the sliver between them like any ink:
//!   it keeps its area, so the error does not grow in area, but it adds up over
//!   re-anchorings (measured: at most 0.15 percentage points of mismatch on the
//!   agreement designs).
//! * *Budget.* Past `max_live` vertices the limits above double up to four times, so a
//!   design with a nonzero [`TraceStats::level`] meets the contract at T·2^level only.
//!
//! The agreement test measures the whole at T = 1: 21 random designs (mixed and
//! drop-heavy up to 300 ops, comb-heavy up to 150), at most 1 % of pixels differing by
//! more than 48/255 from the CPU reference (worst 0.95 %). A 300-op comb-heavy design is
//! mostly filaments thinner than T/16 and differs in 6.6 % of pixels.
//!
//! **Vertex counts.** After simplification an arc of curvature radius R output pixels
//! keeps about one vertex per √(8·R·ε) of length (ε = `epsilon`·T); off the canvas a run
//! costs two vertices. Without the thin step counts follow the total filament length,
//! which grows geometrically with the number of strokes; with it they follow the
//! structure wider than w, and the budget caps what is held while tracing.
//! [`TraceOptions::max_vertices`] bounds it absolutely: beyond it the design is refused
//! ([`VectorError::TooComplex`]).

mod canvas;
mod cellhash;
mod curve;
mod error;
mod guard;
mod ngon;
mod options;
mod outline;
mod pinch;
mod raster;
pub mod reference;
mod ring;
pub mod simplify;
mod svg;
mod trace;

pub use canvas::{Canvas, MARGIN_PX};
pub use error::VectorError;
pub use ngon::initial_sides;
pub use options::TraceOptions;
pub use outline::{Outline, TraceStats, VectorDesign};
pub use raster::{Blend, rasterize, render_vector};
pub use svg::{design_to_svg, to_svg};
pub use trace::{check_traceable, trace, trace_with_progress};
