//! The marbler's moves the recipes are written in: throw a colour, rake, comb, draw a
//! stylus. Each move is one step with its caption; lengths are given for the
//! 640 × 400 reference tank and scaled to the requested size.

use super::{Params, Pattern, REFERENCE_HEIGHT, REFERENCE_WIDTH};
use crate::caption::{heading, num, radii_text};
use crate::synth::SplitMix64;
use crate::{
    Design, DropSet, Jiggle, MAX_SIDE, Op, Point, Radii, Rake, Recipe, Rgb8, Stylus, Vec2, Vortex,
    Wavy,
};
use std::sync::Arc;

/// A design being made step by step.
pub struct Maker {
    /// Tank width, design pixels.
    pub w: f64,
    /// Tank height, design pixels.
    pub h: f64,
    /// Design pixels per reference pixel.
    pub u: f64,
    /// Spacing of the finest comb, design pixels.
    pub fine: f64,
    inks: Vec<Rgb8>,
    rng: SplitMix64,
    design: Design,
    captions: Vec<String>,
}

impl Maker {
    pub(super) fn new(p: &Pattern, params: &Params) -> Result<Self, String> {
        for (what, v) in [("width", params.width), ("height", params.height)] {
            if !(16..=MAX_SIDE).contains(&v) {
                return Err(format!("{what} must be 16 to {MAX_SIDE} px, got {v}"));
            }
        }
        let (w, h) = (params.width as f64, params.height as f64);
        let u = (w / REFERENCE_WIDTH).min(h / REFERENCE_HEIGHT);
        let inks = params.colors.clone().unwrap_or_else(|| p.colors.to_vec());
        if inks.is_empty() {
            return Err("colors: give at least one ink".into());
        }
        let fine = params.spacing.unwrap_or(p.spacing * u);
        if !(fine.is_finite() && fine >= 2.0 && fine <= w.max(h)) {
            return Err(format!(
                "spacing must be 2 px to the tank's size, got {}",
                num(fine)
            ));
        }
        let seed =
            p.id.bytes()
                .fold(params.seed, |s, b| s.rotate_left(5) ^ b as u64);
        Ok(Self {
            w,
            h,
            u,
            fine,
            inks,
            rng: SplitMix64(seed),
            design: Design::new(
                params.width,
                params.height,
                params.background.unwrap_or(p.background),
            ),
            captions: Vec::new(),
        })
    }

    pub(super) fn finish(mut self, mut recipe: Recipe) -> Design {
        recipe.captions = self.captions;
        self.design.recipe = Some(recipe);
        self.design
    }

    /// Ink `i` (cycled).
    pub fn ink(&self, i: usize) -> Rgb8 {
        self.inks[i % self.inks.len()]
    }

    /// How many inks were given.
    pub fn ink_count(&self) -> usize {
        self.inks.len()
    }

    /// Uniform random in [lo, hi).
    pub fn random(&mut self, lo: f64, hi: f64) -> f64 {
        self.rng.range(lo, hi)
    }

    /// One step: `ops` made by one gesture, with its caption.
    pub fn step(&mut self, caption: impl Into<String>, ops: Vec<Op>) {
        let mut sizes = self.design.gesture_sizes();
        sizes.push(ops.len());
        self.design.ops.extend(ops);
        self.design.set_gesture_sizes(sizes);
        self.captions.push(caption.into());
    }

    /// Throws ink `i`: `count` drops (at the reference size; scaled with the tank's
    /// area) of radius `lo..hi` reference px, scattered over the whole tank.
    pub fn throw(&mut self, what: &str, i: usize, count: usize, lo: f64, hi: f64) {
        let area = self.w * self.h / (self.u * self.u * REFERENCE_WIDTH * REFERENCE_HEIGHT);
        let n = ((count as f64 * area).round() as usize).clamp(1, crate::ops::MAX_DROPS);
        let (w, h, u) = (self.w, self.h, self.u);
        let mut centers = Vec::with_capacity(n);
        let mut radii = Vec::with_capacity(n);
        for _ in 0..n {
            centers.push(Point::new(self.random(0.0, w), self.random(0.0, h)));
            radii.push((self.random(lo, hi) * u).max(0.5));
        }
        self.drops(what, i, centers, Radii::Each(radii.into()));
    }

    /// Drops of ink `i` at `centers`, one step captioned "`what`: n drops of #…".
    pub fn drops(&mut self, what: &str, i: usize, centers: Vec<Point>, radii: Radii) {
        self.drops_of(what, vec![self.ink(i)], centers, radii);
    }

    /// Drops at `centers` in `colors` (cycled), one step captioned "`what`: n drops
    /// of #… and #…, radius r px".
    pub fn drops_of(&mut self, what: &str, colors: Vec<Rgb8>, centers: Vec<Point>, radii: Radii) {
        let inks: Vec<String> = colors.iter().map(Rgb8::to_string).collect();
        let caption = format!(
            "{what}: {} drops of {}, radius {} px",
            centers.len(),
            inks.join(" and "),
            radii_text(&radii)
        );
        self.drop_set(&caption, colors, centers, radii);
    }

    /// The ground of the combed patterns: the inks laid in rows of drops from the top of
    /// the tank to the bottom, one ink a row in turn, so the rake finds even bands.
    pub fn rows_ground(&mut self) {
        let n = self.ink_count().clamp(2, 5);
        let step = 28.0 * self.u;
        let rows = (self.h / step).ceil() as usize + 1;
        let per_row = (self.w / (1.4 * step)).ceil() as usize + 1;
        let mut centers = Vec::with_capacity(rows * per_row);
        for r in 0..rows {
            let shift = if r % 2 == 1 { 0.7 * step } else { 0.0 };
            for c in 0..per_row {
                centers.push(Point::new(c as f64 * 1.4 * step + shift, r as f64 * step));
            }
        }
        // Colours cycle drop by drop: one ink repeated for a whole row, then the next.
        let colors = (0..n)
            .flat_map(|i| std::iter::repeat_n(self.ink(i), per_row))
            .collect();
        self.drop_set(
            &format!("Lay the inks in rows, top to bottom: {rows} rows of {per_row} drops"),
            colors,
            centers,
            Radii::One(step),
        );
    }

    /// Drops at `centers` in `colors` (cycled drop by drop), one step with `caption`.
    pub fn drop_set(
        &mut self,
        caption: &str,
        colors: Vec<Rgb8>,
        centers: Vec<Point>,
        radii: Radii,
    ) {
        self.step(
            caption,
            vec![Op::Drops(DropSet {
                centers: centers.into(),
                radii,
                colors: colors.into(),
            })],
        );
    }

    /// A rake across the whole tank moving along `dir` (its length does not matter):
    /// tines `spacing` apart, the first through `offset` along the tine normal; shift
    /// `alpha`, decay `lambda` — all in design pixels.
    pub fn rake(
        &mut self,
        what: &str,
        dir: Vec2,
        spacing: f64,
        offset: f64,
        alpha: f64,
        lambda: f64,
    ) {
        let d = dir.normalize();
        let normal = Vec2::new(-d.y, d.x);
        let caption = format!(
            "{what}: rake drawn {}, tines {} px apart, shift {} px, decay {} px",
            heading(d),
            num(spacing),
            num(alpha),
            num(lambda)
        );
        self.step(
            caption,
            vec![Op::Rake(Rake {
                origin: Point::new(self.w / 2.0, self.h / 2.0) + normal * offset,
                direction: d,
                spacing,
                alpha,
                lambda,
            })],
        );
    }

    /// Gel-git ("come and go"): a rake drawn down the tank, then back up between the
    /// first pass's lines.
    pub fn gel_git(&mut self, spacing: f64, alpha: f64) {
        let lambda = spacing / 5.0;
        self.rake(
            "Gel-git, first pass",
            Vec2::new(0.0, 1.0),
            spacing,
            0.0,
            alpha,
            lambda,
        );
        self.rake(
            "Gel-git, back between the first lines",
            Vec2::new(0.0, -1.0),
            spacing,
            spacing / 2.0,
            alpha,
            lambda,
        );
    }

    /// The fine (nonpareil) comb drawn along `dir` with teeth [`Maker::fine`] apart.
    pub fn fine_comb(&mut self, what: &str, dir: Vec2, offset: f64) {
        let s = self.fine;
        self.rake(what, dir, s, offset, 1.6 * s, 0.5 * s);
    }

    /// A wavy comb: everything moves along the `angle` direction by `amplitude` ·
    /// sin(2π·(distance across) / `wavelength`).
    pub fn wavy(&mut self, what: &str, angle: f64, amplitude: f64, wavelength: f64, phase: f64) {
        let caption = format!(
            "{what}: wavy comb moving {}, amplitude {} px, wavelength {} px",
            heading(Vec2::new(angle.cos(), angle.sin())),
            num(amplitude),
            num(wavelength)
        );
        self.step(
            caption,
            vec![Op::Wavy(Wavy {
                angle,
                amplitude,
                wavelength,
                phase,
            })],
        );
    }

    /// Swirls (vortices) at `centers`, alternating in sense, one step.
    pub fn swirls(&mut self, what: &str, centers: &[Point], alpha: f64, lambda: f64) {
        let caption = format!(
            "{what}: {} swirls, strength {} px, decay {} px, turning alternately",
            centers.len(),
            num(alpha),
            num(lambda)
        );
        let ops = centers
            .iter()
            .enumerate()
            .map(|(k, c)| {
                Op::Vortex(Vortex {
                    center: *c,
                    alpha: if k % 2 == 0 { alpha } else { -alpha },
                    lambda,
                })
            })
            .collect();
        self.step(caption, ops);
    }

    /// A stylus drawn along each path (one tip, or a comb of `tips` offsets across
    /// the path), all in one step.
    pub fn styli(&mut self, what: &str, paths: Vec<Vec<Point>>, wake: f64, tips: Option<Vec<f64>>) {
        let len: f64 = paths
            .iter()
            .flat_map(|p| p.windows(2).map(|w| (w[1] - w[0]).hypot()))
            .sum();
        let tip_text = match &tips {
            None => "one tip".to_string(),
            Some(t) => format!("{} tips", t.len()),
        };
        let caption = format!(
            "{what}: {} drawn, {} px in all, {tip_text}, wake {} px",
            if paths.len() == 1 {
                "one stroke".to_string()
            } else {
                format!("{} strokes", paths.len())
            },
            num(len),
            num(wake)
        );
        let tips: Option<Arc<[f64]>> = tips.map(Into::into);
        let ops = paths
            .into_iter()
            .map(|path| {
                Op::Stylus(Stylus {
                    path: path.into(),
                    wake,
                    tips: tips.clone(),
                })
            })
            .collect();
        self.step(caption, ops);
    }

    /// The tank jiggled (the paper laid down with a rocking motion): bands `wavelength`
    /// px apart along `angle`, pressed `along` px together and moved `across` px.
    pub fn jiggle(&mut self, what: &str, angle: f64, wavelength: f64, along: f64, across: f64) {
        let caption = format!(
            "{what}: jiggle {}, bands {} px apart, {} px along, {} px across",
            heading(Vec2::new(angle.cos(), angle.sin())),
            num(wavelength),
            num(along),
            num(across)
        );
        self.step(
            caption,
            vec![Op::Jiggle(Jiggle {
                angle,
                wavelength,
                along,
                across,
                phase: 0.0,
            })],
        );
    }

    /// Points of a regular grid over the tank: `cols` × `rows` cell centres, every
    /// other row shifted half a cell when `staggered`.
    pub fn grid(&self, cols: usize, rows: usize, staggered: bool) -> Vec<Point> {
        let (dx, dy) = (self.w / cols as f64, self.h / rows as f64);
        let mut out = Vec::with_capacity(cols * rows);
        for r in 0..rows {
            let shift = if staggered && r % 2 == 1 {
                dx / 2.0
            } else {
                0.0
            };
            for c in 0..cols {
                out.push(Point::new(
                    ((c as f64 + 0.5) * dx + shift).rem_euclid(self.w),
                    (r as f64 + 0.5) * dy,
                ));
            }
        }
        out
    }
}
