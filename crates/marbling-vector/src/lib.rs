//! Vector export of marbling designs. Ink outlines come from one of two methods, chosen
//! per design and per region:
//!
//! * **The contour method** reads every region's visible outline off the exact label
//!   raster (which ink each point of a T/4 grid holds, found by the CPU walk) by
//!   marching squares. It is used for every region when that raster costs at most
//!   `contour_all` op-samples (measured on probes: a few seconds), because it is the
//!   more faithful where inks abut: it grows older ink under newer, and it places each
//!   edge for the sRGB blending of SVG renderers.
//! * **Forward tracing** carries each drop's and spray's outline through all later ops
//!   (the "Vector Image Output" section of Lu, Jaffer, Jin, Zhao & Mao 2012), refined
//!   adaptively and simplified within a stated bound. It is resolution independent and
//!   used when the raster would cost more; its vertex count grows with the total
//!   filament length, geometrically with the op count, so regions whose outlines grow
//!   past a vertex budget are handed to the contour method.
//!
//! Pixels where three or more inks meet, and schema v2 noise and grain, become raster
//! layers. The result is written as SVG or rasterised with tiny-skia. A faithful
//! picture at tolerance T never needs more vertices than the ink boundaries visible at
//! T, and that is what the contour method costs.
//!
//! # Forward tracing (op by op)
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
//! 3. **Re-anchoring (bounds the cost of a new point).** Every `anchor` ops (default 32)
//!    each segment's source becomes the quadratic through its start, probe and end, so a
//!    point inserted later is carried through at most `anchor` ops instead of all ops
//!    since its ink was laid.
//! 4. **Vertex budget → contour method.** Whenever more than `max_live`/min(T, 1)
//!    vertices (default 60 000, 240 000 at T = 0.25) are held after an op, the regions
//!    holding the most are handed to the contour method until at most half the budget is
//!    held ([`TraceStats::contour_regions`]); within the last 16 ops the budget grows
//!    as 16 / (ops left), since finishing costs the vertices held times the ops left.
//!    Nothing is coarsened: a region is either traced within the limits above or
//!    contoured.
//! 5. **The thin step (optional, off by default).** With `thin` > 0, whenever a region
//!    has grown by half, each ring is *pinched* where a vertex lies within w = `thin`·T
//!    of a distant segment of the same ring (an exact cut), and pieces of mean width
//!    2·|area|/perimeter below w are dropped ([`TraceStats::dropped_area`]).
//! 6. **Simplification** ([`simplify`]). Runs of vertices in one half-plane outside the
//!    canvas collapse to their end points; then Ramer–Douglas–Peucker removes every
//!    vertex within `epsilon`·T of the segment replacing it, unless the shortcut would
//!    sweep over another part of the same ring.
//!
//! # The contour method ([`contour`], [`labels`], [`dense`])
//! 1. **Label raster.** Every point of a square grid of spacing `contour_step`·T output
//!    pixels (default T/4: at T = 1 the 4×4 grid of the reference's `grid4`
//!    antialiasing) is walked back through all ops like the CPU renderer's samples,
//!    giving the ink (or the background) it holds. One point in 4×4 is walked first;
//!    the rest only in blocks where those disagree or next to such blocks.
//! 2. **Dense pixels.** An output pixel whose grid points hold three or more labels has
//!    detail finer than T that no stack of antialiased fills reproduces (a fill blends
//!    by coverage as if spread evenly over what lies beneath); so does a pixel with three
//!    such neighbours. These pixels go into one RGBA patch at the output size, coloured
//!    as the mean of their grid points in linear light (the reference's 4×4 colour at
//!    T = 1, to 2/255), drawn over the outlines (`data-method="raster"`).
//! 3. **Marching squares** on each handed region's mask, tile by tile: its own points,
//!    grown `contour_reach` (1.5 output pixels) into newer ink and the patch, never into
//!    older ink. Newer paint covers the growth, so an older region continues under a
//!    newer one and abutting edges leave no antialiased seam. Crossings sit at grid-edge
//!    midpoints, except that a visible edge between two inks moves up to 0.45 grid
//!    steps into the darker one ([`contour::srgb_blend_shift`]): SVG renderers blend an
//!    edge pixel on sRGB codes, and the lighter ink must cover more of it to show the
//!    linear-light mean the reference shows. Rings are directed so that holes wind
//!    opposite to outer rings (nonzero fill).
//! 4. **Simplification**: RDP within one grid step where the ring shows, within half
//!    the growth where newer paint covers it.
//!
//! # Painter's order
//! The background rectangle (and a noise or image background's raster underlay) first, then one
//! filled path per drop or spray in op order whichever method drew it (`data-method`
//! `forward` or `contour`), nonzero rule, then the dense patch, then grain multiplied
//! over everything ([`surface_layers`]). A forward outline encloses its whole region
//! as traced: a later drop is drawn over the hole it pushes into older ink, so forward
//! outlines need no holes.
//!
//! # Tolerance contract (output pixels, `T` = [`TraceOptions::tolerance`])
//! Lengths are output pixels: design pixels × [`TraceOptions::scale`]. Defaults:
//! `deviation` = `epsilon` = 0.04, `chord` = 4, `thin` = 0, `anchor` = 32,
//! `max_live` = 60 000, `contour_all` = 4·10⁹ op-samples, `contour_step` = ¼,
//! `contour_reach` = 1.5.
//!
//! **Forward regions** (exact with `anchor = 0`, `marbling svg --exact`): every vertex
//! and probe is the forward image of a point of the drop's rim, exact to f64 rounding.
//! After the last op every segment on the canvas is at most `chord`·T long and its
//! probe lies within `deviation`·T of it; simplification moves the outline by at most
//! `epsilon`·T; SVG coordinates are rounded to a grid of at most T/50. Between probes
//! the bound is sampled, not proved (one probe per segment, checked after every op). So
//! a canvas point further than about (`deviation` + `epsilon`)·T ≈ T/12 from every
//! true outline gets the right ink. Re-anchoring replaces the true outline between
//! three exact samples by a quadratic within a fraction of `deviation`·T; later ops
//! carry that sliver like ink (area preserved).
//!
//! **Contour regions**: a crossing lies between two grid points (spacing
//! h = `contour_step`·T) holding different labels, so before simplification every grid
//! point lies on the right side of its region's outline and a boundary is placed
//! within h of the true one along each grid line; simplification moves a visible
//! boundary by at most h more (T/4 + T/4 by default), and SVG coordinates are rounded to
//! T/10. An island or filament that touches no walked point of a 3×3 block of coarse
//! cells (4h each) is missed. The dense patch holds each such pixel's grid colour.
//!
//! **Measured** at T = 1 against the exact 4×4 render, the SVG rendered by resvg:
//! random mixed, drop-heavy and comb-heavy designs (chaotic at full comb strength) up to
//! 1,000 ops differ in at most 2 % of pixels by more than 48/255 (the agreement tests;
//! `make bench-svg` for 1024²). Part of what remains is that SVG renderers blend
//! antialiased edges in sRGB while the reference averages in linear light.
//!
//! **Vertex counts.** After simplification an arc of curvature radius R output pixels
//! keeps about one vertex per √(8·R·ε) of length (ε = `epsilon`·T forward, h for
//! contours). The contour method costs the visible boundary length at that resolution,
//! not a function of the op count. [`TraceOptions::max_vertices`] bounds forward
//! refinement absolutely: beyond it the design is refused ([`VectorError::TooComplex`]).

mod canvas;
mod cellhash;
pub mod contour;
mod curve;
pub mod dense;
mod error;
mod guard;
pub mod labels;
mod ngon;
mod options;
mod outline;
mod pinch;
mod raster;
pub mod reference;
mod ring;
pub mod simplify;
pub mod surface_layers;
mod svg;
mod trace;

pub use canvas::{Canvas, MARGIN_PX};
pub use error::VectorError;
pub use ngon::initial_sides;
pub use options::TraceOptions;
pub use outline::{Method, Outline, TraceStats, VectorDesign};
pub use raster::{Blend, rasterize, render_vector};
pub use svg::{design_to_svg, to_svg};
pub use trace::{Tracer, check_traceable, trace, trace_with_progress};
