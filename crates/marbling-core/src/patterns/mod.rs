//! Traditional marbled-paper patterns as recipes: each builds a design from drops and
//! tools step by step, the way a marbler makes the paper, with a name, a line of
//! history and a caption for every step (see [`crate::Recipe`]).
//!
//! The recipes are written for a 640 × 400 tank and scale with [`Params`] (size,
//! colours, comb spacing, seed). `examples/patterns/ID.json` holds each one at its
//! defaults; the app bundles those files and `marbling pattern` writes any variant.

mod combed;
mod drawn;
mod maker;
mod thrown;

pub use maker::Maker;

use crate::{Design, Recipe, Rgb8};

/// What a recipe may be asked for; `None` fields take the pattern's defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    /// Tank width, design pixels.
    pub width: u32,
    /// Tank height, design pixels.
    pub height: u32,
    /// Colour of the bath.
    pub background: Option<Rgb8>,
    /// Inks in the order they are thrown (cycled where a recipe needs more).
    pub colors: Option<Vec<Rgb8>>,
    /// Spacing of the finest comb, design pixels at this size.
    pub spacing: Option<f64>,
    /// Seed of the throws' scatter.
    pub seed: u64,
}

impl Default for Params {
    fn default() -> Self {
        Self {
            width: REFERENCE_WIDTH as u32,
            height: REFERENCE_HEIGHT as u32,
            background: None,
            colors: None,
            spacing: None,
            seed: 1,
        }
    }
}

/// The tank the recipes are written for, design pixels.
pub const REFERENCE_WIDTH: f64 = 640.0;
/// The tank the recipes are written for, design pixels.
pub const REFERENCE_HEIGHT: f64 = 400.0;

/// One traditional pattern.
pub struct Pattern {
    /// File name in `examples/patterns/` and the CLI's name for it ("gel-git").
    pub id: &'static str,
    /// Name shown to people ("Gel-git").
    pub name: &'static str,
    /// Where the pattern comes from, one line.
    pub history: &'static str,
    /// Default bath colour.
    pub background: Rgb8,
    /// Default inks in throwing order.
    pub colors: &'static [Rgb8],
    /// Default spacing of the finest comb at 640 × 400, design pixels.
    pub spacing: f64,
    /// The making, step by step.
    make: fn(&mut Maker),
}

impl Pattern {
    /// The pattern made with `params`: a valid design with its recipe. Errors name
    /// the parameter that cannot be used.
    pub fn design(&self, params: &Params) -> Result<Design, String> {
        let mut m = Maker::new(self, params)?;
        (self.make)(&mut m);
        let design = m.finish(Recipe {
            name: self.name.into(),
            history: self.history.into(),
            captions: Vec::new(),
        });
        design
            .validate()
            .map_err(|e| format!("pattern {} with these parameters: {e}", self.id))?;
        Ok(design)
    }
}

/// Every pattern, in gallery order.
pub fn all() -> Vec<&'static Pattern> {
    let mut list: Vec<&'static Pattern> = Vec::new();
    list.extend(thrown::PATTERNS.iter());
    list.extend(combed::PATTERNS.iter());
    list.extend(drawn::PATTERNS.iter());
    list
}

/// The pattern called `id`, or an error listing the names.
pub fn find(id: &str) -> Result<&'static Pattern, String> {
    all().into_iter().find(|p| p.id == id).ok_or_else(|| {
        let ids: Vec<&str> = all().iter().map(|p| p.id).collect();
        format!("unknown pattern {id:?}; expected one of {}", ids.join(", "))
    })
}

const fn rgb(hex: u32) -> Rgb8 {
    Rgb8::new((hex >> 16) as u8, (hex >> 8) as u8, hex as u8)
}
