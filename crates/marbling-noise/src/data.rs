//! Data grids that drive a noise (Khlebnikov et al. 2013: frequency, orientation and colour from three
//! scalar attributes): a PNG (8- or 16-bit, 1–3 channels), a CSV grid (one channel), or
//! the built-in analytic `weather` field. Values are normalised to [0, 1]; each channel
//! keeps its name and the physical range the normalised values stand for (for legends).
//!
//! A grid is stretched over the output frame (the square output of `marbling noise`, the
//! sheet in the app) and sampled bilinearly between texel centres, clamped at the edges.

use std::f32::consts::PI;
use std::sync::Arc;

/// Largest grid side accepted, texels.
pub const MAX_DATA_SIDE: usize = 4096;
/// Name of the built-in analytic weather data set.
pub const WEATHER: &str = "weather";
/// Side of the built-in weather grid, texels (4:3, like the default sheet).
pub const WEATHER_SIZE: [usize; 2] = [160, 120];

/// One channel's meaning: a name and the physical values 0 and 1 stand for.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// Shown in legends ("temperature").
    pub name: String,
    /// Unit of `range` ("°C"), empty when none.
    pub unit: String,
    /// The values that normalised 0 and 1 stand for.
    pub range: [f32; 2],
}

/// A grid of 1–3 channels of values in [0, 1], row-major, channel-interleaved.
#[derive(Clone, Debug, PartialEq)]
pub struct DataGrid {
    /// Texels per row.
    pub width: usize,
    /// Rows.
    pub height: usize,
    /// What each channel means.
    pub channels: Vec<Channel>,
    values: Vec<f32>,
}

/// Why a data file could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DataError {
    /// Not a PNG we can decode.
    #[error("not a readable PNG: {0}")]
    Png(String),
    /// A CSV cell that is not a number, or rows of different lengths.
    #[error("line {line}: {message}")]
    Csv {
        /// 1-based line.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// Too big or empty.
    #[error("{width}×{height} texels: a data grid must be 1 to {MAX_DATA_SIDE} texels on a side")]
    Size {
        /// Texels per row.
        width: usize,
        /// Rows.
        height: usize,
    },
}

fn check_size(width: usize, height: usize) -> Result<(), DataError> {
    if width == 0 || height == 0 || width > MAX_DATA_SIDE || height > MAX_DATA_SIDE {
        return Err(DataError::Size { width, height });
    }
    Ok(())
}

impl DataGrid {
    /// A grid from normalised values (`channels.len()` per texel, row-major).
    ///
    /// # Panics
    /// When `values` does not hold `width · height · channels.len()` numbers.
    #[must_use]
    pub fn new(width: usize, height: usize, channels: Vec<Channel>, values: Vec<f32>) -> Self {
        assert_eq!(values.len(), width * height * channels.len(), "grid size");
        Self {
            width,
            height,
            channels,
            values,
        }
    }

    /// Reads a PNG: grey (1 channel) or RGB (3 channels), alpha ignored, palettes
    /// expanded; 8-bit samples ÷ 255, 16-bit ÷ 65535. Channels are named after their
    /// colour and span [0, 1].
    pub fn from_png(bytes: &[u8]) -> Result<Self, DataError> {
        let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        decoder.set_transformations(png::Transformations::EXPAND);
        let mut reader = decoder
            .read_info()
            .map_err(|e| DataError::Png(e.to_string()))?;
        let (width, height) = {
            let info = reader.info();
            (info.width as usize, info.height as usize)
        };
        check_size(width, height)?;
        let size = reader
            .output_buffer_size()
            .ok_or_else(|| DataError::Png("image too large".into()))?;
        let mut buf = vec![0; size];
        let frame = reader
            .next_frame(&mut buf)
            .map_err(|e| DataError::Png(e.to_string()))?;
        let (colour, depth) = (frame.color_type, frame.bit_depth);
        let samples = colour.samples();
        let kept = if samples >= 3 { 3 } else { 1 };
        let wide = depth == png::BitDepth::Sixteen;
        let bytes_per = if wide { 2 } else { 1 };
        let mut values = Vec::with_capacity(width * height * kept);
        for row in buf[..frame.buffer_size()].chunks_exact(frame.line_size) {
            for px in row[..width * samples * bytes_per].chunks_exact(samples * bytes_per) {
                for c in 0..kept {
                    let v = if wide {
                        f32::from(u16::from_be_bytes([px[2 * c], px[2 * c + 1]])) / 65535.0
                    } else {
                        // Bit depths below 8 are expanded to 8 by the decoder.
                        f32::from(px[c]) / 255.0
                    };
                    values.push(v);
                }
            }
        }
        let names: &[&str] = if kept == 3 {
            &["red", "green", "blue"]
        } else {
            &["grey"]
        };
        let channels = names
            .iter()
            .map(|n| Channel {
                name: (*n).to_owned(),
                unit: String::new(),
                range: [0.0, 1.0],
            })
            .collect();
        Ok(Self::new(width, height, channels, values))
    }

    /// Reads a CSV grid: each non-empty line a row, cells separated by commas (or
    /// semicolons, tabs), every row as long as the first. One channel, normalised by the
    /// grid's minimum and maximum (a constant grid reads as 0.5); named `name`.
    pub fn from_csv(text: &str, name: &str) -> Result<Self, DataError> {
        let mut rows: Vec<Vec<f32>> = Vec::new();
        for (i, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() {
                continue;
            }
            let cells = line
                .split([',', ';', '\t'])
                .map(|c| {
                    let c = c.trim();
                    c.parse::<f32>()
                        .ok()
                        .filter(|v| v.is_finite())
                        .ok_or_else(|| DataError::Csv {
                            line: i + 1,
                            message: format!("'{c}' is not a finite number"),
                        })
                })
                .collect::<Result<Vec<f32>, _>>()?;
            if let Some(first) = rows.first()
                && first.len() != cells.len()
            {
                return Err(DataError::Csv {
                    line: i + 1,
                    message: format!(
                        "{} cells, but the first row has {}",
                        cells.len(),
                        first.len()
                    ),
                });
            }
            rows.push(cells);
        }
        let height = rows.len();
        let width = rows.first().map_or(0, Vec::len);
        check_size(width, height)?;
        let values: Vec<f32> = rows.into_iter().flatten().collect();
        let lo = values.iter().copied().fold(f32::INFINITY, f32::min);
        let hi = values.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        let normalised = values
            .iter()
            .map(|v| if hi > lo { (v - lo) / (hi - lo) } else { 0.5 })
            .collect();
        let channel = Channel {
            name: name.to_owned(),
            unit: String::new(),
            range: [lo, hi],
        };
        Ok(Self::new(width, height, vec![channel], normalised))
    }

    /// The built-in analytic weather field over a 4:3 map: channel 1 temperature (warm
    /// equator, cool poles, a warm and a cold anomaly), channel 2 wind direction (the
    /// flow around a low and a high plus westerlies), channel 3 pressure (the low and
    /// the high).
    #[must_use]
    pub fn weather() -> Self {
        let [w, h] = WEATHER_SIZE;
        let mut values = Vec::with_capacity(w * h * 3);
        for j in 0..h {
            for i in 0..w {
                let [t, d, p] =
                    weather_at((i as f32 + 0.5) / w as f32, (j as f32 + 0.5) / h as f32);
                values.extend_from_slice(&[t, d, p]);
            }
        }
        let ch = |name: &str, unit: &str, range: [f32; 2]| Channel {
            name: name.to_owned(),
            unit: unit.to_owned(),
            range,
        };
        let channels = vec![
            ch("temperature", "°C", WEATHER_TEMPERATURE),
            ch("wind direction", "°", [0.0, 180.0]),
            ch("pressure", "hPa", WEATHER_PRESSURE),
        ];
        Self::new(w, h, channels, values)
    }

    /// A built-in data set by name (computed once, then shared).
    #[must_use]
    pub fn builtin(name: &str) -> Option<Arc<Self>> {
        static WEATHER_GRID: std::sync::OnceLock<Arc<DataGrid>> = std::sync::OnceLock::new();
        (name == WEATHER).then(|| {
            WEATHER_GRID
                .get_or_init(|| Arc::new(Self::weather()))
                .clone()
        })
    }

    /// Channel `c` (0-based) at texel (i, j).
    #[must_use]
    pub fn texel(&self, i: usize, j: usize, c: usize) -> f32 {
        let n = self.channels.len();
        self.values[(j * self.width + i) * n + c]
    }

    /// Channel `c` (0-based) at (u, v) ∈ [0, 1]² of the grid (u right, v down),
    /// bilinear between texel centres, clamped at the edges.
    #[must_use]
    pub fn sample(&self, c: usize, u: f32, v: f32) -> f32 {
        let x = (u * self.width as f32 - 0.5).clamp(0.0, (self.width - 1) as f32);
        let y = (v * self.height as f32 - 0.5).clamp(0.0, (self.height - 1) as f32);
        let (i0, j0) = (x.floor() as usize, y.floor() as usize);
        let (i1, j1) = ((i0 + 1).min(self.width - 1), (j0 + 1).min(self.height - 1));
        let (fx, fy) = (x - i0 as f32, y - j0 as f32);
        let top = self.texel(i0, j0, c) * (1.0 - fx) + self.texel(i1, j0, c) * fx;
        let bottom = self.texel(i0, j1, c) * (1.0 - fx) + self.texel(i1, j1, c) * fx;
        top * (1.0 - fy) + bottom * fy
    }
}

/// °C that the weather's temperature 0 and 1 stand for.
pub const WEATHER_TEMPERATURE: [f32; 2] = [-10.0, 35.0];
/// hPa that the weather's pressure 0 and 1 stand for.
pub const WEATHER_PRESSURE: [f32; 2] = [980.0, 1040.0];

/// Normalised (temperature, wind direction, pressure) of the weather map at (u, v).
fn weather_at(u: f32, v: f32) -> [f32; 3] {
    let bump = |cx: f32, cy: f32, r: f32| {
        let (dx, dy) = ((u - cx) * 4.0 / 3.0, v - cy);
        (-(dx * dx + dy * dy) / (r * r)).exp()
    };
    // Temperature: warm at the equator (v = 0.5), anomalies east and west.
    let lat = (v - 0.5) * 2.0;
    let temp_c = 30.0 - 32.0 * lat * lat + 6.0 * bump(0.25, 0.45, 0.12) - 8.0 * bump(0.7, 0.3, 0.1)
        + 2.0 * (u * 2.0 * PI * 3.0).sin() * (v * PI).sin();
    // Pressure: a low west of centre, a high east.
    let low = bump(0.33, 0.5, 0.18);
    let high = bump(0.72, 0.55, 0.2);
    let p_hpa = 1012.0 - 28.0 * low + 22.0 * high;
    // Wind: anticlockwise around the low, clockwise around the high (northern
    // hemisphere, y down), plus westerlies; the direction's axis in [0°, 180°).
    let around = |cx: f32, cy: f32, sign: f32, w: f32| {
        let (dx, dy) = ((u - cx) * 4.0 / 3.0, v - cy);
        [-dy * sign * w, dx * sign * w]
    };
    let a = around(0.33, 0.5, -1.0, low * 6.0);
    let b = around(0.72, 0.55, 1.0, high * 6.0);
    let (wx, wy) = (a[0] + b[0] + 0.15, a[1] + b[1]);
    let axis = wy.atan2(wx).rem_euclid(PI) / PI;
    let norm = |x: f32, r: [f32; 2]| ((x - r[0]) / (r[1] - r[0])).clamp(0.0, 1.0);
    [
        norm(temp_c, WEATHER_TEMPERATURE),
        axis,
        norm(p_hpa, WEATHER_PRESSURE),
    ]
}

/// A channel of a named data set, as a spec refers to it: `{"data": NAME, "channel": K}`
/// (K from 1). The grid is attached after parsing ([`crate::NoiseSpec::attach_data`]);
/// built-in names are attached by the parser.
#[derive(Clone, Debug)]
pub struct DataRef {
    /// A built-in name or a file (a path relative to the spec file in the CLI).
    pub name: String,
    /// 1-based channel.
    pub channel: usize,
    /// The data, once attached.
    pub grid: Option<Arc<DataGrid>>,
}

impl PartialEq for DataRef {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name && self.channel == other.channel
    }
}

impl DataRef {
    /// A reference to `name`'s channel `channel`, attached when `name` is built in.
    #[must_use]
    pub fn new(name: &str, channel: usize) -> Self {
        Self {
            name: name.to_owned(),
            channel,
            grid: DataGrid::builtin(name),
        }
    }

    /// The value in [0, 1] at (x, y) output pixels of a `frame` (width, height in output
    /// pixels) the grid is stretched over; 0 when no grid is attached or the channel is
    /// missing.
    #[must_use]
    pub fn sample(&self, x: f32, y: f32, frame: [f32; 2]) -> f32 {
        match &self.grid {
            Some(g) if (1..=g.channels.len()).contains(&self.channel) => {
                g.sample(self.channel - 1, x / frame[0], y / frame[1])
            }
            _ => 0.0,
        }
    }

    /// The channel's description, when attached.
    #[must_use]
    pub fn channel_info(&self) -> Option<&Channel> {
        self.grid
            .as_ref()?
            .channels
            .get(self.channel.checked_sub(1)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_grids_normalise_and_refuse_ragged_rows() {
        let g = DataGrid::from_csv("1, 2\n3;5\n", "h").expect("grid");
        assert_eq!((g.width, g.height), (2, 2));
        assert_eq!(g.texel(1, 1, 0), 1.0);
        assert_eq!(g.texel(0, 0, 0), 0.0);
        assert_eq!(g.channels[0].range, [1.0, 5.0]);
        assert_eq!(g.texel(0, 1, 0), 0.5);
        let e = DataGrid::from_csv("1,2\n3\n", "h").expect_err("ragged");
        assert_eq!(e.to_string(), "line 2: 1 cells, but the first row has 2");
        let e = DataGrid::from_csv("1,x\n", "h").expect_err("text");
        assert_eq!(e.to_string(), "line 1: 'x' is not a finite number");
        assert!(matches!(
            DataGrid::from_csv("", "h"),
            Err(DataError::Size { .. })
        ));
    }

    #[test]
    fn sampling_is_bilinear_between_texel_centres_and_clamped() {
        let g = DataGrid::from_csv("0,1\n", "x").expect("grid");
        assert_eq!(g.sample(0, 0.25, 0.5), 0.0);
        assert_eq!(g.sample(0, 0.5, 0.5), 0.5);
        assert_eq!(g.sample(0, 0.75, 0.5), 1.0);
        assert_eq!(g.sample(0, 1.5, -3.0), 1.0);
    }

    #[test]
    fn the_weather_spans_its_channels() {
        let g = DataGrid::weather();
        assert_eq!(g.channels.len(), 3);
        for c in 0..3 {
            let (mut lo, mut hi) = (1f32, 0f32);
            for j in 0..g.height {
                for i in 0..g.width {
                    let v = g.texel(i, j, c);
                    lo = lo.min(v);
                    hi = hi.max(v);
                }
            }
            assert!(
                lo >= 0.0 && hi <= 1.0 && hi - lo > 0.5,
                "channel {c}: {lo}..{hi}"
            );
        }
    }

    #[test]
    fn pngs_read_8_and_16_bit_channels() {
        for (depth, max) in [
            (png::BitDepth::Eight, 255.0),
            (png::BitDepth::Sixteen, 65535.0),
        ] {
            let mut bytes = Vec::new();
            {
                let mut enc = png::Encoder::new(&mut bytes, 2, 1);
                enc.set_color(png::ColorType::Rgb);
                enc.set_depth(depth);
                let mut w = enc.write_header().expect("header");
                let data: Vec<u8> = if depth == png::BitDepth::Eight {
                    vec![0, 128, 255, 10, 20, 30]
                } else {
                    [0u16, 32768, 65535, 10, 20, 30]
                        .iter()
                        .flat_map(|v| v.to_be_bytes())
                        .collect()
                };
                w.write_image_data(&data).expect("data");
            }
            let g = DataGrid::from_png(&bytes).expect("png");
            assert_eq!((g.width, g.height, g.channels.len()), (2, 1, 3));
            let want = if max == 255.0 { 128.0 } else { 32768.0 };
            assert_eq!(g.texel(0, 0, 1), want / max);
            assert_eq!(g.texel(0, 0, 2), 1.0);
        }
        assert!(matches!(
            DataGrid::from_png(b"not a png"),
            Err(DataError::Png(_))
        ));
    }
}
