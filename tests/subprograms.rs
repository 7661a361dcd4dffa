//! Behaviour 19 (`docs/behaviour.md`): subprograms — the programs of a
//! file called by number (M98 P… L…, Fanuc's P LLLLNNNN), Haas's local
//! M97, M99 back to the caller, to a sequence number, or to the main
//! program's start; the nesting limit and the alarms; each block's program
//! and call stack; a program that never ends stopped at the block limit;
//! checkpoints inside a subprogram. Positions are worked out by hand in
//! the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::report::Run;
use offsetlab::setup::{Control, MainM99, SubprogramP};
use offsetlab::view::block_view;
use offsetlab::{End, RunOptions, Setup, report_at, run, run_with};

fn with_control(control: Control) -> Setup {
    let mut s = Setup::default();
    s.settings.control = control;
    s
}

/// The deepest Z any move reaches, and where the last move ends.
fn lowest_z(r: &Run) -> f64 {
    r.moves
        .iter()
        .map(|m| m.to[2])
        .fold(f64::INFINITY, f64::min)
}

/// The (line, program, stack) of every block report.
fn places<'a>(r: &'a Run, text: &'a str) -> Vec<(u32, Option<String>, Vec<String>)> {
    r.blocks
        .iter()
        .map(|b| {
            let v = block_view(b, text);
            (v.line, v.program, v.stack)
        })
        .collect()
}

/// A square contour stepped down 1 mm each time in G91, called four times.
const STEP_DOWN: &str = "%
O1000 (MAIN)
N10 G90 G00 X0 Y0 Z5.
N20 G01 Z0 F100
N30 M98 P2000 L4
N40 G90 G00 Z5.
N50 M30
%
O2000 (STEP DOWN)
N1 G91 G01 Z-1.
N2 X10.
N3 Y10.
N4 X-10.
N5 Y-10.
N6 M99
%
";

#[test]
fn behaviour19_3_m98_l_repeats_the_subprogram() {
    let r = ok(STEP_DOWN, &Setup::default());
    // Blocks: O1000, N10, N20, N30 (4); O2000 and N1–N6 (7) four times
    // (28); N40, N50 (2): 34.
    assert_eq!(r.block_count, 34);
    // Moves: N10, N20, five per pass (20), N40: 23.
    assert_eq!(r.moves.len(), 23);
    // Each pass starts Z-1 lower in G91: -1, -2, -3, -4.
    let passes: Vec<f64> = r
        .moves
        .iter()
        .filter(|m| m.line == 10)
        .map(|m| m.to[2])
        .collect();
    assert_eq!(passes, vec![-1.0, -2.0, -3.0, -4.0]);
    assert_eq!(lowest_z(&r), -4.0);
    // The square's corners, every pass: X10, then X10 Y10, X0 Y10, X0 Y0.
    let last_pass: Vec<[f64; 3]> = r.moves[17..22].iter().map(|m| m.to).collect();
    assert_eq!(
        last_pass,
        vec![
            [0.0, 0.0, -4.0],
            [10.0, 0.0, -4.0],
            [10.0, 10.0, -4.0],
            [0.0, 10.0, -4.0],
            [0.0, 0.0, -4.0]
        ]
    );
    // N40 G90 Z5. after the return: back on line 6.
    same(r.moves[22].to, [0.0, 0.0, 5.0]);
    assert_eq!(r.end, End::ProgramEnd { line: 7 });
    let call = at_line(&r, STEP_DOWN, 5);
    assert_eq!(
        call.explanation,
        "M98: calls O2000, 4 times; it returns to line 6."
    );
    // The M99 of the second pass says which pass comes; the last returns.
    let m99: Vec<String> = r
        .blocks
        .iter()
        .filter(|b| b.span.line == 15)
        .map(|b| b.explanation())
        .collect();
    assert_eq!(
        m99,
        vec![
            "M99: O2000 again, time 2 of 4.",
            "M99: O2000 again, time 3 of 4.",
            "M99: O2000 again, time 4 of 4.",
            "M99: back to O1000, line 6, after the call at O1000 N30."
        ]
    );
}

#[test]
fn behaviour19_7_each_block_names_its_program_and_the_call_stack() {
    let r = ok(STEP_DOWN, &Setup::default());
    let p = places(&r, STEP_DOWN);
    // The main program's blocks carry none (the M98 block ran in it).
    assert_eq!(p[3], (5, None, vec![]));
    let sub = |line| {
        (
            line,
            Some("O2000".to_string()),
            vec!["O1000 N30".to_string(), "O2000".to_string()],
        )
    };
    assert_eq!(p[4], sub(9));
    assert_eq!(p[10], sub(15));
    assert_eq!(p[32], (6, None, vec![]));
    // In the CLI's JSON: `program` and `stack` per block.
    let json = serde_json::to_value(block_view(&r.blocks[5], STEP_DOWN)).unwrap();
    assert_eq!(json["program"], "O2000");
    assert_eq!(json["stack"], serde_json::json!(["O1000 N30", "O2000"]));
}

#[test]
fn behaviour19_3_the_8_digit_p_form_is_the_repeat_count_and_the_number() {
    let text = "O1\nG00 X0 Y0 Z5.\nM98 P00032000\nM30\nO2000\nG91 G00 X1.\nM99\n";
    // P00032000 is 32000: repeat 3, program O2000 (Fanuc, YASNAC): X 0 →
    // 1 → 2 → 3 after the move to Z5.
    for control in [Control::Fanuc, Control::Yasnac] {
        let r = ok(text, &with_control(control));
        same(r.moves.last().unwrap().to, [3.0, 0.0, 5.0]);
        assert_eq!(r.moves.len(), 4);
    }
    // Haas: P is the number, O32000 is no program: alarm at P (3:5).
    let r = run(text, &with_control(Control::Haas));
    assert_eq!(first_error(&r), ("program-not-found", 3, 5));
    // Setting 7.36 on Fanuc: `number` reads it as Haas does.
    let mut s = with_control(Control::Fanuc);
    s.settings.subprogram_p = Some(SubprogramP::Number);
    assert_eq!(first_error(&run(text, &s)).0, "program-not-found");
    // With L, P is the number whatever its digits: P2000 L2 → X2.
    let r = ok(
        "O1\nG00 X0 Y0 Z5.\nM98 P2000 L2\nM30\nO2000\nG91 G00 X1.\nM99\n",
        &with_control(Control::Haas),
    );
    same(r.moves.last().unwrap().to, [2.0, 0.0, 5.0]);
}

#[test]
fn behaviour19_3_the_motion_of_the_call_block_comes_first() {
    let text = "O1\nG90 G00 X0 Y0 Z5.\nG01 X5. F100 M98 P2\nM30\nO2\nG00 Y7.\nM99\n";
    let r = ok(text, &Setup::default());
    // Line 3 moves to X5. first, then O2 moves to X5. Y7.
    assert_eq!(r.moves[1].line, 3);
    same(r.moves[1].to, [5.0, 0.0, 5.0]);
    assert_eq!(r.moves[2].line, 6);
    same(r.moves[2].to, [5.0, 7.0, 5.0]);
}

const NESTED: &str = "O0001
N10 G90 G00 X0 Y0 Z0
N20 M98 P0002
N30 M30
O0002
N10 G91 G00 X1.
N20 M98 P0003
N30 M99
O0003
N10 G91 G00 Y1.
N20 M98 P0004
N30 M99
O0004
N10 G91 G00 Z-1.
N20 M99
";

#[test]
fn behaviour19_6_calls_nest_three_deep_and_return_in_order() {
    let r = ok(NESTED, &Setup::default());
    // X+1 in O0002, Y+1 in O0003, Z-1 in O0004: (1, 1, -1).
    same(r.moves.last().unwrap().to, [1.0, 1.0, -1.0]);
    let p = places(&r, NESTED);
    let deepest = p.iter().find(|(line, _, _)| *line == 14).unwrap();
    assert_eq!(deepest.1.as_deref(), Some("O0004"));
    assert_eq!(
        deepest.2,
        vec!["O0001 N20", "O0002 N20", "O0003 N20", "O0004"]
    );
    // The returns unwind: O0004's M99 to O0003 line 12, O0003's to O0002
    // line 8, O0002's to O0001 line 4.
    let returns: Vec<String> = r
        .blocks
        .iter()
        .filter(|b| b.explanation().starts_with("M99"))
        .map(|b| b.explanation())
        .collect();
    assert_eq!(
        returns,
        vec![
            "M99: back to O0003, line 12, after the call at O0003 N20.",
            "M99: back to O0002, line 8, after the call at O0002 N20.",
            "M99: back to O0001, line 4, after the call at O0001 N20."
        ]
    );
    assert_eq!(r.end, End::ProgramEnd { line: 4 });
}

#[test]
fn behaviour19_6_nesting_past_the_control_depth_is_alarm_ps0077() {
    // O2 calls itself: the 1st call from O1 opens level 1, O2's own calls
    // levels 2, 3, 4; the 5th call (level 5) is past YASNAC's 4.
    let text = "O1\nM98 P2\nM30\nO2\nG91 G00 X1.\nM98 P2\nM99\n";
    let r = run(text, &Setup::default());
    assert_eq!(first_error(&r), ("nesting-too-deep", 6, 1));
    // Four levels ran one X+1 each before the alarm.
    same(r.moves.last().unwrap().to, [4.0, 0.0, 0.0]);
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert!(d.message.contains("PS0077"), "{}", d.message);
    // Fanuc nests 10: ten moves; setting 7.37 at 2: two.
    let r = run(text, &with_control(Control::Fanuc));
    assert_eq!(r.moves.len(), 10);
    let mut s = Setup::default();
    s.settings.subprogram_nesting = Some(2);
    assert_eq!(run(text, &s).moves.len(), 2);
}

#[test]
fn behaviour19_3_an_unknown_program_is_alarm_ps0076_at_p() {
    let r = run("O1\nG00 X1.\nM98 P1234\nM30\n", &Setup::default());
    assert_eq!(first_error(&r), ("program-not-found", 3, 5));
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert!(d.message.contains("O1234"), "{}", d.message);
    assert!(d.message.contains("PS0076"), "{}", d.message);
    // The block with the call does not run: one move, then the stop.
    assert_eq!((r.block_count, r.moves.len()), (2, 1));
    assert_eq!(r.end, End::Error { line: 3 });
    // M98 without P.
    assert_eq!(
        first_error(&run("M98 L2\n", &Setup::default())),
        ("missing-word", 1, 1)
    );
}

#[test]
fn behaviour19_4_m99_p_returns_to_a_sequence_number_of_the_caller() {
    let text = "O1\nN10 G90 G00 X0 Y0 Z5.\nN20 M98 P2\nN30 G00 X50.\nN40 G00 X60.\nN50 M30\nO2\nN1 G00 Y5.\nN2 M99 P40\n";
    let r = ok(text, &Setup::default());
    // N30 is passed over: X0 → (Y5 in O2) → N40 X60.
    let xs: Vec<f64> = r.moves.iter().map(|m| m.to[0]).collect();
    assert_eq!(xs, vec![0.0, 0.0, 60.0]);
    assert!(r.blocks.iter().all(|b| b.span.line != 4));
    assert_eq!(
        at_line(&r, text, 9).explanation,
        "M99 P40: back to O0001 at N40, line 5."
    );
    // No N45 in the caller: alarm PS0078 at P.
    let r = run(&text.replace("P40", "P45"), &Setup::default());
    assert_eq!(first_error(&r), ("sequence-not-found", 9, 8));
}

#[test]
fn behaviour19_5_m97_calls_blocks_of_the_same_program() {
    // The Haas manual's M97 example in millimetres: N1000 steps Z down
    // 0.1 and goes X2. and back, five times.
    let text = "O00011\nG00 G90 X0 Y0 Z1.\nG01 Z0 F500\nM97 P1000 L5\nG00 G90 Z1.\nM30\nN1000 G01 G91 Z-0.1\nG90 X2.\nG91 Z-0.1\nG90 X0\nM99\n";
    let r = ok(text, &with_control(Control::Haas));
    // Two Z-0.1 steps per pass, five passes: Z0 - 10 × 0.1 = -1.0.
    assert!((lowest_z(&r) + 1.0).abs() < 1e-9, "{}", lowest_z(&r));
    // 2 moves before, 4 per pass (20), then Z1.: 23.
    assert_eq!(r.moves.len(), 23);
    same(r.moves.last().unwrap().to, [0.0, 0.0, 1.0]);
    let p = places(&r, text);
    let first = p.iter().find(|(line, _, _)| *line == 7).unwrap();
    assert_eq!(first.1.as_deref(), Some("O0011 N1000"));
    assert_eq!(first.2, vec!["O0011 line 4", "O0011 N1000"]);
    // No such N: alarm at P.
    let r = run(&text.replace("P1000", "P999"), &with_control(Control::Haas));
    assert_eq!(first_error(&r), ("sequence-not-found", 4, 5));
}

#[test]
fn behaviour19_8_a_runaway_m99_loop_stops_at_the_block_limit_at_its_line() {
    // M99 in the main program goes back to its start, for ever: three
    // blocks a pass (O1, G01, M99). With a limit of 1,000 blocks, blocks
    // 0–999 run; the M99s are blocks 2, 5, …, 998: 333 of them.
    let text = "O1\nG91 G01 X1. F100\nM99\n";
    let options = RunOptions {
        max_blocks: 1000,
        ..RunOptions::default()
    };
    let mut looping = Setup::default();
    looping.settings.main_m99 = Some(MainM99::Loop);
    let r = run_with(text, &looping, options);
    assert_eq!(r.block_count, 1000);
    // X+1 per pass: blocks 1, 4, …, 997 moved, (997 - 1) / 3 + 1 = 333.
    assert_eq!(r.moves.len(), 333);
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.code, d.line, d.column), ("too-many-blocks", 3, 1));
    assert!(
        d.message
            .starts_with("M99 at line 3 returned to the start 333 times"),
        "{}",
        d.message
    );
    assert_eq!(r.end, End::Error { line: 3 });
    // Each M99 says so (the first, the 333rd).
    assert_eq!(
        r.blocks[2].explanation(),
        "M99 in the main program: back to its start (1 time)."
    );
    assert_eq!(
        r.blocks[998].explanation(),
        "M99 in the main program: back to its start (333 times)."
    );
}

#[test]
fn behaviour7_42_m99_in_the_main_program_ends_the_run_after_one_pass() {
    // Left out, main_m99 is `once` on every profile: the pass is drawn
    // (X+1 from X0: one move to X1) and the run ends at the M99's line,
    // which says what the control would do.
    let text = "O1\nG91 G01 X1. F100\nM99\n";
    for control in [Control::Yasnac, Control::Fanuc, Control::Haas] {
        let r = ok(text, &with_control(control));
        assert_eq!(r.block_count, 3);
        assert_eq!(r.moves.len(), 1);
        assert_eq!(r.end, End::ProgramEnd { line: 3 });
        assert!(
            r.blocks[2]
                .explanation()
                .starts_with("M99 in the main program: a control goes back to its start and runs the program again until it is stopped"),
            "{}",
            r.blocks[2].explanation()
        );
    }
    // M99 P20 in the main program: the note names the block it would go
    // on at; the blocks after the M99 never run.
    let r = ok(
        "O1\nN20 G91 G01 X1. F100\nM99 P20\nX5.\n",
        &Setup::default(),
    );
    assert_eq!(r.moves.len(), 1);
    assert!(r.blocks[2].explanation().contains("goes on at N20"));
    // In a subprogram M99 returns as before, whatever the setting.
    let r = ok(
        "O1\nM98 P2\nG00 X0\nM30\nO2\nG00 X7.\nM99\n",
        &Setup::default(),
    );
    assert_eq!(r.moves.len(), 2);
    assert_eq!(r.end, End::ProgramEnd { line: 4 });
}

#[test]
fn behaviour19_8_a_subprogram_without_m99_stops_at_its_end() {
    let text = "O1\nM98 P2\nM30\nO2\nG00 X1.\n%\n";
    let r = run(text, &Setup::default());
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(d.code, "missing-m99");
    assert!(
        d.message.contains("O0002 (called at O0001 line 2)"),
        "{}",
        d.message
    );
    assert_eq!(r.moves.len(), 1);
}

#[test]
fn behaviour19_9_a_checkpoint_inside_a_subprogram_gives_the_same_report() {
    let m97 = "O11\nG00 X0 Y0 Z0\nM97 P100 L3\nM30\nN100 G91 G01 X1. F100\nM99\n";
    for (text, setup) in [
        (STEP_DOWN, Setup::default()),
        (NESTED, Setup::default()),
        (m97, with_control(Control::Haas)),
    ] {
        let full = run(text, &setup);
        for every in [1, 2, 3, 7, 1000] {
            let (light, checkpoints) = checkpointed(text, &setup, every);
            assert!(checkpoints.calls);
            assert_eq!(light.block_count, full.block_count);
            assert_eq!(light.moves, full.moves);
            assert_eq!(light.diagnostics, full.diagnostics);
            assert_eq!(light.end, full.end);
            for (i, kept) in full.blocks.iter().enumerate() {
                let again = report_at(text, &setup, &checkpoints, i as u32);
                assert_eq!(again.as_ref(), Some(kept), "block {i}, every {every}");
            }
        }
    }
    // A checkpoint inside the subprogram: every 5 blocks of STEP_DOWN puts
    // one before block 5 (N1 of the first pass, line 10), whose report
    // names the call stack.
    let (_, checkpoints) = checkpointed(STEP_DOWN, &Setup::default(), 5);
    let b = report_at(STEP_DOWN, &Setup::default(), &checkpoints, 5).unwrap();
    assert_eq!(b.span.line, 10);
    assert_eq!(b.place.unwrap().stack, vec!["O1000 N30", "O2000"]);
}

#[test]
fn behaviour19_9_a_program_with_calls_runs_the_same_on_two_threads() {
    // The run on two threads hands such a program to one thread.
    let setup = Setup::default();
    let one = run_with(STEP_DOWN, &setup, RunOptions::default());
    match offsetlab::run_on_two_threads(STEP_DOWN, &setup, RunOptions::default()) {
        Some(two) => assert_eq!(two, one),
        None => assert_eq!(
            offsetlab::run_pipelined(STEP_DOWN, &setup, RunOptions::default()),
            one
        ),
    }
}
