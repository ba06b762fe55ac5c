//! Image backgrounds (schema v2 `background: {"image": …, "fit": …}`): a photo marbled
//! like ink.
//!
//! # Conventions (keep in sync with `surface.wgsl` in marbling-gpu)
//! - The image is a PNG, JPEG or WebP given as a `data:` URI; it decodes to at most
//!   [`MAX_IMAGE_SIDE`]² pixels from at most [`MAX_IMAGE_BYTES`] bytes.
//! - A sample whose walk leaves the oldest op without meeting ink shows the image at
//!   the **back-traced** design point (x, y): image pixel coordinates
//!   u = (x − ox)·kx, v = (y − oy)·ky ([`ImageMap`]), texel centres at whole + ½,
//!   interpolated bilinearly **in linear light**, clamped to the image's edge.
//! - [`ImageFit::Stretch`] maps the image onto the sheet [0, W]×[0, H];
//!   [`ImageFit::Cover`] scales it uniformly to cover the sheet, centred (the overflow is
//!   cut off); [`ImageFit::Contain`] scales it uniformly to fit inside, centred, and
//!   points outside the image show the paper colour (`Design::background`).

use base64::Engine as _;
use std::fmt;
use std::sync::{Arc, OnceLock};

/// Largest decoded image side, pixels (WebGL2 guarantees textures of 4096²).
pub const MAX_IMAGE_SIDE: u32 = 4096;
/// Largest image file, bytes.
pub const MAX_IMAGE_BYTES: usize = 8 * 1024 * 1024;
/// Names accepted as `fit`.
pub const IMAGE_FITS: &[&str] = &["stretch", "cover", "contain"];

/// How an image is laid on the sheet.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ImageFit {
    /// Onto the whole sheet, each axis scaled on its own.
    Stretch,
    /// Uniformly scaled to cover the sheet, centred.
    #[default]
    Cover,
    /// Uniformly scaled to fit inside the sheet, centred, letterboxed with the paper.
    Contain,
}

impl ImageFit {
    /// The `fit` name in JSON.
    pub fn name(self) -> &'static str {
        match self {
            ImageFit::Stretch => "stretch",
            ImageFit::Cover => "cover",
            ImageFit::Contain => "contain",
        }
    }

    /// The fit called `name` in JSON.
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "stretch" => Some(ImageFit::Stretch),
            "cover" => Some(ImageFit::Cover),
            "contain" => Some(ImageFit::Contain),
            _ => None,
        }
    }
}

/// Why an image cannot be a background.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ImageError {
    /// The file is too big.
    #[error("image file of {0} bytes is too large (at most {MAX_IMAGE_BYTES} bytes, 8 MB)")]
    FileTooLarge(usize),
    /// The decoded picture is too big.
    #[error(
        "image of {width}×{height} pixels is too large (at most {MAX_IMAGE_SIDE}×{MAX_IMAGE_SIDE})"
    )]
    TooLarge {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
    },
    /// Not a `data:` URI with base64 content.
    #[error("must be a data: URI (data:image/png;base64,…), got {0:?}")]
    NotDataUri(String),
    /// Not a picture in a supported format, or a damaged one.
    #[error("cannot decode the image (PNG, JPEG or WebP expected): {0}")]
    Decode(String),
}

/// Decoded pixels, sRGB bytes (alpha dropped: composited onto nothing, the sheet is
/// opaque).
#[derive(Clone, PartialEq, Eq)]
pub struct ImagePixels {
    /// Width, pixels.
    pub width: u32,
    /// Height, pixels.
    pub height: u32,
    /// Row-major RGBA, alpha always 255.
    pub rgba: Vec<u8>,
}

impl fmt::Debug for ImagePixels {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "ImagePixels({}×{})", self.width, self.height)
    }
}

impl ImagePixels {
    /// Pixels of a picture file (PNG, JPEG or WebP), within the limits.
    pub fn decode(bytes: &[u8]) -> Result<Self, ImageError> {
        if bytes.len() > MAX_IMAGE_BYTES {
            return Err(ImageError::FileTooLarge(bytes.len()));
        }
        let reader = image::ImageReader::new(std::io::Cursor::new(bytes))
            .with_guessed_format()
            .map_err(|e| ImageError::Decode(e.to_string()))?;
        let (width, height) = reader
            .into_dimensions()
            .map_err(|e| ImageError::Decode(e.to_string()))?;
        if width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
            return Err(ImageError::TooLarge { width, height });
        }
        let decoded =
            image::load_from_memory(bytes).map_err(|e| ImageError::Decode(e.to_string()))?;
        let mut rgba = decoded.into_rgba8();
        rgba.pixels_mut().for_each(|p| p.0[3] = 255);
        Ok(Self {
            width,
            height,
            rgba: rgba.into_raw(),
        })
    }

    /// Pixels from row-major RGBA bytes (a video frame); alpha is set to 255.
    pub fn from_rgba(width: u32, height: u32, mut rgba: Vec<u8>) -> Result<Self, ImageError> {
        if width == 0 || height == 0 || width > MAX_IMAGE_SIDE || height > MAX_IMAGE_SIDE {
            return Err(ImageError::TooLarge { width, height });
        }
        if rgba.len() != width as usize * height as usize * 4 {
            return Err(ImageError::Decode(format!(
                "{} bytes for {width}×{height} RGBA pixels",
                rgba.len()
            )));
        }
        rgba.chunks_exact_mut(4).for_each(|p| p[3] = 255);
        Ok(Self {
            width,
            height,
            rgba,
        })
    }

    /// Linear colour of texel (i, j) (clamped to the image).
    #[inline]
    fn texel(&self, i: i64, j: i64) -> [f32; 3] {
        let i = i.clamp(0, i64::from(self.width) - 1) as usize;
        let j = j.clamp(0, i64::from(self.height) - 1) as usize;
        let k = (j * self.width as usize + i) * 4;
        let lut = srgb_lut();
        [
            lut[self.rgba[k] as usize],
            lut[self.rgba[k + 1] as usize],
            lut[self.rgba[k + 2] as usize],
        ]
    }

    /// Bilinear linear-light colour at image pixel coordinates (u, v) (texel centres at
    /// whole + ½), clamped to the edge.
    pub fn bilinear(&self, u: f64, v: f64) -> [f32; 3] {
        let (fx, fy) = (u - 0.5, v - 0.5);
        let (x0, y0) = (fx.floor(), fy.floor());
        let (tx, ty) = ((fx - x0) as f32, (fy - y0) as f32);
        let (i, j) = (x0 as i64, y0 as i64);
        let a = self.texel(i, j);
        let b = self.texel(i + 1, j);
        let c = self.texel(i, j + 1);
        let d = self.texel(i + 1, j + 1);
        std::array::from_fn(|k| {
            let top = a[k] + (b[k] - a[k]) * tx;
            let bottom = c[k] + (d[k] - c[k]) * tx;
            top + (bottom - top) * ty
        })
    }

    /// The pixels encoded as JPEG of `quality` (1..=100), at most `max_side` per side
    /// (downscaled with a triangle filter when larger).
    pub fn to_jpeg(&self, max_side: u32, quality: u8) -> Vec<u8> {
        let rgba = image::RgbaImage::from_raw(self.width, self.height, self.rgba.clone())
            .unwrap_or_else(|| unreachable!("ImagePixels always holds width·height·4 bytes"));
        let mut rgb = image::DynamicImage::ImageRgba8(rgba).into_rgb8();
        if self.width.max(self.height) > max_side {
            let k = f64::from(max_side) / f64::from(self.width.max(self.height));
            let w = ((f64::from(self.width) * k).round() as u32).max(1);
            let h = ((f64::from(self.height) * k).round() as u32).max(1);
            rgb = image::imageops::resize(&rgb, w, h, image::imageops::FilterType::Triangle);
        }
        let mut out = Vec::new();
        let enc = image::codecs::jpeg::JpegEncoder::new_with_quality(&mut out, quality);
        // Encoding an in-memory RGB buffer into a Vec cannot fail.
        let _ = rgb.write_with_encoder(enc);
        out
    }
}

/// sRGB byte → linear light (the GPU's `…UnormSrgb` decode).
fn srgb_lut() -> &'static [f32; 256] {
    static LUT: OnceLock<[f32; 256]> = OnceLock::new();
    LUT.get_or_init(|| {
        std::array::from_fn(|i| crate::surface::srgb_unit_to_linear(i as f32 / 255.0))
    })
}

/// Where the image lies on a sheet: image pixel u = (x − origin.0)·scale.0,
/// v = (y − origin.1)·scale.1 for design point (x, y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageMap {
    /// Design point of the image's top-left corner.
    pub origin: (f64, f64),
    /// Image pixels per design pixel along x and y.
    pub scale: (f64, f64),
    /// Whether points outside the image show the paper (contain) rather than the
    /// clamped edge.
    pub letterbox: bool,
}

/// A picture background: the `data:` URI as written (kept so the design writes it back
/// unchanged), its decoded pixels and its fit. Cloning shares the pixels.
#[derive(Clone)]
pub struct ImageBackground {
    source: Arc<str>,
    pixels: Arc<ImagePixels>,
    /// How the picture is laid on the sheet.
    pub fit: ImageFit,
}

impl fmt::Debug for ImageBackground {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "ImageBackground({:?}, {} bytes of data URI, {:?})",
            self.pixels,
            self.source.len(),
            self.fit
        )
    }
}

impl PartialEq for ImageBackground {
    fn eq(&self, other: &Self) -> bool {
        self.fit == other.fit
            && (Arc::ptr_eq(&self.source, &other.source) || self.source == other.source)
    }
}

impl ImageBackground {
    /// A background of the picture in the `data:` URI `uri`.
    pub fn from_data_uri(uri: &str, fit: ImageFit) -> Result<Self, ImageError> {
        let bytes = data_uri_bytes(uri)?;
        let pixels = ImagePixels::decode(&bytes)?;
        Ok(Self {
            source: uri.into(),
            pixels: Arc::new(pixels),
            fit,
        })
    }

    /// A background of the picture file `bytes` (PNG, JPEG or WebP), kept as a `data:`
    /// URI of those bytes.
    pub fn from_file_bytes(bytes: &[u8], fit: ImageFit) -> Result<Self, ImageError> {
        let pixels = ImagePixels::decode(bytes)?;
        let mime = mime_of(bytes);
        Ok(Self {
            source: data_uri(mime, bytes).into(),
            pixels: Arc::new(pixels),
            fit,
        })
    }

    /// The same picture with another fit (the pixels are shared).
    pub fn with_fit(&self, fit: ImageFit) -> Self {
        Self {
            fit,
            ..self.clone()
        }
    }

    /// The picture re-encoded as a JPEG `data:` URI of at most `max_side` pixels per
    /// side (for share links that must stay short).
    pub fn downscaled(&self, max_side: u32, quality: u8) -> Self {
        let jpeg = self.pixels.to_jpeg(max_side, quality);
        Self::from_file_bytes(&jpeg, self.fit)
            .unwrap_or_else(|_| unreachable!("a JPEG we encoded decodes within the limits"))
    }

    /// The `data:` URI as written.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The decoded pixels.
    pub fn pixels(&self) -> &ImagePixels {
        &self.pixels
    }

    /// The shared pixels (GPU uploads compare them by pointer to skip re-uploads).
    pub fn pixels_arc(&self) -> &Arc<ImagePixels> {
        &self.pixels
    }

    /// Where the picture lies on a `width`×`height` sheet.
    pub fn map(&self, width: u32, height: u32) -> ImageMap {
        fit_map(
            self.fit,
            (self.pixels.width, self.pixels.height),
            (width, height),
        )
    }
}

/// Where an `image` (width, height) lies on a `sheet` (width, height) under `fit`.
pub fn fit_map(fit: ImageFit, image: (u32, u32), sheet: (u32, u32)) -> ImageMap {
    let (iw, ih) = (f64::from(image.0), f64::from(image.1));
    let (w, h) = (f64::from(sheet.0), f64::from(sheet.1));
    let uniform = |s: f64| ImageMap {
        origin: ((w - iw * s) / 2.0, (h - ih * s) / 2.0),
        scale: (1.0 / s, 1.0 / s),
        letterbox: fit == ImageFit::Contain,
    };
    match fit {
        ImageFit::Stretch => ImageMap {
            origin: (0.0, 0.0),
            scale: (iw / w, ih / h),
            letterbox: false,
        },
        ImageFit::Cover => uniform((w / iw).max(h / ih)),
        ImageFit::Contain => uniform((w / iw).min(h / ih)),
    }
}

impl ImageMap {
    /// Linear colour of `pixels` laid by this map at design point (x, y), or `paper`
    /// (linear) outside a letterboxed image.
    #[inline]
    pub fn sample(&self, pixels: &ImagePixels, x: f64, y: f64, paper: [f32; 3]) -> [f32; 3] {
        let u = (x - self.origin.0) * self.scale.0;
        let v = (y - self.origin.1) * self.scale.1;
        let inside = (0.0..=f64::from(pixels.width)).contains(&u)
            && (0.0..=f64::from(pixels.height)).contains(&v);
        if self.letterbox && !inside {
            return paper;
        }
        pixels.bilinear(u, v)
    }
}

/// The file type of picture `bytes` as a MIME type (PNG when unknown).
fn mime_of(bytes: &[u8]) -> &'static str {
    match image::guess_format(bytes) {
        Ok(image::ImageFormat::Jpeg) => "image/jpeg",
        Ok(image::ImageFormat::WebP) => "image/webp",
        _ => "image/png",
    }
}

/// `data:MIME;base64,…` of `bytes`.
pub fn data_uri(mime: &str, bytes: &[u8]) -> String {
    format!(
        "data:{mime};base64,{}",
        base64::engine::general_purpose::STANDARD.encode(bytes)
    )
}

/// The bytes of a base64 `data:` URI.
fn data_uri_bytes(uri: &str) -> Result<Vec<u8>, ImageError> {
    let preview = || uri.chars().take(40).collect::<String>();
    let rest = uri
        .strip_prefix("data:")
        .ok_or_else(|| ImageError::NotDataUri(preview()))?;
    let (head, payload) = rest
        .split_once(',')
        .ok_or_else(|| ImageError::NotDataUri(preview()))?;
    if !head.ends_with(";base64") {
        return Err(ImageError::NotDataUri(preview()));
    }
    if payload.len() / 4 * 3 > MAX_IMAGE_BYTES + 3 {
        return Err(ImageError::FileTooLarge(payload.len() / 4 * 3));
    }
    let clean: String = payload.chars().filter(|c| !c.is_whitespace()).collect();
    base64::engine::general_purpose::STANDARD
        .decode(clean)
        .map_err(|e| ImageError::Decode(format!("bad base64: {e}")))
}
