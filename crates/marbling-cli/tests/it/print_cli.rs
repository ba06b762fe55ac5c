//! `marbling render --print`: the pixel size is mm / 25.4 × DPI, the PNG carries the
//! DPI, the trimmed sheet is the plain render, and the bleed is more of the design.

use crate::common::marbling;
use marbling_core::RgbaImage;

/// 400×200 design px; a drop centred on the left edge, so ink lies past the sheet.
const EDGE_DROP: &str = r##"{"version":1,"width":400,"height":200,"background":"#f3ead7","ops":[
  {"type":"drop","center":[0,100],"radius":60,"color":"#1d3557"},
  {"type":"drop","center":[250,90],"radius":40,"color":"#e63946"},
  {"type":"tine","origin":[0,120],"direction":[1,0],"alpha":30,"lambda":12}]}"##;

fn temp(name: &str) -> String {
    std::env::temp_dir()
        .join(format!("marbling-print-{}-{name}", std::process::id()))
        .to_string_lossy()
        .into_owned()
}

/// The PNG's pixels and its `pHYs` (pixels per metre), if any.
fn read_png(path: &str) -> (RgbaImage, Option<u32>) {
    let bytes = std::fs::read(path).expect("read the PNG");
    let mut reader = png::Decoder::new(std::io::Cursor::new(&bytes))
        .read_info()
        .expect("a PNG");
    let ppm = reader.info().pixel_dims.map(|d| {
        assert_eq!(d.unit, png::Unit::Meter);
        assert_eq!(d.xppu, d.yppu);
        d.xppu
    });
    let mut buf = vec![0; reader.output_buffer_size().expect("a size")];
    let info = reader.next_frame(&mut buf).expect("the pixels");
    buf.truncate(info.buffer_size());
    // The print is RGB, a plain render RGBA.
    let pixels = match info.color_type {
        png::ColorType::Rgb => buf
            .chunks_exact(3)
            .flat_map(|c| [c[0], c[1], c[2], 255])
            .collect(),
        png::ColorType::Rgba => buf,
        other => panic!("unexpected colour type {other:?}"),
    };
    (
        RgbaImage {
            width: info.width,
            height: info.height,
            pixels,
        },
        ppm,
    )
}

#[test]
fn a_print_is_mm_over_25_4_times_dpi_carries_its_dpi_and_bleeds_the_design() {
    let design = temp("edge.json");
    std::fs::write(&design, EDGE_DROP).expect("write");
    // 40×20 mm at 254 DPI is 400×200 px: scale 1, so the trim is the plain render; the
    // 2 mm bleed is 20 px more of the design on every side.
    let print = temp("print.png");
    let o = marbling(
        &[
            "render", &design, "-o", &print, "--print", "40x20mm", "--dpi", "254", "--bleed", "2mm",
        ],
        None,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (img, ppm) = read_png(&print);
    assert_eq!((img.width, img.height), (440, 240));
    assert_eq!(ppm, Some(10_000), "254 DPI = 10,000 px/m");
    let plain = temp("plain.png");
    let o = marbling(&["render", &design, "-o", &plain], None);
    assert!(o.status.success());
    let (flat, none) = read_png(&plain);
    assert_eq!(none, None, "a plain render has no pHYs");
    let mut off = 0;
    for y in 0..200 {
        for x in 0..400 {
            let a = flat.pixel(x, y);
            let b = img.pixel(x + 20, y + 20);
            off += usize::from(a[..3] != b[..3]);
        }
    }
    assert_eq!(off, 0, "pixels of the trim differ from the plain render");
    // The bleed is the design going on: the left drop's ink fills the left bleed beside
    // its centre, where a border would be one colour all round.
    let ink = [0x1d, 0x35, 0x57];
    assert_eq!(
        img.pixel(5, 120)[..3],
        ink,
        "the drop reaches into the bleed"
    );
    assert_ne!(
        img.pixel(5, 5)[..3],
        ink,
        "the corner of the bleed is paper"
    );

    // A preset turns to the design (landscape) and the pixel size follows the DPI.
    let a4 = temp("a4.png");
    let o = marbling(
        &[
            "render", &design, "-o", &a4, "--print", "A4", "--dpi", "20", "--aa", "none",
        ],
        None,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let (img, ppm) = read_png(&a4);
    // 297 mm / 25.4 × 20 = 233.9 → 234; 210 → 165.4 → 165; 20 DPI = 787.4 → 787 px/m.
    assert_eq!((img.width, img.height, ppm), (234, 165, Some(787)));

    // Bad input is named.
    for (args, needle) in [
        (
            vec!["--print", "297x210"],
            "expected a sheet size like 297x210mm",
        ),
        (
            vec!["--print", "A4", "--dpi", "5"],
            "the DPI must be 10 to 4800",
        ),
        (
            vec!["--print", "A4", "--bleed", "90mm"],
            "the bleed must be 0 to 50 mm",
        ),
        (
            vec!["--print", "A4", "--backend", "gpu"],
            "--print renders with the exact CPU walk",
        ),
        (vec!["--dpi", "300"], "--print"),
    ] {
        let mut all = vec!["render", design.as_str(), "-o", a4.as_str()];
        all.extend(args);
        let o = marbling(&all, None);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success() && err.contains(needle),
            "{all:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
}
