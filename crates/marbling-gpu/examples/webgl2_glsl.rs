//! Writes the GLSL ES 3.00 that WebGL2 compiles for exact-renderer modules, as
//! `DIR/NAME.vert` and `DIR/NAME.frag` (naga's WebGL2 writer, as wgpu's GL backend uses
//! it), for timing their compile in a browser (`tests/browser/diagnose/compile-time.mjs`).
//!
//! `cargo run -p marbling-gpu --example webgl2_glsl -- DIR` writes `plain` and each noise
//! type's surface variant; `… -- DIR NAME FILE.wgsl` translates one WGSL file.

use marbling_gpu::shaders::ExactVariant;
use marbling_noise::wgsl::{NoiseKind, NoiseKinds};
use marbling_testkit::wgsl::webgl2_glsl;
use std::path::Path;

/// Writes `source`'s `vs_main` and `fs_main` to `dir/name.vert` and `dir/name.frag`.
fn write(dir: &Path, name: &str, source: &str) -> Result<(), String> {
    for (stage, entry, ext) in [
        (naga::ShaderStage::Vertex, "vs_main", "vert"),
        (naga::ShaderStage::Fragment, "fs_main", "frag"),
    ] {
        let out = webgl2_glsl(source, stage, entry).map_err(|e| format!("{name}: {e}"))?;
        let path = dir.join(format!("{name}.{ext}"));
        std::fs::write(&path, out).map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

fn run(args: &[String]) -> Result<(), String> {
    let [dir, rest @ ..] = args else {
        return Err("usage: webgl2_glsl DIR [NAME FILE.wgsl]".to_owned());
    };
    let dir = Path::new(dir);
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    if let [name, file] = rest {
        let source = std::fs::read_to_string(file).map_err(|e| format!("{file}: {e}"))?;
        return write(dir, name, &source);
    }
    write(dir, "plain", &ExactVariant::PLAIN.render_wgsl())?;
    for kind in NoiseKind::ALL {
        let variant = ExactVariant {
            noises: NoiseKinds::NONE.with(kind),
            ..ExactVariant::PLAIN
        };
        write(dir, kind.name(), &variant.render_wgsl())?;
    }
    Ok(())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if let Err(e) = run(&args) {
        eprintln!("webgl2_glsl: {e}");
        std::process::exit(1);
    }
}
