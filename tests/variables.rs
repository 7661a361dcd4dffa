//! Behaviour 21.12–21.14 (`docs/behaviour.md`): what a block reports of
//! the variables the program touched — for the page's Variables panel and
//! the CLI's JSON — their values after the block and the line that last
//! set each, per local variable level, made again the same from
//! checkpoints and after an edit. Values worked out by hand in the
//! comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::machine::{WatchView, Watched};
use offsetlab::report::{BlockReport, Run};
use offsetlab::view::block_view;
use offsetlab::{Earlier, RunOptions, Setup, report_at, rerun_observed};

/// One variable as a block reports it: (number, value, line that set it).
type Row = (u32, Option<f64>, Option<u32>);

/// The level and the variables a block reports.
fn watched(b: &BlockReport) -> (u8, Vec<Row>) {
    let w: &WatchView = b.watch.as_deref().expect("a watch");
    let v = w
        .variables
        .iter()
        .map(
            |&Watched {
                 variable,
                 value,
                 line,
             }| (variable, value, line),
        )
        .collect();
    (w.level, v)
}

/// The reports of the blocks on `line`, in the order they ran.
fn on_line(r: &Run, line: u32) -> Vec<&BlockReport> {
    r.blocks.iter().filter(|b| b.span.line == line).collect()
}

#[test]
fn behaviour21_12_each_block_reports_the_variables_touched_with_the_line_that_set_them() {
    let r = ok(programs::WHILE_BOLT_CIRCLE, &mill(&[]));
    // Before line 3 the program touched no variable: no watch at all.
    assert!(r.blocks[0].watch.is_none() && r.blocks[1].watch.is_none());
    // Line 3 sets #1 = 50.
    assert_eq!(watched(&r.blocks[2]), (0, vec![(1, Some(50.0), Some(3))]));
    // The second pass's #4 (line 7): #3 is 1 since the first pass's line 9
    // (#3 = 0 + 1), so #4 = 1 * 360 / 6 = 60.
    let fours = on_line(&r, 7);
    assert_eq!(
        watched(fours[1]),
        (
            0,
            vec![
                (1, Some(50.0), Some(3)),
                (2, Some(6.0), Some(4)),
                (3, Some(1.0), Some(9)),
                (4, Some(60.0), Some(7)),
            ]
        )
    );
    // After the last pass: #3 = 6 (six passes of line 9), #4 = 5 * 60 = 300;
    // the M30 block still shows them.
    let last = r.blocks.last().unwrap();
    assert_eq!(last.span.line, 12);
    assert_eq!(
        watched(last).1[2..],
        [(3, Some(6.0), Some(9)), (4, Some(300.0), Some(7))]
    );
    // The CLI's JSON carries it as `watch`.
    let json = serde_json::to_value(block_view(last, programs::WHILE_BOLT_CIRCLE)).unwrap();
    assert_eq!(json["watch"]["variables"][3]["value"], 300.0);
    assert_eq!(json["watch"]["variables"][3]["line"], 7);
}

#[test]
fn behaviour21_12_a_variable_only_read_is_shown_vacant_with_no_line() {
    // #101 is read (the X word left out, 20.4) and never set: vacant, no
    // line. #102 = #101 + 2 reads it again: vacant + 2 = 2 (20.4).
    let text = "G00 X#101 Y1.\n#102 = #101 + 2\nM30\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(watched(&r.blocks[0]), (0, vec![(101, None, None)]));
    assert_eq!(
        watched(&r.blocks[1]),
        (0, vec![(101, None, None), (102, Some(2.0), Some(2))])
    );
    // A program without `#` reports no watch in any block.
    let plain = ok("G00 X1.\nG01 Y2. F100\nM30\n", &mill(&[]));
    assert!(plain.blocks.iter().all(|b| b.watch.is_none()));
}

#[test]
fn behaviour21_12_a_system_variable_shows_the_tables_value_after_each_block() {
    // #5221 is G54's X (20.10): set to 100 at line 2, then G10 L2 P1 X50.
    // sets G54 X to 50 at line 3 — the panel reads the table after each
    // block, and the line that set it through the variable stays line 2.
    let text = "G90 G54\n#5221 = 100.\nG10 L2 P1 X50.\nM30\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(
        watched(&r.blocks[1]),
        (0, vec![(5221, Some(100.0), Some(2))])
    );
    assert_eq!(
        watched(&r.blocks[2]),
        (0, vec![(5221, Some(50.0), Some(2))])
    );
    // #2001 (tool offset 1, memory type A) read at line 1: 5.
    let r = ok("#1 = #2001 * 2\nM30\n", &mill(&[(1, 5.0)]));
    assert_eq!(
        watched(&r.blocks[0]),
        (0, vec![(1, Some(10.0), Some(1)), (2001, Some(5.0), None)])
    );
}

#[test]
fn behaviour21_13_a_macro_shows_its_own_level_and_the_caller_gets_its_marks_back() {
    let r = ok(programs::G65_BOLT_CIRCLE, &mill(&[]));
    // Before the call the main program's #1 = 7, from line 2.
    assert_eq!(watched(&r.blocks[2]), (0, vec![(1, Some(7.0), Some(2))]));
    // After the G65 block the macro's level 1 stands, its locals the
    // arguments set at the G65's line 4: A45. → #1, R20. → #18, X10. →
    // #24, Y5. → #25; the blocks of the macro show the same.
    let args = (
        1,
        vec![
            (1, Some(45.0), Some(4)),
            (18, Some(20.0), Some(4)),
            (24, Some(10.0), Some(4)),
            (25, Some(5.0), Some(4)),
        ],
    );
    assert_eq!(watched(on_line(&r, 4)[0]), args);
    let moves = on_line(&r, 11);
    assert_eq!(watched(moves[0]), args);
    // After the M99 the caller's level 0 stands again: #1 = 7 from line 2.
    assert_eq!(
        watched(on_line(&r, 12)[0]),
        (0, vec![(1, Some(7.0), Some(2))])
    );
    // The fourth call, from line 7: A315.
    assert_eq!(watched(moves[3]).1[0], (1, Some(315.0), Some(7)));
    // Back in the main program: #1 is 7 again, set at line 2, and
    // #101 = #1 = 7 at line 8.
    let back = on_line(&r, 8);
    assert_eq!(
        watched(back[0]),
        (0, vec![(1, Some(7.0), Some(2)), (101, Some(7.0), Some(8))])
    );
}

#[test]
fn behaviour21_13_a_modal_calls_arguments_are_set_at_the_g66() {
    // Line 3's move calls O9020 with G66's arguments, written on line 2:
    // Z-5. → #26, R2. → #18. Inside the macro (level 1) they show line 2;
    // after G67 and its M99 the main program touched no variable.
    let text = "G90 G00 X0 Y0 Z10.
G66 P9020 Z-5. R2.
G00 X10.
G67
M30
O9020
G01 Z#26 F100.
M99
";
    let r = ok(text, &mill(&[]));
    let drill = on_line(&r, 7);
    assert_eq!(
        watched(drill[0]),
        (1, vec![(18, Some(2.0), Some(2)), (26, Some(-5.0), Some(2))])
    );
    assert!(on_line(&r, 4)[0].watch.is_none());
}

#[test]
fn behaviour21_13_reports_made_again_from_checkpoints_carry_the_same_variables() {
    for (text, every) in [
        (programs::WHILE_BOLT_CIRCLE, 3),
        (programs::G65_BOLT_CIRCLE, 2),
        (programs::WHILE_BOLT_CIRCLE, 7),
    ] {
        let setup = mill(&[]);
        let kept = ok(text, &setup);
        let (_, checkpoints) = checkpointed(text, &setup, every);
        for b in &kept.blocks {
            let again = report_at(text, &setup, &checkpoints, b.index).unwrap();
            assert_eq!(again.watch, b.watch, "block {} every {every}", b.index);
        }
    }
}

fn page(every: u32) -> RunOptions {
    RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: every,
        ..RunOptions::default()
    }
}

#[test]
fn behaviour21_14_an_edit_of_a_variable_is_run_on_until_the_variables_agree() {
    // #1 is set on line 1 and used only on line 9: a run made again after
    // the edit 5. → 6. stands where the earlier run stood at every
    // checkpoint before line 9 but for #1, so it must not take the earlier
    // run's end (which moved to X5.).
    let before = "#1 = 5.\nG01 X1. F100\nY1.\nX2.\nY2.\nX3.\nY3.\nX4.\nG01 X#1\nM30\n";
    let after = before.replacen("5.", "6.", 1);
    let setup = Setup::default();
    let (old_run, old_points) = checkpointed(before, &setup, 2);
    let earlier = Earlier {
        text: before,
        run: &old_run,
        checkpoints: &old_points,
    };
    let (run, points, _) = rerun_observed(&after, &setup, page(2), Some(earlier), &mut ());
    let whole = ok(&after, &setup);
    assert_eq!(run.bounds, whole.bounds);
    // The last move's block (line 9) ends at X6.
    let last = report_at(&after, &setup, &points, 8).unwrap();
    assert_eq!(last.span.line, 9);
    assert_eq!(last.state.programmed[0], 6.0);
    assert_eq!(last.watch, whole.blocks[8].watch);
}
