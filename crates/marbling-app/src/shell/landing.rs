//! The gallery view: a card per traditional pattern (thumbnails from the prerendered
//! atlas, src/gpu/gallery_atlas.rs; drawn by the GPU renderer, src/gpu/gallery_gpu.rs, only where
//! that file cannot be had) and a blank-sheet card, shown in place of the canvas when the
//! app opens without a link or an autosave, and by the panel's *Gallery* button. A card
//! opens its design for editing.

use crate::action::Action;
use crate::frame::Frame;
use crate::gpu::gallery_atlas::{AtlasLoad, Loaded};
use crate::gpu::gallery_gpu::{ThumbnailCallback, cell_uv};
use crate::shell::gallery::{Card, Entry, entries};
use eframe::egui_wgpu;
use egui::{Color32, RichText, Sense, vec2};
use marbling_core::Design;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The gallery's cards, their designs once made, and where the thumbnails come from.
pub struct GalleryView {
    /// The entries and their cards, in gallery order (an unreadable entry is left out).
    cards: Vec<(Entry, Card)>,
    /// Every card's design, made only where the GPU draws the thumbnails (without the
    /// prerendered atlas); a card's click makes its own.
    designs: Option<Arc<Vec<Design>>>,
    /// Thumbnails in the GPU atlas so far.
    drawn: Arc<AtomicUsize>,
    /// The prerendered thumbnails on their way, and their texture once in.
    atlas: AtlasLoad,
    atlas_texture: Option<egui::TextureHandle>,
}

impl GalleryView {
    /// The cards (no design is made yet) and the prerendered thumbnails, on their way.
    pub fn load(ctx: &egui::Context) -> Self {
        let cards = entries()
            .into_iter()
            .filter_map(|e| e.card().ok().map(|c| (e, c)))
            .collect();
        Self {
            cards,
            designs: None,
            drawn: Arc::default(),
            atlas: AtlasLoad::start(ctx),
            atlas_texture: None,
        }
    }

    /// Every card's design, made on the first call.
    fn designs(&mut self) -> Arc<Vec<Design>> {
        self.designs
            .get_or_insert_with(|| {
                Arc::new(
                    self.cards
                        .iter()
                        .map(|(e, c)| {
                            e.design()
                                .unwrap_or_else(|_| Design::new(c.size.0, c.size.1, c.paper))
                        })
                        .collect(),
                )
            })
            .clone()
    }

    /// Thumbnails shown so far, and how many there are: all of them once the prerendered
    /// atlas is in.
    pub fn progress(&self) -> (usize, usize) {
        let total = self.cards.len();
        match self.atlas_texture {
            Some(_) => (total, total),
            None => (self.drawn.load(Ordering::SeqCst), total),
        }
    }

    /// Where the thumbnails come from: `atlas` (prerendered), `gpu` (drawn here, when the
    /// atlas cannot be had) or `waiting` (the atlas is on its way).
    pub fn source(&self) -> &'static str {
        match (&self.atlas_texture, self.atlas.state()) {
            (Some(_), _) => "atlas",
            (None, Loaded::Failed(_)) => "gpu",
            (None, _) => "waiting",
        }
    }

    /// The prerendered atlas's texture, made on the first call after it came in; `None`
    /// while it is on its way or when it failed (logged once).
    fn atlas_texture(&mut self, ctx: &egui::Context) -> Option<egui::TextureId> {
        if self.atlas_texture.is_none() {
            match self.atlas.state() {
                Loaded::Pixels(p) => {
                    let image = egui::ColorImage::from_rgba_unmultiplied(
                        [p.width as usize, p.height as usize],
                        &p.rgba,
                    );
                    self.atlas_texture = Some(ctx.load_texture(
                        "gallery-thumbnails",
                        image,
                        egui::TextureOptions::LINEAR,
                    ));
                }
                Loaded::Failed(why) if self.drawn.load(Ordering::SeqCst) == 0 => {
                    log::warn!("the gallery's thumbnails are drawn here: {why}");
                }
                _ => {}
            }
        }
        self.atlas_texture.as_ref().map(egui::TextureHandle::id)
    }
}

/// Text on the dark surround.
const LIGHT: Color32 = Color32::from_gray(225);

/// A card's thumbnail size, points (16:10).
const CARD: egui::Vec2 = vec2(176.0, 110.0);

/// A card without a picture: its paper colour with `text` (`size` points) in the middle.
fn plain_card(
    ui: &mut egui::Ui,
    paper: marbling_core::Rgb8,
    text: &str,
    size: f32,
) -> egui::Response {
    let (rect, r) = ui.allocate_exact_size(CARD, Sense::click());
    ui.painter()
        .rect_filled(rect, 2, Color32::from_rgb(paper.r, paper.g, paper.b));
    ui.painter().text(
        rect.center(),
        egui::Align2::CENTER_CENTER,
        text,
        egui::FontId::proportional(size),
        Color32::from_gray(115),
    );
    r
}

/// The gallery shown in place of the canvas: its cards and thumbnails, made on first
/// show, and the texture egui knows the GPU-drawn thumbnails by.
#[derive(Default)]
pub(crate) struct Gallery {
    view: Option<GalleryView>,
    gpu_texture: Option<egui::TextureId>,
}

impl Gallery {
    /// A gallery whose thumbnails, where the GPU draws them, are in texture `id`.
    pub fn with_gpu_texture(id: Option<egui::TextureId>) -> Self {
        Self {
            view: None,
            gpu_texture: id,
        }
    }

    /// The cards and thumbnails, once shown.
    pub fn view(&self) -> Option<&GalleryView> {
        self.view.as_ref()
    }

    /// Shows the gallery in place of the canvas (`gpu`: a GPU renderer exists to draw
    /// thumbnails the prerendered atlas cannot give).
    pub fn ui(&mut self, ui: &mut egui::Ui, gpu: bool, frame: &mut Frame<'_>) {
        let ctx = ui.ctx().clone();
        let view = self.view.get_or_insert_with(|| GalleryView::load(&ctx));
        let atlas = view.atlas_texture(&ctx);
        let drawn_here = view.source() == "gpu";
        let (drawn, total) = view.progress();
        if drawn_here && drawn < total && gpu {
            // Without the prerendered atlas: one thumbnail a frame, drawn in egui's
            // prepare step.
            ui.painter().add(egui_wgpu::Callback::new_paint_callback(
                ui.max_rect(),
                ThumbnailCallback {
                    designs: view.designs(),
                    drawn: view.drawn.clone(),
                },
            ));
            ui.ctx().request_repaint();
        }
        let shown: Vec<Card> = view.cards.iter().map(|(_, c)| c.clone()).collect();
        let ids: Vec<&'static str> = view.cards.iter().map(|(e, _)| e.id).collect();
        let texture = if drawn_here { self.gpu_texture } else { atlas };
        let mut open = None;
        let mut blank = false;
        let mut close = false;
        let mut drawn_controls = Vec::new();
        if frame.layout.touch() {
            crate::shell::layout::touch_spacing(ui);
        }
        // The scroll bar always shows: a cut-off last row says there is more below.
        egui::ScrollArea::vertical()
            .scroll_bar_visibility(egui::scroll_area::ScrollBarVisibility::AlwaysVisible)
            .show(ui, |ui| {
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
                let cols =
                    (((ui.available_width() + gap) / (CARD.x + gap)).floor() as usize).max(1);
                let cards: Vec<Option<usize>> = std::iter::once(None)
                    .chain((0..shown.len()).map(Some))
                    .collect();
                for row in cards.chunks(cols) {
                    ui.horizontal(|ui| {
                        for card in row {
                            ui.vertical(|ui| {
                                ui.set_width(CARD.x);
                                let r = match card {
                                    None => {
                                        let paper = crate::store::file_panel::blank(
                                            crate::store::file_panel::NEW_SIZE,
                                        )
                                        .background;
                                        let r = plain_card(ui, paper, "+", 40.0);
                                        ui.label(
                                            RichText::new("Blank sheet").strong().color(LIGHT),
                                        );
                                        drawn_controls
                                            .push(("gallery-blank".to_owned(), r.clone()));
                                        blank |= r.clicked();
                                        r
                                    }
                                    Some(n) => {
                                        let r = match texture {
                                            Some(id) => ui.add(
                                                egui::Image::new((id, CARD))
                                                    .uv(cell_uv(*n, shown[*n].size))
                                                    .sense(Sense::click()),
                                            ),
                                            None => {
                                                // The atlas is on its way: the paper colour,
                                                // and a word saying so.
                                                plain_card(ui, shown[*n].paper, "loading…", 14.0)
                                            }
                                        };
                                        ui.label(RichText::new(&shown[*n].name).color(LIGHT));
                                        drawn_controls
                                            .push((format!("gallery-{}", ids[*n]), r.clone()));
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
            frame.control(name, &r);
        }
        let opened = open.and_then(|n| {
            let view = self.view.as_ref()?;
            let (entry, card) = view.cards.get(n)?;
            Some((entry.design(), card.name.clone()))
        });
        if let Some((design, name)) = opened {
            match design {
                Ok(design) => frame.act(Action::Load {
                    design,
                    from: name,
                    from_link: false,
                }),
                Err(e) => {
                    frame.act(Action::ShowGallery(false));
                    frame.error(format!("{name}: {e}"));
                }
            }
        } else if blank {
            frame.act(Action::NewSheet);
        } else if close {
            frame.act(Action::ShowGallery(false));
        }
    }
}
