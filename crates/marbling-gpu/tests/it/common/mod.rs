//! Shared by the GPU integration tests: a renderer on any adapter, or a loud failure.

#![allow(dead_code)]

use marbling_core::{Design, Op};
use marbling_gpu::{GpuContext, GpuRenderer};
use marbling_testkit::gpu_or_skip;

/// A headless renderer on the best adapter (lavapipe here); `None` only where
/// `MARBLING_SKIP_GPU=1` lets a missing adapter skip (`marbling_testkit`).
pub fn renderer() -> Option<GpuRenderer> {
    let ctx = gpu_or_skip(GpuContext::new_headless())?;
    eprintln!("adapter: {}", ctx.describe());
    Some(GpuRenderer::new(ctx))
}

/// `design` with every comb and swirl `k` times as strong.
pub fn scaled(mut design: Design, k: f64) -> Design {
    for op in &mut design.ops {
        match op {
            Op::Tine(t) => t.alpha *= k,
            Op::Rake(r) => r.alpha *= k,
            Op::Wavy(w) => w.amplitude *= k,
            Op::Circular(c) => c.alpha *= k,
            Op::Vortex(v) => v.alpha *= k,
            Op::Comb(c) => c.alpha *= k,
            Op::Jiggle(j) => {
                j.along *= k;
                j.across *= k;
            }
            Op::Turn(t) => t.angle *= k,
            Op::Shift(t) => t.offset *= k,
            Op::Flow(f) => f.strength *= k,
            Op::Drop(_) | Op::Spray(_) | Op::Drops(_) | Op::Sprays(_) | Op::Stylus(_) => {}
        }
    }
    design
}

/// `design` with every parameter rounded to the nearest f32 (a relative perturbation
/// of at most 6e-8, the precision the GPU receives).
pub fn rounded_to_f32(mut design: Design) -> Design {
    let r = |v: &mut f64| *v = f64::from(*v as f32);
    let rp = |p: &mut marbling_core::Point| {
        r(&mut p.x);
        r(&mut p.y);
    };
    for op in &mut design.ops {
        match op {
            Op::Drop(d) => {
                rp(&mut d.center);
                r(&mut d.radius);
            }
            Op::Spray(s) => {
                rp(&mut s.center);
                r(&mut s.radius);
            }
            Op::Tine(t) => {
                rp(&mut t.origin);
                r(&mut t.direction.x);
                r(&mut t.direction.y);
                r(&mut t.alpha);
                r(&mut t.lambda);
            }
            Op::Rake(k) => {
                rp(&mut k.origin);
                r(&mut k.direction.x);
                r(&mut k.direction.y);
                r(&mut k.spacing);
                r(&mut k.alpha);
                r(&mut k.lambda);
            }
            Op::Wavy(w) => {
                r(&mut w.angle);
                r(&mut w.amplitude);
                r(&mut w.wavelength);
                r(&mut w.phase);
            }
            Op::Circular(c) => {
                rp(&mut c.center);
                r(&mut c.radius);
                r(&mut c.alpha);
                r(&mut c.lambda);
            }
            Op::Vortex(v) => {
                rp(&mut v.center);
                r(&mut v.alpha);
                r(&mut v.lambda);
            }
            Op::Shift(t) => {
                r(&mut t.offset.x);
                r(&mut t.offset.y);
            }
            Op::Turn(t) => {
                rp(&mut t.center);
                r(&mut t.angle);
            }
            Op::Comb(c) => {
                rp(&mut c.origin);
                r(&mut c.direction.x);
                r(&mut c.direction.y);
                c.tines = c.tines.iter().map(|&o| f64::from(o as f32)).collect();
                r(&mut c.alpha);
                r(&mut c.lambda);
            }
            Op::Drops(d) | Op::Sprays(d) => {
                d.centers = d
                    .centers
                    .iter()
                    .map(|p| {
                        marbling_core::Point::new(f64::from(p.x as f32), f64::from(p.y as f32))
                    })
                    .collect();
                d.radii = match &d.radii {
                    marbling_core::Radii::One(v) => marbling_core::Radii::One(f64::from(*v as f32)),
                    marbling_core::Radii::Each(l) => {
                        marbling_core::Radii::Each(l.iter().map(|&v| f64::from(v as f32)).collect())
                    }
                };
            }
            Op::Jiggle(j) => {
                r(&mut j.angle);
                r(&mut j.wavelength);
                r(&mut j.along);
                r(&mut j.across);
                r(&mut j.phase);
            }
            Op::Stylus(st) => {
                st.path = st
                    .path
                    .iter()
                    .map(|p| {
                        marbling_core::Point::new(f64::from(p.x as f32), f64::from(p.y as f32))
                    })
                    .collect();
                r(&mut st.wake);
            }
            Op::Flow(f) => {
                r(&mut f.strength);
                r(&mut f.time);
            }
        }
    }
    design
}
