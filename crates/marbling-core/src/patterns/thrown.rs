//! Patterns made by throwing colours only, or thrown and then shaken: stone, Italian
//! hair-vein, Turkish spot, French shell, Stormont, Spanish wave, West End.

use super::{Maker, Pattern, rgb};
use crate::{Op, Point, Radii, Tine};

pub(super) const PATTERNS: [Pattern; 7] = [
    Pattern {
        id: "stone",
        name: "Stone (battal)",
        history: "The oldest Turkish ebru ground, battal: colours sprinkled one after another \
                  until each new one squeezes the earlier ones into veins.",
        background: rgb(0xf4ecd8),
        colors: &[rgb(0x1d3557), rgb(0xa4402b), rgb(0xd9a441), rgb(0x5b7fa3)],
        spacing: 10.0,
        make: stone,
    },
    Pattern {
        id: "hair-vein",
        name: "Italian hair-vein",
        history: "An 18th-century Italian stone marble whose veins are drawn out with a pin \
                  into bundles of hair-fine lines.",
        background: rgb(0xefe6d2),
        colors: &[rgb(0x222222), rgb(0x9b2d20), rgb(0x2f4f7f), rgb(0xd8b13a)],
        spacing: 14.0,
        make: hair_vein,
    },
    Pattern {
        id: "turkish-spot",
        name: "Turkish spot",
        history: "The stone ground finished with a last colour thrown in large, separate \
                  spots; the base of the Spanish and Stormont papers.",
        background: rgb(0xf2ead8),
        colors: &[rgb(0x3b2a1a), rgb(0xc0392b), rgb(0xe0b040), rgb(0x3b5b92)],
        spacing: 10.0,
        make: turkish_spot,
    },
    Pattern {
        id: "french-shell",
        name: "French shell",
        history: "French, late 18th century: oil in the colour makes each drop keep an outer \
                  ring of a lighter shade; brown and orange veins on a blue body.",
        background: rgb(0xf1e7d0),
        colors: &[rgb(0x6b3e1f), rgb(0xd9822b), rgb(0x2c4f8a), rgb(0xa9c1e0)],
        spacing: 10.0,
        make: french_shell,
    },
    Pattern {
        id: "stormont",
        name: "Stormont",
        history: "French, early 19th century: turpentine in the top colour breaks it into a \
                  lace of tiny holes over a Turkish ground.",
        background: rgb(0xf3ecdc),
        colors: &[rgb(0x1a1a1a), rgb(0x8e2b22), rgb(0x3d5f8f), rgb(0xdfe6ee)],
        spacing: 10.0,
        make: stormont,
    },
    Pattern {
        id: "spanish-wave",
        name: "Spanish wave",
        history: "18th-century Spain: the paper is laid on a Turkish spot with a rocking \
                  motion, pressing the colours into light and dark waves.",
        background: rgb(0xf2e8d5),
        colors: &[rgb(0x5d3a1a), rgb(0xb8412f), rgb(0x2f5d8a), rgb(0xe3c36a)],
        spacing: 10.0,
        make: spanish_wave,
    },
    Pattern {
        id: "west-end",
        name: "West End",
        history: "Made like the Spanish marble but laid without shading: veins, a dark \
                  colour dotted all over with white, and a lighter top colour.",
        background: rgb(0xf4efe4),
        colors: &[
            rgb(0x1b1b1b),
            rgb(0x8a3324),
            rgb(0x24406b),
            rgb(0xf5f5f0),
            rgb(0x7b9cc7),
        ],
        spacing: 10.0,
        make: west_end,
    },
];

/// Three or four colours thrown in turn; the last covers most of the tank.
fn stone_ground(m: &mut Maker, first_count: usize) {
    let n = m.ink_count().clamp(2, 4);
    for i in 0..n {
        let grow = i as f64 / (n - 1) as f64;
        let count = first_count - first_count * i / (2 * n);
        let (lo, hi) = (12.0 + 12.0 * grow, 26.0 + 22.0 * grow);
        let what = match i {
            0 => "Throw the vein colour".to_string(),
            _ => format!("Throw colour {}", i + 1),
        };
        m.throw(&what, i, count, lo, hi);
    }
}

fn stone(m: &mut Maker) {
    stone_ground(m, 90);
}

fn hair_vein(m: &mut Maker) {
    stone_ground(m, 90);
    // Hairs: a single pin drawn through the veins many times, nearly parallel, each
    // stroke dragging a hair-thin trail of every colour it crosses.
    let (u, s) = (m.u, m.fine);
    let n = (m.w / s).ceil() as usize;
    let ops = (0..n)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + m.random(-0.25, 0.25);
            Op::Tine(Tine {
                origin: Point::new((k as f64 + m.random(0.0, 1.0)) * s, m.h / 2.0),
                direction: crate::Vec2::new(a.cos(), a.sin()) * if k % 2 == 0 { 1.0 } else { -1.0 },
                alpha: 60.0 * u,
                lambda: 0.8 * u,
            })
        })
        .collect();
    m.step(
        format!(
            "Draw hairs: a single pin pulled {n} times up and down, about {} px apart",
            crate::caption::num(s)
        ),
        ops,
    );
}

/// Large separate spots of `ink` on a jittered grid.
fn spots(m: &mut Maker, what: &str, ink: usize, cols: usize, rows: usize, r: f64) -> Vec<Point> {
    let cell = m.w / cols as f64;
    let mut centers = m.grid(cols, rows, true);
    for c in &mut centers {
        c.x += m.random(-0.25, 0.25) * cell;
        c.y += m.random(-0.25, 0.25) * cell;
    }
    m.drops(what, ink, centers.clone(), Radii::One(r * m.u));
    centers
}

fn turkish_spot(m: &mut Maker) {
    for i in 0..3 {
        let what = ["Throw the vein colour", "Throw colour 2", "Throw colour 3"][i];
        m.throw(
            what,
            i,
            100 - 20 * i,
            14.0 + 5.0 * i as f64,
            28.0 + 8.0 * i as f64,
        );
    }
    spots(
        m,
        "Throw the spot colour in large separate drops",
        3,
        8,
        5,
        24.0,
    );
}

fn french_shell(m: &mut Maker) {
    m.throw("Throw the brown vein colour", 0, 90, 12.0, 22.0);
    m.throw("Throw the orange vein colour", 1, 80, 16.0, 28.0);
    m.throw("Throw the blue body colour", 2, 70, 22.0, 38.0);
    // An oiled drop: the colour, then its lighter ring pushed out around a new centre.
    let cell = m.w / 9.0;
    let mut centers = m.grid(9, 5, true);
    for c in &mut centers {
        c.x += m.random(-0.2, 0.2) * cell;
        c.y += m.random(-0.2, 0.2) * cell;
    }
    let shells: Vec<Point> = centers.iter().flat_map(|c| [*c, *c]).collect();
    let radii: Vec<f64> = centers
        .iter()
        .flat_map(|_| [15.0 * m.u, 11.0 * m.u])
        .collect();
    let colors = vec![m.ink(3), m.ink(2)];
    m.drops_of(
        "Throw the oiled shell colour: each drop spreads a lighter ring",
        colors,
        shells,
        Radii::Each(radii.into()),
    );
}

fn stormont(m: &mut Maker) {
    m.throw("Throw the black vein colour", 0, 60, 10.0, 18.0);
    m.throw("Throw the red", 1, 45, 14.0, 24.0);
    m.throw(
        "Throw the blue top colour, full, with turpentine",
        2,
        90,
        24.0,
        40.0,
    );
    m.throw(
        "The turpentine opens the top colour into a lace of tiny holes",
        3,
        900,
        1.2,
        3.2,
    );
}

fn spanish_wave(m: &mut Maker) {
    turkish_spot_ground(m);
    let u = m.u;
    m.jiggle(
        "Lay the paper down rocking it: the first waves",
        std::f64::consts::FRAC_PI_4,
        60.0 * u,
        8.5 * u,
        14.0 * u,
    );
}

fn turkish_spot_ground(m: &mut Maker) {
    m.throw("Throw the vein colour", 0, 100, 14.0, 24.0);
    m.throw("Throw colour 2", 1, 80, 18.0, 30.0);
    m.throw("Throw colour 3", 2, 60, 22.0, 36.0);
    spots(m, "Throw the spot colour in separate drops", 3, 8, 5, 20.0);
}

fn west_end(m: &mut Maker) {
    m.throw("Throw the first vein colour", 0, 50, 8.0, 16.0);
    m.throw("Throw the second vein colour", 1, 40, 10.0, 18.0);
    m.throw(
        "Sprinkle the dark colour on full to drive the veins up",
        2,
        110,
        22.0,
        38.0,
    );
    m.throw(
        "Beat the white on finely and evenly all over",
        3,
        700,
        1.5,
        3.0,
    );
    m.throw(
        "Sprinkle the light top colour lightly and evenly",
        4,
        70,
        5.0,
        10.0,
    );
}
