//! Colour turbulence that loops, exactly (Kung 2019, ch. 5, without the feedback
//! texture): the design streaming along a curl noise, as two layers that never blur.
//!
//! With period P, at time t layer k (phase φ₁ = 0, φ₂ = ½) shows the design after a
//! flow ([`crate::Flow`]) of τₖ = frac(t/P + φₖ)·P: every output sample walks back
//! through that flow, then through the ops (no image is resampled). Its weight is
//! wₖ = 1 − |1 − 2·frac(t/P + φₖ)|, so w₁ + w₂ = 1, a layer fades in from weight 0 at
//! τ = 0 to 1 at τ = P/2 and out again before it jumps back, and frame(t) = frame(t + P).
//! The layers are blended in linear light. A turbulence document is
//! `{"noise": SPEC, "strength": U, "period": P}`, SPEC and U as a flow's.

use crate::color::{linear_to_srgb, srgb_to_linear};
use crate::ops::{MAX_FLOW_STEPS, flow_noise};
use crate::{Design, Flow, Op, RenderError, RenderOptions, RgbaImage, render};
use marbling_json::{FieldError, PathReader};
use marbling_noise::{FbmParams, NoiseSpec, SpecError};

/// A looping turbulence (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Turbulence {
    /// The noise the flow follows, design pixels.
    pub noise: FbmParams,
    /// U, design pixels per unit time.
    pub strength: f64,
    /// P, units of time, > 0.
    pub period: f64,
}

/// One layer of a frame: its flow time τ and weight w.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layer {
    /// τ = frac(t/P + φ)·P.
    pub time: f64,
    /// w = 1 − |1 − 2·frac(t/P + φ)|.
    pub weight: f64,
}

impl Turbulence {
    /// Reads a turbulence document; every problem with its path.
    pub fn from_json(text: &str) -> Result<Self, Vec<FieldError>> {
        let value = marbling_json::parse(text).map_err(|e| {
            vec![FieldError {
                path: String::new(),
                message: format!("line {}, column {}: {}", e.line, e.column, e.message),
            }]
        })?;
        let mut r = PathReader::default();
        let Some(obj) = r.object("", &value, &["noise", "strength", "period"]) else {
            return r.finish(None);
        };
        let noise = match r.field("", obj, "noise").map(NoiseSpec::from_value) {
            Some(Ok(spec)) => flow_noise(&spec).map_err(|m| r.push("noise", m)).ok(),
            Some(Err(SpecError::Invalid(list))) => {
                r.errors.extend(list.into_iter().map(|e| e.under("noise")));
                None
            }
            Some(Err(other)) => {
                r.push("noise", other.to_string());
                None
            }
            None => None,
        };
        let strength = r.number("", obj, "strength");
        let period = r.number("", obj, "period");
        if let Some(s) = strength.filter(|s| !s.is_finite()) {
            r.push("strength", format!("must be a finite number, got {s}"));
        }
        if let Some(p) = period.filter(|p| !(p.is_finite() && *p > 0.0)) {
            r.push("period", format!("must be a number > 0, got {p}"));
        }
        let t = match (noise, strength, period) {
            (Some(noise), Some(strength), Some(period)) => Some(Self {
                noise,
                strength,
                period,
            }),
            _ => None,
        };
        if let Some(t) = &t {
            let steps = t.flow(t.period).sub_steps();
            if r.errors.is_empty() && steps > MAX_FLOW_STEPS {
                r.push(
                    "period",
                    format!(
                        "a flow of one period needs {steps} sub-steps, more than {MAX_FLOW_STEPS}; use a shorter period, a smaller strength or a larger noise"
                    ),
                );
            }
        }
        r.finish(t)
    }

    /// The flow of time `time` along this turbulence's noise.
    pub fn flow(&self, time: f64) -> Flow {
        Flow {
            noise: self.noise,
            strength: self.strength,
            time,
        }
    }

    /// The two layers of the frame at time `t`.
    pub fn layers(&self, t: f64) -> [Layer; 2] {
        [0.0, 0.5].map(|phase| {
            let f = (t / self.period + phase).rem_euclid(1.0);
            Layer {
                time: f * self.period,
                weight: 1.0 - (1.0 - 2.0 * f).abs(),
            }
        })
    }

    /// The frame at time `t`: each layer rendered exactly (`design` then its flow) and
    /// blended in linear light; a layer of weight 0 is not rendered.
    pub fn render(
        &self,
        design: &Design,
        t: f64,
        opts: &RenderOptions,
    ) -> Result<RgbaImage, RenderError> {
        let mut sum: Option<(u32, u32, Vec<f32>)> = None;
        for layer in self.layers(t) {
            if layer.weight <= 0.0 {
                continue;
            }
            let mut flowed = design.clone();
            flowed.ops.push(Op::Flow(self.flow(layer.time)));
            let image = render(&flowed, opts)?;
            let (w, h, acc) = sum
                .get_or_insert_with(|| (image.width, image.height, vec![0.0; image.pixels.len()]));
            debug_assert_eq!((*w, *h), (image.width, image.height));
            let weight = layer.weight as f32;
            for (a, (i, &v)) in acc.iter_mut().zip(image.pixels.iter().enumerate()) {
                // Alpha is blended as it is; colour in linear light.
                *a += weight
                    * if i % 4 == 3 {
                        f32::from(v) / 255.0
                    } else {
                        srgb_to_linear(v)
                    };
            }
        }
        let Some((width, height, acc)) = sum else {
            unreachable!("the two weights add up to 1, so one is positive");
        };
        let pixels = acc
            .iter()
            .enumerate()
            .map(|(i, &v)| {
                if i % 4 == 3 {
                    (v * 255.0).round().clamp(0.0, 255.0) as u8
                } else {
                    linear_to_srgb(v)
                }
            })
            .collect();
        Ok(RgbaImage {
            width,
            height,
            pixels,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turbulence() -> Turbulence {
        Turbulence::from_json(
            r#"{"noise":{"type":"perlin","frequency":0.02,"octaves":2,"seed":5},"strength":10,"period":2}"#,
        )
        .expect("valid")
    }

    #[test]
    fn the_weights_add_up_to_one_and_the_layers_loop() {
        let t = turbulence();
        for k in 0..40 {
            let time = f64::from(k) * 0.137 - 1.0;
            let [a, b] = t.layers(time);
            assert!((a.weight + b.weight - 1.0).abs() < 1e-12, "{time}");
            assert!((0.0..2.0).contains(&a.time) && (0.0..2.0).contains(&b.time));
            let [c, d] = t.layers(time + t.period);
            assert!((a.time - c.time).abs() < 1e-9 && (b.weight - d.weight).abs() < 1e-9);
        }
        // At t = 0 layer one has just jumped back (weight 0), layer two is half way.
        let [a, b] = t.layers(0.0);
        assert_eq!((a.time, a.weight, b.time, b.weight), (0.0, 0.0, 1.0, 1.0));
    }

    #[test]
    fn bad_documents_are_named_with_their_paths() {
        let cases = [
            (
                r#"{"noise":{"type":"worley","frequency":0.05},"strength":1,"period":1}"#,
                "noise: must be a \"perlin\" or \"value\" noise",
            ),
            (
                r#"{"noise":{"type":"perlin","frequency":0.05,"octaves":99},"strength":1,"period":1}"#,
                "noise.octaves:",
            ),
            (
                r#"{"noise":{"type":"perlin","frequency":0.05},"strength":1,"period":0}"#,
                "period: must be a number > 0, got 0",
            ),
            (
                r#"{"noise":{"type":"perlin","frequency":0.05},"period":1}"#,
                "strength: missing",
            ),
            (
                r#"{"noise":{"type":"perlin","frequency":0.05},"strength":500,"period":50}"#,
                "period: a flow of one period needs",
            ),
            (
                r#"{"noise":{"type":"perlin","frequency":0.05},"strength":1,"period":1,"speed":2}"#,
                "speed:",
            ),
        ];
        for (text, expected) in cases {
            let errors = Turbulence::from_json(text).expect_err(text);
            let messages: Vec<String> = errors.iter().map(ToString::to_string).collect();
            assert!(
                messages.iter().any(|m| m.starts_with(expected)),
                "wanted {expected:?} in {messages:?}"
            );
        }
    }
}
