//! MIDI drives the tools (Kung 2019, ch. 4: objects that answer to music; a peer, midi-sink,
//! turns notes into suminagashi drops). A note-on makes a drop of the current ink, or of
//! the palette's colour for the note's pitch class: the pitch places it along a line
//! (notes 36–96, C2–C7, from its start to its end): across the sheet from 10 % to 90 % of
//! the width at a chosen height, or one the user draws on the sheet (*Draw line*). The
//! velocity sets its radius (the drop tool's radius × (¼ + 1½·velocity/127): velocity 64
//! gives the tool's radius). Control changes drive tool parameters — the drop radius,
//! the stylus's wake, the comb's spacing, the flow's strength — and the line's height,
//! each bound to a controller number by *Learn* (the next control change moved). What
//! MIDI makes is an ordinary history step (`Action::Commit`), so it undoes, replays,
//! saves and links like a click.

use crate::action::Action;
use crate::frame::Frame;
use crate::marbling::tools::{self, ToolSettings};
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
    /// The stylus's wake (`ToolSettings::stylus_wake`).
    StylusWake,
    /// The comb's tine spacing (`ToolSettings::comb_spacing`).
    CombSpacing,
    /// The flow's strength (`ToolSettings::flow_strength`).
    FlowStrength,
}

impl Target {
    const ALL: [Target; 5] = [
        Target::DropRadius,
        Target::LineHeight,
        Target::StylusWake,
        Target::CombSpacing,
        Target::FlowStrength,
    ];

    fn label(self) -> &'static str {
        match self {
            Target::DropRadius => "drop radius",
            Target::LineHeight => "line height",
            Target::StylusWake => "stylus wake",
            Target::CombSpacing => "comb spacing",
            Target::FlowStrength => "flow strength",
        }
    }

    fn control(self) -> &'static str {
        match self {
            Target::DropRadius => "midi-learn-radius",
            Target::LineHeight => "midi-learn-line",
            Target::StylusWake => "midi-learn-wake",
            Target::CombSpacing => "midi-learn-spacing",
            Target::FlowStrength => "midi-learn-flow",
        }
    }

    /// Sets this target of `settings` (or the panel's line height) to the share
    /// `share` (0..=1) of its slider: the drop radius and the line linearly, the
    /// logarithmic sliders geometrically.
    fn set(self, share: f64, settings: &mut ToolSettings, line_height: &mut f64) {
        let linear = |r: std::ops::RangeInclusive<f64>| r.start() + share * (r.end() - r.start());
        let geometric =
            |r: std::ops::RangeInclusive<f64>| r.start() * (r.end() / r.start()).powf(share);
        match self {
            Target::DropRadius => settings.drop_radius = linear(tools::DROP_RADIUS).round(),
            Target::LineHeight => *line_height = share,
            Target::StylusWake => settings.stylus_wake = geometric(tools::STYLUS_WAKE),
            Target::CombSpacing => settings.comb_spacing = geometric(tools::COMB_SPACING),
            Target::FlowStrength => settings.flow_strength = geometric(tools::FLOW_STRENGTH),
        }
    }
}

/// Drawing the line notes fall on (*Draw line*: the next drag on the sheet).
#[derive(Clone, Copy, Debug, PartialEq)]
enum LineDrawing {
    Off,
    /// Waiting for the press.
    Armed,
    /// Pressed at `.0`, the pointer at `.1`.
    Dragging(Point, Point),
}

/// The MIDI section's state.
pub(crate) struct MidiPanel {
    /// Height of the line notes fall on, share of the sheet's height from the top.
    line_height: f64,
    /// Colour from the note's pitch class (C = the palette's first ink) instead of the ink.
    colour_by_pitch: bool,
    /// A line drawn on the sheet (start: C2, end: C7), instead of the line across.
    line: Option<[Point; 2]>,
    drawing: LineDrawing,
    /// The controller bound to each target.
    bindings: [Option<u8>; 5],
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
            line: None,
            drawing: LineDrawing::Off,
            bindings: [None; 5],
            learning: None,
            last: None,
        }
    }
}

/// The line across a sheet of `size` at `height` (share of the sheet's height from the
/// top), from 10 % to 90 % of the width.
#[must_use]
pub fn line_across(size: [u32; 2], height: f64) -> [Point; 2] {
    let (w, h) = (f64::from(size[0]), f64::from(size[1]));
    [
        Point::new(w * LINE_MARGIN, h * height),
        Point::new(w * (1.0 - LINE_MARGIN), h * height),
    ]
}

/// The drop a note makes on `line` (C2 at its start, C7 at its end): see the module.
#[must_use]
pub fn note_drop(note: u8, velocity: u8, line: [Point; 2], radius: f64, color: Rgb8) -> Drop {
    let (lo, hi) = NOTES;
    let t = f64::from(note.clamp(lo, hi) - lo) / f64::from(hi - lo);
    let [a, b] = line;
    Drop {
        center: Point::new(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)),
        radius: radius * (0.25 + 1.5 * f64::from(velocity) / 127.0),
        color,
    }
}

impl MidiPanel {
    /// The `data-midi-learning` hook: the control name of the *Learn* button waiting
    /// for a controller.
    pub fn learning_hook(&self) -> Option<String> {
        self.learning.map(|t| t.control().to_owned())
    }

    /// Whether the next drag on the sheet draws the line (the canvas then calls
    /// [`Self::draw_line`] instead of driving the tool).
    pub fn drawing_line(&self) -> bool {
        self.drawing != LineDrawing::Off
    }

    /// The line being drawn: pressed at `at` (`pressed`), dragged to it, released
    /// (`down` false: the line is kept when it is at least a design pixel long).
    pub fn draw_line(&mut self, at: Option<Point>, pressed: bool, down: bool) {
        self.drawing = match (self.drawing, at) {
            (LineDrawing::Armed, Some(p)) if pressed => LineDrawing::Dragging(p, p),
            (LineDrawing::Dragging(a, _), Some(p)) if down => LineDrawing::Dragging(a, p),
            (LineDrawing::Dragging(a, b), _) if !down => {
                if (b.x - a.x).hypot(b.y - a.y) >= 1.0 {
                    self.line = Some([a, b]);
                    self.last = Some("notes fall on the line you drew".to_owned());
                }
                LineDrawing::Off
            }
            (d, _) => d,
        };
    }

    /// The drawn line, or the one being drawn, for the canvas to show.
    pub fn shown_line(&self) -> Option<[Point; 2]> {
        match self.drawing {
            LineDrawing::Dragging(a, b) => Some([a, b]),
            _ => self.line,
        }
    }

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
                let line = self.line.unwrap_or_else(|| {
                    line_across([design.width, design.height], self.line_height)
                });
                let drop = note_drop(data1, data2, line, frame.prefs.settings.drop_radius, color);
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
                    target.set(share, &mut frame.prefs.settings, &mut self.line_height);
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
        ui.horizontal_wrapped(|ui| {
            if self.line.is_none() {
                ui.add(Slider::new(&mut self.line_height, 0.0..=1.0).text("line height"));
            }
            let drawing = self.drawing_line();
            let draw = ui
                .selectable_label(
                    drawing,
                    if drawing {
                        "drag on the sheet…"
                    } else {
                        "Draw line"
                    },
                )
                .on_hover_text(
                    "Drag a line on the sheet: low notes fall at its start, high ones at its end",
                );
            frame.control("midi-draw-line", &draw);
            if draw.clicked() {
                self.drawing = if drawing {
                    LineDrawing::Off
                } else {
                    LineDrawing::Armed
                };
            }
            if self.line.is_some() {
                let across = ui
                    .button("Line across")
                    .on_hover_text("Back to the line across the sheet");
                frame.control("midi-line-across", &across);
                if across.clicked() {
                    self.line = None;
                }
            }
        });
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
        let middle = line_across([1000, 500], 0.5);
        let low = note_drop(36, 64, middle, 30.0, ink);
        assert_eq!((low.center.x, low.center.y), (100.0, 250.0));
        assert!((low.radius - 30.0 * (0.25 + 1.5 * 64.0 / 127.0)).abs() < 1e-12);
        let high = note_drop(96, 127, line_across([1000, 500], 0.2), 30.0, ink);
        assert_eq!((high.center.x, high.center.y), (900.0, 100.0));
        assert!((high.radius - 52.5).abs() < 1e-12);
        // Notes outside C2–C7 land at the line's ends.
        assert_eq!(note_drop(0, 1, middle, 30.0, ink).center.x, 100.0);
        assert_eq!(note_drop(127, 1, middle, 30.0, ink).center.x, 900.0);
        // Middle C (60) is 24/60 of the way along.
        assert!((note_drop(60, 64, middle, 30.0, ink).center.x - 420.0).abs() < 1e-9);
        // Along a drawn line, upwards: C2 at its start, C7 at its end.
        let drawn = [Point::new(50.0, 400.0), Point::new(50.0, 100.0)];
        assert_eq!(note_drop(36, 64, drawn, 30.0, ink).center, drawn[0]);
        assert_eq!(note_drop(96, 64, drawn, 30.0, ink).center, drawn[1]);
        assert_eq!(
            note_drop(66, 64, drawn, 30.0, ink).center,
            Point::new(50.0, 250.0)
        );
    }

    #[test]
    fn a_drag_draws_the_line_and_a_click_keeps_the_old_one() {
        let mut m = MidiPanel::default();
        m.draw_line(Some(Point::new(1.0, 1.0)), true, true);
        assert_eq!(m.shown_line(), None, "not armed: the drag is the tool's");
        m.drawing = LineDrawing::Armed;
        assert!(m.drawing_line());
        m.draw_line(Some(Point::new(10.0, 20.0)), true, true);
        m.draw_line(Some(Point::new(30.0, 20.0)), false, true);
        assert_eq!(
            m.shown_line(),
            Some([Point::new(10.0, 20.0), Point::new(30.0, 20.0)])
        );
        m.draw_line(None, false, false);
        assert!(!m.drawing_line());
        assert_eq!(
            m.line,
            Some([Point::new(10.0, 20.0), Point::new(30.0, 20.0)])
        );
        // A click (shorter than a pixel) leaves the line as it was.
        m.drawing = LineDrawing::Armed;
        m.draw_line(Some(Point::new(5.0, 5.0)), true, true);
        m.draw_line(Some(Point::new(5.2, 5.0)), false, false);
        assert_eq!(
            m.line,
            Some([Point::new(10.0, 20.0), Point::new(30.0, 20.0)])
        );
    }

    #[test]
    fn controllers_move_each_target_across_its_slider() {
        let mut s = ToolSettings::default();
        let mut height = 0.5;
        for (target, lo, hi) in [
            (Target::StylusWake, tools::STYLUS_WAKE),
            (Target::CombSpacing, tools::COMB_SPACING),
            (Target::FlowStrength, tools::FLOW_STRENGTH),
        ]
        .map(|(t, r)| (t, *r.start(), *r.end()))
        {
            let read = |s: &ToolSettings| match target {
                Target::StylusWake => s.stylus_wake,
                Target::CombSpacing => s.comb_spacing,
                _ => s.flow_strength,
            };
            target.set(0.0, &mut s, &mut height);
            assert!((read(&s) - lo).abs() < 1e-9 * hi, "{target:?}");
            target.set(1.0, &mut s, &mut height);
            assert!((read(&s) - hi).abs() < 1e-9 * hi, "{target:?}");
            // Half way on a logarithmic slider is the geometric mean.
            target.set(0.5, &mut s, &mut height);
            assert!(
                (read(&s) - (lo * hi).sqrt()).abs() < 1e-9 * hi,
                "{target:?}"
            );
        }
        Target::DropRadius.set(1.0, &mut s, &mut height);
        assert_eq!(s.drop_radius, *tools::DROP_RADIUS.end());
        Target::LineHeight.set(0.25, &mut s, &mut height);
        assert_eq!(height, 0.25);
    }
}
