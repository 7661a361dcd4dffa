use super::*;
use crate::{Setup, run};

#[test]
fn one_end_vertex_per_move_and_equal_lengths() {
    let mut setup = Setup::default();
    setup.set_register("01=6").unwrap();
    let r = run(
        "G91 G00 G46 X30. Y20. D01\nG01 G47 X80. F200.\nG03 X-10. Y10. I-10. F100.",
        &setup,
    );
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    let t = Toolpath::from_run(&r);
    assert_eq!(t.len(), 3);
    assert_eq!(t.actual.len(), t.programmed.len());
    // Each move continues from the previous end: 1 start + 3 ends.
    assert_eq!(t.vertex_count(), 4);
    assert_eq!(t.starts, vec![0, 1, 2]);
    assert_eq!(&t.actual[3..6], &[24.0, 14.0, 0.0]);
    assert_eq!(t.kinds, vec![0, 1, 3]);
    assert_eq!(t.arc_moves, vec![2]);
    let [[_, _], [_, end]] = t.ends(2).unwrap();
    assert_eq!(end, [100.0, 30.0, 0.0]);
    // Tessellated: the arc has many points, the last exactly its end.
    let mut points = Vec::new();
    t.for_each_point(
        2..3,
        true,
        (0.01, ArcPoints::Exact),
        |_| true,
        |_, _, p| points.push(p),
    );
    assert!(points.len() > 10, "arcs are tessellated");
    assert_eq!(*points.last().unwrap(), [100.0, 30.0, 0.0]);
    // Every move within the chord tolerance: both ends of each line, the
    // arc in many points.
    let mut per_move = [0usize; 3];
    t.for_each_point(
        0..t.len(),
        false,
        (CHORD_TOLERANCE, ArcPoints::Exact),
        |_| true,
        |m, _, _| per_move[m] += 1,
    );
    assert_eq!(per_move[..2], [2, 2]);
    assert!(per_move[2] > 10);
}

#[test]
fn a_move_that_does_not_start_at_the_last_end_gets_its_own_start() {
    // G92 moves the work coordinates between the moves: the second move
    // starts (in the new coordinates) away from where the first ended.
    let r = run("G01 X10. F100.\nG92 X0\nG01 X5.", &Setup::default());
    let t = Toolpath::from_run(&r);
    assert_eq!(t.len(), 2);
    assert_eq!(t.vertex_count(), 4);
    assert_eq!(t.starts, vec![0, 2]);
    assert_eq!(t.ends(1).unwrap()[0], [[0.0, 0.0, 0.0], [5.0, 0.0, 0.0]]);
}

#[test]
fn arc_points_lie_on_the_circle_within_tolerance() {
    let r = run("G02 X20. Y0 I10. J0 F100.", &Setup::default());
    let t = Toolpath::from_run(&r);
    for tolerance in [CHORD_TOLERANCE, 0.5, 3.0] {
        let mut v = Vec::new();
        t.for_each_point(
            0..1,
            false,
            (tolerance, ArcPoints::Exact),
            |_| true,
            |_, _, p| v.push(p),
        );
        for p in &v {
            let d = ((p[0] - 10.0).powi(2) + p[1].powi(2)).sqrt();
            assert!((d - 10.0).abs() < 1e-9);
        }
        // Chord midpoints stay within the tolerance.
        for w in v.windows(2) {
            let mx = (w[0][0] + w[1][0]) / 2.0 - 10.0;
            let my = (w[0][1] + w[1][1]) / 2.0;
            assert!(10.0 - (mx * mx + my * my).sqrt() <= tolerance + 1e-12);
        }
    }
}

#[test]
fn rotated_arc_points_stay_within_a_trillionth_of_the_exact_ones() {
    // A helix quarter, a half circle and a full circle of 50 m (1024
    // segments, the most turns) on the mill; a lathe arc (X diameter).
    let mill = "G02 X0 Y0 I50000. F100.\nG03 X-10. Y10. Z-3. I-10.\nG02 X10. Y10. R10.";
    let lathe = Setup {
        machine: MachineKind::Lathe,
        ..Setup::default()
    };
    let lathe_arc = "G18 G02 X20. Z-10. R10. F0.2";
    for (program, setup, at_least) in [(mill, Setup::default(), 1026), (lathe_arc, lathe, 20)] {
        let r = run(program, &setup);
        assert!(!r.has_errors(), "{:?}", r.diagnostics);
        let t = Toolpath::from_run(&r);
        let points = |arcs| {
            let mut v = Vec::new();
            t.for_each_point(
                0..t.len(),
                false,
                (0.001, arcs),
                |_| true,
                |_, _, p| v.push(p),
            );
            v
        };
        let (exact, rotated) = (points(ArcPoints::Exact), points(ArcPoints::Rotated));
        assert_eq!(exact.len(), rotated.len());
        assert!(exact.len() >= at_least, "{}", exact.len());
        // A trillionth of the largest radius (50 m): 5e-8 mm.
        for (e, r) in exact.iter().zip(&rotated) {
            assert!((0..3).all(|k| (e[k] - r[k]).abs() <= 5e-8), "{e:?} {r:?}");
        }
    }
}

#[test]
fn bounds_hold_the_arcs_extremes() {
    // A half circle from (0,0) to (20,0) clockwise through (10,10).
    let r = run("G02 X20. Y0 I10. J0 F100.", &Setup::default());
    let (min, max) = Toolpath::from_run(&r).bounds().unwrap();
    assert_eq!(min, [0.0, 0.0, 0.0]);
    assert!((max[1] - 10.0).abs() < 1e-9 && max[0] == 20.0, "{max:?}");
}

#[test]
fn inch_runs_are_drawn_in_inches() {
    let r = run("G20\nG01 X1. F10.", &Setup::default());
    let t = Toolpath::from_run(&r);
    assert_eq!(t.units, Units::Inch);
    assert!((t.actual[3] - 1.0).abs() < 1e-12);
}

#[test]
fn a_million_block_toolpath_costs_well_under_200_bytes_a_move() {
    // Issue 6, target 2: the page keeps this toolpath, not the moves.
    // Half the moves arcs (a CAM program has fewer): 61 bytes a move
    // plus 92 an arc.
    let block = "G01 X10. Y5.\nG02 X20. Y5. R5.\nG01 X0 Y0\nG03 X0 Y0 I3. J0\n";
    let r = run(&block.repeat(2_500), &Setup::default());
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    let mut t = Toolpath::from_run(&r);
    t.shrink_to_fit();
    let per_move = t.heap_bytes() as f64 / t.len() as f64;
    assert!(per_move < 110.0, "{per_move} bytes a move");
}

#[test]
fn shared_moves_are_the_same_at_the_start_and_at_the_end() {
    let path = |p: &str| {
        let r = run(p, &Setup::default());
        assert!(!r.has_errors(), "{:?}", r.diagnostics);
        Toolpath::from_run(&r)
    };
    // Moves: X10, the arc, Y10, the rapid to X0, Y0, X5, X8.
    let base = "G90 G01 X10. F100.\nG02 X20. R5.\nG01 Y10.\nG00 X0\nG01 Y0\nG01 X5.\nG01 X8.\n";
    let t = path(base);
    assert_eq!(t.len(), 7);
    assert_eq!(t.shared_moves(&t), (7, 0), "all at the start, none left");
    // A coordinate moved: the moves up to where Y is set again change.
    let moved = path(&base.replace("Y10.", "Y10.5"));
    assert_eq!(moved.shared_moves(&t), (2, 2));
    // Blocks inserted: the moves after them are the same, further on.
    let inserted = path(&base.replace("G01 Y10.\n", "G01 Y10.\nG01 X15.\nG01 X20.\n"));
    assert_eq!(inserted.shared_moves(&t), (3, 4));
    assert_eq!(t.shared_moves(&inserted), (3, 4));
    // Only the arc's circle differs (the other way round): its ends stay.
    let turned = path(&base.replace("G02", "G03"));
    assert_eq!(turned.shared_moves(&t), (1, 5));
    // A rapid instead of a feed: the kind differs.
    let rapid = path(&base.replace("G01 Y0", "G00 Y0"));
    assert_eq!(rapid.shared_moves(&t), (4, 2));
    assert_eq!(Toolpath::default().shared_moves(&t), (0, 0));
}

#[test]
fn a_remembered_answer_is_worked_out_again_once_moves_are_added() {
    let r = run("G01 X10. F100.\nG01 Y5.", &Setup::default());
    let mut t = Toolpath::new(r.machine, r.units);
    t.push(&r.moves[0]);
    let walks = std::cell::Cell::new(0);
    let moves = |t: &Toolpath| {
        walks.set(walks.get() + 1);
        t.len() > 1
    };
    // One move: worked out once (false), then read back without a walk.
    assert!(!t.remembered(0, moves));
    assert!(!t.remembered(0, moves));
    // A clone keeps the answer; equality does not look at answers.
    let copy = t.clone();
    assert!(!copy.remembered(0, moves));
    assert_eq!(walks.get(), 1);
    assert_eq!(
        copy,
        Toolpath::from_run(&run("G01 X10. F100.", &Setup::default()))
    );
    // Another slot is its own question.
    assert!(!t.remembered(1, moves));
    assert_eq!(walks.get(), 2);
    // A second move: the answer is about two moves now (true).
    t.push(&r.moves[1]);
    assert!(t.remembered(0, moves));
    assert!(t.remembered(0, moves));
    assert_eq!(walks.get(), 3);
    // Past the slots: worked out every time, never kept.
    assert!(t.remembered(MEMO_SLOTS, moves));
    assert!(t.remembered(MEMO_SLOTS, moves));
    assert_eq!(walks.get(), 5);
}
