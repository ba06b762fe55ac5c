//! The relief view of the noise lab: a patch of the noise (its top-left 512 px at the
//! export size, or the whole export when smaller) sampled on a 128² grid within a time
//! budget per frame, turned into the normal map Export writes
//! (`marbling_core::view3d::ReliefMap`) and lit on the 3D view's plane
//! (`marbling_core::view3d::render_relief`). Drag the picture to turn the plane; the light
//! and the relief have their own controls. Nothing is redrawn unless the noise, the relief,
//! the light or the camera changed.

use crate::frame::Frame;
use crate::noise::export::FRAME_BUDGET_MS;
use egui::{RichText, Slider};
use marbling_core::Antialias;
use marbling_core::view3d::{Camera, Light, ReliefMap, Shape, View3d, render_relief};
use marbling_noise::{NoiseSpec, Renderer, ranges};

/// Samples per side of the height grid.
pub const GRID: usize = 128;
/// Longest side of the noise patch shown, output pixels.
pub const PATCH: u32 = 512;
/// Size of the lit picture, pixels.
const VIEW: [u32; 2] = [288, 216];
/// Degrees the plane turns per point dragged.
const TURN_PER_POINT: f64 = 0.4;

/// Heights and colours of the patch, sampled row by row.
struct Heights {
    spec: NoiseSpec,
    size: u32,
    renderer: Renderer,
    /// Output pixels between samples.
    cell: f32,
    heights: Vec<f32>,
    colors: Vec<[f32; 3]>,
    /// +1 for every new sampling, so a drawn picture knows which one it shows.
    generation: u64,
}

impl Heights {
    fn done(&self) -> bool {
        self.heights.len() == GRID * GRID
    }

    /// Samples rows until `budget_ms` has passed.
    fn advance(&mut self, budget_ms: f64, now: impl Fn() -> f64) {
        let start = now();
        while !self.done() {
            let j = self.heights.len() / GRID;
            let xs: Vec<f32> = (0..GRID).map(|i| (i as f32 + 0.5) * self.cell).collect();
            let y = (j as f32 + 0.5) * self.cell;
            let mut row = vec![0.0; GRID];
            self.renderer.intensity_row(&xs, y, &mut row);
            self.colors.extend(self.renderer.colors_of(&xs, y, &row));
            self.heights.extend(row);
            if now() - start > budget_ms {
                break;
            }
        }
    }
}

/// What a drawn picture shows.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Drawn {
    generation: u64,
    relief: f32,
    light: Light,
    yaw: f64,
    pitch: f64,
}

/// The relief view's state.
pub(crate) struct ReliefView {
    relief: f32,
    open: bool,
    light: Light,
    yaw: f64,
    pitch: f64,
    heights: Option<Heights>,
    shown: Option<(Drawn, egui::TextureHandle)>,
    generations: u64,
}

impl Default for ReliefView {
    fn default() -> Self {
        Self {
            relief: ranges::DEFAULT_RELIEF as f32,
            open: false,
            light: Light::default(),
            yaw: 0.0,
            pitch: 30.0,
            heights: None,
            shown: None,
            generations: 0,
        }
    }
}

impl ReliefView {
    /// Height of intensity 1 above 0, output pixels (the normal map's relief).
    pub(crate) fn relief(&self) -> f32 {
        self.relief
    }

    /// The relief in pixels and the toggle of the lit view (in the export row).
    pub(crate) fn relief_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        let range = ranges::RELIEF.slider(0.1);
        let r = ui
            .add(
                egui::DragValue::new(&mut self.relief)
                    .range(*range.start() as f32..=*range.end() as f32)
                    .speed(0.2)
                    .suffix(" px relief"),
            )
            .on_hover_text("Height of the brightest intensity above the darkest, pixels");
        frame.control("noise-relief", &r);
        let t = ui
            .toggle_value(&mut self.open, "Relief view")
            .on_hover_text("The noise as a relief, lit on the 3D view's plane (drag it to turn)");
        frame.control("noise-relief-toggle", &t);
    }

    /// The lit picture of `spec` exported at `size`² (under the export row), when open.
    pub(crate) fn view_ui(
        &mut self,
        ui: &mut egui::Ui,
        spec: &NoiseSpec,
        size: u32,
        frame: &mut Frame<'_>,
    ) {
        if !self.open {
            return;
        }
        let stale = self
            .heights
            .as_ref()
            .is_none_or(|h| h.size != size || &h.spec != spec);
        if stale {
            match Renderer::new(spec, size) {
                Ok(renderer) => {
                    self.generations += 1;
                    self.heights = Some(Heights {
                        spec: spec.clone(),
                        size,
                        renderer,
                        cell: size.min(PATCH) as f32 / GRID as f32,
                        heights: Vec::with_capacity(GRID * GRID),
                        colors: Vec::with_capacity(GRID * GRID),
                        generation: self.generations,
                    });
                }
                Err(e) => {
                    self.heights = None;
                    ui.label(RichText::new(format!("relief: {e}")).weak());
                    return;
                }
            }
        }
        let Some(h) = self.heights.as_mut() else {
            return;
        };
        if !h.done() {
            h.advance(FRAME_BUDGET_MS, crate::platform::now_ms);
            ui.ctx().request_repaint();
        }
        if !h.done() {
            let share = h.heights.len() as f32 / (GRID * GRID) as f32;
            ui.label(format!("sampling the relief… {:.0} %", 100.0 * share));
            return;
        }
        let drawn = Drawn {
            generation: h.generation,
            relief: self.relief,
            light: self.light,
            yaw: self.yaw,
            pitch: self.pitch,
        };
        if self.shown.as_ref().is_none_or(|(d, _)| *d != drawn) {
            let Some(map) =
                ReliefMap::from_heights(GRID, &h.heights, &h.colors, h.cell, self.relief)
            else {
                return;
            };
            let image = render_relief(&map, self.light, &self.view());
            let picture = egui::ColorImage::from_rgba_unmultiplied(
                [image.width as usize, image.height as usize],
                &image.pixels,
            );
            match &mut self.shown {
                Some((d, texture)) => {
                    texture.set(picture, egui::TextureOptions::LINEAR);
                    *d = drawn;
                }
                None => {
                    let texture = ui.ctx().load_texture(
                        "noise-relief",
                        picture,
                        egui::TextureOptions::LINEAR,
                    );
                    self.shown = Some((drawn, texture));
                }
            }
        }
        let Some((_, texture)) = &self.shown else {
            return;
        };
        let width = ui.available_width().min(VIEW[0] as f32);
        let height = width * VIEW[1] as f32 / VIEW[0] as f32;
        let r = ui.add(
            egui::Image::new((texture.id(), egui::vec2(width, height))).sense(egui::Sense::drag()),
        );
        frame.control("noise-relief-view", &r);
        if r.dragged() {
            let d = r.drag_delta();
            self.yaw -= f64::from(d.x) * TURN_PER_POINT;
            self.pitch = (self.pitch + f64::from(d.y) * TURN_PER_POINT).clamp(-85.0, 85.0);
        }
        ui.add(Slider::new(&mut self.light.azimuth, 0.0..=360.0).text("light from (°)"))
            .on_hover_text("0: from the right, 90: from the top");
        ui.add(Slider::new(&mut self.light.elevation, 5.0..=90.0).text("light height (°)"));
    }

    /// The camera of the picture: the plane, turned by the drags.
    fn view(&self) -> View3d {
        View3d {
            shape: Shape::Plane,
            camera: Camera {
                yaw: Some(self.yaw),
                pitch: Some(self.pitch),
                zoom: 1.0,
                look_at: None,
                dolly: 1.0,
            },
            width: VIEW[0],
            height: VIEW[1],
            antialias: Antialias::None,
            texture: None,
            displace: marbling_core::view3d::Displace::default(),
        }
    }
}
