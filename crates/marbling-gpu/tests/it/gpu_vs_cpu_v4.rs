//! Schema v4's flow on the GPU against the f64 CPU reference: random designs (combs at
//! 0.3 strength, as tests/it/gpu_vs_cpu.rs) with flows along Perlin and value noise
//! between their ops, within 0.5 % of pixels, and the comparison shown to see a flow
//! that runs 30 % too long.

use marbling_core::compare::compare;
use marbling_core::synth::{Mix, random_design};
use marbling_core::{Antialias, Design, Flow, Op, RenderOptions, render};
use marbling_noise::{Basis, FbmParams};

/// A channel difference above this counts as a differing pixel (out of 255).
const THRESHOLD: u8 = 8;

fn flow(k: u32, time: f64) -> Op {
    Op::Flow(Flow {
        noise: FbmParams {
            basis: if k.is_multiple_of(2) {
                Basis::Perlin
            } else {
                Basis::Value
            },
            frequency: 1.0 / (40.0 + 20.0 * k as f32),
            octaves: 1 + k % 3,
            seed: 11 + k,
            ..FbmParams::default()
        },
        strength: 12.0,
        time,
    })
}

/// A random design of `ops` ops with a flow after every third of them (drop-heavy, so
/// the sheet is full of ink edges for the flows to move).
fn design(i: u64, ops: usize) -> Design {
    let mix = [Mix::DropHeavy, Mix::DropHeavy, Mix::Mixed][i as usize % 3];
    let mut d = random_design(400 + i, 120, 90, ops, mix);
    for op in &mut d.ops {
        match op {
            Op::Tine(t) => t.alpha *= 0.3,
            Op::Rake(r) => r.alpha *= 0.3,
            Op::Wavy(w) => w.amplitude *= 0.3,
            Op::Circular(c) => c.alpha *= 0.3,
            Op::Vortex(v) => v.alpha *= 0.3,
            _ => {}
        }
    }
    for k in (1..=3).rev() {
        let at = ops * k / 3;
        d.ops.insert(
            at,
            flow(i as u32 + k as u32, if k == 2 { -0.8 } else { 1.0 }),
        );
    }
    d
}

#[test]
fn flows_in_random_designs_match_the_cpu() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    for (i, ops, aa) in [
        (0, 30, Antialias::None),
        (1, 60, Antialias::None),
        (2, 120, Antialias::Rgss),
    ] {
        let d = design(i, ops);
        assert_eq!(d.version(), 4);
        let opts = RenderOptions {
            scale: 1.0,
            antialias: aa,
        };
        let c = render(&d, &opts).expect("CPU render");
        let g = gpu.render(&d, &opts).expect("GPU render");
        let r = compare(&c, &g, THRESHOLD).expect("same size");
        println!("flow design {i}, {ops} ops, aa {}: {r:?}", aa.name());
        assert!(r.fraction() <= 0.005, "design {i}: {r:?}");
        // The flows matter: without them a tenth of the pixels or more change.
        let mut still = d.clone();
        still.ops.retain(|op| !op.is_v4());
        let s = compare(&c, &render(&still, &opts).expect("CPU"), THRESHOLD).expect("size");
        assert!(
            s.fraction() > 0.1,
            "design {i}: the flows moved little: {s:?}"
        );
    }
}

#[test]
fn a_flow_that_runs_longer_fails_the_comparison() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let d = design(1, 60);
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::None,
    };
    let c = render(&d, &opts).expect("CPU render");
    let mut longer = d.clone();
    for op in &mut longer.ops {
        if let Op::Flow(f) = op {
            f.time *= 1.3;
        }
    }
    let g = gpu.render(&longer, &opts).expect("GPU render");
    let r = compare(&c, &g, THRESHOLD).expect("same size");
    println!("flows 30 % longer: {r:?}");
    assert!(r.fraction() > 0.02, "{r:?}");
}

/// A looping turbulence of a drop design (`Turbulence` of marbling-core).
fn turbulence() -> (Design, marbling_core::turbulence::Turbulence) {
    let d = design(0, 30);
    let Op::Flow(f) = flow(2, 1.0) else {
        unreachable!("flow() makes flows");
    };
    let t = marbling_core::turbulence::Turbulence {
        noise: f.noise,
        strength: 12.0,
        period: 3.0,
    };
    (d, t)
}

/// Each GPU sample walks back through both layers' flows and blends them as the CPU
/// does, at a time when both layers show (weights ⅓ and ⅔) and when one does; a frame a
/// tenth of a period later differs (so the comparison can tell frames apart).
#[test]
fn turbulence_frames_match_the_cpu() {
    let Some(gpu) = crate::common::renderer() else {
        return;
    };
    let (d, turb) = turbulence();
    let opts = RenderOptions {
        scale: 1.0,
        antialias: Antialias::Rgss,
    };
    for t in [1.0, 0.0, 4.0] {
        let c = turb.render(&d, t, &opts).expect("CPU turbulence");
        let g = gpu
            .render_turbulence(&d, &turb, t, &opts)
            .expect("GPU turbulence");
        let r = compare(&c, &g, THRESHOLD).expect("same size");
        println!("turbulence at t = {t}: {r:?}");
        assert!(r.fraction() <= 0.005, "t = {t}: {r:?}");
    }
    let c = turb.render(&d, 1.0, &opts).expect("CPU turbulence");
    let later = gpu
        .render_turbulence(&d, &turb, 1.3, &opts)
        .expect("GPU turbulence");
    let r = compare(&c, &later, THRESHOLD).expect("same size");
    println!("turbulence a tenth of a period later: {r:?}");
    assert!(r.fraction() > 0.02, "{r:?}");
}
