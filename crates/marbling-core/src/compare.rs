//! Pixel comparison of two renders with a stated budget, and golden-image snapshots.

use crate::RgbaImage;
use std::path::Path;

/// How two images of the same size differ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageDiff {
    /// Pixels where some channel differs by more than the threshold.
    pub differing: usize,
    /// Pixels compared.
    pub total: usize,
    /// Largest channel difference seen anywhere, 0..=255.
    pub max_channel_diff: u8,
}

impl ImageDiff {
    /// Fraction of differing pixels, 0..=1.
    pub fn fraction(&self) -> f64 {
        self.differing as f64 / self.total.max(1) as f64
    }
}

/// Images whose sizes differ cannot be compared.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("image sizes differ: {0}×{1} vs {2}×{3}")]
pub struct SizeMismatch(pub u32, pub u32, pub u32, pub u32);

fn max_channel_diff(a: &[u8], b: &[u8]) -> u8 {
    a.iter()
        .zip(b)
        .map(|(x, y)| x.abs_diff(*y))
        .max()
        .unwrap_or(0)
}

/// Counts pixels where any channel differs by more than `threshold` (0..=255).
pub fn compare(a: &RgbaImage, b: &RgbaImage, threshold: u8) -> Result<ImageDiff, SizeMismatch> {
    if (a.width, a.height) != (b.width, b.height) {
        return Err(SizeMismatch(a.width, a.height, b.width, b.height));
    }
    let mut diff = ImageDiff {
        differing: 0,
        total: a.pixels.len() / 4,
        max_channel_diff: 0,
    };
    for (pa, pb) in a.pixels.chunks_exact(4).zip(b.pixels.chunks_exact(4)) {
        let m = max_channel_diff(pa, pb);
        diff.max_channel_diff = diff.max_channel_diff.max(m);
        if m > threshold {
            diff.differing += 1;
        }
    }
    Ok(diff)
}

/// `expected | diff | actual` side by side; the diff is red where a channel differs by
/// more than `threshold`, a faded copy of `expected` elsewhere. Sizes must match.
pub fn diff_strip(expected: &RgbaImage, actual: &RgbaImage, threshold: u8) -> RgbaImage {
    let (w, h) = (expected.width, expected.height);
    let mut out = RgbaImage::filled(w * 3, h, [0, 0, 0, 255]);
    for y in 0..h {
        for x in 0..w {
            let (e, a) = (expected.pixel(x, y), actual.pixel(x, y));
            let faded = [e[0] / 4 + 191, e[1] / 4 + 191, e[2] / 4 + 191, 255];
            let d = if max_channel_diff(&e, &a) > threshold {
                [255, 0, 0, 255]
            } else {
                faded
            };
            out.set_pixel(x, y, e);
            out.set_pixel(w + x, y, d);
            out.set_pixel(2 * w + x, y, a);
        }
    }
    out
}

/// Checks `actual` against the golden PNG at `path`: at most `max_fraction` of pixels
/// may differ by more than `threshold`. Only with `UPDATE_SNAPSHOTS=1` set is the golden
/// (re)written instead; a missing golden is a failure. On failure writes
/// `<name>.actual.png` and `<name>.diff.png` (expected | diff | actual) beside it.
pub fn check_snapshot(
    path: &Path,
    actual: &RgbaImage,
    threshold: u8,
    max_fraction: f64,
) -> Result<(), String> {
    let update = std::env::var_os("UPDATE_SNAPSHOTS").is_some_and(|v| v == "1");
    check_snapshot_with(path, actual, threshold, max_fraction, update)
}

/// [`check_snapshot`] with the update decision made by the caller.
pub fn check_snapshot_with(
    path: &Path,
    actual: &RgbaImage,
    threshold: u8,
    max_fraction: f64,
    update: bool,
) -> Result<(), String> {
    let write = |p: &Path, img: &RgbaImage| -> Result<(), String> {
        if let Some(dir) = p.parent() {
            std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        }
        let bytes = img.to_png().map_err(|e| e.to_string())?;
        std::fs::write(p, bytes).map_err(|e| format!("{}: {e}", p.display()))
    };
    if update {
        return write(path, actual);
    }
    let bytes = std::fs::read(path).map_err(|e| {
        format!(
            "golden {} unreadable ({e}); run with UPDATE_SNAPSHOTS=1 to create it",
            path.display()
        )
    })?;
    let expected = RgbaImage::from_png(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    let diff = compare(&expected, actual, threshold);
    let failure = match &diff {
        Err(e) => e.to_string(),
        Ok(d) if d.fraction() > max_fraction => format!(
            "{} of {} pixels ({:.3} %) differ by more than {threshold}/255 (budget {:.3} %, max diff {})",
            d.differing,
            d.total,
            100.0 * d.fraction(),
            100.0 * max_fraction,
            d.max_channel_diff
        ),
        Ok(_) => return Ok(()),
    };
    let with_ext = |ext: &str| path.with_extension(ext);
    write(&with_ext("actual.png"), actual)?;
    if diff.is_ok() {
        write(
            &with_ext("diff.png"),
            &diff_strip(&expected, actual, threshold),
        )?;
    }
    Err(format!(
        "snapshot {} mismatch: {failure}; see {}",
        path.display(),
        with_ext("diff.png").display()
    ))
}
