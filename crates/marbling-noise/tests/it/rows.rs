//! The row path (`Renderer::png_row`, `render_rows`, `sample_grid`, through the row
//! kernels) equals the point path (`Renderer::intensity`/`color`, `Field::sample`) bit
//! for bit, for every example noise in examples/noise/ and a few layered and tiled specs.

use marbling_noise::{Depth, NoiseSpec, Renderer, noise_field, sample_grid};
use std::path::PathBuf;

/// Side of the compared images (small: every example at both paths).
const SIZE: u32 = 48;

/// Specs that reach the row kernels through products, layers, masks and tiling.
const EXTRA: &[&str] = &[
    r#"{"type":"perlin","frequency":0.31,"octaves":4,"seed":2,"tile":true}"#,
    r#"{"type":"worley","frequency":0.2,"feature":"f2","metric":"manhattan","seed":3,"tile":true}"#,
    r#"{"type":"product","inputs":[{"type":"perlin","frequency":0.05,"seed":1},{"type":"worley","frequency":0.1,"seed":2}]}"#,
];

fn specs() -> Vec<(String, NoiseSpec)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/noise");
    let mut out: Vec<(String, NoiseSpec)> = std::fs::read_dir(&dir)
        .map(|d| {
            d.filter_map(Result::ok)
                .map(|e| e.path())
                .collect::<Vec<_>>()
        })
        .unwrap_or_default()
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .filter_map(|p| {
            let text = std::fs::read_to_string(&p).ok()?;
            let spec = NoiseSpec::from_json(&text).ok()?;
            // Specs with data sets need them attached; the rest are enough here.
            Renderer::new(&spec, SIZE).ok()?;
            Some((p.display().to_string(), spec))
        })
        .collect();
    assert!(out.len() >= 20, "examples found: {}", out.len());
    for (i, json) in EXTRA.iter().enumerate() {
        let spec = NoiseSpec::from_json(json).unwrap_or_else(|e| panic!("extra {i}: {e}"));
        out.push((format!("extra {i}"), spec));
    }
    out
}

/// PNG row bytes from the per-point methods, as `png_row` wrote them before rows.
fn point_row(r: &Renderer, j: u32) -> Vec<u8> {
    let mut out = Vec::new();
    for i in 0..r.size() {
        let (x, y) = (i as f32 + 0.5, j as f32 + 0.5);
        let c = if r.greyscale() {
            [r.intensity(x, y); 3]
        } else {
            r.color(x, y)
        };
        let channels = if r.greyscale() { 1 } else { 3 };
        for &v in &c[..channels] {
            out.extend_from_slice(&((v.clamp(0.0, 1.0) * 65535.0).round() as u16).to_be_bytes());
        }
    }
    out
}

#[test]
fn rows_equal_points_for_every_example() {
    let mut report = Vec::new();
    for (name, spec) in specs() {
        let r = Renderer::new(&spec, SIZE).unwrap_or_else(|e| panic!("{name}: {e}"));
        for j in 0..SIZE {
            if r.png_row(j, Depth::Sixteen) != point_row(&r, j) {
                report.push(format!("{name}: row {j} differs"));
                break;
            }
        }
        if let (Some(grid), Some(f)) = (sample_grid(&spec, SIZE), noise_field(&spec, SIZE)) {
            let n = SIZE as usize;
            let differs = grid.iter().enumerate().any(|(k, &v)| {
                let want = f.sample((k % n) as f32 + 0.5, (k / n) as f32 + 0.5);
                v.to_bits() != want.to_bits() && !(v.is_nan() && want.is_nan())
            });
            if differs {
                report.push(format!("{name}: sample_grid differs"));
            }
        }
    }
    assert!(report.is_empty(), "{report:#?}");
}

#[test]
fn the_row_comparison_notices_another_noise() {
    let a = NoiseSpec::from_json(r#"{"type":"worley","frequency":0.05,"seed":1}"#);
    let b = NoiseSpec::from_json(r#"{"type":"worley","frequency":0.05,"seed":2}"#);
    let (Ok(a), Ok(b)) = (a, b) else {
        panic!("specs parse");
    };
    let (ra, rb) = (Renderer::new(&a, SIZE), Renderer::new(&b, SIZE));
    let (Ok(ra), Ok(rb)) = (ra, rb) else {
        panic!("renderers");
    };
    assert_ne!(ra.png_row(7, Depth::Sixteen), point_row(&rb, 7));
}
