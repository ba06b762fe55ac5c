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
//!    mapped through that op ([`marbling_core::CompiledOp::forward`], f64). A segment is
//!    bisected at its probe while its chord is longer than `chord`·T or its probe lies
//!    further than `deviation`·T from the chord; the two new probes are the source
//!    curve's points at the quarter parameters, carried through every op since the
//!    curve was anchored. Off the canvas (enlarged by 2 output pixels) both limits relax
//!    to the distance from it. Two consecutive segments well within half the limits
//!    merge back (checked every fourth op).
//! 3. **Re-anchoring (lossy, bounded cost).** Every `anchor` ops (default 16) each
//!    segment's source becomes the quadratic through its start, probe and end, so a
//!    point inserted later is carried through at most `anchor` ops. Merged segments get
//!    the same kind of source.
//! 4. **The thin step (lossy, bounded count).** Whenever a region has grown by half
//!    since the last time (and after the last op), each ring is *pinched*: where a
//!    vertex lies within w = `thin`·T of a segment of the same ring more than
//!    max(4w, 2·`chord`·T) of arc away, the ring is cut along the short chord into two
//!    rings. Cutting is exact (the chord is traversed once each way, so winding numbers
//!    add up to the original's everywhere). Pieces whose mean width 2·|area|/perimeter
//!    is below w are then dropped: filaments of ink, and thin gaps of other ink inside
//!    a region, narrower than w.
//! 5. **Simplification** ([`simplify`]). Runs of vertices in one half-plane outside the
//!    canvas collapse to their end points; then Ramer–Douglas–Peucker removes every
//!    vertex within `epsilon`·T of the segment replacing it, unless the shortcut would
//!    sweep over another part of the same ring.
//! 6. **Painter's order.** The background rectangle first, then one filled path per
//!    drop or spray in op order (later inks over earlier), its rings as subpaths,
//!    nonzero rule. A later drop is drawn over the hole it pushes into older ink, so
//!    older outlines need no holes.
//!
//! # Tolerance contract (output pixels, `T` = [`TraceOptions::tolerance`])
//! Lengths are output pixels: design pixels × [`TraceOptions::scale`]. Defaults:
//! `deviation` = `epsilon` = 1/8, `chord` = 4, `thin` = 1/4, `anchor` = 16.
//!
//! **What T guarantees** (the exact part, `thin = 0`, `anchor = 0`): every vertex and
//! probe is the exact forward image of a point of the drop's rim (to f64 rounding). After
//! the last op every segment on the canvas is at most `chord`·T long and its probe lies
//! within `deviation`·T of it; simplification moves the outline by at most `epsilon`·T
//! (Hausdorff distance between refined and simplified polyline inside the canvas,
//! exact); SVG coordinates are rounded to a grid of at most T/50. Between probes the
//! bound is sampled, not proved (no sampling-based flattener of an arbitrary map can
//! prove it). So a canvas point further than about (`deviation` + `epsilon`)·T = T/4
//! from every true outline gets the right ink. Outside the canvas enlarged by 2 output
//! pixels an outline is only guaranteed to stay outside: collapsing a run in one
//! half-plane changes the fill only inside that half-plane.
//!
//! **What the lossy steps give up** (defaults):
//! * *Thin pieces.* Dropped pieces had mean width below T/4 when dropped. All seven ops
//!   preserve area, so the dropped ink keeps its area ([`TraceStats::dropped_area`],
//!   design px²) through every later op; later ops usually stretch it thinner still (a
//!   shear can widen a filament by at most the factor it shortens it). Pixels that may
//!   differ are those such a piece crosses: a filament of width w < T/4 covers under a
//!   quarter of each pixel it crosses at scale 1, so with the 48/255 threshold of the
//!   agreement test only high-contrast pixels hit by a point sample change. Ink pushed
//!   off the canvas and ink later covered by newer drops count in `dropped_area` too, so
//!   it overstates the visible loss.
//! * *Re-anchoring.* Between its three exact samples a segment's true outline is
//!   replaced by a quadratic; on a segment within the limits above the two differ by a
//!   fraction of `deviation`·T. Later ops carry that difference like any other ink:
//!   the sliver between the two curves keeps its area, so it stays a sliver.
//! * Regions pushed so far off the canvas that they only come back through later ops
//!   are refined with relaxed limits while off it (exact points, coarser polygon).
//!
//! The agreement test measures the whole: 21 random designs of up to 300 ops, T = 1,
//! at most 1 % of pixels differing by more than 48/255 from the CPU reference.
//!
//! **Vertex counts.** After simplification an arc of curvature radius R output pixels
//! keeps about one vertex per √(8·R·`epsilon`·T) of length; off the canvas a run costs
//! two vertices. Without the thin step counts follow the total filament length, which
//! grows geometrically with the number of strokes; with it they follow the visible
//! structure wider than T/4. [`TraceOptions::max_vertices`] bounds the live count while
//! tracing; beyond it the design is refused ([`VectorError::TooComplex`]).

mod canvas;
mod cellhash;
mod curve;
mod error;
mod guard;
mod ngon;
mod options;
mod outline;
mod pinch;
mod preview;
pub mod refine;
mod ring;
pub mod simplify;
mod svg;
mod trace;

pub use canvas::{Canvas, MARGIN_PX};
pub use error::VectorError;
pub use ngon::initial_sides;
pub use options::TraceOptions;
pub use outline::{Outline, TraceStats, VectorDesign};
pub use preview::{Blend, preview, render_vector};
pub use svg::{design_to_svg, to_svg};
pub use trace::{check_traceable, trace, trace_with_progress};
