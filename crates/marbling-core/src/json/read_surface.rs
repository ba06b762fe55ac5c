//! The design reader's schema-v2 parts: a noise background with its palette, grain
//! overlays, and the noise specs inside them (read by `marbling-noise`, their problems
//! reported under the design's path).

use super::read::Reader;
use crate::Rgb8;
use crate::image_background::{IMAGE_FITS, ImageBackground, ImageFit};
use crate::surface::{GrainKind, NoiseBackground, NoiseLayer, Overlay, Palette};
use marbling_json::short;
use serde_json::Value;

impl Reader {
    /// A noise spec at `path`, its problems reported under that path.
    fn noise(&mut self, path: &str, v: Option<&Value>) -> Option<NoiseLayer> {
        let Some(v) = v else {
            self.push(path, "missing");
            return None;
        };
        match NoiseLayer::from_value(v) {
            Ok(n) => Some(n),
            Err(problems) => {
                self.errors
                    .extend(problems.into_iter().map(|p| p.under(path)));
                None
            }
        }
    }

    fn palette(&mut self, path: &str, v: Option<&Value>) -> Option<Palette> {
        let result = match v {
            None => Palette::named("grey"),
            Some(Value::String(name)) => Palette::named(name),
            Some(Value::Array(items)) => {
                let mut stops = Vec::new();
                for (i, it) in items.iter().enumerate() {
                    match it.as_str().map(str::parse::<Rgb8>) {
                        Some(Ok(c)) => stops.push(c),
                        _ => self.push(
                            format!("{path}[{i}]"),
                            format!("must be a colour \"#rrggbb\", got {}", short(it)),
                        ),
                    }
                }
                if stops.len() != items.len() {
                    return None;
                }
                Palette::from_stops(stops)
            }
            Some(other) => {
                self.push(
                    path,
                    format!(
                        "must be a palette name or an array of \"#rrggbb\", got {}",
                        short(other)
                    ),
                );
                return None;
            }
        };
        result.map_err(|e| self.push(path, e.to_string())).ok()
    }

    pub(super) fn noise_background(&mut self, v: &Value) -> Option<NoiseBackground> {
        let obj = self.object("background", v, &["noise", "palette"])?;
        let noise = self.noise("background.noise", obj.get("noise"));
        let palette = self.palette("background.palette", obj.get("palette"));
        Some(NoiseBackground::new(noise?, palette?))
    }

    /// `{"image": DATA-URI, "fit": …, "paper": "#rrggbb"}`: the paper colour (white
    /// when absent) and the picture.
    pub(super) fn image_background(&mut self, v: &Value) -> Option<(Rgb8, ImageBackground)> {
        let obj = self.object("background", v, &["image", "fit", "paper"])?;
        let fit = match obj.get("fit") {
            None => Some(ImageFit::default()),
            Some(Value::String(s)) if ImageFit::from_name(s).is_some() => ImageFit::from_name(s),
            Some(other) => {
                self.push(
                    "background.fit",
                    format!(
                        "unknown fit {}; expected one of {}",
                        short(other),
                        IMAGE_FITS.join(", ")
                    ),
                );
                None
            }
        };
        let paper = match obj.get("paper") {
            None => Some(Rgb8::WHITE),
            Some(_) => self.color("background", obj, "paper"),
        };
        let image = match obj.get("image") {
            Some(Value::String(uri)) => {
                match ImageBackground::from_data_uri(uri, fit.unwrap_or_default()) {
                    Ok(img) => Some(img),
                    Err(e) => {
                        self.push("background.image", e.to_string());
                        None
                    }
                }
            }
            other => {
                self.push(
                    "background.image",
                    format!(
                        "must be a data: URI string, got {}",
                        other.map_or("nothing".to_owned(), short)
                    ),
                );
                None
            }
        };
        Some((paper?, image?.with_fit(fit?)))
    }

    pub(super) fn overlay(&mut self, i: usize, v: &Value) -> Option<Overlay> {
        let path = format!("overlays[{i}]");
        let obj = self.object(&path, v, &["type", "noise", "strength"])?;
        let kind = match obj.get("type") {
            Some(Value::String(s)) if s == "paper-grain" => Some(GrainKind::Paper),
            Some(Value::String(s)) if s == "pigment-grain" => Some(GrainKind::Pigment),
            Some(other) => {
                self.push(
                    format!("{path}.type"),
                    format!(
                        "unknown overlay type {}; expected one of {}",
                        short(other),
                        crate::OVERLAY_TYPES.join(", ")
                    ),
                );
                None
            }
            None => {
                self.push(format!("{path}.type"), "missing");
                None
            }
        };
        let noise = self.noise(&format!("{path}.noise"), obj.get("noise"));
        let strength = self.number(&path, obj, "strength");
        if let Some(s) = strength {
            self.rules().strength(&format!("{path}.strength"), s);
        }
        Some(Overlay {
            kind: kind?,
            noise: noise?,
            strength: strength?,
        })
    }
}
