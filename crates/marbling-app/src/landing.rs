//! The gallery view: a card per traditional pattern (thumbnails drawn by the GPU
//! renderer, src/gallery_gpu.rs) and a blank-sheet card, shown in place of the canvas
//! when the app opens without a link or an autosave, and by the panel's *Gallery*
//! button. A card opens its design for editing.

use crate::action::Action;
use crate::app::MarblingApp;
use crate::gallery::ENTRIES;
use crate::gallery_gpu::{ThumbnailCallback, cell_uv};
use eframe::egui_wgpu;
use egui::{Color32, RichText, Sense, vec2};
use marbling_core::Design;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The gallery's designs, their names, and how many thumbnails are drawn.
pub struct GalleryView {
    /// The designs in [`ENTRIES`] order (an unreadable entry is left out).
    pub designs: Arc<Vec<Design>>,
    /// (entry index, name) of each design.
    pub names: Vec<(usize, String)>,
    /// Thumbnails in the atlas so far.
    pub drawn: Arc<AtomicUsize>,
}

impl GalleryView {
    /// Reads the bundled designs.
    pub fn load() -> Self {
        let mut designs = Vec::new();
        let mut names = Vec::new();
        for (i, e) in ENTRIES.iter().enumerate() {
            if let Ok(d) = e.design() {
                names.push((i, e.name(&d)));
                designs.push(d);
            }
        }
        Self {
            designs: Arc::new(designs),
            names,
            drawn: Arc::default(),
        }
    }

    /// Thumbnails drawn so far, and how many there are.
    pub fn progress(&self) -> (usize, usize) {
        (self.drawn.load(Ordering::SeqCst), self.designs.len())
    }
}

/// Text on the dark surround.
const LIGHT: Color32 = Color32::from_gray(225);

/// A card's thumbnail size, points (16:10).
const CARD: egui::Vec2 = vec2(176.0, 110.0);

impl MarblingApp {
    /// Shows the gallery in place of the canvas.
    pub(crate) fn landing(&mut self, ui: &mut egui::Ui) {
        let view = self.panels.gallery.get_or_insert_with(GalleryView::load);
        let (drawn, total) = view.progress();
        if drawn < total && self.rendering.gpu {
            // One thumbnail a frame, drawn in egui's prepare step.
            ui.painter().add(egui_wgpu::Callback::new_paint_callback(
                ui.max_rect(),
                ThumbnailCallback {
                    designs: view.designs.clone(),
                    drawn: view.drawn.clone(),
                },
            ));
            ui.ctx().request_repaint();
        }
        let designs = view.designs.clone();
        let names = view.names.clone();
        let texture = self.panels.gallery_texture;
        let mut open = None;
        let mut blank = false;
        let mut close = false;
        let mut drawn_controls = Vec::new();
        if self.panels.layout.touch() {
            crate::layout::touch_spacing(ui);
        }
        egui::ScrollArea::vertical().show(ui, |ui| {
            ui.add_space(8.0);
            ui.horizontal(|ui| {
                ui.label(
                    RichText::new("Start from a traditional pattern")
                        .heading()
                        .color(LIGHT),
                );
                let back = ui.button("Back to the editor");
                drawn_controls.push(("gallery-close".to_owned(), back.clone()));
                close = back.clicked();
            });
            ui.label(
                RichText::new(
                    "Each pattern is a recipe made step by step the way a marbler makes it; \
                     it opens as an editable design, and Play walks through its making.",
                )
                .color(LIGHT),
            );
            ui.add_space(8.0);
            let gap = ui.spacing().item_spacing.x;
            let cols = (((ui.available_width() + gap) / (CARD.x + gap)).floor() as usize).max(1);
            let cards: Vec<Option<usize>> = std::iter::once(None)
                .chain((0..designs.len()).map(Some))
                .collect();
            for row in cards.chunks(cols) {
                ui.horizontal(|ui| {
                    for card in row {
                        ui.vertical(|ui| {
                            ui.set_width(CARD.x);
                            let r = match card {
                                None => {
                                    let (rect, r) = ui.allocate_exact_size(CARD, Sense::click());
                                    let paper = crate::app::blank(crate::app::NEW_SIZE).background;
                                    ui.painter().rect_filled(
                                        rect,
                                        2,
                                        Color32::from_rgb(paper.r, paper.g, paper.b),
                                    );
                                    ui.painter().text(
                                        rect.center(),
                                        egui::Align2::CENTER_CENTER,
                                        "+",
                                        egui::FontId::proportional(40.0),
                                        Color32::from_gray(120),
                                    );
                                    ui.label(RichText::new("Blank sheet").strong().color(LIGHT));
                                    drawn_controls.push(("gallery-blank".to_owned(), r.clone()));
                                    blank |= r.clicked();
                                    r
                                }
                                Some(n) => {
                                    let r = match texture {
                                        Some(id) => ui.add(
                                            egui::Image::new((id, CARD))
                                                .uv(cell_uv(*n, &designs[*n]))
                                                .sense(Sense::click()),
                                        ),
                                        None => ui.allocate_exact_size(CARD, Sense::click()).1,
                                    };
                                    let (entry, name) = &names[*n];
                                    ui.label(RichText::new(name).color(LIGHT));
                                    drawn_controls.push((
                                        format!("gallery-{}", ENTRIES[*entry].id),
                                        r.clone(),
                                    ));
                                    if r.clicked() {
                                        open = Some(*n);
                                    }
                                    r
                                }
                            };
                            if r.hovered() {
                                ui.painter().rect_stroke(
                                    r.rect.expand(1.0),
                                    2,
                                    ui.visuals().widgets.hovered.fg_stroke,
                                    egui::StrokeKind::Outside,
                                );
                            }
                        });
                    }
                });
                ui.add_space(6.0);
            }
        });
        for (name, r) in drawn_controls {
            self.control(name, &r);
        }
        if let Some(n) = open {
            let name = names[n].1.clone();
            self.editor.landing = false;
            self.apply(Action::Load {
                design: designs[n].clone(),
                from: name,
                from_link: false,
            });
        } else if blank {
            self.editor.landing = false;
            self.apply(Action::NewSheet);
        } else if close {
            self.editor.landing = false;
        }
    }
}
