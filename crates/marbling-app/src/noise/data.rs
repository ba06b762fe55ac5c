//! Data for Khlebnikov et al. (2013)'s data-driven Gabor in the noise playground: the data sets a user
//! loaded (PNG or CSV, by file name) beside the built-in `weather`, attaching them to
//! specs, and the panel section that maps three channels to frequency, orientation and
//! colour, with its explanation and legend.

use crate::frame::Frame;
use crate::noise::Noise;
use egui::{Color32, RichText};
use marbling_noise::GaborSpec;
use marbling_noise::{
    BlendBase, DataGrid, DataRef, DecayValue, DriveSource, NoiseSpec, Source, Transfer, WEATHER,
};
use std::collections::BTreeMap;
use std::sync::Arc;

/// Largest data file the playground reads, bytes.
pub const MAX_DATA_BYTES: usize = 16 << 20;

/// The data sets loaded in this session, by name.
#[derive(Clone, Debug, Default)]
pub struct NoiseData {
    loaded: BTreeMap<String, Arc<DataGrid>>,
}

impl NoiseData {
    /// Reads a PNG (by its signature) or a CSV grid named `name`; replaces a set of the
    /// same name. Returns the grid's description for the status line.
    pub fn load(&mut self, name: &str, bytes: &[u8]) -> Result<String, String> {
        if bytes.len() > MAX_DATA_BYTES {
            return Err(format!(
                "{name}: {} bytes; data files are read up to {MAX_DATA_BYTES}",
                bytes.len()
            ));
        }
        if name == WEATHER {
            return Err(format!("{name}: the name of the built-in data set"));
        }
        let grid = if bytes.starts_with(b"\x89PNG") {
            DataGrid::from_png(bytes)
        } else {
            let text = std::str::from_utf8(bytes)
                .map_err(|_| format!("{name}: neither a PNG nor a CSV text"))?;
            DataGrid::from_csv(text, name)
        }
        .map_err(|e| format!("{name}: {e}"))?;
        let text = format!(
            "{name}: {}×{} texels, {} channel(s)",
            grid.width,
            grid.height,
            grid.channels.len()
        );
        self.loaded.insert(name.to_owned(), Arc::new(grid));
        Ok(text)
    }

    /// The names a spec may refer to: the built-in set, then the loaded ones.
    pub fn names(&self) -> Vec<String> {
        std::iter::once(WEATHER.to_owned())
            .chain(self.loaded.keys().cloned())
            .collect()
    }

    /// The grid called `name`.
    pub fn get(&self, name: &str) -> Option<Arc<DataGrid>> {
        DataGrid::builtin(name).or_else(|| self.loaded.get(name).cloned())
    }

    /// Attaches every data set `spec` names; an error naming the first one not loaded.
    pub fn attach(&self, spec: &mut NoiseSpec) -> Result<(), String> {
        spec.attach_data(&mut |name| {
            self.get(name)
                .ok_or_else(|| "is not loaded: load it in the Data section first".to_owned())
        })
        .map_err(|e| e.to_string())
    }
}

/// Which spec field a data channel feeds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Frequency,
    Orientation,
    Colour,
}

/// The data reference of `role` in `spec`, if any.
fn data_of(spec: &NoiseSpec, role: Role) -> Option<&DataRef> {
    match role {
        Role::Frequency | Role::Orientation => match &spec.source {
            Source::Gabor(GaborSpec {
                frequency_field,
                orientation_field,
                ..
            }) => {
                let d = if role == Role::Frequency {
                    frequency_field
                } else {
                    orientation_field
                };
                match &d.as_ref()?.by {
                    DriveSource::Data(r) => Some(r),
                    DriveSource::Noise(_) => None,
                }
            }
            _ => None,
        },
        Role::Colour => match &spec.blend.as_ref()?.base {
            BlendBase::Data { value, .. } => Some(value),
            _ => None,
        },
    }
}

/// Points every data reference of `spec` at `name` (keeping channels the set has, else
/// its last): the data set chooser.
fn rename_data(spec: &mut NoiseSpec, name: &str, data: &NoiseData) {
    let grid = data.get(name);
    let count = grid.as_ref().map_or(1, |g| g.channels.len());
    for r in spec.data_refs_mut() {
        r.name = name.to_owned();
        r.grid = grid.clone();
        r.channel = r.channel.min(count);
    }
}

/// Sets the channel (1-based) of the reference of `role`, and of the spline decay that
/// follows the frequency's channel.
fn set_channel(spec: &mut NoiseSpec, role: Role, channel: usize) {
    if let Source::Gabor(GaborSpec {
        frequency_field,
        orientation_field,
        ..
    }) = &mut spec.source
    {
        let d = match role {
            Role::Frequency => frequency_field,
            Role::Orientation => orientation_field,
            Role::Colour => &mut None,
        };
        if let Some(d) = d
            && let DriveSource::Data(r) = &mut d.by
        {
            r.channel = channel;
        }
    }
    if role == Role::Frequency
        && let Some(Transfer::SplineDecay(DecayValue::Data(r))) = &mut spec.transfer
    {
        r.channel = channel;
    }
    if role == Role::Colour
        && let Some(b) = &mut spec.blend
        && let BlendBase::Data { value, .. } = &mut b.base
    {
        value.channel = channel;
    }
}

impl Noise {
    /// Takes a picked data file into the loaded sets and points the spec at it.
    pub(crate) fn poll_picked_data(&mut self, frame: &mut Frame<'_>) {
        let picked = self.data_pick.lock().ok().and_then(|mut s| s.take());
        match picked {
            Some(Ok((name, bytes))) => {
                let name = name.rsplit(['/', '\\']).next().unwrap_or(&name).to_owned();
                match self.data.load(&name, &bytes) {
                    Ok(text) => {
                        if !self.settings().spec.has_data_frequency() {
                            self.weather_example();
                        }
                        let data = self.data.clone();
                        rename_data(&mut self.edit().spec, &name, &data);
                        frame.info(text);
                    }
                    Err(e) => frame.error(format!("Load data: {e}")),
                }
            }
            Some(Err(e)) => frame.error(format!("Load data: {e}")),
            None => {}
        }
    }

    /// Khlebnikov et al. (2013)'s weather figure in the panel's palette, zoom-independent.
    fn weather_example(&mut self) {
        let palette = marbling_noise::ColorRamp::named(self.settings().palette_name())
            .or_else(|| marbling_noise::ColorRamp::named("viridis"));
        if let Some(p) = palette {
            let s = self.edit();
            s.spec = NoiseSpec::weather_example(p, s.spec.source.seed());
            s.zoom_independent = true;
        }
    }

    /// The Data section: examples, loading, the channel mapping, the explanation and
    /// the legend.
    pub(crate) fn data_section_ui(&mut self, ui: &mut egui::Ui, frame: &mut Frame<'_>) {
        ui.label(RichText::new("Data (Khlebnikov et al. 2013)").strong());
        {
            ui.horizontal_wrapped(|ui| {
                let weather = ui.button("Weather example").on_hover_text(
                    "Temperature → frequency and brightness, wind → orientation, pressure → colour",
                );
                frame.control("noise-weather", &weather);
                if weather.clicked() {
                    self.weather_example();
                }
                let load = ui
                    .button("Load data…")
                    .on_hover_text("A PNG (8/16-bit, up to 3 channels) or a CSV grid");
                frame.control("noise-load-data", &load);
                if load.clicked() {
                    crate::platform::pick_file(
                        self.data_pick.clone(),
                        crate::platform::DATA_FILE,
                        ui.ctx().clone(),
                    );
                }
            });
            if self.settings().spec.has_data_frequency() {
                self.data_mapping(ui);
            } else {
                ui.label(
                    RichText::new(
                        "Show three data attributes in one texture that stays legible at \
                             every zoom: start from the weather example or load your data.",
                    )
                    .weak(),
                );
            }
        }
    }

    fn data_mapping(&mut self, ui: &mut egui::Ui) {
        let data = self.data.clone();
        self.edit_in(|s| {
            let spec = &mut s.spec;
            let current = data_of(spec, Role::Frequency).map(|r| r.name.clone());
            egui::ComboBox::from_label("data set")
                .selected_text(current.clone().unwrap_or_default())
                .show_ui(ui, |ui| {
                    for name in data.names() {
                        if ui
                            .selectable_label(current.as_deref() == Some(&name), &name)
                            .clicked()
                        {
                            rename_data(spec, &name, &data);
                        }
                    }
                });
            for (role, what) in [
                (Role::Frequency, "frequency + brightness"),
                (Role::Orientation, "orientation"),
                (Role::Colour, "colour"),
            ] {
                let Some(r) = data_of(spec, role).cloned() else {
                    continue;
                };
                let count = r.grid.as_ref().map_or(1, |g| g.channels.len());
                let name = |c: usize| {
                    r.grid
                        .as_ref()
                        .and_then(|g| g.channels.get(c - 1))
                        .map_or_else(|| format!("channel {c}"), |ch| format!("{c}: {}", ch.name))
                };
                let mut channel = r.channel.min(count);
                egui::ComboBox::from_label(what)
                    .selected_text(name(channel))
                    .show_ui(ui, |ui| {
                        for c in 1..=count {
                            ui.selectable_value(&mut channel, c, name(c));
                        }
                    });
                if channel != r.channel {
                    set_channel(spec, role, channel);
                }
            }
        });
        ui.label(
            RichText::new(
                "Khlebnikov et al. 2013: the first attribute sets the texture's frequency (features from \
                 40 screen px at its lowest to 4 px at its highest, at every zoom when \
                 zoom-independent is on) and, through the spline decay, its mean \
                 brightness; the second turns the texture's orientation through 180°; the \
                 third picks the hue from the palette, blended with the texture at β = 0.6.",
            )
            .weak(),
        );
        self.data_legend(ui);
    }

    /// One line per mapped channel: its name and physical range, and for the colour a
    /// bar of the palette from its low to its high value.
    fn data_legend(&self, ui: &mut egui::Ui) {
        let spec = &self.settings().spec;
        for (role, what) in [
            (Role::Frequency, "coarse → fine"),
            (Role::Orientation, "0° → 180°"),
            (Role::Colour, ""),
        ] {
            let Some(r) = data_of(spec, role) else {
                continue;
            };
            let Some(ch) = r.channel_info() else {
                continue;
            };
            let [lo, hi] = ch.range;
            let text = format!("{}: {lo:.4} … {hi:.4} {}", ch.name, ch.unit);
            ui.horizontal(|ui| {
                ui.label(text.replace(".0000", ""));
                if role == Role::Colour {
                    palette_bar(ui, self.settings().palette_name());
                } else {
                    ui.label(RichText::new(what).weak());
                }
            });
        }
    }
}

/// A small horizontal bar of the named palette, low values on the left.
fn palette_bar(ui: &mut egui::Ui, palette: &str) {
    let Some(ramp) = marbling_noise::ColorRamp::named(palette) else {
        return;
    };
    let (rect, _) = ui.allocate_exact_size(egui::vec2(96.0, 12.0), egui::Sense::hover());
    let steps = 24;
    for i in 0..steps {
        let t = (i as f32 + 0.5) / steps as f32;
        let [r, g, b] = ramp
            .sample(t)
            .map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
        let x0 = rect.left() + rect.width() * i as f32 / steps as f32;
        let x1 = rect.left() + rect.width() * (i + 1) as f32 / steps as f32;
        ui.painter().rect_filled(
            egui::Rect::from_x_y_ranges(x0..=x1, rect.y_range()),
            0.0,
            Color32::from_rgb(r, g, b),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn loaded_sets_attach_and_missing_ones_are_named() {
        let mut data = NoiseData::default();
        let text = data.load("grid.csv", b"1,2,3\n4,5,6\n").expect("csv");
        assert_eq!(text, "grid.csv: 3×2 texels, 1 channel(s)");
        assert_eq!(data.names(), ["weather", "grid.csv"]);
        let mut spec = NoiseSpec::from_json(
            r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"grid.csv","channel":1,"amount":2}}"#,
        )
        .expect("valid");
        data.attach(&mut spec).expect("loaded");
        assert!(marbling_noise::Renderer::new(&spec, 8).is_ok());
        let mut other = NoiseSpec::from_json(
            r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,"frequency_field":{"data":"x.png","amount":2}}"#,
        )
        .expect("valid");
        let e = data.attach(&mut other).expect_err("not loaded");
        assert_eq!(
            e,
            "data: 'x.png': is not loaded: load it in the Data section first"
        );
        let e = data.load("bad.csv", b"1,2\n3\n").expect_err("ragged");
        assert_eq!(e, "bad.csv: line 2: 1 cells, but the first row has 2");
        assert!(data.load("weather", b"1").is_err());
    }

    #[test]
    fn the_chooser_moves_every_reference_and_channels_follow_their_role() {
        let mut data = NoiseData::default();
        data.load("t.csv", b"0,1\n").expect("csv");
        let mut spec = NoiseSpec::weather_example(
            marbling_noise::ColorRamp::named("ember").expect("named"),
            1,
        );
        set_channel(&mut spec, Role::Frequency, 3);
        assert_eq!(data_of(&spec, Role::Frequency).map(|r| r.channel), Some(3));
        let Some(Transfer::SplineDecay(DecayValue::Data(r))) = &spec.transfer else {
            panic!("decay")
        };
        assert_eq!(r.channel, 3, "the decay follows the frequency's channel");
        assert_eq!(
            data_of(&spec, Role::Orientation).map(|r| r.channel),
            Some(2)
        );
        rename_data(&mut spec, "t.csv", &data);
        assert!(
            spec.data_refs_mut()
                .iter()
                .all(|r| r.name == "t.csv" && r.grid.is_some())
        );
    }
}
