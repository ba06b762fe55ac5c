//! Khlebnikov et al. (2013)'s data-driven Gabor: a data image's first channel sets the local frequency
//! (F₀·2^(amount·v)) and its second the orientation (ω₀ + amount·v). Measured by a DFT
//! of two 64² windows: the spectral peak of each follows its region's data.

use marbling_noise::{DataGrid, NoiseSpec, Renderer};
use std::f32::consts::PI;
use std::sync::Arc;

const N: u32 = 256;
const W: usize = 64;

/// A 2×1 RGB PNG: red drives the frequency, green the orientation.
fn two_region_png(left: [u8; 2], right: [u8; 2]) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut enc = png::Encoder::new(&mut bytes, 2, 1);
    enc.set_color(png::ColorType::Rgb);
    let mut w = enc.write_header().expect("header");
    w.write_image_data(&[left[0], left[1], 0, right[0], right[1], 0])
        .expect("pixels");
    drop(w);
    bytes
}

fn spec(png: Vec<u8>) -> NoiseSpec {
    let mut spec = NoiseSpec::from_json(
        r#"{"type":"gabor","kind":"anisotropic","frequency":0.03125,"orientation":0,
            "bandwidth":0.02,"impulses":64,"seed":3,
            "frequency_field":{"data":"regions.png","channel":1,"amount":2},
            "orientation_field":{"data":"regions.png","channel":2,"amount":1.5707964}}"#,
    )
    .expect("valid");
    let grid = Arc::new(DataGrid::from_png(&png).expect("png"));
    spec.attach_data(&mut |name| {
        assert_eq!(name, "regions.png");
        Ok(grid.clone())
    })
    .expect("attached");
    spec
}

/// The (kx, ky) of the strongest DFT bin (cycles per window, ky ∈ [−W/2, W/2]) of a
/// Hann-windowed W² window at column `x0`, mean removed.
fn peak(r: &Renderer, x0: u32) -> (f32, f32) {
    let hann = |i: usize| 0.5 - 0.5 * (2.0 * PI * (i as f32 + 0.5) / W as f32).cos();
    let mut v = vec![0f32; W * W];
    for j in 0..W {
        for i in 0..W {
            v[j * W + i] = r.intensity((x0 as usize + i) as f32 + 0.5, (96 + j) as f32 + 0.5);
        }
    }
    let mean = v.iter().sum::<f32>() / v.len() as f32;
    for j in 0..W {
        for i in 0..W {
            v[j * W + i] = (v[j * W + i] - mean) * hann(i) * hann(j);
        }
    }
    let half = (W / 2) as i32;
    let mut best = (0.0f32, (0.0, 0.0));
    for ky in -half..=half {
        for kx in 1..=half {
            let (mut re, mut im) = (0f32, 0f32);
            for j in 0..W {
                for i in 0..W {
                    let a = -2.0 * PI * (kx as f32 * i as f32 + ky as f32 * j as f32) / W as f32;
                    re += v[j * W + i] * a.cos();
                    im += v[j * W + i] * a.sin();
                }
            }
            let p = re * re + im * im;
            if p > best.0 {
                best = (p, (kx as f32, ky as f32));
            }
        }
        // kx = 0 with ky > 0 covers vertical frequency vectors.
        if ky > 0 {
            let (mut re, mut im) = (0f32, 0f32);
            for j in 0..W {
                for i in 0..W {
                    let a = -2.0 * PI * ky as f32 * j as f32 / W as f32;
                    re += v[j * W + i] * a.cos();
                    im += v[j * W + i] * a.sin();
                }
            }
            let p = re * re + im * im;
            if p > best.0 {
                best = (p, (0.0, ky as f32));
            }
        }
    }
    best.1
}

#[test]
fn the_local_spectral_peak_follows_the_data() {
    // Left: v = 0 (F₀ = 1/32, 2 cycles per window, ω = 0: horizontal frequency vector);
    // right: v = 1 (F₀·4 = 8 cycles per window, ω = π/2: vertical).
    let r = Renderer::new(&spec(two_region_png([0, 0], [255, 255])), N).expect("size");
    let (lx, ly) = peak(&r, 0);
    let (rx, ry) = peak(&r, N - W as u32);
    let left_radius = lx.hypot(ly);
    let right_radius = rx.hypot(ry);
    assert!((1.0..=3.0).contains(&left_radius), "left peak ({lx}, {ly})");
    assert!(ly.abs() <= 1.0, "left orientation: peak ({lx}, {ly})");
    assert!(
        (6.0..=10.0).contains(&right_radius),
        "right peak ({rx}, {ry})"
    );
    assert!(rx.abs() <= 1.5, "right orientation: peak ({rx}, {ry})");

    // The measure tells the regions apart only when the data differs: with the same data
    // on both sides, both peaks sit at the left's frequency and orientation.
    let same = Renderer::new(&spec(two_region_png([0, 0], [0, 0])), N).expect("size");
    let (sx, sy) = peak(&same, N - W as u32);
    assert!(
        sx.hypot(sy) <= 3.0 && sy.abs() <= 1.0,
        "constant data: ({sx}, {sy})"
    );
}

#[test]
fn specs_naming_data_refuse_to_render_until_it_is_attached() {
    let spec = NoiseSpec::from_json(
        r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,
            "orientation_field":{"data":"wind.png","channel":2,"amount":3}}"#,
    )
    .expect("valid");
    let e = Renderer::new(&spec, 16).err().expect("not attached");
    assert_eq!(e.to_string(), "data 'wind.png' is not loaded");
    let mut spec = spec;
    let grey = DataGrid::from_csv("0,1\n", "h").expect("csv");
    let e = spec
        .attach_data(&mut |_| Ok(Arc::new(grey.clone())))
        .expect_err("one channel");
    assert_eq!(
        e.to_string(),
        "channel: 'wind.png' has 1 channels, got channel 2"
    );
    // The built-in weather needs no attaching.
    let weather = NoiseSpec::from_json(
        r#"{"type":"gabor","frequency":0.05,"bandwidth":0.05,
            "orientation_field":{"data":"weather","channel":2,"amount":3}}"#,
    )
    .expect("valid");
    assert!(Renderer::new(&weather, 16).is_ok());
}
