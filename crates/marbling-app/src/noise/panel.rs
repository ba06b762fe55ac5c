//! The noise playground's side panel: pick a noise, set its parameters, read its value
//! statistics, histogram and radially averaged power spectrum, and put it to use as the
//! design's marbled background or as paper or pigment grain. The canvas shows the noise
//! itself (drawn by the GPU renderer as a design with a noise background and no ops).

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::view::ViewState;
use crate::noise::Noise;
use egui::{RichText, Slider};
use egui_plot::{Bar, BarChart, Line, Plot};
use marbling_core::{GrainKind, NoiseBackground, NoiseLayer, Overlay, Palette};
use marbling_noise::analysis::{Stats, histogram, radial_spectrum, stats};
use marbling_noise::ranges::{self, Range};
use marbling_noise::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use marbling_noise::{
    DriveSource, DriveSpec, EDIT_FLOOR, FbmParams, FiberLayout, NOISE_TYPES, NoiseSpec, Source,
};
use std::ops::RangeInclusive;

/// Side of the sample grid the statistics and spectrum are computed on, design pixels.
pub const ANALYSIS_SIDE: usize = 128;
/// Histogram bins over n ∈ [−4, 4] (unit-variance noise).
pub const HISTOGRAM_BINS: usize = 48;

/// What the panel shows about the current noise.
#[derive(Clone, Debug)]
pub struct NoiseAnalysis {
    /// Statistics of the unit-variance noise values.
    pub stats: Stats,
    /// Counts per bin over [−4, 4].
    pub histogram: Vec<u32>,
    /// (cycles per design pixel, share of the power).
    pub spectrum: Vec<(f64, f64)>,
}

impl NoiseAnalysis {
    /// Samples `layer` over the top-left `ANALYSIS_SIDE`² design pixels (paper and
    /// canvas, whose fibers are slow on the CPU, over a quarter of that).
    pub fn of(layer: &NoiseLayer) -> Option<Self> {
        let side = if matches!(layer.type_name(), "paper" | "canvas") {
            ANALYSIS_SIDE / 2
        } else {
            ANALYSIS_SIDE
        };
        let values = marbling_noise::sample_grid(layer.spec(), side as u32)?;
        Some(Self {
            stats: stats(&values)?,
            histogram: histogram(&values, HISTOGRAM_BINS, -4.0, 4.0),
            spectrum: radial_spectrum(&values, side),
        })
    }
}

impl Noise {
    /// The zoom factor the zoom-independent rule applies at `view`'s zoom (1 when it
    /// is off).
    pub(crate) fn factor_at(&self, view: Option<ViewState>) -> f64 {
        self.settings().zoom_factor(view.map_or(1.0, |v| v.zoom))
    }

    /// The noise layer of the current settings at `view`'s zoom, made once per change
    /// of them (`follow` forgets it), not once a frame.
    pub(crate) fn layer_for(&mut self, view: Option<ViewState>) -> Result<NoiseLayer, String> {
        let factor = self.factor_at(view);
        self.layer_at(factor)
    }

    /// The noise panel.
    pub(crate) fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.label(RichText::new("Noise").strong());
        let mut types = Vec::new();
        let (controls, zoom_box) = self.edit_in(|s| {
            let shown = s.spec.source.type_name();
            let combo = egui::ComboBox::from_label("noise")
                .selected_text(shown)
                .show_ui(ui, |ui| {
                    // A product (cross-hatching) is read from JSON; it has no sliders here.
                    for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
                        let r = ui.selectable_label(t == shown, t);
                        if r.clicked() && t != shown {
                            s.set_type(t);
                        }
                        types.push((t, r));
                    }
                });
            types.push(("", combo.response));
            noise_parameters(ui, &mut s.spec);
            let mut controls = crate::noise::controls::transfer_section(ui, &mut s.spec);
            controls.extend(crate::noise::controls::tile_section(ui, s));
            controls.extend(crate::noise::controls::blend_section(ui, &mut s.spec));
            controls.extend(crate::noise::controls::cross_hatch(ui, &mut s.spec));
            controls.extend(crate::noise::controls::layers_section(ui, &mut s.spec));
            egui::ComboBox::from_label("palette")
                .selected_text(s.palette_name())
                .show_ui(ui, |ui| {
                    for (i, name) in marbling_noise::PALETTES.iter().enumerate() {
                        ui.selectable_value(&mut s.palette, i, *name);
                    }
                });
            let zoom_box = ui
                .checkbox(&mut s.zoom_independent, "zoom-independent")
                .on_hover_text(
                    "Keep features 4–40 screen pixels wide while zooming (octave steps)",
                );
            (controls, zoom_box)
        });
        for (name, response) in &controls {
            frame.control(*name, response);
        }
        // `noise-type` opens the list; `noise-type-gabor` and so on are its entries.
        for (t, response) in &types {
            match *t {
                "" => frame.control("noise-type", response),
                t => frame.control(format!("noise-type-{t}"), response),
            }
        }
        frame.control("noise-zoom-independent", &zoom_box);
        self.data_section_ui(ui, frame);
        let view = frame.editor.view;
        let factor = self.factor_at(view);
        if factor != 1.0 {
            ui.label(RichText::new(format!("frequency × {factor:.3} at this zoom")).weak());
        }
        self.readout(ui, view);
        ui.separator();
        self.uses_ui(ui, frame);
    }

    /// Min/max/mean, the histogram and the spectrum.
    fn readout(&mut self, ui: &mut egui::Ui, view: Option<ViewState>) {
        if self.analysis.is_none() {
            let layer = self.layer_for(view);
            self.analysis = Some(layer.ok().and_then(|l| NoiseAnalysis::of(&l)));
        }
        let Some(Some(a)) = &self.analysis else {
            ui.label("no statistics for this noise");
            return;
        };
        ui.label(format!(
            "min {:.2}  max {:.2}  mean {:.3}  σ {:.3}",
            a.stats.min, a.stats.max, a.stats.mean, a.stats.std_dev
        ))
        .on_hover_text("Of the unit-variance noise over a 128 px square (before the palette)");
        let width = 8.0 / HISTOGRAM_BINS as f64;
        let bars: Vec<Bar> = a
            .histogram
            .iter()
            .enumerate()
            .map(|(i, &c)| Bar::new(-4.0 + (i as f64 + 0.5) * width, f64::from(c)).width(width))
            .collect();
        Plot::new("noise_histogram")
            .height(80.0)
            .allow_zoom(false)
            .allow_drag(false)
            .allow_scroll(false)
            .show_axes([true, false])
            .x_axis_label("value")
            .show(ui, |p| p.bar_chart(BarChart::new("histogram", bars)));
        let points: Vec<[f64; 2]> = a
            .spectrum
            .iter()
            .map(|&(f, power)| [f, (power.max(1e-12)).log10()])
            .collect();
        Plot::new("noise_spectrum")
            .height(80.0)
            .allow_zoom(false)
            .allow_drag(false)
            .allow_scroll(false)
            .x_axis_label("cycles / px")
            .show(ui, |p| p.line(Line::new("log₁₀ power", points)));
    }

    /// Export, link, and putting the noise on the design.
    fn uses_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.horizontal_wrapped(|ui| {
            let link = ui
                .button("Copy noise link")
                .on_hover_text("A link (#n=) that opens this noise in the Noise tab");
            frame.control("noise-copy-link", &link);
            if link.clicked() {
                let link = format!(
                    "{}#{}",
                    crate::platform::base_url(),
                    marbling_core::noise_fragment(&self.settings().export_spec())
                );
                ui.ctx().copy_text(link.clone());
                frame.info(format!("noise link copied ({} characters)", link.len()));
            }
            let copy = ui
                .button("Copy spec")
                .on_hover_text("The JSON that `marbling noise SPEC -o OUT.png` renders");
            frame.control("noise-copy-spec", &copy);
            if copy.clicked() {
                let v = self.settings().export_spec().to_value();
                ui.ctx()
                    .copy_text(serde_json::to_string_pretty(&v).unwrap_or_else(|_| v.to_string()));
                frame.info("noise spec copied");
            }
        });
        self.export_ui(ui, frame);
        ui.label(RichText::new("Use on the design").strong());
        if self.settings().needs_preview() {
            ui.label(
                RichText::new(
                    "A design holds the base noise only (no layers, tiling, curve, spline \
                     decay, blend or data)",
                )
                .weak(),
            );
        }
        let layer = match self.layer_for(frame.editor.view) {
            Ok(l) => l,
            Err(e) => {
                ui.label(RichText::new(e).color(egui::Color32::from_rgb(255, 110, 110)));
                return;
            }
        };
        ui.horizontal_wrapped(|ui| {
            let bg = ui
                .button("Marble it")
                .on_hover_text("The design's background becomes this noise, marbled like ink");
            frame.control("noise-background", &bg);
            if bg.clicked() {
                match Palette::named(self.settings().palette_name()) {
                    Ok(p) => {
                        let mut surface = frame.editor.history.surface();
                        surface.0 = Some(NoiseBackground::new(layer.clone(), p));
                        frame.act(Action::SetSurface {
                            surface,
                            what: "noise background".to_owned(),
                        });
                    }
                    Err(e) => frame.error(e.to_string()),
                }
            }
        });
        self.edit_in(|s| {
            ui.add(Slider::new(&mut s.grain_strength, 0.0..=1.0).text("grain strength"))
        });
        ui.horizontal_wrapped(|ui| {
            let paper = ui
                .button("Paper grain")
                .on_hover_text("Fixed to the paper: it stays put while the ink moves");
            frame.control("noise-paper-grain", &paper);
            let pigment = ui
                .button("Pigment grain")
                .on_hover_text("Flows with the ink: combs drag it along");
            frame.control("noise-pigment-grain", &pigment);
            let kind = if paper.clicked() {
                Some(GrainKind::Paper)
            } else if pigment.clicked() {
                Some(GrainKind::Pigment)
            } else {
                None
            };
            if let Some(kind) = kind {
                let strength = self.settings().grain_strength;
                let overlay = match kind {
                    GrainKind::Paper => Overlay::paper_grain(layer.clone(), strength),
                    GrainKind::Pigment => Overlay::pigment_grain(layer.clone(), strength),
                };
                let mut surface = frame.editor.history.surface();
                surface.1.retain(|o| o.kind != kind);
                surface.1.push(overlay);
                frame.act(Action::SetSurface {
                    surface,
                    what: kind.name().to_owned(),
                });
            }
        });
    }
}

/// The design's noise background and overlays, with a way to remove them.
pub(crate) fn surface_ui(ui: &mut egui::Ui, frame: &mut Frame<'_>) {
    let (background, overlays) = frame.editor.history.surface();
    if background.is_none() && overlays.is_empty() {
        return;
    }
    ui.label(RichText::new("Surface").strong());
    if let Some(b) = &background {
        ui.horizontal(|ui| {
            ui.label(format!("background: {} noise", b.noise.type_name()));
            let remove = ui.small_button("remove");
            frame.control("remove-background-noise", &remove);
            if remove.clicked() {
                frame.act(Action::SetSurface {
                    surface: (None, overlays.clone()),
                    what: "plain background".to_owned(),
                });
            }
        });
    }
    for o in &overlays {
        ui.horizontal(|ui| {
            ui.label(format!(
                "{}: {} at {:.2}",
                o.kind.name(),
                o.noise.type_name(),
                o.strength
            ));
            if ui.small_button("remove").clicked() {
                let kept = overlays
                    .iter()
                    .filter(|x| x.kind != o.kind)
                    .cloned()
                    .collect();
                frame.act(Action::SetSurface {
                    surface: (background.clone(), kept),
                    what: "overlay removed".to_owned(),
                });
            }
        });
    }
}

/// A slider's range for a spec range (open ranges start at [`EDIT_FLOOR`]).
pub(crate) fn slider(r: Range) -> RangeInclusive<f32> {
    let s = r.slider(EDIT_FLOOR);
    (*s.start() as f32)..=(*s.end() as f32)
}

/// One button per name of a `marbling_noise::ranges` table.
fn choice<T: PartialEq + Copy>(ui: &mut egui::Ui, label: &str, options: &[(&str, T)], v: &mut T) {
    ui.horizontal_wrapped(|ui| {
        ui.label(label);
        for &(name, option) in options {
            ui.selectable_value(v, option, name);
        }
    });
}

fn frequency(ui: &mut egui::Ui, f: &mut f32, range: Range) {
    ui.add(
        Slider::new(f, slider(range))
            .text("frequency (cycles/px)")
            .logarithmic(true),
    );
}

fn fbm(ui: &mut egui::Ui, p: &mut FbmParams) {
    frequency(ui, &mut p.frequency, ranges::FREQUENCY);
    let octaves = (ranges::OCTAVES.lo as u32)..=(ranges::OCTAVES.hi as u32);
    ui.add(Slider::new(&mut p.octaves, octaves).text("octaves"));
    ui.add(Slider::new(&mut p.lacunarity, slider(ranges::LACUNARITY)).text("lacunarity"));
    ui.add(Slider::new(&mut p.persistence, slider(ranges::PERSISTENCE)).text("persistence"));
}

/// A Gabor parameter varying over space (Khlebnikov et al. (2013)'s spatially varying Gabor): driven by
/// a slow Perlin fBm, `amount` units per standard deviation up to `max` (0 turns the
/// drive off; a data drive is set in the Data section and left alone here).
fn noise_drive(
    ui: &mut egui::Ui,
    field: &mut Option<DriveSpec>,
    seed: u32,
    label: &str,
    max: f32,
    hover: &str,
) {
    if matches!(
        field,
        Some(DriveSpec {
            by: DriveSource::Data(_),
            ..
        })
    ) {
        return;
    }
    let mut amount = field.as_ref().map_or(0.0, |d| d.amount);
    ui.add(Slider::new(&mut amount, 0.0..=max).text(label))
        .on_hover_text(hover);
    *field = (amount > 0.0).then(|| {
        let by = match field.take() {
            Some(DriveSpec { by, .. }) => by,
            None => {
                let mut p =
                    Source::starting("perlin", seed).unwrap_or(Source::White(WhiteSpec { seed }));
                if let Source::Fbm(f) = &mut p {
                    f.frequency = 0.008;
                    f.octaves = 2;
                }
                DriveSource::Noise(Box::new(NoiseSpec::plain(p)))
            }
        };
        DriveSpec { by, amount }
    });
}

/// The sliders of the spec's noise: each edits one field of the typed spec, within the
/// range the spec parser accepts (`marbling_noise::ranges`).
pub(crate) fn noise_parameters(ui: &mut egui::Ui, spec: &mut NoiseSpec) {
    match &mut spec.source {
        Source::Gabor(GaborSpec {
            kind,
            frequency: f,
            orientation,
            bandwidth,
            impulses,
            seed,
            orientation_field,
            frequency_field,
            profile,
        }) => {
            if let Some(p) = profile {
                choice(ui, "profile", &ranges::PHASOR_PROFILES, p);
            }
            choice(ui, "kind", &ranges::GABOR_KINDS, kind);
            frequency(ui, f, ranges::GABOR_FREQUENCY);
            if *kind != marbling_noise::GaborKind::Isotropic {
                ui.add(
                    Slider::new(orientation, 0.0..=std::f32::consts::PI).text("orientation (rad)"),
                );
                noise_drive(
                    ui,
                    orientation_field,
                    seed.wrapping_add(1),
                    "swirl (rad/σ)",
                    3.0,
                    "Turn the orientation along a slow Perlin noise",
                );
            }
            noise_drive(
                ui,
                frequency_field,
                seed.wrapping_add(2),
                "frequency drift (octaves/σ)",
                1.5,
                "Vary the frequency along a slow Perlin noise",
            );
            ui.add(
                Slider::new(bandwidth, slider(ranges::BANDWIDTH))
                    .text("bandwidth a (1/px)")
                    .logarithmic(true),
            );
            ui.add(
                Slider::new(impulses, slider(ranges::IMPULSES))
                    .text("impulses")
                    .integer(),
            );
        }
        Source::Fbm(p) => fbm(ui, p),
        Source::Curl(CurlSpec {
            potential,
            component,
        }) => {
            fbm(ui, potential);
            choice(ui, "component", &ranges::CURL_COMPONENTS, component);
        }
        Source::Worley(WorleySpec {
            frequency: f,
            feature,
            metric,
            ..
        }) => {
            frequency(ui, f, ranges::FREQUENCY);
            choice(ui, "feature", &ranges::WORLEY_FEATURES, feature);
            choice(ui, "metric", &ranges::WORLEY_METRICS, metric);
        }
        Source::White(WhiteSpec { .. }) => {}
        Source::Fibers(p) => {
            ui.add(
                Slider::new(&mut p.length, slider(ranges::FIBER_LENGTH))
                    .text("fiber length (px)")
                    .logarithmic(true),
            );
            ui.add(Slider::new(&mut p.width, slider(ranges::FIBER_WIDTH)).text("fiber width (px)"));
            ui.add(
                Slider::new(&mut p.density, slider(ranges::FIBER_DENSITY))
                    .text("density (/px²)")
                    .logarithmic(true),
            );
            if let FiberLayout::Canvas { weights } = &mut p.layout {
                ui.add(Slider::new(&mut weights[0], 0.0..=4.0).text("horizontal threads"));
                ui.add(Slider::new(&mut weights[1], 0.0..=4.0).text("vertical threads"));
            }
        }
        Source::Product(inputs) => {
            ui.label(format!(
                "product of {} noises (cross-hatching)",
                inputs.len()
            ));
            for (i, input) in inputs.iter_mut().enumerate() {
                egui::CollapsingHeader::new(format!(
                    "input {}: {}",
                    i + 1,
                    input.source.type_name()
                ))
                .id_salt(("product-input", i))
                .show(ui, |ui| {
                    noise_parameters(ui, input);
                    crate::noise::controls::threshold_only(ui, input);
                });
            }
        }
    }
    if let Some(seed) = spec.source.seed_mut() {
        ui.add(egui::DragValue::new(seed).prefix("seed "));
    }
}
