use super::*;

const INK: Rgb8 = Rgb8::new(1, 2, 3);

fn drag(a: (f64, f64), b: (f64, f64)) -> Gesture {
    let mut g = Gesture::new(Point::new(a.0, a.1));
    g.path.push(Point::new(b.0, b.1));
    g
}

#[test]
fn a_held_drop_grows_up_to_its_cap() {
    let s = ToolSettings::default();
    let mut g = Gesture::new(Point::new(5.0, 6.0));
    assert_eq!(
        ops_for(ToolKind::Drop, &s, &g, &[INK], 0),
        vec![Op::Drop(Drop {
            center: g.start,
            radius: 30.0,
            color: INK
        })]
    );
    g.held_seconds = 2.0;
    let Op::Drop(d) = ops_for(ToolKind::Drop, &s, &g, &[INK], 0)[0] else {
        panic!()
    };
    assert_eq!(d.radius, 110.0);
    g.held_seconds = 1000.0;
    let Op::Drop(d) = ops_for(ToolKind::Drop, &s, &g, &[INK], 0)[0] else {
        panic!()
    };
    assert_eq!(d.radius, 300.0);
}

#[test]
fn a_tine_runs_through_a_along_the_drag_with_its_length_as_strength() {
    let s = ToolSettings::default();
    let ops = ops_for(
        ToolKind::Tine,
        &s,
        &drag((10.0, 20.0), (13.0, 24.0)),
        &[INK],
        0,
    );
    assert_eq!(
        ops,
        vec![Op::Tine(Tine {
            origin: Point::new(10.0, 20.0),
            direction: Vec2::new(3.0, 4.0),
            alpha: 5.0,
            lambda: 8.0
        })]
    );
    assert!(ops_for(ToolKind::Tine, &s, &drag((1.0, 1.0), (1.2, 1.0)), &[INK], 0).is_empty());
}

#[test]
fn a_rake_is_a_whole_sheet_rake_or_that_many_tines() {
    let mut s = ToolSettings::default();
    let ops = ops_for(
        ToolKind::Comb,
        &s,
        &drag((0.0, 0.0), (0.0, 50.0)),
        &[INK],
        0,
    );
    assert!(matches!(
        ops[..],
        [Op::Rake(Rake {
            spacing: 40.0,
            alpha: 50.0,
            ..
        })]
    ));
    s.comb_tines = 3;
    // A comb of that many tines is one op (one record of tine offsets on the GPU).
    let ops = ops_for(
        ToolKind::Comb,
        &s,
        &drag((100.0, 0.0), (100.0, 50.0)),
        &[INK],
        0,
    );
    let [Op::Comb(c)] = &ops[..] else {
        panic!("{ops:?}")
    };
    assert_eq!((c.origin, c.alpha), (Point::new(100.0, 0.0), 50.0));
    assert_eq!(&c.tines[..], [-40.0, 0.0, 40.0]);
    // Offsets are along n = (−m.y, m.x) = (−1, 0): the first tine is at x = 140.
    let mut p = Point::new(140.0, 10.0);
    p = Op::Comb(c.clone()).forward(p);
    assert!((p.y - 60.0).abs() < 1e-9, "{p:?}");
}

#[test]
fn wavy_takes_its_angle_from_the_drag() {
    let s = ToolSettings::default();
    let Op::Wavy(w) = ops_for(
        ToolKind::Wavy,
        &s,
        &drag((0.0, 0.0), (0.0, 10.0)),
        &[INK],
        0,
    )[0] else {
        panic!()
    };
    // Angles are rounded to 1e-4 rad (`Op::rounded`).
    assert!((w.angle - std::f64::consts::FRAC_PI_2).abs() <= 0.5e-4);
}

#[test]
fn circular_and_vortex_follow_the_pointer_around_the_centre() {
    let s = ToolSettings::default();
    // A quarter turn clockwise on screen (y down) at radius 100.
    let mut g = Gesture::new(Point::new(0.0, 0.0));
    for i in 0..=10 {
        let t = f64::from(i) / 10.0 * std::f64::consts::FRAC_PI_2;
        g.path.push(Point::new(100.0 * t.cos(), 100.0 * t.sin()));
    }
    let Op::Circular(c) = ops_for(ToolKind::Circular, &s, &g, &[INK], 0)[0] else {
        panic!()
    };
    assert!((c.radius - 100.0).abs() < 1e-9);
    // Strengths are rounded to 0.01 design px (`Op::rounded`).
    assert!(
        (c.alpha - 50.0 * std::f64::consts::PI).abs() <= 0.005,
        "{}",
        c.alpha
    );
    let Op::Vortex(v) = ops_for(ToolKind::Vortex, &s, &g, &[INK], 0)[0] else {
        panic!()
    };
    assert!(v.alpha > 0.0);
    // A click without travel makes nothing.
    assert!(ops_for(ToolKind::Vortex, &s, &Gesture::new(Point::ZERO), &[INK], 0).is_empty());
}

#[test]
fn spray_scatters_reproducible_droplets_near_the_path() {
    let s = ToolSettings::default();
    let g = drag((0.0, 0.0), (100.0, 0.0));
    let ops = ops_for(ToolKind::Spray, &s, &g, &[INK], 42);
    assert_eq!(ops.len(), 30);
    assert_eq!(ops, ops_for(ToolKind::Spray, &s, &g, &[INK], 42));
    for op in &ops {
        let Op::Spray(d) = op else { panic!() };
        assert!(d.center.y.abs() <= s.spray_spread + 1e-9 && (-25.0..=125.0).contains(&d.center.x));
        assert!((s.spray_min_radius..=s.spray_max_radius).contains(&d.radius));
    }
}

#[test]
fn a_stylus_follows_the_free_hand_path_kept_within_half_a_pixel() {
    let mut s = ToolSettings::default();
    let mut g = Gesture::new(Point::new(0.0, 0.0));
    for i in 1..=100 {
        let t = f64::from(i) / 100.0;
        g.path.push(Point::new(200.0 * t, 30.0 * (5.0 * t).sin()));
    }
    g.pixel = 0.5;
    let ops = ops_for(ToolKind::Stylus, &s, &g, &[INK], 0);
    let [Op::Stylus(st)] = &ops[..] else {
        panic!("{ops:?}")
    };
    assert!(st.path.len() > 5 && st.path.len() < 60, "{}", st.path.len());
    assert_eq!(st.wake, 6.0);
    assert!(st.tips.is_none());
    s.stylus_tips = 3;
    let ops = ops_for(ToolKind::Stylus, &s, &g, &[INK], 0);
    let Op::Stylus(st) = &ops[0] else { panic!() };
    assert_eq!(st.tips.as_deref(), Some(&[-40.0, 0.0, 40.0][..]));
    assert!(ops_for(ToolKind::Stylus, &s, &Gesture::new(Point::ZERO), &[INK], 0).is_empty());
}

#[test]
fn a_drop_pattern_is_one_op_cycling_the_palette() {
    let mut s = ToolSettings {
        drop_pattern: DropPattern::Ring,
        pattern_rings: 1,
        cycle_colors: true,
        ..ToolSettings::default()
    };
    let inks = [INK, Rgb8::new(9, 9, 9)];
    let g = Gesture::new(Point::new(50.0, 50.0));
    let ops = ops_for(ToolKind::Drop, &s, &g, &inks, 7);
    let [Op::Drops(d)] = &ops[..] else {
        panic!("{ops:?}")
    };
    assert_eq!(d.len(), 8);
    assert_eq!(&d.colors[..], inks);
    // The ghosts drawn before the click, to rounding (0.005 design px).
    let ghosts = drop_centers(&s, g.start, g.start, 7);
    assert_eq!(ghosts.len(), d.len());
    for (c, ghost) in d.centers.iter().zip(&ghosts) {
        assert!((*c - *ghost).hypot() <= 0.01, "{c:?} vs {ghost:?}");
    }
    s.cycle_colors = false;
    let Op::Drops(d) = &ops_for(ToolKind::Drop, &s, &g, &inks, 7)[0] else {
        panic!()
    };
    assert_eq!(&d.colors[..], [INK]);
}

#[test]
fn jiggle_shift_and_turn_take_their_geometry_from_the_drag() {
    let s = ToolSettings {
        jiggle_along: 1000.0,
        ..ToolSettings::default()
    };
    let Op::Jiggle(j) = ops_for(
        ToolKind::Jiggle,
        &s,
        &drag((0.0, 0.0), (0.0, 30.0)),
        &[INK],
        0,
    )[0] else {
        panic!()
    };
    assert!((j.angle - std::f64::consts::FRAC_PI_2).abs() <= 0.5e-4);
    // Clamped so that it cannot fold the tank: |kA| < 1.
    assert!(j.k_along().abs() < 1.0);
    let Op::Shift(t) = ops_for(
        ToolKind::Shift,
        &s,
        &drag((5.0, 5.0), (8.0, 1.0)),
        &[INK],
        0,
    )[0] else {
        panic!()
    };
    assert_eq!(t.offset, Vec2::new(3.0, -4.0));
    let mut g = Gesture::new(Point::new(0.0, 0.0));
    g.path.push(Point::new(100.0, 0.0));
    g.path.push(Point::new(0.0, 100.0));
    let Op::Turn(t) = ops_for(ToolKind::Turn, &s, &g, &[INK], 0)[0] else {
        panic!()
    };
    assert!((t.angle - std::f64::consts::FRAC_PI_2).abs() <= 0.5e-4);
}

#[test]
fn tool_names_are_their_stored_names() {
    for t in ToolKind::ALL {
        assert_eq!(
            serde_json::to_string(&t).expect("serialises"),
            format!("\"{}\"", t.name())
        );
    }
}

#[test]
fn pressure_scales_the_drop_it_pressed() {
    assert_eq!(pressure_scale(None), 1.0);
    assert_eq!(pressure_scale(Some(0.5)), 1.0);
    assert_eq!(pressure_scale(Some(1.0)), 2.0);
    assert_eq!(pressure_scale(Some(0.05)), 0.25);
    assert_eq!(pressure_scale(Some(f64::NAN)), 1.0);
    let s = ToolSettings::default();
    let mut g = Gesture::new(Point::new(5.0, 6.0));
    g.feel(pressure_scale(Some(0.75)));
    g.feel(pressure_scale(Some(1.0)));
    g.feel(pressure_scale(Some(0.6)));
    // The hardest press of the hold sets the size.
    let ops = ops_for(ToolKind::Drop, &s, &g, &[Rgb8::new(1, 2, 3)], 0);
    match ops.first() {
        Some(Op::Drop(d)) => assert_eq!(d.radius, s.drop_radius * 2.0),
        other => panic!("not a drop: {other:?}"),
    }
}

#[test]
fn a_flow_streams_for_the_drag_over_its_strength_and_stays_valid() {
    let mut s = ToolSettings::default();
    let ops = ops_for(
        ToolKind::Flow,
        &s,
        &drag((10.0, 10.0), (130.0, 10.0)),
        &[INK],
        0,
    );
    let [Op::Flow(f)] = ops.as_slice() else {
        panic!("one flow: {ops:?}")
    };
    // 120 px of drag at 40 px per unit time.
    assert_eq!(f.time, 3.0);
    assert_eq!(f.noise.frequency, 1.0 / 160.0);
    assert_eq!(f.noise.octaves, 2);
    let mut d = marbling_core::Design::new(400, 300, Rgb8::WHITE);
    d.ops.push(Op::Flow(f.clone()));
    assert!(d.validate().is_ok(), "{:?}", d.validate());
    // A drag far longer than the sub-step cap allows is cut to the cap, still valid.
    s.flow_strength = 200.0;
    s.flow_size = 20.0;
    let ops = ops_for(
        ToolKind::Flow,
        &s,
        &drag((0.0, 0.0), (5000.0, 0.0)),
        &[INK],
        0,
    );
    let [Op::Flow(f)] = ops.as_slice() else {
        panic!("one flow: {ops:?}")
    };
    assert!(f.time < 25.0 && f.time > 0.1, "{}", f.time);
    assert!(f.sub_steps() <= marbling_core::MAX_FLOW_STEPS);
    assert!(f.sub_steps() > marbling_core::MAX_FLOW_STEPS / 2);
    // A click makes nothing.
    assert!(ops_for(ToolKind::Flow, &s, &drag((0.0, 0.0), (0.5, 0.0)), &[INK], 0).is_empty());
}
