//! `marbling validate`: a one-line summary, or every error with its path.

use crate::input::{display_name, read_design};
use anyhow::Result;
use clap::Args;

/// Arguments of `marbling validate`.
#[derive(Args)]
pub struct ValidateArgs {
    /// Design document (JSON); `-` reads standard input.
    design: String,
}

/// Prints `NAME: valid, W×H, N ops: a drop, b tine, …`, for drop patterns `(M counted
/// toward the cap)`, for styli their sub-steps, and for schema v2 `; perlin noise
/// background, paper-grain, …`.
pub fn run(args: &ValidateArgs) -> Result<()> {
    let d = read_design(&args.design)?;
    let counts: Vec<String> = d
        .op_counts()
        .iter()
        .map(|(t, n)| format!("{n} {t}"))
        .collect();
    let mut detail = if counts.is_empty() {
        String::new()
    } else {
        format!(": {}", counts.join(", "))
    };
    if d.counted_ops() != d.ops.len() {
        detail += &format!(
            " ({} counted toward the {}-op cap: every drop of a pattern counts)",
            d.counted_ops(),
            marbling_core::MAX_OPS
        );
    }
    let sub_steps: usize = d
        .ops
        .iter()
        .map(|op| match op {
            marbling_core::Op::Stylus(s) => s.sub_steps() * s.tip_count(),
            _ => 0,
        })
        .sum();
    if sub_steps > 0 {
        detail += &format!("; styli: {sub_steps} sub-steps × tips");
    }
    let mut v2 = Vec::new();
    if let Some(bg) = &d.background_noise {
        v2.push(format!("{} noise background", bg.noise.type_name()));
    }
    if let Some(img) = &d.background_image {
        let p = img.pixels();
        v2.push(format!(
            "{}×{} image background ({})",
            p.width,
            p.height,
            img.fit.name()
        ));
    }
    v2.extend(d.overlays.iter().map(|o| o.kind.name().to_owned()));
    let surface = if v2.is_empty() {
        String::new()
    } else {
        format!("; {}", v2.join(", "))
    };
    println!(
        "{}: valid, {}×{}, {} ops{detail}{surface}",
        display_name(&args.design),
        d.width,
        d.height,
        d.ops.len()
    );
    Ok(())
}
