//! Drop patterns: many drops (or spray droplets) in one op, exactly the sequence of
//! single `drop` (or `spray`) ops i = 0, 1, … with colour `colors[i mod len]`.

use super::MIN_SCALED_RADIUS;
use super::OpType;
use super::rounding as round;
use super::{Drop, Op, Spray};
use crate::Rgb8;
use crate::caption::num;
use crate::caption::{plural, radii_text};
use crate::explain::{DROP_FORWARD, DROP_INVERSE, DROP_SYMBOLS, Formula, SPRAY_SYMBOLS, pt};
use crate::json::{FieldReader, FieldWriter};
use crate::validate::OpCheck;
use kurbo::Point;
use std::sync::Arc;

/// Most drops in one op.
pub const MAX_DROPS: usize = 10_000;

/// The radius of every drop, or one per drop.
#[derive(Clone, Debug, PartialEq)]
pub enum Radii {
    /// Every drop has this radius, design pixels (`"radius"`).
    One(f64),
    /// Drop i has radius i, design pixels (`"radii"`, as long as `centers`).
    Each(Arc<[f64]>),
}

/// Drops at `centers`, laid in order.
#[derive(Clone, Debug, PartialEq)]
pub struct DropSet {
    /// Centres, design pixels, in the order the drops fall; 1..=[`MAX_DROPS`].
    pub centers: Arc<[Point]>,
    /// Their radii.
    pub radii: Radii,
    /// Colours, cycled: drop i has `colors[i mod len]` (at least one).
    pub colors: Arc<[Rgb8]>,
}

impl DropSet {
    /// Number of drops.
    pub fn len(&self) -> usize {
        self.centers.len()
    }

    /// True when there are no drops (never for a valid op).
    pub fn is_empty(&self) -> bool {
        self.centers.is_empty()
    }

    /// Radius of drop `i` (0 past the end of a short `radii` list).
    pub fn radius(&self, i: usize) -> f64 {
        match &self.radii {
            Radii::One(r) => *r,
            Radii::Each(list) => list.get(i).copied().unwrap_or(0.0),
        }
    }

    /// Colour of drop `i`.
    pub fn color(&self, i: usize) -> Rgb8 {
        self.colors[i % self.colors.len()]
    }

    /// The single ops this set stands for, in order: drops, or spray droplets when
    /// `spray`.
    pub fn expand(&self, spray: bool) -> impl DoubleEndedIterator<Item = Op> + '_ {
        (0..self.len()).map(move |i| {
            let (center, radius, color) = (self.centers[i], self.radius(i), self.color(i));
            if spray {
                Op::Spray(Spray {
                    center,
                    radius,
                    color,
                })
            } else {
                Op::Drop(Drop {
                    center,
                    radius,
                    color,
                })
            }
        })
    }
}

impl OpType for DropSet {
    const FIELDS: &'static [&'static str] = &["type", "centers", "radius", "radii", "colors"];

    /// `centers`, `radius` or `radii` (one of them), `colors`.
    fn read(r: &mut FieldReader<'_>) -> Option<Self> {
        let centers = r.points("centers");
        let radii = match (r.has("radius"), r.has("radii")) {
            (true, false) => r.number("radius").map(Radii::One),
            (false, true) => r.numbers("radii").map(Radii::Each),
            (both, _) => {
                let m = if both {
                    "give either \"radius\" (one for all) or \"radii\" (one per centre), not both"
                } else {
                    "missing; give \"radius\" (one for all) or \"radii\" (one per centre)"
                };
                r.push("radius", m);
                None
            }
        };
        let colors = r.colors("colors");
        Some(DropSet {
            centers: centers?,
            radii: radii?,
            colors: colors?,
        })
    }

    fn write(&self, w: &mut FieldWriter) {
        w.points("centers", &self.centers);
        match &self.radii {
            Radii::One(r) => w.number("radius", *r),
            Radii::Each(list) => w.numbers("radii", list),
        }
        w.colors("colors", &self.colors);
    }

    fn check(&self, c: &mut OpCheck<'_>) {
        if c.count("centers", self.len(), 1, MAX_DROPS, "centres") {
            for (i, &p) in self.centers.iter().enumerate() {
                c.point(&format!("centers[{i}]"), p);
            }
        }
        match &self.radii {
            Radii::One(r) => c.positive("radius", *r),
            Radii::Each(list) => {
                if list.len() != self.len() {
                    c.push(
                        "radii",
                        format!(
                            "must hold one radius per centre ({}), got {}",
                            self.len(),
                            list.len()
                        ),
                    );
                }
                for (i, &r) in list.iter().enumerate() {
                    c.positive(&format!("radii[{i}]"), r);
                }
            }
        }
        if self.colors.is_empty() {
            c.push("colors", "must hold at least one colour, got none");
        }
    }

    fn round(&mut self) {
        self.centers = self.centers.iter().map(|&p| round::point(p)).collect();
        self.radii = match &self.radii {
            Radii::One(r) => Radii::One(round::positive(*r)),
            Radii::Each(list) => Radii::Each(list.iter().map(|&r| round::positive(r)).collect()),
        };
    }

    fn scale(&mut self, s: f64) {
        self.radii = match &self.radii {
            Radii::One(r) => Radii::One((r * s).max(MIN_SCALED_RADIUS)),
            Radii::Each(list) => Radii::Each(
                list.iter()
                    .map(|r| (r * s).max(MIN_SCALED_RADIUS))
                    .collect(),
            ),
        }
    }

    fn caption(&self, tag: &str) -> String {
        let (one, many) = if tag == "sprays" {
            ("spray", "sprays")
        } else {
            ("drop", "drops")
        };
        let colors = if self.colors.len() == 1 {
            format!("of {}", self.colors[0])
        } else {
            format!("in {} colours", self.colors.len())
        };
        format!(
            "{} {colors}, radius {} px",
            plural(self.centers.len(), one, many),
            radii_text(&self.radii)
        )
    }

    fn label(&self, tag: &str) -> String {
        if tag == "sprays" {
            format!("{} spray droplets", self.len())
        } else {
            format!("{} drops", self.len())
        }
    }

    fn formula(&self, tag: &str) -> Formula {
        if tag == "sprays" {
            return Formula {
                forward: "P′ = P (sprays lay ink on top without moving anything)".into(),
                inverse: "P = P′; inside a spray's disc: its ink".into(),
                values: format!(
                    "{} sprays, C₁ = {}",
                    self.centers.len(),
                    pt(self.centers[0])
                ),
                symbols: SPRAY_SYMBOLS.into(),
                area_preserving: true,
            };
        }
        let r = match &self.radii {
            Radii::One(r) => num(*r),
            Radii::Each(list) => format!("{} (first of {})", num(list[0]), list.len()),
        };
        Formula {
            forward: format!("{DROP_FORWARD}, once per drop in order"),
            inverse: format!("the drops undone newest first: {DROP_INVERSE}"),
            values: format!(
                "{} drops, C₁ = {}, r₁ = {r}",
                self.centers.len(),
                pt(self.centers[0])
            ),
            symbols: DROP_SYMBOLS.into(),
            area_preserving: true,
        }
    }
}
