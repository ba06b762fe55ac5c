//! Writes the gallery's prerendered thumbnails, `web/gallery-thumbnails.jpg`
//! (src/gpu/gallery_atlas.rs): `make gallery` runs it after a pattern or gallery entry changes.

use marbling_app::gallery::entries;
use marbling_app::gallery_atlas::{FILE_NAME, encode, render_atlas};
use std::path::Path;

fn main() -> Result<(), String> {
    let designs = entries()
        .iter()
        .map(|e| e.design().map_err(|err| format!("{}: {err}", e.id)))
        .collect::<Result<Vec<_>, _>>()?;
    let atlas = render_atlas(&designs, marbling_app::canvas_gpu::SURROUND)?;
    let bytes = encode(&atlas)?;
    let out = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../web")
        .join(FILE_NAME);
    std::fs::write(&out, &bytes).map_err(|e| format!("{}: {e}", out.display()))?;
    println!(
        "{}: {} thumbnails, {} bytes",
        out.display(),
        designs.len(),
        bytes.len()
    );
    Ok(())
}
