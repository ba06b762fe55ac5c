//! Combed patterns: a thrown ground raked into gel-git, then combs, rakes and wavy
//! combs drawn through it (chevron, the nonpareil family, feather, bouquet, peacock,
//! bird wing, serpentine, Old Dutch, Dutch scallops, şal).

use super::{Maker, Pattern, rgb};
use crate::{Point, Rgb8, Vec2};
use std::f64::consts::{FRAC_PI_2, PI};

const DUTCH: &[Rgb8] = &[rgb(0x1f3f8f), rgb(0xb22222), rgb(0xe1b12c), rgb(0x2e7d32)];
const SOFT: &[Rgb8] = &[
    rgb(0x355070),
    rgb(0x6d597a),
    rgb(0xb56576),
    rgb(0xe56b6f),
    rgb(0xeaac8b),
];
const OCEAN: &[Rgb8] = &[rgb(0x14213d), rgb(0xfca311), rgb(0x2a9d8f), rgb(0xe76f51)];

const RIGHT: Vec2 = Vec2::new(1.0, 0.0);
const LEFT: Vec2 = Vec2::new(-1.0, 0.0);
const DOWN: Vec2 = Vec2::new(0.0, 1.0);
const UP: Vec2 = Vec2::new(0.0, -1.0);

pub(super) const PATTERNS: [Pattern; 13] = [
    Pattern {
        id: "gel-git",
        name: "Gel-git",
        history: "Turkish \"come and go\": the thrown colours are raked up and down the tank, \
                  the ground of every combed pattern.",
        background: rgb(0xf7f3e8),
        colors: OCEAN,
        spacing: 16.0,
        make: gel_git,
    },
    Pattern {
        id: "chevron",
        name: "Chevron",
        history: "A gel-git raked across once each way with a coarse rake, folding the \
                  stripes into arrowheads; common on 19th-century ledgers.",
        background: rgb(0xf7efe2),
        colors: SOFT,
        spacing: 16.0,
        make: chevron,
    },
    Pattern {
        id: "nonpareil",
        name: "Nonpareil",
        history: "\"Without equal\": a gel-git drawn through once with a fine comb, the most \
                  common combed paper of the 18th and 19th centuries.",
        background: rgb(0xf4ecd8),
        colors: DUTCH,
        spacing: 16.0,
        make: nonpareil,
    },
    Pattern {
        id: "reversed-nonpareil",
        name: "Reversed nonpareil",
        history: "A nonpareil with the fine comb drawn back through it between its first \
                  lines, turning each little arch into a loop.",
        background: rgb(0xf4ecd8),
        colors: SOFT,
        spacing: 16.0,
        make: reversed_nonpareil,
    },
    Pattern {
        id: "wave-nonpareil",
        name: "Wave nonpareil",
        history: "A nonpareil whose comb is moved in a gentle wave as it is drawn, so the \
                  rows of arches ripple.",
        background: rgb(0xf4ecd8),
        colors: OCEAN,
        spacing: 16.0,
        make: wave_nonpareil,
    },
    Pattern {
        id: "feather",
        name: "Feather",
        history: "A nonpareil drawn through with a coarse rake, down and up in alternate \
                  lines, so the arches fold into feathers.",
        background: rgb(0xf7f3e8),
        colors: SOFT,
        spacing: 16.0,
        make: feather,
    },
    Pattern {
        id: "bouquet",
        name: "Bouquet",
        history: "A nonpareil combed again with a comb moved in small waves, opening each \
                  row into bouquets.",
        background: rgb(0xf7efe2),
        colors: SOFT,
        spacing: 16.0,
        make: bouquet,
    },
    Pattern {
        id: "peacock",
        name: "Peacock",
        history: "A gel-git combed with a wavy-moving comb and then a fine comb: rows of \
                  peacock eyes, a 19th-century revival favourite.",
        background: rgb(0xf4efe1),
        colors: &[rgb(0x0b3954), rgb(0x087e8b), rgb(0xbfd7ea), rgb(0xc81d25)],
        spacing: 16.0,
        make: peacock,
    },
    Pattern {
        id: "bird-wing",
        name: "Bird wing",
        history: "A nonpareil drawn through with curved strokes that sweep the arches \
                  into the shape of a spread wing.",
        background: rgb(0xf5eee0),
        colors: &[rgb(0x2b2d42), rgb(0x8d99ae), rgb(0xd90429), rgb(0xedf2f4)],
        spacing: 16.0,
        make: bird_wing,
    },
    Pattern {
        id: "serpentine",
        name: "Serpentine",
        history: "Colours raked into stripes and then moved with a wavy comb into \
                  snaking bands.",
        background: rgb(0xf7f3e8),
        colors: OCEAN,
        spacing: 24.0,
        make: serpentine,
    },
    Pattern {
        id: "old-dutch",
        name: "Old Dutch",
        history: "The 17th–18th-century Dutch combed paper in red, blue, yellow and green, \
                  made in Holland and Germany and wrapped round exported toys.",
        background: rgb(0xf3ead6),
        colors: DUTCH,
        spacing: 16.0,
        make: old_dutch,
    },
    Pattern {
        id: "dutch-scallops",
        name: "Dutch scallops",
        history: "A Dutch combed ground drawn through with a comb moved in half circles, \
                  leaving rows of scallop shells.",
        background: rgb(0xf3ead6),
        colors: DUTCH,
        spacing: 16.0,
        make: dutch_scallops,
    },
    Pattern {
        id: "sal",
        name: "Şal",
        history: "Turkish şal (shawl) ebru: the gel-git worked with wavy combs in both \
                  directions into the curling figures of a Kashmir shawl.",
        background: rgb(0xf6eddc),
        colors: &[rgb(0x5a1807), rgb(0xd4a017), rgb(0x1b4965), rgb(0x9b2226)],
        spacing: 16.0,
        make: sal,
    },
];

fn ground(m: &mut Maker) {
    m.rows_ground();
}

fn gel_git(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
}

fn chevron(m: &mut Maker) {
    gel_git(m);
    let u = m.u;
    m.rake(
        "Chevron, first pass",
        RIGHT,
        80.0 * u,
        0.0,
        60.0 * u,
        16.0 * u,
    );
    m.rake(
        "Chevron, back between",
        LEFT,
        80.0 * u,
        40.0 * u,
        60.0 * u,
        16.0 * u,
    );
}

fn nonpareil(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    m.fine_comb("Nonpareil comb", RIGHT, 0.0);
}

fn reversed_nonpareil(m: &mut Maker) {
    nonpareil(m);
    let s = m.fine;
    m.fine_comb("The comb drawn back between its lines", LEFT, s / 2.0);
}

fn wave_nonpareil(m: &mut Maker) {
    nonpareil(m);
    let u = m.u;
    m.wavy("The comb's wave", FRAC_PI_2, 10.0 * u, 160.0 * u, 0.0);
}

fn feather(m: &mut Maker) {
    nonpareil(m);
    let u = m.u;
    m.rake("Feather rake down", DOWN, 96.0 * u, 0.0, 40.0 * u, 10.0 * u);
    m.rake(
        "Feather rake up",
        UP,
        96.0 * u,
        48.0 * u,
        40.0 * u,
        10.0 * u,
    );
}

fn bouquet(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    m.fine_comb("Nonpareil comb", RIGHT, 0.0);
    m.wavy(
        "The bouquet comb's small waves",
        0.0,
        14.0 * u,
        64.0 * u,
        0.0,
    );
}

fn peacock(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    m.wavy("The wavy comb", 0.0, 12.0 * u, 40.0 * u, 0.0);
    m.fine_comb("The fine comb through the waves", DOWN, 0.0);
}

fn bird_wing(m: &mut Maker) {
    nonpareil(m);
    let u = m.u;
    // Curved strokes across the tank, each bowed like the edge of a wing.
    let rows = (m.h / (56.0 * u)).ceil() as usize;
    let paths = (0..=rows)
        .map(|r| {
            let y0 = r as f64 * 56.0 * u;
            (0..=24)
                .map(|k| {
                    let t = k as f64 / 24.0;
                    Point::new(
                        -20.0 * u + (m.w + 40.0 * u) * t,
                        y0 + 70.0 * u * (PI * t).sin(),
                    )
                })
                .collect()
        })
        .collect();
    m.styli("Wing strokes drawn across in curves", paths, 9.0 * u, None);
}

fn serpentine(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    m.wavy("The serpentine wave", 0.0, 30.0 * u, 160.0 * u, 0.0);
    m.wavy("A second, shorter wave", 0.0, 10.0 * u, 70.0 * u, 1.0);
}

fn old_dutch(m: &mut Maker) {
    ground(m);
    let u = m.u;
    let s = m.fine;
    m.gel_git(48.0 * u, 100.0 * u);
    m.rake(
        "The Dutch comb drawn across",
        RIGHT,
        s,
        0.0,
        1.5 * s,
        0.3 * s,
    );
    m.rake(
        "The comb drawn back",
        LEFT,
        2.0 * s,
        s / 2.0,
        1.2 * s,
        0.3 * s,
    );
}

fn dutch_scallops(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    // A comb of tines moved along a chain of half circles.
    let r = 40.0 * u;
    let rows = (m.h / (4.0 * r)).ceil() as usize;
    let mut paths = Vec::new();
    for row in 0..rows {
        let y0 = (row as f64 + 0.5) * 4.0 * r;
        let mut path = vec![Point::new(-r, y0)];
        let mut x = -r;
        while x < m.w + r {
            for k in 1..=8 {
                let a = PI * k as f64 / 8.0;
                path.push(Point::new(x + r - r * a.cos(), y0 - r * a.sin()));
            }
            x += 2.0 * r;
        }
        paths.push(path);
    }
    let tips: Vec<f64> = (0..9).map(|k| (k as f64 - 4.0) * 10.0 * u).collect();
    m.styli(
        "Scallop comb drawn in half circles",
        paths,
        6.0 * u,
        Some(tips),
    );
}

fn sal(m: &mut Maker) {
    ground(m);
    let u = m.u;
    m.gel_git(48.0 * u, 100.0 * u);
    m.wavy("Wavy comb across", 0.0, 16.0 * u, 80.0 * u, 0.0);
    m.wavy("Wavy comb down", FRAC_PI_2, 16.0 * u, 120.0 * u, 0.5);
    m.fine_comb("Fine comb to finish", RIGHT, 0.0);
}
