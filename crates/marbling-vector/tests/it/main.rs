//! The integration tests of `marbling-vector`, in one test binary (one link instead of one per
//! file): each module is one area, named as its file.

mod agreement;
mod comparator;
mod contour;
mod exact;
mod lossy;
mod resumable;
mod svg_resvg;
mod tolerance;
