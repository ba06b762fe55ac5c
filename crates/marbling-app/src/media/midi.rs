//! MIDI drives the tools (Kung 2019, ch. 4: objects that answer to music; a peer, midi-sink,
//! turns notes into suminagashi drops). A note-on makes a drop of the current ink, or of
//! the palette's colour for the note's pitch class: the pitch places it along a line across
//! the sheet (notes 36–96, C2–C7, from 10 % to 90 % of the width, the line at a chosen
//! height), the velocity sets its radius (the drop tool's radius × (¼ + 1½·velocity/127):
//! velocity 64 gives the tool's radius). Control changes drive the drop radius and the
//! line's height, each bound to a controller number by *Learn* (the next control change
//! moved). What MIDI makes is an ordinary history step (`Action::Commit`), so it undoes,
//! replays, saves and links like a click.

use crate::action::Action;
use crate::frame::Frame;
use crate::media::midi_input::{self, MidiStatus};
use egui::{RichText, Slider};
use marbling_core::{Drop, Op, Point, Rgb8};

/// Lowest and highest notes placed along the line (C2, C7); others are clamped.
pub const NOTES: (u8, u8) = (36, 96);
/// Share of the sheet's width the line leaves empty at each end.
const LINE_MARGIN: f64 = 0.1;

/// A parameter a controller can move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The drop tool's radius (`ToolSettings::drop_radius`).
    DropRadius,
    /// The height of the line notes fall on.
    LineHeight,
}

impl Target {
    const ALL: [Target; 2] = [Target::DropRadius, Target::LineHeight];

    fn label(self) -> &'static str {
        match self {
            Target::DropRadius => "drop radius",
            Target::LineHeight => "line height",
        }
    }

    fn control(self) -> &'static str {
        match self {
            Target::DropRadius => "midi-learn-radius",
            Target::LineHeight => "midi-learn-line",
        }
    }
}

/// The MIDI section's state.
pub(crate) struct MidiPanel {
    /// Height of the line notes fall on, share of the sheet's height from the top.
    line_height: f64,
    /// Colour from the note's pitch class (C = the palette's first ink) instead of the ink.
    colour_by_pitch: bool,
    /// The controller bound to each target.
    bindings: [Option<u8>; 2],
    /// The target waiting for its controller.
    learning: Option<Target>,
    /// The last message, as the panel shows it.
    last: Option<String>,
}

impl Default for MidiPanel {
    fn default() -> Self {
        Self {
            line_height: 0.5,
            colour_by_pitch: false,
            bindings: [None; 2],
            learning: None,
            last: None,
        }
    }
}

/// The drop a note makes: see the module.
#[must_use]
pub fn note_drop(
    note: u8,
    velocity: u8,
    size: [u32; 2],
    line_height: f64,
    radius: f64,
    color: Rgb8,
) -> Drop {
    let (lo, hi) = NOTES;
    let t = f64::from(note.clamp(lo, hi) - lo) / f64::from(hi - lo);
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    Drop {
        center: Point::new(
            w * (LINE_MARGIN + (1.0 - 2.0 * LINE_MARGIN) * t),
            h * line_height,
        ),
        radius: radius * (0.25 + 1.5 * f64::from(velocity) / 127.0),
        color,
    }
}

impl MidiPanel {
    /// Takes the messages that arrived since the last frame (in any mode or tab).
    pub(crate) fn tick(&mut self, ctx: &egui::Context, frame: &mut Frame<'_>) {
        for message in midi_input::take(ctx) {
            self.handle(message, frame);
        }
    }

    fn handle(&mut self, [status, data1, data2]: [u8; 3], frame: &mut Frame<'_>) {
        match status & 0xF0 {
            // A note-on of velocity 0 is a note-off.
            0x90 if data2 > 0 => {
                let design = frame.editor.history.design();
                let inks = frame.prefs.inks();
                let color = match (self.colour_by_pitch, inks.len()) {
                    (true, n) if n > 0 => inks[usize::from(data1 % 12) % n],
                    _ => frame.prefs.ink,
                };
                let drop = note_drop(
                    data1,
                    data2,
                    [design.width, design.height],
                    self.line_height,
                    frame.prefs.settings.drop_radius,
                    color,
                );
                self.last = Some(format!("note {data1}, velocity {data2}: a drop"));
                frame.act(Action::Commit(vec![Op::Drop(drop)]));
            }
            0xB0 => {
                if let Some(target) = self.learning.take() {
                    self.bindings[target as usize] = Some(data1);
                    self.last = Some(format!("controller {data1} moves the {}", target.label()));
                    return;
                }
                let share = f64::from(data2) / 127.0;
                for target in Target::ALL {
                    if self.bindings[target as usize] != Some(data1) {
                        continue;
                    }
                    match target {
                        Target::DropRadius => {
                            let r = crate::marbling::tools::DROP_RADIUS;
                            frame.prefs.settings.drop_radius =
                                (r.start() + share * (r.end() - r.start())).round();
                        }
                        Target::LineHeight => self.line_height = share,
                    }
                }
                self.last = Some(format!("controller {data1}: {data2}"));
            }
            _ => {}
        }
    }

    /// The MIDI section: connecting, the line, the colours and the controller bindings.
    pub(crate) fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.label(RichText::new("MIDI").strong());
        match midi_input::status() {
            MidiStatus::Ready => {
                let r = ui.button("Connect MIDI").on_hover_text(
                    "Listen to MIDI keyboards and controllers (the browser asks first)",
                );
                frame.control("midi-connect", &r);
                if r.clicked() {
                    midi_input::connect();
                }
            }
            MidiStatus::Asking => {
                ui.label("asking the browser for MIDI…");
            }
            MidiStatus::Listening(n) => {
                ui.label(format!(
                    "listening to {n} MIDI input{}",
                    if n == 1 { "" } else { "s" }
                ));
            }
            MidiStatus::Unavailable(why) => {
                ui.label(RichText::new(why).weak());
            }
        }
        ui.label(
            RichText::new("A note drops ink on the line: pitch → place, velocity → size").weak(),
        );
        ui.add(Slider::new(&mut self.line_height, 0.0..=1.0).text("line height"));
        let r = ui.checkbox(&mut self.colour_by_pitch, "colour from pitch");
        frame.control("midi-colour-by-pitch", &r);
        for target in Target::ALL {
            ui.horizontal_wrapped(|ui| {
                let bound = match self.bindings[target as usize] {
                    Some(cc) => format!("{}: controller {cc}", target.label()),
                    None => format!("{}: no controller", target.label()),
                };
                ui.label(bound);
                let learning = self.learning == Some(target);
                let r = ui
                    .selectable_label(
                        learning,
                        if learning {
                            "move a control…"
                        } else {
                            "Learn"
                        },
                    )
                    .on_hover_text("Bind the next controller you move");
                frame.control(target.control(), &r);
                if r.clicked() {
                    self.learning = if learning { None } else { Some(target) };
                }
            });
        }
        if let Some(last) = &self.last {
            ui.label(RichText::new(last).weak());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pitch_places_and_velocity_sizes_a_drop() {
        let ink = Rgb8::new(10, 20, 30);
        let low = note_drop(36, 64, [1000, 500], 0.5, 30.0, ink);
        assert_eq!((low.center.x, low.center.y), (100.0, 250.0));
        assert!((low.radius - 30.0 * (0.25 + 1.5 * 64.0 / 127.0)).abs() < 1e-12);
        let high = note_drop(96, 127, [1000, 500], 0.2, 30.0, ink);
        assert_eq!((high.center.x, high.center.y), (900.0, 100.0));
        assert!((high.radius - 52.5).abs() < 1e-12);
        // Notes outside C2–C7 land at the line's ends.
        assert_eq!(note_drop(0, 1, [1000, 500], 0.5, 30.0, ink).center.x, 100.0);
        assert_eq!(
            note_drop(127, 1, [1000, 500], 0.5, 30.0, ink).center.x,
            900.0
        );
        // Middle C (60) is 24/60 of the way along.
        assert!((note_drop(60, 64, [1000, 500], 0.5, 30.0, ink).center.x - 420.0).abs() < 1e-9);
    }
}
