//! Curl divergence, fBm range, determinism by seed and tileability of every noise.

use marbling_noise::{Curl, Fbm, FbmParams, NoiseSpec, sample_grid};

fn spec(text: &str) -> NoiseSpec {
    NoiseSpec::from_json(text).expect("valid spec")
}

#[test]
fn curl_is_divergence_free() {
    let f = 1.0 / 48.0;
    let curl = Curl::new(Fbm::new(FbmParams {
        frequency: f,
        octaves: 3,
        seed: 5,
        ..FbmParams::default()
    }));
    // Fourth-order central differences of the analytic velocity, step h pixels.
    let h = 0.25_f32;
    let d =
        |g: &dyn Fn(f32) -> f32| (8.0 * (g(h) - g(-h)) - (g(2.0 * h) - g(-2.0 * h))) / (12.0 * h);
    let (mut div2, mut jac2, mut v2) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut worst = 0.0_f64;
    for j in 0..64 {
        for i in 0..64 {
            let (x, y) = (i as f32 * 3.7 + 0.3, j as f32 * 3.1 + 0.6);
            let dvx_dx = d(&|e| curl.velocity(x + e, y)[0]);
            let dvy_dy = d(&|e| curl.velocity(x, y + e)[1]);
            let dvx_dy = d(&|e| curl.velocity(x, y + e)[0]);
            let dvy_dx = d(&|e| curl.velocity(x + e, y)[1]);
            let div = f64::from(dvx_dx + dvy_dy);
            div2 += div * div;
            jac2 += f64::from(dvx_dx.powi(2) + dvy_dy.powi(2) + dvx_dy.powi(2) + dvy_dx.powi(2));
            let [vx, vy] = curl.velocity(x, y);
            v2 += f64::from(vx * vx + vy * vy);
            worst = worst.max(div.abs());
        }
    }
    let c = 64.0 * 64.0;
    let (div_rms, jac_rms, v_rms) = ((div2 / c).sqrt(), (jac2 / c).sqrt(), (v2 / c).sqrt());
    // Divergence per base wavelength relative to |v|: (|∇·v| / f) / |v|.
    let rel = div_rms / f64::from(f) / v_rms;
    println!(
        "curl: rms div {div_rms:.3e}, rms |J| {jac_rms:.3e}, rms |v| {v_rms:.3e}, rel {rel:.2e}, worst {worst:.2e}"
    );
    assert!(rel < 1e-3, "relative divergence {rel}");
    assert!(div_rms < 1e-3 * jac_rms);
}

#[test]
fn fbm_range_and_spec_statistics() {
    let fbm = Fbm::new(FbmParams {
        frequency: 1.0 / 64.0,
        octaves: 5,
        seed: 1,
        ..FbmParams::default()
    });
    let (mut lo, mut hi) = (f32::MAX, f32::MIN);
    for j in 0..256 {
        for i in 0..256 {
            let v = fbm.eval_bounded(i as f32 * 2.0, j as f32 * 2.0);
            lo = lo.min(v);
            hi = hi.max(v);
        }
    }
    assert!(
        (-1.0..=-0.35).contains(&lo) && (0.35..=1.0).contains(&hi),
        "{lo} {hi}"
    );
    for text in [
        r#"{"type":"perlin","frequency":0.05,"octaves":5,"seed":2}"#,
        r#"{"type":"value","frequency":0.05,"octaves":4,"seed":2}"#,
        r#"{"type":"worley","frequency":0.06,"feature":"f2-f1","metric":"manhattan"}"#,
        r#"{"type":"white","seed":3}"#,
        r#"{"type":"curl","frequency":0.03,"octaves":2,"component":"x"}"#,
        r#"{"type":"paper","length":10,"width":1.5,"density":0.3}"#,
        r#"{"type":"gabor","kind":"isotropic","frequency":0.12,"bandwidth":0.08}"#,
    ] {
        let v = sample_grid(&spec(text), 256).expect("noise");
        let mean = v.iter().map(|&x| f64::from(x)).sum::<f64>() / v.len() as f64;
        let var = v
            .iter()
            .map(|&x| (f64::from(x) - mean).powi(2))
            .sum::<f64>()
            / v.len() as f64;
        println!("{text}: mean {mean:.3} var {var:.3}");
        assert!(
            mean.abs() < 0.25 && (0.6..1.5).contains(&var),
            "{text}: {mean} {var}"
        );
    }
}

#[test]
fn deterministic_by_seed() {
    for (a, b) in [
        (
            r#"{"type":"gabor","frequency":0.1,"bandwidth":0.06,"seed":1}"#,
            r#"{"type":"gabor","frequency":0.1,"bandwidth":0.06,"seed":2}"#,
        ),
        (
            r#"{"type":"perlin","frequency":0.05,"octaves":3,"seed":1}"#,
            r#"{"type":"perlin","frequency":0.05,"octaves":3,"seed":2}"#,
        ),
        (
            r#"{"type":"canvas","length":12,"width":2,"density":0.2,"seed":1}"#,
            r#"{"type":"canvas","length":12,"width":2,"density":0.2,"seed":2}"#,
        ),
        (
            r#"{"type":"worley","frequency":0.05,"seed":1}"#,
            r#"{"type":"worley","frequency":0.05,"seed":2}"#,
        ),
    ] {
        let x = sample_grid(&spec(a), 64);
        assert_eq!(x, sample_grid(&spec(a), 64), "{a}");
        assert_ne!(x, sample_grid(&spec(b), 64), "{a}");
    }
}

#[test]
fn tileable_variants_wrap() {
    let n = 96.0_f32;
    for text in [
        r#"{"type":"perlin","frequency":0.043,"octaves":4,"tile":true}"#,
        r#"{"type":"value","frequency":0.043,"octaves":3,"tile":true}"#,
        r#"{"type":"worley","frequency":0.05,"feature":"f2","tile":true}"#,
        r#"{"type":"white","tile":true}"#,
        r#"{"type":"curl","frequency":0.03,"tile":true}"#,
        r#"{"type":"gabor","frequency":0.1,"bandwidth":0.07,"orientation":0.4,"tile":true}"#,
        r#"{"type":"gabor","kind":"isotropic","frequency":0.1,"bandwidth":0.07,"tile":true}"#,
        r#"{"type":"gabor","kind":"random-phase","frequency":0.1,"bandwidth":0.07,"tile":true,
            "orientation_field":{"noise":{"type":"perlin","frequency":0.02},"amount":1}}"#,
        r#"{"type":"gabor","frequency":0.1,"bandwidth":0.01,"impulses":200,"tile":true}"#,
        r#"{"type":"paper","length":12,"width":1.5,"density":0.2,"tile":true,"impurities":{"density":0.002}}"#,
        r#"{"type":"canvas","length":9,"width":2,"density":0.2,"tile":true}"#,
    ] {
        let f = marbling_noise::noise_field(&spec(text), n as u32).expect("field");
        let mut worst = 0.0_f32;
        for k in 0..200 {
            // Off pixel boundaries, so white noise cannot switch pixel by rounding.
            let (x, y) = (
                (k * 37 % 96) as f32 + 0.3 + (k % 5) as f32 * 0.1,
                (k * 53 % 96) as f32 + 0.6 - (k % 3) as f32 * 0.1,
            );
            let a = f.sample(x, y);
            worst = worst.max((a - f.sample(x + n, y)).abs());
            worst = worst.max((a - f.sample(x, y + n)).abs());
            worst = worst.max((a - f.sample(x - n, y - n)).abs());
        }
        assert!(worst < 2e-3, "{text}: {worst}");
        // The left edge continues the right edge: the step across the seam is like the
        // steps between neighbouring columns inside the image (averaged over columns).
        let col = |x: f32| -> f32 {
            (0..96)
                .map(|j| (f.sample(x + 1.0, j as f32 + 0.5) - f.sample(x, j as f32 + 0.5)).abs())
                .sum()
        };
        let seam = col(n - 0.5);
        let inner = (0..95).map(|i| col(i as f32 + 0.5)).sum::<f32>() / 95.0;
        let within = seam < 3.0 * inner + 1e-3 || text.contains("white");
        assert!(within, "{text}: seam {seam} inner {inner}");
    }
}

#[test]
fn spline_decay_mean_intensity_tracks_value_on_gabor() {
    // Khlebnikov et al. 2013: on random-phase Gabor noise the mean of D(n) equals v.
    let n = sample_grid(
        &spec(r#"{"type":"gabor","kind":"random-phase","frequency":0.1,"orientation":0.4,"bandwidth":0.06,"seed":12}"#),
        256,
    )
    .expect("noise");
    let table = marbling_noise::SplineDecayTable::new();
    for v in [0.1_f32, 0.3, 0.5, 0.7, 0.9] {
        let d = table.decay(v);
        let mean = n.iter().map(|&x| f64::from(d.apply(x))).sum::<f64>() / n.len() as f64;
        println!("v {v}: mean intensity {mean:.3}");
        assert!((mean - f64::from(v)).abs() < 0.04, "v {v}: mean {mean}");
    }
}

#[test]
fn cross_hatch_is_the_product_of_two_hatchings() {
    let a = r#"{"type":"gabor","frequency":0.1,"orientation":0.785,"bandwidth":0.04,"seed":1,"transfer":{"type":"threshold","threshold":0.5,"width":0.6,"invert":true}}"#;
    let b = r#"{"type":"gabor","frequency":0.1,"orientation":-0.785,"bandwidth":0.04,"seed":2,"transfer":{"type":"threshold","threshold":0.5,"width":0.6,"invert":true}}"#;
    let product = format!(r#"{{"type":"product","inputs":[{a},{b}]}}"#);
    let r = |t: &str| marbling_noise::Renderer::new(&spec(t), 64).expect("size");
    let (ra, rb, rp) = (r(a), r(b), r(&product));
    for k in 0..64 {
        let (x, y) = (k as f32 + 0.5, (k * 7 % 64) as f32 + 0.5);
        let expected = ra.intensity(x, y) * rb.intensity(x, y);
        assert!((rp.intensity(x, y) - expected).abs() < 1e-6);
    }
}

/// `"tile": N` repeats every N pixels whatever the output size.
#[test]
fn a_tile_period_in_pixels_repeats_at_any_size() {
    for text in [
        r#"{"type":"perlin","frequency":0.03,"octaves":3,"seed":2,"tile":48}"#,
        r#"{"type":"worley","frequency":0.05,"seed":2,"tile":48}"#,
        r#"{"type":"gabor","frequency":0.1,"bandwidth":0.08,"impulses":16,"seed":2,"tile":48}"#,
    ] {
        let s = spec(text);
        let r = marbling_noise::Renderer::new(&s, 200).expect("size");
        for (x, y) in [(3.5, 7.5), (20.25, 40.0), (47.0, 1.0)] {
            let a = r.intensity(x, y);
            for (dx, dy) in [(48.0, 0.0), (0.0, 96.0), (144.0, 48.0)] {
                let b = r.intensity(x + dx, y + dy);
                assert!(
                    (a - b).abs() < 1e-4,
                    "{text}: ({x}, {y}) + ({dx}, {dy}): {a} vs {b}"
                );
            }
        }
        // Not every shift repeats: the comparison can fail.
        assert!(
            (r.intensity(3.5, 7.5) - r.intensity(27.5, 7.5)).abs() > 1e-4,
            "{text}"
        );
    }
}
