//! A view of the sheet as text, `x,y,scale`: the design point at the view's centre
//! (design pixels) and the output pixels per design pixel. The CLI's `--view` and a
//! share link's `v=` parameter both read it, so a deep spot opened from a link renders
//! the same window from the command line.

use kurbo::Point;
use std::fmt;

/// Deepest scale a view may ask for, output pixels per design pixel (the f64 walk stays
/// exact to 10⁻² pixel at 10⁶ on a 1,000-px sheet; past 10⁹ a pixel nears f64's last bit).
pub const MAX_VIEW_SCALE: f64 = 1e9;
/// Smallest scale a view may ask for.
pub const MIN_VIEW_SCALE: f64 = 1e-3;
/// Farthest a view's centre may be from the origin, design pixels.
pub const MAX_VIEW_CENTRE: f64 = 1e7;

/// A window's centre and scale, as `x,y,scale`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewSpec {
    /// The design point at the view's centre, design pixels.
    pub centre: Point,
    /// Output pixels per design pixel.
    pub scale: f64,
}

/// Why a view's text was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ViewSpecError {
    /// Not three comma-separated numbers.
    #[error("view: expected x,y,scale (three numbers), got \"{0}\"")]
    Shape(String),
    /// A part is not a number.
    #[error("view: {part} is not a number: \"{text}\"")]
    NotANumber {
        /// `x`, `y` or `scale`.
        part: &'static str,
        /// What was there.
        text: String,
    },
    /// A number is out of range.
    #[error("view: {part} must be {range}, got {value}")]
    Range {
        /// `x`, `y` or `scale`.
        part: &'static str,
        /// The allowed range, as words.
        range: String,
        /// The value given.
        value: String,
    },
}

impl ViewSpec {
    /// Reads `x,y,scale`.
    pub fn parse(text: &str) -> Result<Self, ViewSpecError> {
        let parts: Vec<&str> = text.trim().split(',').map(str::trim).collect();
        let [x, y, scale] = parts[..] else {
            return Err(ViewSpecError::Shape(text.to_owned()));
        };
        let number = |part: &'static str, t: &str| {
            t.parse::<f64>().map_err(|_| ViewSpecError::NotANumber {
                part,
                text: t.to_owned(),
            })
        };
        let (x, y, scale) = (number("x", x)?, number("y", y)?, number("scale", scale)?);
        for (part, v) in [("x", x), ("y", y)] {
            if !(v.is_finite() && v.abs() <= MAX_VIEW_CENTRE) {
                return Err(ViewSpecError::Range {
                    part,
                    range: format!("a finite number within ±{MAX_VIEW_CENTRE:e}"),
                    value: v.to_string(),
                });
            }
        }
        if !(scale.is_finite() && (MIN_VIEW_SCALE..=MAX_VIEW_SCALE).contains(&scale)) {
            return Err(ViewSpecError::Range {
                part: "scale",
                range: format!("{MIN_VIEW_SCALE:e} to {MAX_VIEW_SCALE:e}"),
                value: scale.to_string(),
            });
        }
        Ok(Self {
            centre: Point::new(x, y),
            scale,
        })
    }

    /// `x,y,scale` for people to read and type: the centre to a hundredth of an output
    /// pixel, the scale to six significant digits (a link keeps `Display`'s every digit).
    pub fn to_rounded_string(&self) -> String {
        let magnitude = self.scale.log10();
        let centre_decimals = (magnitude + 2.0).ceil().clamp(0.0, 17.0) as usize;
        let scale_decimals = (5.0 - magnitude.floor()).clamp(0.0, 17.0) as usize;
        let trim = |text: String| -> String {
            if text.contains('.') {
                text.trim_end_matches('0').trim_end_matches('.').to_owned()
            } else {
                text
            }
        };
        format!(
            "{},{},{}",
            trim(format!("{:.*}", centre_decimals, self.centre.x)),
            trim(format!("{:.*}", centre_decimals, self.centre.y)),
            trim(format!("{:.*}", scale_decimals, self.scale))
        )
    }
}

/// `x,y,scale` with every digit f64 needs to read back the same numbers.
impl fmt::Display for ViewSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{},{},{}", self.centre.x, self.centre.y, self.scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rounded_view_reads_back_within_a_hundredth_of_a_pixel() {
        let short = ViewSpec {
            centre: Point::new(206.048_950_357_967_39, 171.3),
            scale: 2.45,
        };
        assert_eq!(short.to_rounded_string(), "206.049,171.3,2.45");
        for (x, y, scale) in [
            (99.999_990_123_4, 40.000_020_987_6, 500_000.123_456),
            (-2.718_281_9, 1e6 / 3.0, 0.001_234_567),
            (512.0, 384.0, 1.0),
            (0.000_001_25, -7.5, 987_654_321.0),
        ] {
            let v = ViewSpec {
                centre: Point::new(x, y),
                scale,
            };
            let text = v.to_rounded_string();
            let back = ViewSpec::parse(&text).map_err(|e| e.to_string());
            let Ok(back) = back else {
                panic!("{text}: {back:?}");
            };
            let moved = (back.centre - v.centre).hypot() * v.scale;
            assert!(
                moved <= 0.01 * 2f64.sqrt(),
                "{text}: moved {moved} output px"
            );
            assert!(
                (back.scale / v.scale - 1.0).abs() <= 5e-6,
                "{text}: scale {}",
                back.scale
            );
        }
    }

    #[test]
    fn a_view_reads_back_exactly_what_it_wrote() {
        let v = ViewSpec {
            centre: Point::new(512.123_456_789_012_3, -0.000_001_25),
            scale: 987_654.321,
        };
        assert_eq!(ViewSpec::parse(&v.to_string()), Ok(v));
        assert_eq!(
            ViewSpec::parse(" 10, 20 ,1e6"),
            Ok(ViewSpec {
                centre: Point::new(10.0, 20.0),
                scale: 1e6
            })
        );
    }

    #[test]
    fn bad_views_are_refused_with_the_part_named() {
        let err = |t: &str| ViewSpec::parse(t).map_err(|e| e.to_string());
        assert_eq!(
            err("1,2"),
            Err("view: expected x,y,scale (three numbers), got \"1,2\"".to_owned())
        );
        assert_eq!(
            err("1,b,3"),
            Err("view: y is not a number: \"b\"".to_owned())
        );
        assert_eq!(
            err("1,2,0"),
            Err("view: scale must be 1e-3 to 1e9, got 0".to_owned())
        );
        assert_eq!(
            err("NaN,2,3"),
            Err("view: x must be a finite number within ±1e7, got NaN".to_owned())
        );
    }
}
