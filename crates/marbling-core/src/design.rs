//! The design document: canvas size, background and the history of operations.

use crate::{GestureSpan, ImageBackground, NoiseBackground, Op, Overlay, Rgb8};

/// Largest accepted canvas side, design pixels.
pub const MAX_SIDE: u32 = 16_384;
/// Largest accepted number of operations in one design.
pub const MAX_OPS: usize = 100_000;
/// The newest schema version this crate writes (designs that need none of its
/// additions are still written as version 1, see [`Design::version`]).
pub const CURRENT_VERSION: u64 = 4;
/// Every schema version this crate reads.
pub const SUPPORTED_VERSIONS: &[u64] = &[1, 2, 3, 4];

/// A marbled design: its history of operations, oldest first, on a plain or noise
/// background, with optional grain overlays (schema v2; see [`crate::surface`] for
/// the exact colour rules).
///
/// Coordinates are design pixels, origin top-left, x right, y down; angles in radians.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// Canvas width, design pixels, 1..=[`MAX_SIDE`].
    pub width: u32,
    /// Canvas height, design pixels, 1..=[`MAX_SIDE`].
    pub height: u32,
    /// Colour of the tank before any ink. With a [`Design::background_noise`] this is
    /// only the colour that stands for it where one colour is needed (set by
    /// [`Design::set_background_noise`] and by the reader to the palette's middle).
    pub background: Rgb8,
    /// Schema v2: a noise texture mapped to a palette, marbled like ink; `None` for a
    /// plain [`Design::background`].
    pub background_noise: Option<NoiseBackground>,
    /// Schema v2: a picture marbled like ink (see [`crate::image_background`]), with
    /// [`Design::background`] as the paper around a letterboxed one; `None` for none.
    /// A design has at most one of a noise and an image background.
    pub background_image: Option<ImageBackground>,
    /// Schema v2: grain overlays applied after marbling, in order.
    pub overlays: Vec<Overlay>,
    /// Operations, oldest first.
    pub ops: Vec<Op>,
    /// Runs of two or more ops made by one gesture, sorted and disjoint (see
    /// [`crate::GestureSpan`]); every other op is a gesture of its own.
    pub gestures: Vec<GestureSpan>,
    /// The pattern recipe the design was made from: name, history, step captions (any
    /// schema version; it does not change the picture).
    pub recipe: Option<crate::Recipe>,
}

impl Design {
    /// An empty design of the given size and background.
    pub fn new(width: u32, height: u32, background: Rgb8) -> Self {
        Self {
            width,
            height,
            background,
            background_noise: None,
            background_image: None,
            overlays: Vec::new(),
            ops: Vec::new(),
            gestures: Vec::new(),
            recipe: None,
        }
    }

    /// The schema version this design is written as: 4 when it holds a flow, else 3
    /// when it holds a v3 op, else 2 when it has a noise background or overlays, else 1
    /// (so v1, v2 and v3 documents and share links stay byte-identical).
    pub fn version(&self) -> u64 {
        if self.ops.iter().any(Op::is_v4) {
            4
        } else if self.ops.iter().any(Op::is_v3) {
            3
        } else if self.uses_v2() {
            2
        } else {
            1
        }
    }

    /// How many ops the design counts as toward [`MAX_OPS`] (every drop of a drop
    /// pattern counts).
    pub fn counted_ops(&self) -> usize {
        self.ops.iter().map(Op::counted_ops).sum()
    }

    /// Whether the design uses a schema v2 feature (noise or image background, or
    /// overlays), which only raster renderers draw exactly.
    pub fn uses_v2(&self) -> bool {
        self.background_noise.is_some()
            || self.background_image.is_some()
            || !self.overlays.is_empty()
    }

    /// What a sample's noise background and grain overlays cost a GPU beyond the walk
    /// through the ops, in simple ops walked ([`marbling_noise::NoiseSpec::sample_cost`];
    /// 0 without noise): renderers size their tiles by it with [`Op::walk_cost`].
    pub fn surface_cost(&self) -> u64 {
        let background = self.background_noise.iter().map(|b| &b.noise);
        background
            .chain(self.overlays.iter().map(|o| &o.noise))
            .map(|n| n.spec().sample_cost())
            .sum()
    }

    /// Sets a noise background (and [`Design::background`] to the colour that stands
    /// for it), or a plain one with `None`.
    pub fn set_background_noise(&mut self, noise: Option<NoiseBackground>) {
        if let Some(n) = &noise {
            self.background = n.mid_color();
            self.background_image = None;
        }
        self.background_noise = noise;
    }

    /// Sets a picture background (dropping a noise one; [`Design::background`] stays
    /// the paper around a letterboxed picture), or none with `None`.
    pub fn set_background_image(&mut self, image: Option<ImageBackground>) {
        if image.is_some() {
            self.background_noise = None;
        }
        self.background_image = image;
    }

    /// How many ops of each type, as `(type, count)` in [`crate::OP_TYPES`] order,
    /// omitting types that do not occur.
    pub fn op_counts(&self) -> Vec<(&'static str, usize)> {
        crate::OP_TYPES
            .iter()
            .map(|&t| (t, self.ops.iter().filter(|o| o.type_name() == t).count()))
            .filter(|&(_, n)| n > 0)
            .collect()
    }
}
