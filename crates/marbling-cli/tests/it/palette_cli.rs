//! `marbling palette`: a `.gpl`, a picture or hex text in, a `.gpl` out; a bad file is
//! named with its line.

use crate::common::marbling;
use marbling_core::RgbaImage;

fn temp(name: &str) -> String {
    std::env::temp_dir()
        .join(format!("marbling-palette-{}-{name}", std::process::id()))
        .to_string_lossy()
        .into_owned()
}

#[test]
fn palettes_come_from_gpl_pictures_and_hex_text_and_bad_files_are_named() {
    // Hex text in, a .gpl out, which reads back as the same colours.
    let out = temp("pasted.gpl");
    let o = marbling(&["palette", "-", "-o", &out], Some("#1d3557, e63946\n#abc"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("3 colours: #1d3557 #e63946 #aabbcc"));
    let gpl = std::fs::read_to_string(&out).expect("the .gpl");
    assert!(
        gpl.starts_with("GIMP Palette\nName: palette\nColumns: 3\n"),
        "{gpl}"
    );
    let again = marbling(&["palette", &out], None);
    assert!(again.status.success());
    assert_eq!(
        String::from_utf8_lossy(&again.stdout),
        gpl,
        "a .gpl read back is the same file"
    );

    // A picture: half indigo, a quarter red, a quarter paper → those three, most first.
    let mut img = RgbaImage::filled(40, 20, [29, 53, 87, 255]);
    for y in 0..20 {
        for x in 20..40 {
            let c = if x < 30 {
                [230, 57, 70, 255]
            } else {
                [244, 236, 216, 255]
            };
            let i = ((y * 40 + x) * 4) as usize;
            img.pixels[i..i + 4].copy_from_slice(&c);
        }
    }
    let png = temp("three.png");
    std::fs::write(&png, img.to_png().expect("png")).expect("write");
    let o = marbling(&["palette", &png, "--colors", "3"], None);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    let lines: Vec<&str> = text.lines().skip(4).collect();
    assert_eq!(
        lines,
        [
            " 29  53  87\t#1d3557",
            "230  57  70\t#e63946",
            "244 236 216\t#f4ecd8"
        ],
        "{text}"
    );

    // Bad input: named, non-zero, no panic.
    let bad = temp("bad.gpl");
    std::fs::write(&bad, "GIMP Palette\nName: x\n10 20 30\n300 0 0 Too red\n").expect("write");
    for (args, needle) in [
        (
            vec!["palette", bad.as_str()],
            "bad.gpl': line 4: expected three numbers 0–255",
        ),
        (
            vec!["palette", png.as_str(), "--colors", "11"],
            "a picture gives 2 to 10 colours, not 11",
        ),
        (
            vec!["palette", "/nonexistent/p.gpl"],
            "cannot read '/nonexistent/p.gpl'",
        ),
    ] {
        let o = marbling(&args, None);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            !o.status.success() && err.contains(needle),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
    let o = marbling(&["palette", "-"], Some("#123456 #zzzzzz"));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("colour 2: \"#zzzzzz\" is not a hex colour")
    );
}
