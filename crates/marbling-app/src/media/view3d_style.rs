//! The 3D view's *Style* rows: marks (Bénard et al. 2010: hatching, stipple, crosshatch,
//! graphite, and the media that work the design's colour, watercolor, felt, painterly)
//! or fibres (Kaplan & Cohen 2005: paper, canvas), sized in screen pixels yet anchored on
//! the surface, so they stay flat and move with the object. The style's field is
//! computed on the CPU ([`marbling_core::view3d::style`], the same as `marbling render-3d
//! --style`) whenever the view, the design or the style changes, and the panes' shader
//! blends it into each pixel (`View3dRenderer::set_style`). *Anchored* switches the marks
//! to the two naive answers of the paper's figure 1: a noise fixed to the screen, or one
//! mapped as a texture; *strokes* turn them with the screen, around the object, or along
//! the marbled ink's own stretch; *darker denser* ties their frequency to the shading.

use marbling_core::Design;
use marbling_core::view3d::View3d;
use marbling_core::view3d::style::{StyleFrame, style_frame};
use marbling_noise::style::{
    FIBERS_PER_PIXEL, MARK_FREQUENCY, MARK_FREQUENCY_SHADING, MARK_TONE, OPACITY,
};
use marbling_noise::{Anchoring, Follow, STYLE_KINDS, StyleBlend, StyleKind, StyleSpec};

/// What the overlay was computed for.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Made {
    design_key: u64,
    view: View3d,
    spec: StyleSpec,
}

/// The style the 3D view draws with, and its overlay.
#[derive(Default)]
pub struct StyleControls {
    /// The style (`None`: the plain render).
    spec: Option<StyleSpec>,
    /// The style's field and what it shows.
    shown: Option<(Made, StyleFrame)>,
    /// Counts the changes of the field (a new one, or none): the panes redraw on it.
    revision: u64,
    /// What the last overlay drew: kernels or fibres, and its time in ms.
    drawn: (usize, usize, f64),
    /// The last problem, shown under the row.
    error: Option<String>,
}

impl StyleControls {
    /// The style's name, or "none".
    pub fn name(&self) -> &'static str {
        self.spec.map_or("none", |s| s.kind.name())
    }

    /// The rows of controls (always four, so the pane keeps its size whatever the
    /// style); names them in `controls` for automation.
    pub fn ui(
        &mut self,
        ui: &mut egui::Ui,
        controls: &mut Vec<(std::borrow::Cow<'static, str>, egui::Rect)>,
    ) {
        let on = self.spec.is_some();
        // With no style the sliders show hatching's values, disabled.
        let mut spec = self.spec.unwrap_or(StyleSpec::preset(StyleKind::Hatching));
        let fibres = spec.kind.is_fibres();
        let overlay = spec.kind.blend() == StyleBlend::Overlay;
        ui.horizontal_wrapped(|ui| {
            let r = egui::ComboBox::from_id_salt("view3d-style")
                .selected_text(self.name())
                .show_ui(ui, |ui| {
                    let mut picked = self.spec.map(|s| s.kind);
                    let r = ui.selectable_value(&mut picked, None, "none");
                    controls.push(("view3d-style-none".into(), r.rect));
                    for (name, kind) in STYLE_KINDS {
                        let r = ui.selectable_value(&mut picked, Some(kind), name);
                        controls.push((format!("view3d-style-{name}").into(), r.rect));
                    }
                    if picked != self.spec.map(|s| s.kind) {
                        self.spec = picked.map(StyleSpec::preset);
                    }
                })
                .response
                .on_hover_text(
                    "Draws the object with marks sized on the screen but fixed to its \
                     surface (Bénard et al. 2010) — in ink, or working the design's own \
                     colour (watercolor, felt, painterly) — or with paper or canvas fibres \
                     that move with it (Kaplan & Cohen 2005)",
                );
            controls.push(("view3d-style".into(), r.rect));
            ui.add_enabled_ui(on && !fibres, |ui| {
                let r = egui::ComboBox::from_id_salt("view3d-style-anchoring")
                    .selected_text(anchoring_label(spec.anchoring))
                    .show_ui(ui, |ui| {
                        for a in [Anchoring::Surface, Anchoring::Screen, Anchoring::Texture] {
                            let r = ui.selectable_value(&mut spec.anchoring, a, anchoring_label(a));
                            let name = a.name();
                            controls
                                .push((format!("view3d-style-anchoring-{name}").into(), r.rect));
                        }
                    })
                    .response
                    .on_hover_text(
                        "Where the marks live: on the surface, sized on the screen (flat and \
                         moving); on the screen (the object slides under them); or in \
                         texture space (they shrink as the object recedes)",
                    );
                controls.push(("view3d-style-anchoring".into(), r.rect));
                let r = egui::ComboBox::from_id_salt("view3d-style-follow")
                    .selected_text(follow_label(spec.marks.follow))
                    .show_ui(ui, |ui| {
                        for f in [Follow::Screen, Follow::Curvature, Follow::Stretch] {
                            let r = ui.selectable_value(&mut spec.marks.follow, f, follow_label(f));
                            let name = f.name();
                            controls.push((format!("view3d-style-follow-{name}").into(), r.rect));
                        }
                    })
                    .response
                    .on_hover_text(
                        "Which way the strokes run: fixed on the screen, around the object \
                         (its principal curvature), or along the marbled ink's own stretch",
                    );
                controls.push(("view3d-style-follow".into(), r.rect));
            });
        });
        // One slider a row: a phone's width holds one slider, not two.
        ui.horizontal_wrapped(|ui| {
            let r = if fibres {
                let range = FIBERS_PER_PIXEL.slider(0.005);
                ui.add_enabled(
                    on,
                    egui::Slider::new(
                        &mut spec.fibres.per_pixel,
                        *range.start() as f32..=*range.end() as f32,
                    )
                    .logarithmic(true)
                    .text("fibres/px"),
                )
                .on_hover_text("Fibres per screen pixel, at every distance")
            } else {
                ui.add_enabled(
                    on,
                    egui::Slider::new(&mut spec.marks.frequency, 0.03..=MARK_FREQUENCY.hi as f32)
                        .logarithmic(true)
                        .text("marks/px"),
                )
                .on_hover_text("The marks' frequency, cycles per screen pixel")
            };
            controls.push(("view3d-style-density".into(), r.rect));
        });
        ui.horizontal_wrapped(|ui| {
            let r = if fibres || overlay {
                ui.add_enabled(
                    on,
                    egui::Slider::new(&mut spec.opacity, OPACITY.lo as f32..=OPACITY.hi as f32)
                        .text(if fibres { "opacity" } else { "strength" }),
                )
                .on_hover_text(if fibres {
                    "How much one fibre darkens what lies under it"
                } else {
                    "How strongly the pigment or the relief works the colour"
                })
            } else {
                ui.add_enabled(
                    on,
                    egui::Slider::new(
                        &mut spec.marks.tone,
                        MARK_TONE.lo as f32..=MARK_TONE.hi as f32,
                    )
                    .text("ink"),
                )
                .on_hover_text("More or less ink: the threshold of the marks")
            };
            controls.push(("view3d-style-tone".into(), r.rect));
        });
        ui.horizontal_wrapped(|ui| {
            let range = MARK_FREQUENCY_SHADING.lo as f32..=MARK_FREQUENCY_SHADING.hi as f32;
            let r = ui
                .add_enabled(
                    on && !fibres,
                    egui::Slider::new(&mut spec.marks.frequency_shading, range)
                        .text("darker denser"),
                )
                .on_hover_text(
                    "Finer marks where the object is darker: the frequency grows with the \
                     shade at each mark's centre",
                );
            controls.push(("view3d-style-frequency-shading".into(), r.rect));
        });
        if on && self.spec.map(|s| s.kind) == Some(spec.kind) {
            self.spec = Some(spec);
        }
        if let Some(e) = &self.error {
            ui.colored_label(egui::Color32::from_rgb(230, 90, 80), e);
        }
    }

    /// Computes the style's field for `view` of `design` when something changed (none
    /// without a style, or when it cannot be drawn).
    pub fn update(&mut self, design: &Design, design_key: u64, view: &View3d) {
        let Some(spec) = self.spec else {
            self.release();
            return;
        };
        let made = Made {
            design_key,
            view: View3d {
                antialias: marbling_core::Antialias::None,
                texture: None,
                ..*view
            },
            spec,
        };
        if !self.shown.as_ref().is_some_and(|(m, _)| *m == made) {
            let start = crate::platform::now_ms();
            match style_frame(design, &made.view, &spec) {
                Ok(frame) => {
                    self.error = None;
                    self.drawn = (
                        frame.kernels,
                        frame.fibres.len(),
                        crate::platform::now_ms() - start,
                    );
                    self.shown = Some((made, frame));
                }
                Err(e) => {
                    self.error = Some(format!("cannot draw the style: {e}"));
                    self.shown = None;
                }
            }
            self.revision += 1;
        }
    }

    /// The field of the last [`StyleControls::update`].
    pub fn frame(&self) -> Option<&StyleFrame> {
        self.shown.as_ref().map(|(_, f)| f)
    }

    /// Counts the field's changes (a pane drawn at another revision is out of date).
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// Forgets the field (the window closed).
    pub fn release(&mut self) {
        if self.shown.take().is_some() {
            self.revision += 1;
        }
    }

    /// The `style` member of the `data-view3d` hook.
    pub fn hook(&self) -> serde_json::Value {
        match &self.spec {
            None => serde_json::Value::Null,
            Some(spec) => serde_json::json!({
                "style": spec.kind.name(),
                "anchoring": spec.anchoring.name(),
                "follow": spec.marks.follow.name(),
                "kernels": self.drawn.0,
                "fibres": self.drawn.1,
                "ms": self.drawn.2,
            }),
        }
    }
}

fn follow_label(f: Follow) -> &'static str {
    match f {
        Follow::Screen => "strokes on the screen",
        Follow::Curvature => "strokes around the object",
        Follow::Stretch => "strokes along the ink",
    }
}

fn anchoring_label(a: Anchoring) -> &'static str {
    match a {
        Anchoring::Surface => "on the surface",
        Anchoring::Screen => "on the screen (2D noise)",
        Anchoring::Texture => "as a texture",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_style_is_offered_and_names_its_anchoring() {
        for (_, kind) in STYLE_KINDS {
            let c = StyleControls {
                spec: Some(StyleSpec::preset(kind)),
                ..Default::default()
            };
            assert_eq!(c.hook()["style"], kind.name());
            assert_eq!(c.hook()["anchoring"], "surface");
        }
        assert!(StyleControls::default().hook().is_null());
    }
}
