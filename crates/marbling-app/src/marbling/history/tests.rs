use super::*;
use marbling_core::{Point, Spray, Tine, Vec2};

fn spray(x: f64) -> Op {
    Op::Spray(Spray {
        center: Point::new(x, 0.0),
        radius: 1.0,
        color: Rgb8::new(0, 0, 0),
    })
}

fn tine(y: f64) -> Op {
    Op::Tine(Tine {
        origin: Point::new(0.0, y),
        direction: Vec2::new(0.0, 1.0),
        alpha: 10.0,
        lambda: 4.0,
    })
}

fn blank() -> Design {
    Design::new(10, 10, Rgb8::new(1, 1, 1))
}

fn xs(d: &Design) -> Vec<f64> {
    d.ops
        .iter()
        .map(|o| match o {
            Op::Spray(s) => s.center.x,
            _ => -1.0,
        })
        .collect()
}

#[test]
fn a_stroke_is_one_step_undone_and_redone_whole() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(0.0)]).expect("a value");
    h.push_ops((1..=340).map(|i| spray(f64::from(i))).collect())
        .expect("a value");
    h.push_ops((0..9).map(|i| tine(f64::from(i))).collect())
        .expect("a value");
    assert_eq!(h.steps().len(), 3);
    assert_eq!(h.steps()[1].label, "spray stroke, 340 droplets");
    assert_eq!(h.steps()[2].label, "rake ↓ 9 tines");
    assert_eq!(h.design().gesture_sizes(), vec![1, 340, 9]);
    let full = h.design().clone();
    assert!(h.undo());
    assert_eq!(h.design().ops.len(), 341);
    assert!(h.undo());
    assert_eq!(xs(h.design()), vec![0.0]);
    assert!(h.design().gestures.is_empty());
    // The undone steps, listed greyed in the panel, in the order Redo brings them.
    let undone: Vec<&str> = h.undone().map(|s| s.label.as_str()).collect();
    assert_eq!(undone, ["spray stroke, 340 droplets", "rake ↓ 9 tines"]);
    assert!(h.redo() && h.redo() && !h.redo());
    assert_eq!(h.undone().count(), 0);
    assert_eq!(h.design(), &full);
}

#[test]
fn grouping_survives_a_round_trip_through_json() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(0.0)]).expect("a value");
    h.push_ops(vec![spray(1.0), spray(2.0), spray(3.0)])
        .expect("a value");
    h.push_ops(vec![spray(4.0)]).expect("a value");
    let json = h.design().to_json_pretty();
    assert!(json.contains("\"gestures\": [[1,3]]"), "{json}");
    let back = Design::from_json(&json).expect("valid");
    let again = History::new(back);
    assert_eq!(again.steps(), h.steps());
    assert_eq!(again.design(), h.design());
    // A document without gestures loads as one step per op.
    let mut plain = h.design().clone();
    plain.gestures.clear();
    assert_eq!(History::new(plain).steps().len(), 5);
}

#[test]
fn new_then_undo_restores_the_design_and_paper_is_undoable() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(0.0), spray(1.0)]).expect("a value");
    let made = h.design().clone();
    h.push_document(Design::new(30, 20, Rgb8::new(9, 9, 9)), "new sheet");
    assert_eq!((h.design().width, h.design().ops.len()), (30, 0));
    assert!(h.undo());
    assert_eq!(h.design(), &made);
    let mut paper = Paper::of(&made);
    paper.background = Rgb8::new(200, 10, 10);
    h.push_paper(paper.clone(), "#c80a0a", true);
    paper.background = Rgb8::new(200, 10, 11);
    h.push_paper(paper, "#c80a0b", true);
    assert_eq!(h.steps().len(), 2, "picks in a row are one step");
    assert_eq!(h.steps()[1].label, "paper #c80a0b");
    assert_eq!(h.design().background, Rgb8::new(200, 10, 11));
    assert_eq!(h.design().ops, made.ops);
    assert!(h.undo());
    assert_eq!(h.design(), &made);
    assert!(h.redo());
    assert_eq!(h.design().background, Rgb8::new(200, 10, 11));
}

#[test]
fn editing_an_earlier_step_branches_and_the_abandoned_steps_are_restorable() {
    let mut h = History::new(blank());
    for i in 0..5 {
        h.push_ops(vec![spray(f64::from(i)), spray(f64::from(i) + 0.5)])
            .expect("a value");
    }
    let full = h.design().clone();
    h.view(Some(2));
    assert_eq!(h.shown().op_count(), 4);
    assert_eq!(h.design(), &full);
    h.view(Some(99));
    assert_eq!(h.shown_steps(), 5);
    h.view(Some(2));
    h.push_ops(vec![spray(9.0)]).expect("a value");
    assert_eq!(xs(h.design()), vec![0.0, 0.5, 1.0, 1.5, 9.0]);
    assert_eq!(h.branches().len(), 1);
    assert_eq!(h.branches()[0].steps.len(), 3);
    assert_eq!(h.branches()[0].design, full);
    assert!(h.restore(0));
    assert_eq!(h.design(), &full);
    // The restored steps come back one by one: undo walks through them, then to
    // the fork, then to the edit that made the branch.
    assert!(h.undo());
    assert_eq!(h.design().ops.len(), 8);
    assert!(h.undo() && h.undo());
    assert_eq!(h.design().ops.len(), 4);
    assert!(h.undo());
    assert_eq!(xs(h.design()), vec![0.0, 0.5, 1.0, 1.5, 9.0]);
}

#[test]
fn a_new_step_after_undo_keeps_the_undone_steps_as_a_branch() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(1.0)]).expect("a value");
    h.push_ops(vec![spray(2.0)]).expect("a value");
    h.undo();
    h.push_ops(vec![spray(3.0)]).expect("a value");
    assert!(!h.can_redo());
    assert_eq!(xs(h.design()), vec![1.0, 3.0]);
    assert_eq!(xs(&h.branches()[0].design), vec![1.0, 2.0]);
}

#[test]
fn only_the_newest_branches_are_kept() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(0.0)]).expect("a value");
    // Undo then edit, again and again: each round abandons one step.
    for i in 1..=MAX_BRANCHES + 5 {
        h.push_ops(vec![spray(i as f64)]).expect("a value");
        h.undo();
        h.push_ops(vec![spray(-(i as f64))]).expect("a value");
        h.undo();
    }
    assert_eq!(h.branches().len(), MAX_BRANCHES);
    // The newest branch is the last round's.
    let newest = &h.branches()[MAX_BRANCHES - 1].design;
    assert_eq!(xs(newest), vec![0.0, (MAX_BRANCHES + 5) as f64]);
}

#[test]
fn earlier_states_fold_over_documents_and_paper() {
    let mut h = History::new(blank());
    h.push_ops(vec![spray(1.0)]).expect("a value");
    let mut other = Design::new(20, 20, Rgb8::new(5, 5, 5));
    other.ops = vec![spray(7.0), spray(8.0)];
    other.set_gesture_sizes([2]);
    h.push_document(other.clone(), "opened other.json");
    h.push_ops(vec![spray(9.0)]).expect("a value");
    let mut p = Paper::of(h.design());
    p.background = Rgb8::new(0, 0, 200);
    h.push_paper(p, "paper", false);
    assert_eq!(xs(&h.state_at(1)), vec![1.0]);
    assert_eq!(h.state_at(2), other);
    assert_eq!(xs(&h.state_at(3)), vec![7.0, 8.0, 9.0]);
    assert_eq!(h.state_at(3).background, Rgb8::new(5, 5, 5));
    assert_eq!(h.state_at(4).background, Rgb8::new(0, 0, 200));
    assert_eq!(h.state_at(4), *h.design());
    // Undo through everything lands on the start.
    while h.undo() {}
    assert_eq!(h.design(), &blank());
}

#[test]
fn an_edit_past_the_op_cap_is_refused_and_changes_nothing() {
    let mut d = blank();
    d.ops = (0..MAX_OPS - 10).map(|i| spray(i as f64)).collect();
    let mut h = History::new(d);
    let before = h.clone();
    let err = h
        .push_ops((0..11).map(|i| spray(f64::from(i))).collect())
        .expect_err("an error");
    assert_eq!(
        err,
        EditError::TooManyOps {
            have: MAX_OPS - 10,
            adding: 11
        }
    );
    assert!(err.to_string().contains("nothing was added"));
    assert_eq!(h, before);
    h.push_ops((0..10).map(|i| spray(f64::from(i))).collect())
        .expect("a value");
    assert_eq!(h.design().ops.len(), MAX_OPS);
    assert!(h.design().validate().is_ok());
}

#[test]
fn every_drop_of_a_pattern_counts_toward_the_cap() {
    use marbling_core::{DropSet, Point, Radii};
    let mut d = blank();
    d.ops = (0..MAX_OPS - 10).map(|i| spray(i as f64)).collect();
    let mut h = History::new(d);
    let pattern = |n: usize| {
        Op::Drops(DropSet {
            centers: (0..n).map(|i| Point::new(i as f64, 5.0)).collect(),
            radii: Radii::One(2.0),
            colors: std::sync::Arc::from([Rgb8::new(1, 2, 3)]),
        })
    };
    let err = h.push_ops(vec![pattern(11)]).expect_err("over the cap");
    assert_eq!(
        err,
        EditError::TooManyOps {
            have: MAX_OPS - 10,
            adding: 11
        }
    );
    h.push_ops(vec![pattern(10)]).expect("at the cap");
    assert_eq!(h.design().counted_ops(), MAX_OPS);
    assert!(h.design().validate().is_ok());
}
