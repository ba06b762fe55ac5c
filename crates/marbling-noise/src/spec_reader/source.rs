//! A spec's noise source: its type's fields, the fBm octaves, paper and canvas fibres.

use super::{Reader, Role, Rule};
use crate::fbm::{Basis, FbmParams};
use crate::fibers::{FiberLayout, FiberParams, Impurities};
use crate::gabor::GaborKind;
use crate::phasor::PhasorProfile;
use crate::ranges;
use crate::spec::{CurlSpec, GaborSpec, WhiteSpec, WorleySpec};
use crate::spec::{NoiseSpec, Source};
use crate::{CurlComponent, Metric, WorleyFeature};
use marbling_json::{join, short};
use serde_json::{Map, Value};

impl Reader {
    pub(super) fn fbm(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        basis: Basis,
    ) -> Option<FbmParams> {
        let frequency = self.bounded(path, obj, "frequency", None, ranges::FREQUENCY.into());
        let octaves = self.bounded(path, obj, "octaves", Some(1.0), ranges::OCTAVES.into());
        if octaves.is_some_and(|o| o.fract() != 0.0) {
            self.push(join(path, "octaves"), "must be a whole number");
        }
        let lacunarity = self.bounded(
            path,
            obj,
            "lacunarity",
            Some(2.0),
            ranges::LACUNARITY.into(),
        );
        let persistence = self.bounded(
            path,
            obj,
            "persistence",
            Some(0.5),
            ranges::PERSISTENCE.into(),
        );
        let seed = self.seed(path, obj);
        Some(FbmParams {
            basis,
            frequency: frequency? as f32,
            octaves: octaves? as u32,
            lacunarity: lacunarity? as f32,
            persistence: persistence? as f32,
            seed: seed?,
            period: None,
        })
    }

    pub(super) fn source(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        kind: &str,
    ) -> Option<Source> {
        match kind {
            "gabor" | "phasor" => {
                let profile = if kind == "phasor" {
                    self.choice(
                        path,
                        obj,
                        "profile",
                        PhasorProfile::Sine,
                        &ranges::PHASOR_PROFILES,
                    )
                    .map(Some)
                } else {
                    Some(None)
                };
                let gk = self.choice(
                    path,
                    obj,
                    "kind",
                    GaborKind::Anisotropic,
                    &ranges::GABOR_KINDS,
                );
                let frequency =
                    self.bounded(path, obj, "frequency", None, ranges::GABOR_FREQUENCY.into());
                let orientation = self.bounded(path, obj, "orientation", Some(0.0), Rule::Any);
                // Radius √(−ln 0.05/π)/a ≤ 512 px.
                let bandwidth =
                    self.bounded(path, obj, "bandwidth", None, ranges::BANDWIDTH.into());
                let impulses =
                    self.bounded(path, obj, "impulses", Some(64.0), ranges::IMPULSES.into());
                let seed = self.seed(path, obj);
                let orientation_field = obj
                    .get("orientation_field")
                    .map(|d| self.drive(&join(path, "orientation_field"), d));
                let frequency_field = obj
                    .get("frequency_field")
                    .map(|d| self.drive(&join(path, "frequency_field"), d));
                if gk == Some(GaborKind::Isotropic) && orientation_field.is_some() {
                    self.push(
                        join(path, "orientation_field"),
                        "not allowed for kind isotropic (its orientations are random)",
                    );
                }
                Some(Source::Gabor(GaborSpec {
                    kind: gk?,
                    frequency: frequency? as f32,
                    orientation: orientation? as f32,
                    bandwidth: bandwidth? as f32,
                    impulses: impulses? as f32,
                    seed: seed?,
                    orientation_field: orientation_field.map_or(Some(None), |d| d.map(Some))?,
                    frequency_field: frequency_field.map_or(Some(None), |d| d.map(Some))?,
                    profile: profile?,
                }))
            }
            "perlin" => self.fbm(path, obj, Basis::Perlin).map(Source::Fbm),
            "value" => self.fbm(path, obj, Basis::Value).map(Source::Fbm),
            "worley" => {
                let frequency =
                    self.bounded(path, obj, "frequency", None, ranges::FREQUENCY.into());
                let feature = self.choice(
                    path,
                    obj,
                    "feature",
                    WorleyFeature::F1,
                    &ranges::WORLEY_FEATURES,
                );
                let metric = self.choice(
                    path,
                    obj,
                    "metric",
                    Metric::Euclidean,
                    &ranges::WORLEY_METRICS,
                );
                let seed = self.seed(path, obj);
                Some(Source::Worley(WorleySpec {
                    frequency: frequency? as f32,
                    feature: feature?,
                    metric: metric?,
                    seed: seed?,
                }))
            }
            "white" => Some(Source::White(WhiteSpec {
                seed: self.seed(path, obj)?,
            })),
            "curl" => {
                let potential = self.fbm(path, obj, Basis::Perlin);
                let component = self.choice(
                    path,
                    obj,
                    "component",
                    CurlComponent::Magnitude,
                    &ranges::CURL_COMPONENTS,
                );
                Some(Source::Curl(CurlSpec {
                    potential: potential?,
                    component: component?,
                }))
            }
            "paper" | "canvas" => self.fibers(path, obj, kind == "canvas"),
            "product" => {
                let p = join(path, "inputs");
                match obj.get("inputs") {
                    Some(Value::Array(items)) if items.len() >= 2 => {
                        let parsed: Vec<Option<NoiseSpec>> = items
                            .iter()
                            .enumerate()
                            .map(|(i, it)| self.spec(&format!("{p}[{i}]"), it, Role::ProductInput))
                            .collect();
                        parsed
                            .into_iter()
                            .collect::<Option<Vec<_>>>()
                            .map(Source::Product)
                    }
                    Some(v) => {
                        self.push(
                            p,
                            format!("must be an array of at least two specs, got {}", short(v)),
                        );
                        None
                    }
                    None => {
                        self.push(p, "missing");
                        None
                    }
                }
            }
            _ => None,
        }
    }

    pub(super) fn fibers(
        &mut self,
        path: &str,
        obj: &Map<String, Value>,
        canvas: bool,
    ) -> Option<Source> {
        let length = self.bounded(path, obj, "length", Some(20.0), ranges::FIBER_LENGTH.into());
        let width = self.bounded(path, obj, "width", Some(1.5), ranges::FIBER_WIDTH.into());
        let density = self.bounded(
            path,
            obj,
            "density",
            Some(0.3),
            ranges::FIBER_DENSITY.into(),
        );
        let seed = self.seed(path, obj);
        let layout = if canvas {
            let p = join(path, "weights");
            match obj.get("weights") {
                None => Some(FiberLayout::Canvas {
                    weights: [1.0, 1.0],
                }),
                Some(v) => match v.as_array().map(Vec::as_slice) {
                    Some([h, w]) => match (h.as_f64(), w.as_f64()) {
                        (Some(h), Some(w)) if h >= 0.0 && w >= 0.0 && h + w > 0.0 => {
                            Some(FiberLayout::Canvas {
                                weights: [h as f32, w as f32],
                            })
                        }
                        _ => {
                            self.push(
                                p,
                                format!(
                                    "must be [horizontal, vertical] weights ≥ 0, not both 0, got {}",
                                    short(v)
                                ),
                            );
                            None
                        }
                    },
                    _ => {
                        self.push(
                            p,
                            format!(
                                "must be an array [horizontal, vertical] of two numbers, got {}",
                                short(v)
                            ),
                        );
                        None
                    }
                },
            }
        } else {
            Some(FiberLayout::Paper)
        };
        let impurities = match obj.get("impurities") {
            None => Some(None),
            Some(v) => {
                let p = join(path, "impurities");
                self.object(&p, v, &["density", "radius", "strength"])
                    .and_then(|o| {
                        let density =
                            self.bounded(&p, o, "density", Some(0.0005), Rule::Above(0.0, 0.1));
                        let radius =
                            self.bounded(&p, o, "radius", Some(1.5), Rule::Within(0.5, 16.0));
                        let strength =
                            self.bounded(&p, o, "strength", Some(2.0), Rule::Within(-20.0, 20.0));
                        Some(Some(Impurities {
                            density: density? as f32,
                            radius: radius? as f32,
                            strength: strength? as f32,
                        }))
                    })
            }
        };
        Some(Source::Fibers(FiberParams {
            layout: layout?,
            length: length? as f32,
            width: width? as f32,
            density: density? as f32,
            seed: seed?,
            period: None,
            impurities: impurities?,
        }))
    }
}
