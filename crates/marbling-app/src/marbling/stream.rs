//! *Stream* (under the Flow tool): the design streaming along the Flow tool's curl noise
//! as a looping colour turbulence (`marbling_core::turbulence`; Kung 2019, ch. 5,
//! without its feedback texture). Every frame is exact: each sample walks back through
//! the flow for each of the two layers' times, then through the ops, and the layers are
//! blended in linear light, so no frame is blurred and frame(t) = frame(t + P). The
//! noise and strength are the Flow tool's; the period and speed are the stream's own.
//! The next frame is asked for once the canvas shows the last one whole, at the time the
//! clock has reached by then (t advances by the seconds passed × speed), so a slow GPU
//! shows fewer frames, never a torn or blended one. *Record* films one period of it to a
//! WebM. While it shows, its controls stay under whichever tool is picked (drawing goes
//! on: a drag shows the still design with the tool's op, and the stream resumes on the
//! new design).

use crate::frame::Frame;
use crate::marbling::tools::ToolSettings;
use crate::media::recorder::Recorder;
use egui::{RichText, Slider};
use marbling_core::Flow;
use marbling_core::turbulence::{Layer, Turbulence};

/// Periods offered, units of flow time.
pub const PERIOD: std::ops::RangeInclusive<f64> = 0.2..=20.0;
/// Speeds offered, units of flow time per second.
pub const SPEED: std::ops::RangeInclusive<f64> = 0.05..=4.0;
/// Frames per second the recording is filmed at.
const RECORD_FPS: f64 = 30.0;

/// One frame of the stream, as the canvas draws it.
#[derive(Clone, Debug, PartialEq)]
pub struct StreamFrame {
    /// Frames asked for since the stream started (a new time is a new frame).
    pub number: u64,
    /// The flow of one period (its noise and strength are the turbulence's; the
    /// renderer replaces its time by each layer's).
    pub flow: Flow,
    /// The two layers at the frame's time.
    pub layers: [Layer; 2],
}

/// The stream's state: off, playing or paused at a time.
pub(crate) struct FlowStream {
    /// Shown on the canvas (playing or paused).
    on: bool,
    playing: bool,
    /// P, units of flow time.
    period: f64,
    /// Units of flow time per second.
    speed: f64,
    /// The time t of the frame asked for (not wrapped: a recording ends a period on).
    time: f64,
    /// The number of the frame asked for.
    number: u64,
    /// The UI clock (s) when the frame asked for was taken.
    taken_s: Option<f64>,
    /// A recording and the time it began at.
    recording: Option<(Recorder, f64)>,
    /// Factors on the speed and the strength (sound drives them; 1: as set).
    drive: [f64; 2],
    /// The strength factor of the frame asked for (taken from `drive` with each new
    /// frame, so a frame being drawn is never changed under it).
    strength: f64,
}

impl Default for FlowStream {
    fn default() -> Self {
        Self {
            on: false,
            playing: false,
            period: 4.0,
            speed: 1.0,
            time: 0.0,
            number: 0,
            taken_s: None,
            recording: None,
            drive: [1.0; 2],
            strength: 1.0,
        }
    }
}

/// The turbulence of the Flow tool's noise and strength (× `strength`) with period
/// `period`, shortened where a period's flow would need more than [`marbling_core::MAX_FLOW_STEPS`]
/// sub-steps.
pub fn turbulence(settings: &ToolSettings, period: f64, strength: f64) -> Turbulence {
    let mut f = crate::marbling::tools::flow(settings, 0.0);
    f.strength = (f.strength * strength).max(0.01);
    Turbulence {
        period: period.min(f.longest_time()),
        noise: f.noise,
        strength: f.strength,
    }
}

impl FlowStream {
    /// The turbulence shown: the tool's, this period, the strength as sound drove it
    /// when the frame was taken.
    fn turbulence(&self, settings: &ToolSettings) -> Turbulence {
        turbulence(settings, self.period, self.strength)
    }

    /// Sound's factors on the speed and the strength (`None`: as set).
    pub fn drive(&mut self, speed: Option<f64>, strength: Option<f64>) {
        self.drive = [speed.unwrap_or(1.0), strength.unwrap_or(1.0)];
    }

    /// The frame the canvas shows, while the stream is on.
    pub fn frame(&self, settings: &ToolSettings) -> Option<StreamFrame> {
        if !self.on {
            return None;
        }
        let t = self.turbulence(settings);
        Some(StreamFrame {
            number: self.number,
            flow: t.flow(t.period),
            layers: t.layers(self.time),
        })
    }

    /// Whether the stream is on the canvas (playing or paused).
    pub fn is_on(&self) -> bool {
        self.on
    }

    /// Whether the stream is on the canvas and moving.
    pub fn is_playing(&self) -> bool {
        self.on && self.playing
    }

    /// `data-stream`: the turbulence document of the frame shown with its time and
    /// frame number, `{"noise":…,"strength":U,"period":P,"time":t,"frame":n,"playing":b}`.
    pub fn hook(&self, settings: &ToolSettings) -> Option<String> {
        if !self.on {
            return None;
        }
        let t = self.turbulence(settings);
        let noise = marbling_noise::NoiseSpec::from_source(marbling_noise::Source::Fbm(t.noise));
        Some(format!(
            r#"{{"noise":{},"strength":{},"period":{},"time":{},"frame":{},"playing":{}}}"#,
            noise.to_value(),
            t.strength,
            t.period,
            self.time.rem_euclid(t.period),
            self.number,
            self.playing
        ))
    }

    /// Moves the clock on once the canvas shows frame `drawn` (the number of the stream
    /// frame it drew last) whole, at the UI clock `now` (s); finishes a recording a
    /// period after it began.
    pub fn tick(
        &mut self,
        ctx: &egui::Context,
        drawn: Option<u64>,
        now: f64,
        frame: &mut Frame<'_>,
    ) {
        if !self.on || !self.playing {
            self.taken_s = None;
            return;
        }
        ctx.request_repaint();
        if drawn != Some(self.number) {
            return;
        }
        // The clock starts when the first frame is on screen (no frame is asked for twice).
        let Some(taken) = self.taken_s.replace(now) else {
            return;
        };
        self.time += (now - taken).max(0.0) * self.speed * self.drive[0];
        self.strength = self.drive[1];
        self.number += 1;
        let period = self.turbulence(&frame.prefs.settings).period;
        if self
            .recording
            .as_ref()
            .is_some_and(|(_, began)| self.time - began >= period)
        {
            self.finish_recording(frame);
        }
    }

    fn finish_recording(&mut self, frame: &mut Frame<'_>) {
        if let Some((recorder, _)) = self.recording.take() {
            recorder.finish("marbling-flow-loop.webm");
            frame.info("one period of the stream recorded: marbling-flow-loop.webm");
        }
    }

    /// The stream's controls, under the Flow tool's.
    pub fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.add_space(4.0);
        ui.label(RichText::new("Stream").strong()).on_hover_text(
            "the design streaming along this curl noise, looping: every frame exact, none blurred",
        );
        ui.horizontal_wrapped(|ui| {
            let play = ui
                .selectable_label(
                    self.on && self.playing,
                    if self.on && self.playing {
                        "Pause"
                    } else {
                        "▶ Stream"
                    },
                )
                .on_hover_text("the design flows along the noise above and loops every period");
            frame.control("flow-stream", &play);
            if play.clicked() {
                if self.on && self.playing {
                    self.playing = false;
                } else {
                    self.on = true;
                    self.playing = true;
                }
            }
            if self.on {
                let stop = ui
                    .button("■ Stop")
                    .on_hover_text("back to the still design");
                frame.control("flow-stream-stop", &stop);
                if stop.clicked() {
                    self.finish_recording(frame);
                    *self = Self {
                        period: self.period,
                        speed: self.speed,
                        ..Self::default()
                    };
                }
            }
            let recording = self.recording.is_some();
            let record = ui
                .selectable_label(
                    recording,
                    if recording {
                        "Stop recording"
                    } else {
                        "Record"
                    },
                )
                .on_hover_text("films one period of the stream to a WebM (it loops)");
            frame.control("flow-record", &record);
            if record.clicked() {
                if recording {
                    self.finish_recording(frame);
                } else {
                    match Recorder::start(RECORD_FPS) {
                        Ok(r) => {
                            (self.on, self.playing) = (true, true);
                            self.recording = Some((r, self.time));
                            frame.info("recording one period of the stream…");
                        }
                        Err(e) => frame.error(e),
                    }
                }
            }
        });
        let longest = crate::marbling::tools::flow(&frame.prefs.settings, 0.0).longest_time();
        let period = ui
            .add(
                Slider::new(&mut self.period, PERIOD)
                    .text("period")
                    .logarithmic(true),
            )
            .on_hover_text("flow time after which the stream repeats exactly");
        frame.control("flow-period", &period);
        if self.period > longest {
            ui.label(format!(
                "at this strength and noise a period is at most {longest:.2}"
            ));
        }
        let speed = ui
            .add(
                Slider::new(&mut self.speed, SPEED)
                    .text("speed /s")
                    .logarithmic(true),
            )
            .on_hover_text("flow time per second");
        frame.control("flow-speed", &speed);
        if self.on {
            let t = self.turbulence(&frame.prefs.settings);
            ui.label(
                RichText::new(format!(
                    "t = {:.2} of {:.2}",
                    self.time.rem_euclid(t.period),
                    t.period
                ))
                .small(),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn settings() -> ToolSettings {
        ToolSettings {
            flow_size: 60.0,
            flow_octaves: 1,
            flow_strength: 20.0,
            flow_seed: 3,
            ..ToolSettings::default()
        }
    }

    #[test]
    fn the_frame_follows_the_tools_noise_and_the_streams_time() {
        let mut s = FlowStream::default();
        assert_eq!(s.frame(&settings()), None);
        (s.on, s.time) = (true, 1.0);
        let f = s.frame(&settings()).expect("on");
        let t = turbulence(&settings(), 4.0, 1.0);
        assert_eq!(f.flow, t.flow(4.0));
        assert_eq!(f.layers, t.layers(1.0));
        assert_eq!(f.flow.strength, 20.0);
        assert!((f64::from(f.flow.noise.frequency) - 1.0 / 60.0).abs() < 1e-7);
        // The hook is a turbulence document the CLI reads, with the time.
        let hook = s.hook(&settings()).expect("on");
        let doc =
            Turbulence::from_json(&hook.replace(r#","time":1,"frame":0,"playing":false"#, ""))
                .expect("a turbulence document");
        assert_eq!(doc, t);
        assert!(
            hook.ends_with(r#","time":1,"frame":0,"playing":false}"#),
            "{hook}"
        );
    }

    #[test]
    fn a_period_too_long_for_the_strength_is_shortened() {
        let strong = ToolSettings {
            flow_strength: 200.0,
            flow_size: 20.0,
            ..settings()
        };
        let t = turbulence(&strong, 20.0, 1.0);
        assert!(t.period < 20.0, "{}", t.period);
        assert!(t.flow(t.period).sub_steps() <= marbling_core::MAX_FLOW_STEPS);
        assert_eq!(turbulence(&settings(), 2.0, 1.0).period, 2.0);
        // Sound doubling the strength halves the longest period.
        let driven = turbulence(&strong, 20.0, 2.0);
        assert!((driven.period - t.period / 2.0).abs() < 1e-9 * t.period);
        assert_eq!(driven.strength, 400.0);
    }
}
