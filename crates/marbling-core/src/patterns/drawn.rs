//! Patterns drawn with a stylus or swirled: French curl (snail), bülbülyuvası
//! (nightingale's nest), a Turkish tulip and hearts.

use super::{Maker, Pattern, rgb};
use crate::{Point, Radii};
use std::f64::consts::PI;

pub(super) const PATTERNS: [Pattern; 4] = [
    Pattern {
        id: "french-curl",
        name: "French curl (snail)",
        history: "French, 17th–18th century: a combed or stone ground turned into rows of \
                  snail curls by a frame of pins twisted in the bath.",
        background: rgb(0xf4ecd8),
        colors: &[rgb(0x1d3557), rgb(0xa4402b), rgb(0xd9a441), rgb(0x457b9d)],
        spacing: 10.0,
        make: french_curl,
    },
    Pattern {
        id: "nightingale-nest",
        name: "Bülbülyuvası (nightingale's nest)",
        history: "Turkish ebru: on a gel-git ground the stylus winds spirals from the centre \
                  out, each one a nightingale's nest.",
        background: rgb(0xf6efe0),
        colors: &[rgb(0x264653), rgb(0xe9c46a), rgb(0xe76f51), rgb(0x2a9d8f)],
        spacing: 10.0,
        make: nightingale_nest,
    },
    Pattern {
        id: "tulip",
        name: "Turkish tulip",
        history: "Çiçekli ebru, the flower marbling of Necmeddin Okyay (1883–1976): drops \
                  inside drops shaped into tulips with the stylus.",
        background: rgb(0xf2ecd9),
        colors: &[rgb(0xc1121f), rgb(0xf4a261), rgb(0x780000), rgb(0x386641)],
        spacing: 10.0,
        make: tulip,
    },
    Pattern {
        id: "hearts",
        name: "Hearts",
        history: "A row of drops within drops cut by one straight stylus line through their \
                  centres: each becomes a heart, a classic first exercise.",
        background: rgb(0xf7efe6),
        colors: &[rgb(0x9d0208), rgb(0xf48c06), rgb(0xffe5d9), rgb(0x6a040f)],
        spacing: 10.0,
        make: hearts,
    },
];

fn french_curl(m: &mut Maker) {
    let n = m.ink_count().clamp(2, 4);
    for i in 0..n {
        m.throw(&format!("Throw colour {}", i + 1), i, 320 / n, 14.0, 28.0);
    }
    let u = m.u;
    m.gel_git(30.0 * u, 40.0 * u);
    let centers = m.grid(6, 4, true);
    m.swirls("Twist the curl pins", &centers, 150.0 * u, 22.0 * u);
}

/// A spiral of `turns` turns from the centre out to radius `r`, `per_turn` points a turn.
fn spiral(c: Point, r: f64, turns: f64, per_turn: usize) -> Vec<Point> {
    let n = (turns * per_turn as f64) as usize;
    (0..=n)
        .map(|k| {
            let t = k as f64 / n as f64;
            let a = 2.0 * PI * turns * t;
            Point::new(c.x + r * t * a.cos(), c.y + r * t * a.sin())
        })
        .collect()
}

fn nightingale_nest(m: &mut Maker) {
    m.rows_ground();
    let u = m.u;
    m.gel_git(32.0 * u, 70.0 * u);
    let paths = m
        .grid(5, 3, true)
        .into_iter()
        .map(|c| spiral(c, 54.0 * u, 4.0, 24))
        .collect();
    m.styli(
        "Wind a nest from each centre outwards",
        paths,
        5.0 * u,
        None,
    );
}

fn tulip(m: &mut Maker) {
    let u = m.u;
    m.throw("Throw a sparse battal ground", 3, 40, 6.0, 12.0);
    let centers: Vec<Point> = (0..3)
        .map(|k| Point::new(m.w * (k as f64 + 0.5) / 3.0, m.h * 0.42))
        .collect();
    // The flower: a large drop with smaller ones dropped into its centre.
    for (i, r, what) in [
        (0, 58.0, "Drop the petal colour"),
        (1, 40.0, "Drop the lighter heart into each"),
        (2, 18.0, "Drop the dark eye into each"),
    ] {
        m.drops(what, i, centers.clone(), Radii::One(r * u));
    }
    // The cup: strokes from above pull the top into three petals; a stroke up from
    // below points the base.
    let mut petals = Vec::new();
    for c in &centers {
        for dx in [-26.0, 0.0, 26.0] {
            petals.push(vec![
                Point::new(c.x + dx * u, c.y - 90.0 * u),
                Point::new(c.x + dx * 0.6 * u, c.y - 10.0 * u),
            ]);
        }
    }
    m.styli("Pull the petals down from above", petals, 6.0 * u, None);
    let base = centers
        .iter()
        .map(|c| {
            vec![
                Point::new(c.x, c.y + 85.0 * u),
                Point::new(c.x, c.y + 20.0 * u),
            ]
        })
        .collect();
    m.styli(
        "Point the base with a stroke up from below",
        base,
        6.0 * u,
        None,
    );
    // The stem: a row of small green drops pulled into a line.
    let mut stem = Vec::new();
    for c in &centers {
        for k in 0..5 {
            stem.push(Point::new(c.x, c.y + (80.0 + 22.0 * k as f64) * u));
        }
    }
    m.drops("Drop the stem", 3, stem, Radii::One(9.0 * u));
    let strokes = centers
        .iter()
        .map(|c| {
            vec![
                Point::new(c.x, c.y + 62.0 * u),
                Point::new(c.x, m.h + 20.0 * u),
            ]
        })
        .collect();
    m.styli("Draw the stem down", strokes, 4.0 * u, None);
}

fn hearts(m: &mut Maker) {
    let u = m.u;
    m.throw("Throw a light ground", 2, 60, 14.0, 26.0);
    for (row, y) in [(0, 0.3), (1, 0.72)] {
        let centers: Vec<Point> = (0..5)
            .map(|k| Point::new(m.w * (k as f64 + 0.5) / 5.0, m.h * y))
            .collect();
        let (outer, inner) = if row == 0 { (0, 1) } else { (3, 1) };
        m.drops(
            "Drop a row of drops",
            outer,
            centers.clone(),
            Radii::One(40.0 * u),
        );
        m.drops(
            "Drop a second colour into each",
            inner,
            centers.clone(),
            Radii::One(22.0 * u),
        );
        let (from, to) = if row == 0 {
            (
                Point::new(-20.0, centers[0].y),
                Point::new(m.w + 20.0, centers[0].y),
            )
        } else {
            (
                Point::new(m.w + 20.0, centers[0].y),
                Point::new(-20.0, centers[0].y),
            )
        };
        m.styli(
            "One straight line through every centre",
            vec![vec![from, to]],
            7.0 * u,
            None,
        );
    }
}
