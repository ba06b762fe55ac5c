//! The noise panel's controls for everything beyond one noise's parameters: the
//! transfer (threshold, Khlebnikov et al. (2013)'s spline decay, a curve with control points), tiling,
//! the HSV blend, cross-hatching and the layer stack. Each edits the typed spec within
//! the ranges the spec reader accepts, and returns the responses that automation names.

use crate::noise::panel::noise_parameters;
use crate::noise::settings::NoiseSettings;
use egui::{Color32, Pos2, Rect, Response, Sense, Slider, Stroke, pos2, vec2};
use marbling_noise::{
    Blend, BlendBase, COMBINES, Combine, Curve, DecayValue, Layer, MAX_CURVE_POINTS, MAX_LAYERS,
    NOISE_TYPES, NoiseSpec, Source, Threshold, Tile, Transfer, ranges,
};
use marbling_noise::{GaborSpec, WhiteSpec};

/// Named responses for `Frame::control` (the `data-controls` hook).
pub type Controls = Vec<(&'static str, Response)>;

/// A threshold's starting values: level 0, edge width 0.5 σ, not inverted.
fn default_threshold() -> Transfer {
    Transfer::Threshold(Threshold {
        threshold: 0.0,
        width: 0.5,
        invert: false,
    })
}

fn threshold_sliders(ui: &mut egui::Ui, t: &mut Threshold) {
    // The level in noise standard deviations: ±3σ holds nearly every value.
    ui.add(Slider::new(&mut t.threshold, -3.0..=3.0).text("level (σ)"));
    ui.add(
        Slider::new(
            &mut t.width,
            crate::noise::panel::slider(ranges::THRESHOLD_WIDTH)
                .start()
                .max(0.01)..=3.0,
        )
        .text("edge width (σ)")
        .logarithmic(true),
    );
    ui.checkbox(&mut t.invert, "invert");
}

/// A checkbox for a threshold transfer and its sliders (product inputs, layers).
pub fn threshold_only(ui: &mut egui::Ui, spec: &mut NoiseSpec) {
    let mut on = matches!(spec.transfer, Some(Transfer::Threshold(_)));
    ui.checkbox(&mut on, "threshold");
    match (on, &mut spec.transfer) {
        (true, Some(Transfer::Threshold(t))) => threshold_sliders(ui, t),
        (true, _) => spec.transfer = Some(default_threshold()),
        (false, _) => spec.transfer = None,
    }
}

/// The transfer: none (0.5 + n/6), threshold, spline decay (Khlebnikov et al. 2013) or curve.
pub fn transfer_section(ui: &mut egui::Ui, spec: &mut NoiseSpec) -> Controls {
    let mut out = Controls::new();
    let kind = match &spec.transfer {
        None => 0,
        Some(Transfer::Threshold(_)) => 1,
        Some(Transfer::SplineDecay(_)) => 2,
        Some(Transfer::Curve(_)) => 3,
    };
    ui.horizontal_wrapped(|ui| {
        ui.label("transfer");
        let options: [(&'static str, &str, &str); 4] = [
            ("noise-transfer-none", "none", "Intensity 0.5 + n/6"),
            (
                "noise-threshold",
                "threshold",
                "Intensity = a smoothstep of the noise around a level (sharp-edged patches)",
            ),
            (
                "noise-spline-decay",
                "spline decay",
                "Khlebnikov et al. 2013: a cubic spline of the noise whose mean intensity is v, without added aliasing",
            ),
            (
                "noise-curve",
                "curve",
                "Remap the intensity through control points (drag them; double-click adds, right-click removes)",
            ),
        ];
        for (i, (name, label, hover)) in options.into_iter().enumerate() {
            let r = ui.selectable_label(kind == i, label).on_hover_text(hover);
            if r.clicked() && kind != i {
                spec.transfer = match i {
                    1 => Some(default_threshold()),
                    2 => Some(Transfer::SplineDecay(DecayValue::Constant(0.5))),
                    3 => Some(Transfer::Curve(Curve::identity())),
                    _ => None,
                };
            }
            out.push((name, r));
        }
    });
    match &mut spec.transfer {
        Some(Transfer::Threshold(t)) => threshold_sliders(ui, t),
        Some(Transfer::SplineDecay(DecayValue::Constant(v))) => {
            ui.add(Slider::new(v, 0.0..=1.0).text("v (mean intensity)"));
        }
        Some(Transfer::SplineDecay(DecayValue::RampX)) => {
            ui.label("v rises from 0 at the left edge to 1 at the right");
        }
        Some(Transfer::SplineDecay(DecayValue::Data(r))) => {
            ui.label(format!("v from {} channel {}", r.name, r.channel));
        }
        Some(Transfer::Curve(c)) => {
            let r = curve_editor(ui, c);
            out.push(("noise-curve-editor", r));
        }
        None => {}
    }
    out
}

/// Side of the curve editor, points.
const CURVE_SIDE: egui::Vec2 = vec2(200.0, 130.0);

/// Drag a point to move it (between its neighbours), double-click to add one,
/// right-click a point to remove it (at least two stay).
fn curve_editor(ui: &mut egui::Ui, curve: &mut Curve) -> Response {
    let (rect, response) = ui.allocate_exact_size(CURVE_SIDE, Sense::click());
    let to_screen = |p: [f32; 2]| {
        pos2(
            rect.left() + p[0] * rect.width(),
            rect.bottom() - p[1] * rect.height(),
        )
    };
    let to_curve = |p: Pos2| {
        [
            ((p.x - rect.left()) / rect.width()).clamp(0.0, 1.0),
            ((rect.bottom() - p.y) / rect.height()).clamp(0.0, 1.0),
        ]
    };
    let painter = ui.painter_at(rect.expand(4.0));
    painter.rect_filled(rect, 2.0, Color32::from_gray(24));
    painter.line_segment(
        [to_screen([0.0, 0.0]), to_screen([1.0, 1.0])],
        Stroke::new(1.0, Color32::from_gray(60)),
    );
    let mut points = curve.points().to_vec();
    let mut changed = false;
    let mut remove = None;
    let n = points.len();
    for i in 0..n {
        let centre = to_screen(points[i]);
        let id = response.id.with(("curve-point", i));
        let r = ui.interact(
            Rect::from_center_size(centre, vec2(14.0, 14.0)),
            id,
            Sense::click_and_drag(),
        );
        if r.dragged()
            && let Some(p) = r.interact_pointer_pos()
        {
            let [mut x, y] = to_curve(p);
            let lo = if i == 0 { 0.0 } else { points[i - 1][0] + 0.01 };
            let hi = if i + 1 == n {
                1.0
            } else {
                points[i + 1][0] - 0.01
            };
            x = x.clamp(lo, hi.max(lo));
            points[i] = [x, y];
            changed = true;
        }
        if r.secondary_clicked() && n > 2 {
            remove = Some(i);
        }
    }
    if let Some(i) = remove {
        points.remove(i);
        changed = true;
    }
    if response.double_clicked()
        && points.len() < MAX_CURVE_POINTS
        && let Some(p) = response.interact_pointer_pos()
    {
        let q = to_curve(p);
        let at = points.partition_point(|a| a[0] < q[0]);
        let clear = |k: usize| points.get(k).is_none_or(|a| (a[0] - q[0]).abs() > 0.01);
        if clear(at) && (at == 0 || clear(at - 1)) {
            points.insert(at, q);
            changed = true;
        }
    }
    if changed && let Ok(c) = Curve::new(points) {
        *curve = c;
    }
    let line: Vec<Pos2> = (0..=64)
        .map(|k| {
            let t = k as f32 / 64.0;
            to_screen([t, curve.eval(t)])
        })
        .collect();
    painter.add(egui::Shape::line(
        line,
        Stroke::new(2.0, Color32::from_rgb(240, 200, 120)),
    ));
    for p in curve.points() {
        painter.circle_filled(to_screen(*p), 4.5, Color32::WHITE);
    }
    response
        .on_hover_text("Drag a point; double-click to add one; right-click a point to remove it")
}

/// Tiling: a period in pixels, and whether the preview shows 2×2 copies.
pub fn tile_section(ui: &mut egui::Ui, s: &mut NoiseSettings) -> Controls {
    let mut on = s.spec.tile.is_on();
    let r = ui.checkbox(&mut on, "tileable").on_hover_text(
        "Repeat every period: opposite edges continue each other (seamless textures)",
    );
    let period = match s.spec.tile {
        Tile::Period(p) => p,
        _ => 256,
    };
    if !on {
        s.set_tile(None);
        return vec![("noise-tile", r)];
    }
    let mut p = period;
    ui.add(
        Slider::new(&mut p, 16..=2048)
            .text("period (px)")
            .logarithmic(true),
    );
    s.set_tile(Some(p));
    let shown = ui
        .checkbox(&mut s.show_tiles, "show 2×2 tiles")
        .on_hover_text("The canvas shows four copies of one tile: look for seams");
    if !s.spec.clone().data_refs_mut().is_empty() {
        ui.label(
            egui::RichText::new("Data does not repeat: the tile shows seams where it differs")
                .weak(),
        );
    }
    vec![("noise-tile", r), ("noise-show-tiles", shown)]
}

/// Khlebnikov et al. (2013)'s HSV value blend of the intensity into a base colour (β: the base's share).
pub fn blend_section(ui: &mut egui::Ui, spec: &mut NoiseSpec) -> Controls {
    let mut on = spec.blend.is_some();
    let r = ui
        .checkbox(&mut on, "HSV blend")
        .on_hover_text("Khlebnikov et al. 2013: the noise sets the value of a base colour; β keeps that much of the colour's own value");
    match (on, &mut spec.blend) {
        (true, Some(b)) => {
            ui.add(Slider::new(&mut b.beta, 0.0..=1.0).text("β"));
            match &mut b.base {
                BlendBase::Color(c) => {
                    let mut rgb = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
                    ui.horizontal(|ui| {
                        ui.label("base colour");
                        ui.color_edit_button_srgb(&mut rgb);
                    });
                    *c = rgb.map(|v| f32::from(v) / 255.0);
                }
                BlendBase::Ramp(_) => {
                    ui.label("base: the palette, left to right");
                }
                BlendBase::Data { value, .. } => {
                    ui.label(format!(
                        "base: the palette at {} channel {}",
                        value.name, value.channel
                    ));
                }
            }
        }
        (true, None) => {
            spec.blend = Some(Blend {
                beta: 0.6,
                base: BlendBase::Color([0.2, 0.45, 0.7]),
            });
        }
        (false, _) => spec.blend = None,
    }
    vec![("noise-blend", r)]
}

/// Cross-hatching (Bénard et al.): a Gabor becomes the product of two thresholded
/// copies at right angles; a product can be taken apart again.
pub fn cross_hatch(ui: &mut egui::Ui, spec: &mut NoiseSpec) -> Controls {
    match &spec.source {
        Source::Gabor(GaborSpec { .. }) if spec.layers.is_empty() => {
            let r = ui
                .button("Cross-hatch")
                .on_hover_text("The product of this Gabor's hatching and a copy turned by 90°");
            if r.clicked() {
                let hatch = Transfer::Threshold(Threshold {
                    threshold: 0.8,
                    width: 0.5,
                    invert: true,
                });
                let mut a = NoiseSpec::plain(spec.source.clone());
                a.transfer = Some(hatch.clone());
                let mut b = a.clone();
                if let Source::Gabor(GaborSpec {
                    orientation, seed, ..
                }) = &mut b.source
                {
                    *orientation += std::f32::consts::FRAC_PI_2;
                    *seed = seed.wrapping_add(1);
                }
                spec.source = Source::Product(vec![a, b]);
                spec.transfer = None;
            }
            vec![("noise-cross-hatch", r)]
        }
        Source::Product(inputs) => {
            let r = ui
                .button("Single noise")
                .on_hover_text("Keep the first input only");
            if r.clicked()
                && let Some(first) = inputs.first().cloned()
            {
                spec.source = first.source;
                spec.transfer = first.transfer;
            }
            vec![("noise-split", r)]
        }
        _ => Vec::new(),
    }
}

/// A combo of the noise types (not products) that restarts `spec` at the chosen one.
fn type_choice(ui: &mut egui::Ui, id: (&str, usize), spec: &mut NoiseSpec) {
    let shown = spec.source.type_name();
    egui::ComboBox::from_id_salt(format!("{}-{}", id.0, id.1))
        .selected_text(shown)
        .show_ui(ui, |ui| {
            for &t in NOISE_TYPES.iter().filter(|t| **t != "product") {
                if ui.selectable_label(t == shown, t).clicked()
                    && t != shown
                    && let Some(s) = Source::starting(t, spec.source.seed())
                {
                    spec.source = s;
                }
            }
        });
}

/// The layer stack: up to four noises on the spec's own, each with its type,
/// parameters, threshold, combine mode and weight (and a mask noise for `mask`).
pub fn layers_section(ui: &mut egui::Ui, spec: &mut NoiseSpec) -> Controls {
    let mut out = Controls::new();
    let mut remove = None;
    for (i, layer) in spec.layers.iter_mut().enumerate() {
        let title = format!(
            "layer {}: {} ({})",
            i + 1,
            layer.noise.source.type_name(),
            layer.combine.name()
        );
        egui::CollapsingHeader::new(title)
            .id_salt(("noise-layer", i))
            .default_open(true)
            .show(ui, |ui| {
                type_choice(ui, ("layer-type", i), &mut layer.noise);
                noise_parameters(ui, &mut layer.noise);
                threshold_only(ui, &mut layer.noise);
                ui.horizontal_wrapped(|ui| {
                    ui.label("combine");
                    for (name, c) in COMBINES {
                        ui.selectable_value(&mut layer.combine, c, name);
                    }
                });
                ui.add(Slider::new(&mut layer.weight, 0.0..=1.0).text("weight"));
                match (layer.combine, &mut layer.mask) {
                    (Combine::Mask, Some(mask)) => {
                        ui.label("mask (where it is bright, this layer shows)");
                        type_choice(ui, ("mask-type", i), mask);
                        noise_parameters(ui, mask);
                        threshold_only(ui, mask);
                    }
                    (Combine::Mask, m @ None) => {
                        let mut mask = NoiseSpec::plain(
                            Source::starting("perlin", 11)
                                .unwrap_or(Source::White(WhiteSpec { seed: 11 })),
                        );
                        mask.transfer = Some(default_threshold());
                        *m = Some(mask);
                    }
                    (_, m) => *m = None,
                }
                if ui.small_button("remove layer").clicked() {
                    remove = Some(i);
                }
            });
    }
    if let Some(i) = remove {
        spec.layers.remove(i);
    }
    if spec.layers.len() < MAX_LAYERS {
        let r = ui
            .button("Add layer")
            .on_hover_text("Stack another noise: add, multiply, max, min or mask");
        if r.clicked() {
            let seed = spec
                .source
                .seed()
                .wrapping_add(spec.layers.len() as u32 + 1);
            let source =
                Source::starting("worley", seed).unwrap_or(Source::White(WhiteSpec { seed }));
            spec.layers.push(Layer {
                noise: NoiseSpec::plain(source),
                combine: Combine::Add,
                weight: 0.5,
                mask: None,
            });
        }
        out.push(("noise-add-layer", r));
    }
    out
}
