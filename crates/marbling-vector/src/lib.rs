//! Vector export of marbling designs: every ink drop and spray is traced *forward*
//! through all later operations as a closed outline, refined adaptively, simplified
//! within a stated bound, and written as SVG or rasterised with tiny-skia.
//!
//! This follows the "Vector Image Output" section of Lu, Jaffer, Jin, Zhao & Mao (2012)
//! and bounds the growth of vertex counts that the paper leaves open.
//!
//! # Pipeline
//! 1. **Initial polygon.** A drop or spray of radius r starts as the regular n-gon
//!    inscribed in its circle, with n the smallest count whose sagitta
//!    r·s·(1 − cos(π/n)) is at most T/4 output pixels ([`initial_sides`]), at least 8.
//! 2. **Forward map.** Every vertex, identified by its angle θ on the original circle,
//!    is mapped through every later op (`Op::forward`, exact f64).
//! 3. **Adaptive refinement** ([`refine`]). A segment between mapped vertices θa, θb
//!    is split at the original-arc midpoint (θa + θb)/2 while its mapped chord is longer
//!    than T output pixels or the mapped points at a quarter, half or three quarters of
//!    its arc lie further than T/4 output pixels from the chord, down to [`TraceOptions::max_depth`] bisections of an initial
//!    segment. Segments whose three points lie in one half-plane beyond the canvas
//!    (see "Off-canvas parts" below) are refined only to a spacing of their distance
//!    from the canvas.
//! 4. **Simplification** ([`simplify`]). Runs of vertices in one half-plane outside the
//!    canvas collapse to their end points; then Ramer–Douglas–Peucker removes every
//!    vertex that lies within T/4 output pixels of the segment replacing it, unless the
//!    shortcut would sweep over another part of the same outline (so filaments thinner
//!    than T/4 keep both sides instead of folding into crossing zig-zags).
//! 5. **Painter's order.** The background rectangle first, then one filled region per
//!    drop or spray in op order (later inks over earlier), filled with the nonzero rule.
//!    A later drop is drawn over the hole it pushes into older ink, so older outlines
//!    need no holes.
//!
//! # Tolerance contract (output pixels, `T` = [`TraceOptions::tolerance`])
//! Lengths are output pixels: design pixels × [`TraceOptions::scale`].
//! * Every refined segment spans at most T, and the true outline at its parameter
//!   quarter, half and three-quarter points lies within T/4 of it. Between those samples
//!   the bound is not proved (no sampling-based flattener of an arbitrary map can); tests
//!   measure 32 forward points per segment: typically within T/4, worst 0.66·T where an
//!   outline passes very close to a later drop's centre (the forward map stretches that
//!   tiny arc around the whole drop); they assert T.
//!   Segments still too long after `max_depth` bisections (near a later drop's centre,
//!   where the forward map stretches without bound) are counted in
//!   [`TraceStats::capped`] instead of refined further.
//! * Simplification moves the outline by at most T/4 (the Hausdorff distance between the
//!   refined and the simplified polyline inside the canvas, exact), so the exported
//!   outline is within T/2 of the true one at every sample (about 0.9·T with the measured
//!   worst case between samples), and any canvas point further than that from the true
//!   outline gets the right ink. SVG coordinates are rounded to a grid of at most T/50,
//!   adding at most 0.015·T.
//! * **Off-canvas parts.** Outside the canvas enlarged by a margin of 2 output pixels,
//!   the outline is only guaranteed to stay outside: a run of consecutive vertices in one
//!   half-plane beyond an edge is replaced by the chord between its end points, which
//!   changes the filled area only inside that (convex) half-plane. An outline with every
//!   vertex in one such half-plane is invisible and dropped ([`TraceStats::culled`]).
//! * Vertex counts: after simplification an arc of curvature radius R output pixels
//!   keeps about one vertex per √(2·R·T) of length (a whole circle ≈ π·√(2R/T)
//!   vertices), independent of how finely refinement sampled it; off the canvas a run
//!   costs two vertices whatever its length. Halving T multiplies on-canvas counts by
//!   about √2 after simplification and by about 2 before it. The exception is ink
//!   stretched into filaments thinner than T/4 (many strong combs): both sides of a
//!   filament are kept at spacing ≤ T, so counts follow the filaments' total length,
//!   which grows with every comb stroke; [`TraceOptions::max_vertices`] bounds it.

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
