//! *Sound*: the microphone or an audio file drives the tools (Kung 2019, ch. 4: objects
//! that answer to music). The browser's Web Audio analyser (`sound_input.rs`) gives a
//! spectrum each frame; its power is summed in Kung's six bands — 87–258, 259–602,
//! 603–1290, 1291–2666, 2667–5418 and 5419–10922 Hz — and shown as a meter of levels
//! 0..1 (`data-audio`). Each band can drive one thing: *drop on beat* (a drop of the ink
//! when the band's level rises through the threshold, its radius the drop tool's ×
//! (½ + level)), the Stream's speed or strength, or the pressure of a stroke (the
//! stylus's wake and a drop's size, as a pen's pressure would: × (¼ + 1¾·level)). What
//! sound makes is ordinary history steps (`Action::Commit`), so it undoes, replays and
//! links like a click.
//!
//! The analyser: an FFT of [`FFT_SIZE`] samples (85 ms at 48 kHz, 11.7 Hz per bin, so
//! the lowest band has 15 bins and a tone 40 Hz from a band's edge — 220 Hz — lies
//! outside the ±3 bins of the window's main lobe), Web Audio's fixed Blackman window
//! (side lobes 58 dB down, so a tone stays in its band), smoothing [`SMOOTHING`]
//! between frames. A band's
//! level is its power in dB mapped linearly from [`FLOOR_DB`] (0) to [`FULL_DB`] (1).

use crate::action::Action;
use crate::frame::Frame;
use crate::media::sound_input::{SoundInput, SoundSource};
use egui::{RichText, Slider};
use marbling_core::synth::SplitMix64;
use marbling_core::{Drop, Op, Point};

/// Kung's six bands, Hz (lowest and highest frequency of each).
pub const BANDS: [(f32, f32); 6] = [
    (87.0, 258.0),
    (259.0, 602.0),
    (603.0, 1290.0),
    (1291.0, 2666.0),
    (2667.0, 5418.0),
    (5419.0, 10922.0),
];
/// Samples per FFT of the analyser (a power of two; bins = half of it).
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub const FFT_SIZE: u32 = 4096;
/// The analyser's smoothing between frames (Web Audio's `smoothingTimeConstant`).
#[cfg_attr(not(target_arch = "wasm32"), allow(dead_code))]
pub const SMOOTHING: f64 = 0.5;
/// A band's power at level 0, dB (full scale = 0 dB).
pub const FLOOR_DB: f32 = -80.0;
/// A band's power at level 1, dB (a full-scale sine reads about −12 dB).
pub const FULL_DB: f32 = -10.0;
/// How far below the threshold a band must fall before it can beat again.
const HYSTERESIS: f32 = 0.1;
/// The shortest time between two beats of a band, s.
const MIN_BEAT_S: f64 = 0.15;

/// The levels 0..1 of the six bands of a spectrum: `db[k]` the dB of bin k of an FFT of
/// `2·db.len()` samples at `sample_rate` Hz (bin k centred at k·rate/size). A bin belongs
/// to the band whose range [lo, hi + 1) holds its centre; its power is 10^(dB/10).
pub fn band_levels(db: &[f32], sample_rate: f32) -> [f32; 6] {
    let bin_hz = sample_rate / (2 * db.len().max(1)) as f32;
    BANDS.map(|(lo, hi)| {
        let power: f32 = db
            .iter()
            .enumerate()
            .filter(|(k, _)| {
                let f = *k as f32 * bin_hz;
                f >= lo && f < hi + 1.0
            })
            .map(|(_, &d)| {
                if d.is_finite() {
                    10f32.powf(d / 10.0)
                } else {
                    0.0
                }
            })
            .sum();
        if power <= 0.0 {
            return 0.0;
        }
        ((10.0 * power.log10() - FLOOR_DB) / (FULL_DB - FLOOR_DB)).clamp(0.0, 1.0)
    })
}

/// A band's beats: it beats when its level rises through the threshold, at most once
/// every [`MIN_BEAT_S`], and again only after falling [`HYSTERESIS`] below it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Beat {
    /// Fell below the threshold since the last beat.
    armed: bool,
    /// When it last beat, s.
    last_s: Option<f64>,
}

impl Beat {
    /// Whether `level` at time `now` (s) is a beat.
    pub fn hear(&mut self, level: f32, threshold: f32, now: f64) -> bool {
        if level < threshold - HYSTERESIS {
            self.armed = true;
            return false;
        }
        let rested = self.last_s.is_none_or(|t| now - t >= MIN_BEAT_S);
        if level >= threshold && self.armed && rested {
            self.armed = false;
            self.last_s = Some(now);
            return true;
        }
        false
    }
}

/// What a band drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// Nothing.
    Nothing,
    /// A drop when the band beats.
    DropOnBeat,
    /// The Stream's speed.
    StreamSpeed,
    /// The Stream's strength.
    StreamStrength,
    /// A stroke's pressure: the stylus's wake and a drop's size.
    Pressure,
}

impl Target {
    const ALL: [Target; 5] = [
        Target::Nothing,
        Target::DropOnBeat,
        Target::StreamSpeed,
        Target::StreamStrength,
        Target::Pressure,
    ];

    fn label(self) -> &'static str {
        match self {
            Target::Nothing => "nothing",
            Target::DropOnBeat => "drop on beat",
            Target::StreamSpeed => "stream speed",
            Target::StreamStrength => "stream strength",
            Target::Pressure => "pressure (wake, drop size)",
        }
    }

    fn name(self) -> &'static str {
        match self {
            Target::Nothing => "nothing",
            Target::DropOnBeat => "beat",
            Target::StreamSpeed => "speed",
            Target::StreamStrength => "strength",
            Target::Pressure => "pressure",
        }
    }
}

/// The factor a driving level gives a parameter: ¼ at silence, 2 at level 1.
pub fn drive_factor(level: f32) -> f64 {
    0.25 + 1.75 * f64::from(level.clamp(0.0, 1.0))
}

/// The Sound section's state.
pub(crate) struct SoundPanel {
    input: Option<SoundInput>,
    /// The bands' levels, 0..1.
    levels: [f32; 6],
    targets: [Target; 6],
    /// The level a beat rises through.
    threshold: f32,
    beats: [Beat; 6],
    /// Where the drops fall.
    rng: SplitMix64,
    /// Drops made by beats since start.
    drops: u64,
    pick: crate::platform::PickSlot,
    spectrum: Vec<f32>,
}

impl Default for SoundPanel {
    fn default() -> Self {
        Self {
            input: None,
            levels: [0.0; 6],
            targets: [Target::Nothing; 6],
            threshold: 0.6,
            beats: [Beat::default(); 6],
            rng: SplitMix64(0x5EED),
            drops: 0,
            pick: Default::default(),
            spectrum: Vec::new(),
        }
    }
}

/// Audio files offered by *Audio file…*.
const AUDIO_FILE: crate::platform::FileKind = (
    "Audio",
    &[
        "wav", "mp3", "ogg", "oga", "opus", "flac", "m4a", "aac", "webm",
    ],
);

impl SoundPanel {
    /// The factor the bands bound to `target` give now (the loudest of them; see
    /// [`drive_factor`]), or `None` when no band drives it or no sound is on.
    pub fn factor(&self, target: Target) -> Option<f64> {
        self.input.as_ref()?;
        self.targets
            .iter()
            .zip(self.levels)
            .filter(|(t, _)| **t == target)
            .map(|(_, l)| l)
            .reduce(f32::max)
            .map(drive_factor)
    }

    /// `data-audio`: the six levels, while sound is on.
    pub fn hook(&self) -> Option<String> {
        self.input.as_ref()?;
        Some(
            self.levels
                .iter()
                .map(|l| format!("{l:.3}"))
                .collect::<Vec<_>>()
                .join(","),
        )
    }

    /// Reads the spectrum, moves the meter and makes the beats' drops (every frame
    /// while sound is on; `now` the UI clock, s).
    pub fn tick(&mut self, ctx: &egui::Context, now: f64, frame: &mut Frame<'_>) {
        if let Some(Ok((name, bytes))) = self.pick.lock().ok().and_then(|mut s| s.take()) {
            self.start(SoundSource::File(name, bytes), ctx, frame);
        }
        let Some(input) = &mut self.input else {
            return;
        };
        if let Some(e) = input.take_failure() {
            let what = input.label().to_owned();
            self.stop();
            frame.error(format!("{what}: {e}"));
            return;
        }
        ctx.request_repaint();
        let Some(rate) = input.spectrum(&mut self.spectrum) else {
            return;
        };
        self.levels = band_levels(&self.spectrum, rate);
        for k in 0..BANDS.len() {
            let beat = self.beats[k].hear(self.levels[k], self.threshold, now);
            if beat && self.targets[k] == Target::DropOnBeat {
                let drop = self.beat_drop(self.levels[k], frame);
                frame.act(Action::Commit(vec![Op::Drop(drop)]));
            }
        }
    }

    /// The drop a beat of level `level` makes: somewhere on the sheet (10–90 % of each
    /// side), the drop tool's radius × (½ + level), the ink (or the palette in turn from
    /// it when the tool cycles colours, [`crate::store::prefs::Prefs::cycled_inks`]).
    fn beat_drop(&mut self, level: f32, frame: &Frame<'_>) -> Drop {
        let design = frame.editor.history.design();
        let (x, y) = (self.rng.range(0.1, 0.9), self.rng.range(0.1, 0.9));
        let inks = frame.prefs.cycled_inks();
        let color = inks[self.drops as usize % inks.len()];
        self.drops += 1;
        Drop {
            center: Point::new(f64::from(design.width) * x, f64::from(design.height) * y),
            radius: frame.prefs.settings.drop_radius * (0.5 + f64::from(level)),
            color,
        }
    }

    fn start(&mut self, source: SoundSource, ctx: &egui::Context, frame: &mut Frame<'_>) {
        self.stop();
        match SoundInput::start(source, ctx.clone()) {
            Ok(input) => {
                frame.info(format!("sound: {} starting…", input.label()));
                self.input = Some(input);
            }
            Err(e) => frame.error(format!("cannot start the sound: {e}")),
        }
    }

    fn stop(&mut self) {
        self.input = None;
        self.levels = [0.0; 6];
        self.beats = [Beat::default(); 6];
    }

    /// The Sound section: the sources, the meter and what each band drives.
    pub(crate) fn ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.label(RichText::new("Sound").strong());
        if !SoundInput::available() {
            ui.label(RichText::new("sound input is in the web app").weak());
            return;
        }
        ui.horizontal_wrapped(|ui| {
            let mic = ui
                .button("Microphone")
                .on_hover_text("Listen to the microphone (the browser asks first)");
            frame.control("sound-microphone", &mic);
            if mic.clicked() {
                self.start(SoundSource::Microphone, ui.ctx(), frame);
            }
            let file = ui
                .button("Audio file…")
                .on_hover_text("Play an audio file (looping) and listen to it");
            frame.control("sound-file", &file);
            if file.clicked() {
                crate::platform::pick_file(self.pick.clone(), AUDIO_FILE, ui.ctx().clone());
            }
            if let Some(input) = &self.input {
                ui.label(RichText::new(input.label()).weak());
                let stop = ui.button("Stop");
                frame.control("sound-stop", &stop);
                if stop.clicked() {
                    self.stop();
                    frame.info("sound stopped");
                }
            }
        });
        // One row a band: the meter, the band, what it drives (the lists line up).
        egui::Grid::new("sound-bands").show(ui, |ui| {
            for (k, &(lo, hi)) in BANDS.iter().enumerate() {
                let (rect, _) =
                    ui.allocate_exact_size(egui::vec2(60.0, 12.0), egui::Sense::hover());
                let painter = ui.painter();
                painter.rect_filled(rect, 2.0, ui.visuals().extreme_bg_color);
                painter.rect_stroke(
                    rect,
                    2.0,
                    ui.visuals().widgets.noninteractive.bg_stroke,
                    egui::StrokeKind::Inside,
                );
                let mut lit = rect;
                lit.set_width(rect.width() * self.levels[k]);
                painter.rect_filled(lit, 2.0, ui.visuals().selection.bg_fill);
                let x = rect.left() + rect.width() * self.threshold;
                painter.vline(
                    x,
                    rect.y_range(),
                    egui::Stroke::new(1.0, ui.visuals().warn_fg_color),
                );
                ui.label(RichText::new(format!("{lo:.0}–{hi:.0} Hz")).small());
                let combo = egui::ComboBox::from_id_salt(("sound-target", k))
                    .selected_text(self.targets[k].label())
                    .show_ui(ui, |ui| {
                        for t in Target::ALL {
                            let r = ui.selectable_value(&mut self.targets[k], t, t.label());
                            frame.control(format!("sound-target-{}-{}", k + 1, t.name()), &r);
                        }
                    });
                frame.control(format!("sound-target-{}", k + 1), &combo.response);
                ui.end_row();
            }
        });
        let r = ui.add(Slider::new(&mut self.threshold, 0.05..=0.95).text("beat threshold"));
        frame.control("sound-threshold", &r);
        if self.drops > 0 {
            ui.label(RichText::new(format!("{} drops on beats", self.drops)).weak());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The analyser's spectrum of a sine of `hz` Hz and amplitude `amp` at `rate` Hz:
    /// Blackman-windowed DFT of FFT_SIZE samples, |X[k]|/N in dB (Web Audio's formula).
    fn spectrum(hz: f32, amp: f32, rate: f32) -> Vec<f32> {
        let n = FFT_SIZE as usize;
        let tau = std::f64::consts::TAU;
        let x: Vec<f64> = (0..n)
            .map(|i| {
                let t = i as f64 / n as f64;
                let w = 0.42 - 0.5 * (tau * t).cos() + 0.08 * (2.0 * tau * t).cos();
                w * f64::from(amp) * (tau * f64::from(hz) * i as f64 / f64::from(rate)).sin()
            })
            .collect();
        (0..n / 2)
            .map(|k| {
                // Σ x[i]·e^(−2πik/n), the phasor turned by one step per sample.
                let a = tau * k as f64 / n as f64;
                let (c, s) = (a.cos(), -a.sin());
                let (mut re, mut im, mut pr, mut pi) = (0.0, 0.0, 1.0, 0.0);
                for v in &x {
                    re += v * pr;
                    im += v * pi;
                    (pr, pi) = (pr * c - pi * s, pr * s + pi * c);
                }
                (20.0 * (re.hypot(im) / n as f64).log10()) as f32
            })
            .collect()
    }

    /// Kung's test tones, one per band (220 … 7040 Hz): each drives only its own band.
    #[test]
    fn each_test_tone_drives_only_its_own_band() {
        for (band, hz) in [220.0, 440.0, 880.0, 1760.0, 3520.0, 7040.0]
            .into_iter()
            .enumerate()
        {
            for rate in [44_100.0, 48_000.0] {
                let levels = band_levels(&spectrum(hz, 0.5, rate), rate);
                assert!(levels[band] > 0.8, "{hz} Hz at {rate}: {levels:?}");
                for (k, l) in levels.iter().enumerate() {
                    if k != band {
                        assert!(
                            *l < 0.15,
                            "{hz} Hz at {rate} leaks into band {k}: {levels:?}"
                        );
                    }
                }
            }
        }
        // Silence (−∞ dB from the analyser) is 0 everywhere.
        assert_eq!(band_levels(&[f32::NEG_INFINITY; 1024], 48_000.0), [0.0; 6]);
    }

    #[test]
    fn a_band_beats_when_it_rises_through_the_threshold_once() {
        let mut b = Beat::default();
        // Loud from the start: no beat until it has fallen below.
        assert!(!b.hear(0.9, 0.6, 0.0));
        assert!(!b.hear(0.4, 0.6, 0.1));
        assert!(b.hear(0.7, 0.6, 0.2));
        // Staying up, or dipping only within the hysteresis, is the same beat.
        assert!(!b.hear(0.8, 0.6, 0.3));
        assert!(!b.hear(0.55, 0.6, 0.4));
        assert!(!b.hear(0.8, 0.6, 0.5));
        // A quick flutter within 0.15 s of a beat is not another.
        assert!(!b.hear(0.2, 0.6, 0.6));
        assert!(b.hear(0.9, 0.6, 0.7));
        assert!(!b.hear(0.2, 0.6, 0.75));
        assert!(!b.hear(0.9, 0.6, 0.8));
        assert!(b.hear(0.9, 0.6, 0.86));
    }

    #[test]
    fn drives_scale_from_a_quarter_to_twice() {
        assert_eq!(drive_factor(0.0), 0.25);
        assert_eq!(drive_factor(1.0), 2.0);
        assert_eq!(drive_factor(f32::NAN.max(0.5)), 0.25 + 1.75 * 0.5);
        assert_eq!(drive_factor(3.0), 2.0);
    }
}
