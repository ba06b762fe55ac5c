//! The side panel's *Recent designs* section: the designs New, Open, a link or the
//! gallery replaced, each with a thumbnail made once (one a frame) and its date, ops
//! and size; a click restores one as an undoable step.

use crate::action::Action;
use crate::frame::Frame;
use crate::store::recent::Recent;
use egui::RichText;
use std::collections::HashMap;

/// The section's thumbnails, by share fragment (`None`: too large to draw one quickly,
/// or unreadable).
#[derive(Default)]
pub(crate) struct RecentPanel {
    thumbnails: HashMap<String, Option<egui::TextureHandle>>,
}

impl RecentPanel {
    /// The *Recent designs* section: a thumbnail (one made a frame) and a line per
    /// entry of `recent`; a click restores it (undoable).
    pub fn ui(&mut self, ui: &mut egui::Ui, recent: &Recent, frame: &mut Frame<'_>) {
        let count = recent.entries.len();
        let header = egui::CollapsingHeader::new(format!("Recent designs ({count})"))
            .id_salt("recent")
            .show(ui, |ui| {
                if count == 0 {
                    ui.label(
                        RichText::new(
                            "Designs replaced by New, Open, a link or the gallery are kept here.",
                        )
                        .weak(),
                    );
                }
                let mut open = None;
                let mut made_one = false;
                for i in 0..count {
                    let e = recent.entries[i].clone();
                    let thumb = match self.thumbnails.get(&e.fragment) {
                        Some(t) => t.clone(),
                        None if !made_one => {
                            made_one = true;
                            let t =
                                crate::store::thumbnails::recent_thumbnail(recent, i).map(|img| {
                                    ui.ctx().load_texture(
                                        format!("recent {i}"),
                                        img,
                                        egui::TextureOptions::LINEAR,
                                    )
                                });
                            self.thumbnails.insert(e.fragment.clone(), t.clone());
                            t
                        }
                        None => {
                            ui.ctx().request_repaint();
                            None
                        }
                    };
                    let r = ui
                        .horizontal(|ui| {
                            let size = egui::vec2(64.0, 48.0);
                            match &thumb {
                                Some(t) => {
                                    ui.add(
                                        egui::Image::new((t.id(), size)).fit_to_exact_size(size),
                                    );
                                }
                                None => {
                                    let (rect, _) =
                                        ui.allocate_exact_size(size, egui::Sense::hover());
                                    ui.painter().rect_stroke(
                                        rect,
                                        2.0,
                                        ui.visuals().widgets.noninteractive.bg_stroke,
                                        egui::StrokeKind::Inside,
                                    );
                                    ui.painter().text(
                                        rect.center(),
                                        egui::Align2::CENTER_CENTER,
                                        "no preview",
                                        egui::FontId::proportional(10.0),
                                        ui.visuals().weak_text_color(),
                                    );
                                }
                            }
                            // Labels that cannot be selected, so a click anywhere on
                            // the entry opens it.
                            ui.vertical(|ui| {
                                ui.add(
                                    egui::Label::new(format!(
                                        "{} · {} ops · {}×{}",
                                        crate::store::recent::date_label(e.saved_ms),
                                        e.ops,
                                        e.size[0],
                                        e.size[1]
                                    ))
                                    .selectable(false),
                                );
                                ui.add(
                                    egui::Label::new(RichText::new(&e.label).weak())
                                        .selectable(false),
                                );
                            });
                        })
                        .response
                        .interact(egui::Sense::click())
                        .on_hover_text("Restore this design (undoable)");
                    if r.hovered() {
                        ui.painter().rect_stroke(
                            r.rect.expand(1.0),
                            2,
                            ui.visuals().widgets.hovered.fg_stroke,
                            egui::StrokeKind::Outside,
                        );
                    }
                    frame.control(format!("recent-{i}"), &r);
                    if r.clicked() {
                        open = Some(i);
                    }
                }
                if let Some(i) = open {
                    frame.act(Action::OpenRecent(i));
                }
            });
        frame.control("recent", &header.header_response);
    }
}
