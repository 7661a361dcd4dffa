//! Behaviour 20.11–20.16 (`docs/behaviour.md`): Custom Macro B's jumps
//! and loops in a run — GOTO and IF … GOTO (the sequence number searched
//! forward, then from the program's start), WHILE … DO m / END m and DO m
//! alone, their nesting rules and alarms, the block limit's message for a
//! loop that never ends, checkpoints inside a loop, and the program's own
//! alarm (`#3000`) and message stop (`#3006`). Values worked out by hand
//! in the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::machine::EventKind;
use offsetlab::report::Run;
use offsetlab::{End, RunOptions, Setup, report_at, run, run_observed, run_with};
use proptest::prelude::*;

/// The reports of the blocks on `line`, in the order they ran.
fn on_line(r: &Run, line: u32) -> Vec<&offsetlab::report::BlockReport> {
    r.blocks.iter().filter(|b| b.span.line == line).collect()
}

/// The one error of a run: (code, line, column) and its message.
fn the_error(r: &Run) -> (&'static str, u32, u32, String) {
    let e: Vec<_> = r.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert_eq!(e.len(), 1, "{:#?}", r.diagnostics);
    (e[0].code, e[0].line, e[0].column, e[0].message.clone())
}

fn limited(max_blocks: usize) -> RunOptions {
    RunOptions {
        max_blocks,
        ..RunOptions::default()
    }
}

#[test]
fn behaviour20_13_a_bolt_circle_drilled_by_a_while_loop() {
    let r = ok(programs::WHILE_BOLT_CIRCLE, &mill(&[]));
    // Hole k at 60k degrees on R50: X = 50 cos 60k, Y = 50 sin 60k.
    // k=0: (50, 0); k=1: (25, 43.30127 → 43.301); k=2: (-25, 43.301);
    // k=3: (-50, 50 sin 180 = 6e-15 → 0); k=4: (-25, -43.301); k=5: (25, -43.301).
    let want = [
        (50.0, 0.0),
        (25.0, 43.301),
        (-25.0, 43.301),
        (-50.0, 0.0),
        (-25.0, -43.301),
        (25.0, -43.301),
    ];
    let holes = on_line(&r, 8);
    assert_eq!(holes.len(), 6);
    for (b, (x, y)) in holes.iter().zip(want) {
        assert!(
            (b.state.programmed[0] - x).abs() < 1e-9 && (b.state.programmed[1] - y).abs() < 1e-9,
            "{:?} against ({x}, {y})",
            b.state.programmed
        );
    }
    // 5 blocks before the loop, 5 a pass for 6 passes, the WHILE that
    // finds [6 LT 6] false, G80 and M30: 5 + 30 + 1 + 2 = 38.
    assert_eq!(r.block_count, 38);
    assert_eq!(r.end, End::ProgramEnd { line: 12 });
    // Each WHILE and END says what it did.
    let whiles = on_line(&r, 6);
    assert_eq!(whiles.len(), 7);
    assert_eq!(whiles[0].explanation(), "WHILE [#3 LT #2] true: DO 1.");
    assert_eq!(
        whiles[2].explanation(),
        "WHILE [#3 LT #2] true: DO 1, pass 3."
    );
    assert_eq!(
        whiles[6].explanation(),
        "WHILE [#3 LT #2] false: on after END 1 (line 10)."
    );
    let ends = on_line(&r, 10);
    assert_eq!(
        ends[1].explanation(),
        "END 1: back to WHILE at line 6, pass 3."
    );
}

#[test]
fn behaviour20_11_an_if_goto_counting_loop() {
    // #1 = 1 + 2 + 3 + 4 + 5 = 15: five passes of lines 3–5, the fifth
    // finding [6 LE 5] false.
    let text =
        "#1 = 0\n#2 = 1\nN10 #1 = #1 + #2\n#2 = #2 + 1\nIF [#2 LE 5] GOTO 10\nG00 X#1\nM30\n";
    let r = ok(text, &mill(&[]));
    assert!((on_line(&r, 6).last().unwrap().state.programmed[0] - 15.0).abs() < 1e-9);
    // 2 + 5 × 3 + 2 = 19 blocks.
    assert_eq!(r.block_count, 19);
    let ifs = on_line(&r, 5);
    assert_eq!(ifs[0].explanation(), "IF [#2 LE 5] true: GOTO 10, line 3.");
    assert_eq!(
        ifs[4].explanation(),
        "IF [#2 LE 5] GOTO 10: the condition does not hold, no jump."
    );
}

#[test]
fn behaviour20_11_goto_rounds_its_number_and_searches_forward_first() {
    // GOTO #1 with #1 = 19.6 rounds to 20 (Haas's example: 4.49 → N4,
    // 4.5 → N5); GOTO [#1 - 9.5] = 10.1 → 10.
    let text = "#1 = 19.6\nGOTO #1\nX1.\nN20 G00 X2.\nIF [#2 EQ 1] GOTO 30\n#2 = 1\nGOTO [#1 - 9.5]\nN30 M30\nN10 Y5.\nGOTO 30\n";
    let r = ok(text, &mill(&[]));
    let lines: Vec<u32> = r.blocks.iter().map(|b| b.span.line).collect();
    // 1, 2 → N20 (4), 5 (#2 vacant: [vacant EQ 1] false), 6, 7 → N10
    // (9), 10 → N30 (8).
    assert_eq!(lines, vec![1, 2, 4, 5, 6, 7, 9, 10, 8]);
    // Two blocks N10: GOTO searches from the block after it to the end,
    // then from the start; the N10 after the GOTO is found first (the
    // first N10 of the program would loop for ever).
    let text = "N10 G00 X1.\nGOTO 10\nX2.\nN10 X3.\nM30\n";
    let r = ok(text, &mill(&[]));
    let lines: Vec<u32> = r.blocks.iter().map(|b| b.span.line).collect();
    assert_eq!(lines, vec![1, 2, 4, 5]);
    assert!((r.blocks[2].state.programmed[0] - 3.0).abs() < 1e-9);
    // Back to the start when nothing after it has the number.
    let text = "#1 = 0\nN5 #1 = #1 + 1\nIF [#1 LT 3] GOTO 5\nG00 X#1\n";
    let r = ok(text, &mill(&[]));
    // Lines 2–3 three times: #1 = 3.
    assert!((r.blocks.last().unwrap().state.programmed[0] - 3.0).abs() < 1e-9);
}

#[test]
fn behaviour20_13_nested_loops_do1_and_do2() {
    let text = "G90 G21 G00 Z5.
#1 = 0
WHILE [#1 LT 3] DO1
#2 = 0
WHILE [#2 LT 2] DO2
G01 X[#1*10] Y[#2*20] F200
#2 = #2 + 1
END2
#1 = #1 + 1
END1
M30
";
    let r = ok(text, &mill(&[]));
    // #1 = 0, 1, 2 (X 0, 10, 20) and within each #2 = 0, 1 (Y 0, 20).
    let points: Vec<(f64, f64)> = on_line(&r, 6)
        .iter()
        .map(|b| (b.state.programmed[0], b.state.programmed[1]))
        .collect();
    assert_eq!(
        points,
        vec![
            (0.0, 0.0),
            (0.0, 20.0),
            (10.0, 0.0),
            (10.0, 20.0),
            (20.0, 0.0),
            (20.0, 20.0)
        ]
    );
    // An outer pass: WHILE1, #2 = 0, 2 × (WHILE2, G01, #2, END2), WHILE2
    // false, #1, END1 = 2 + 8 + 1 + 2 = 13 blocks; 2 + 3 × 13 + 1 + 1 = 43.
    assert_eq!(r.block_count, 43);
    // The inner loop starts afresh at each outer pass: its first WHILE of
    // the second outer pass is pass 1 again.
    let inner = on_line(&r, 5);
    assert_eq!(inner[3].explanation(), "WHILE [#2 LT 2] true: DO 2.");
}

#[test]
fn behaviour20_13_loop_numbers_are_reused_and_a_goto_may_leave_a_loop() {
    // The first loop is left by the GOTO at #1 = 3 (X3); DO1 is then free
    // for the second loop, which counts on to 5 (Y5).
    let text = "#1 = 0
WHILE [#1 LT 10] DO1
#1 = #1 + 1
IF [#1 EQ 3] GOTO 20
END1
N20 G00 X#1
WHILE [#1 LT 5] DO1
#1 = #1 + 1
END1
G00 Y#1
M30
";
    let r = ok(text, &mill(&[]));
    assert!((on_line(&r, 6).last().unwrap().state.programmed[0] - 3.0).abs() < 1e-9);
    assert!((on_line(&r, 10).last().unwrap().state.programmed[1] - 5.0).abs() < 1e-9);
}

#[test]
fn behaviour20_12_do_without_while_loops_until_a_goto_leaves() {
    // DO1 … END1 has no condition: the IF … GOTO leaves it after 4 moves.
    let text = "G91 G01 F100\n#1 = 0\nDO1\nX1.\n#1 = #1 + 1\nIF [#1 GE 4] GOTO 9\nEND1\nN9 M30\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.moves.len(), 4);
    let dos = on_line(&r, 3);
    assert_eq!(dos[0].explanation(), "DO 1: a loop without a condition.");
    assert_eq!(
        dos[3].explanation(),
        "DO 1: a loop without a condition, pass 4."
    );
    assert_eq!(
        on_line(&r, 7)[0].explanation(),
        "END 1: back to DO 1 at line 3, pass 2."
    );
}

#[test]
fn behaviour20_14_flow_alarms_stop_at_their_line_and_column() {
    let setup = mill(&[]);
    // PS0128: no N99 (the number at column 6).
    let r = run("G00 X1.\nGOTO 99\nM30\n", &setup);
    let (code, line, col, msg) = the_error(&r);
    assert_eq!((code, line, col), ("macro-sequence-number", 2, 6));
    assert!(
        msg.starts_with("PS0128 ILLEGAL MACRO SEQUENCE NUMBER"),
        "{msg}"
    );
    // The GOTO block does not count as run.
    assert_eq!(r.block_count, 1);
    assert_eq!(r.end, End::Error { line: 2 });
    // PS0124: a WHILE whose END is missing.
    let r = run("#1 = 0\nWHILE [#1 LT 2] DO1\n#1 = #1 + 1\nM30\n", &setup);
    let (code, line, col, msg) = the_error(&r);
    assert_eq!((code, line, col), ("macro-missing-end", 2, 1));
    assert!(msg.starts_with("PS0124 MISSING END STATEMENT"), "{msg}");
    // PS0126: END without a DO running.
    let r = run("X1.\nEND1\nM30\n", &setup);
    let (code, line, _, msg) = the_error(&r);
    assert_eq!((code, line), ("macro-loop-number", 2));
    assert!(msg.starts_with("PS0126 ILLEGAL LOOP NUMBER"), "{msg}");
    assert!(msg.contains("has no DO 1 running"), "{msg}");
    // PS0126: overlapping ranges — END1 while DO2 inside it runs.
    let overlap =
        "#1 = 0\nWHILE [#1 LT 2] DO1\n#2 = 0\nWHILE [#2 LT 2] DO2\n#2 = #2 + 1\nEND1\nEND2\n";
    let (code, line, _, msg) = the_error(&run(overlap, &setup));
    assert_eq!((code, line), ("macro-loop-number", 6));
    assert!(msg.contains("never overlap"), "{msg}");
    // …and at the WHILE when its condition fails and the skip would cross it.
    let overlap_false = overlap.replace("[#1 LT 2]", "[#1 LT 0]");
    let (code, line, _, msg) = the_error(&run(&overlap_false, &setup));
    assert_eq!((code, line), ("macro-loop-number", 2));
    assert!(msg.contains("never overlap"), "{msg}");
    // PS0126: DO1 inside a running DO1.
    let (code, line, _, _) = the_error(&run(
        "WHILE [1 LT 2] DO1\nWHILE [1 LT 2] DO1\nEND1\nEND1\n",
        &setup,
    ));
    assert_eq!((code, line), ("macro-loop-number", 2));
    // A jump into a loop that is not running: at the GOTO.
    let into = "GOTO 10\n#1 = 0\nWHILE [#1 LT 2] DO1\nN10 #1 = #1 + 1\nEND1\n";
    let (code, line, col, msg) = the_error(&run(into, &setup));
    assert_eq!((code, line, col), ("macro-loop-number", 1, 1));
    assert!(msg.contains("leads into the loop DO 1 of line 3"), "{msg}");
    // A loop number other than 1–3 (a parse error, PS0126) and a vacant
    // jump number (PS0128).
    // (each of the two lines is a parse error of its own).
    assert_eq!(
        errors("WHILE [1 LT 2] DO4\nEND4\n", &setup),
        vec!["macro-loop-number", "macro-loop-number"]
    );
    let (code, line, _, _) = the_error(&run("GOTO #1\n", &setup));
    assert_eq!((code, line), ("macro-vacant", 1));
    // Division by zero in a WHILE's condition.
    let (code, line, col, _) = the_error(&run("WHILE [1/#5 LT 2] DO1\nEND1\n", &setup));
    assert_eq!((code, line, col), ("macro-zero-divide", 1, 10));
}

#[test]
fn behaviour20_15_a_runaway_while_stops_at_the_block_limit_at_its_line() {
    // #1 only grows: [#1 GE 0] always holds. With a limit of 1,000
    // blocks, blocks 0–999 run: #1 = 0, then WHILE, #1, END from block 1;
    // the WHILEs are blocks 1, 4, …, 997: 333 passes; the loop began at
    // block 1, so it ran 1000 - 1 = 999 blocks.
    let text = "#1 = 0\nWHILE [#1 GE 0] DO1\n#1 = #1 + 1\nEND1\n";
    let r = run_with(text, &Setup::default(), limited(1000));
    assert_eq!(r.block_count, 1000);
    let (code, line, col, msg) = the_error(&r);
    assert_eq!((code, line, col), ("too-many-blocks", 2, 1));
    assert!(
        msg.starts_with("WHILE at line 2 ran 999 blocks without ending (333 passes)"),
        "{msg}"
    );
    // DO without WHILE: DO, G01, END from block 0; DOs at 0, 3, …, 999:
    // 334 passes; G01 at 1, 4, …, 997: 333 moves.
    let text = "DO1\nG91 G01 X1. F100\nEND1\n";
    let r = run_with(text, &Setup::default(), limited(1000));
    assert_eq!(r.moves.len(), 333);
    let (_, line, _, msg) = the_error(&r);
    assert_eq!(line, 1);
    assert!(
        msg.starts_with("DO 1 at line 1 ran 1,000 blocks without ending (334 passes)"),
        "{msg}"
    );
}

#[test]
fn behaviour20_15_a_runaway_goto_loop_says_how_often_it_jumped_back() {
    // N1, GOTO: blocks 0–999, the GOTOs at 1, 3, …, 999: 500 jumps back.
    let text = "N1 G91 G01 X1. F100\nGOTO 1\n";
    let r = run_with(text, &Setup::default(), limited(1000));
    let (code, line, col, msg) = the_error(&r);
    assert_eq!((code, line, col), ("too-many-blocks", 2, 1));
    assert!(
        msg.starts_with("GOTO at line 2 jumped back 500 times: the program never ends"),
        "{msg}"
    );
    assert_eq!(r.moves.len(), 500);
}

#[test]
fn behaviour20_15_loops_in_a_subprogram_end_with_it() {
    // O2's loop runs twice a call (X+1 each), called twice: X4. The
    // second call's DO1 is a fresh loop (the first ended with its M99).
    let text = "O1\nG91 G01 F100\nM98 P2 L2\nM30\nO2\n#1 = 0\nWHILE [#1 LT 2] DO1\nX1.\n#1 = #1 + 1\nEND1\nM99\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.moves.len(), 4);
    assert!((r.moves.last().unwrap().to[0] - 4.0).abs() < 1e-9);
    // An M99 inside a running loop returns, and the loop is over.
    let text = "O1\nM98 P2\nM98 P2\nM30\nO2\nDO1\nG91 G01 X1. F100\nM99\nEND1\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.moves.len(), 2);
}

#[test]
fn behaviour20_16_alarm_3000_stops_the_run_with_the_programs_message() {
    let text = "G00 X1.\n#1 = 0\nIF [#1 EQ 0] THEN #3000 = 12 (DIAMETER MISSING)\nX2.\n";
    let r = run(text, &mill(&[]));
    let (code, line, col, msg) = the_error(&r);
    // 3000 + 12 = 3012; the statement after THEN starts at column 19.
    assert_eq!((code, line, col), ("macro-alarm", 3, 19));
    assert_eq!(msg, "alarm 3012: DIAMETER MISSING");
    assert_eq!(r.block_count, 2);
    assert_eq!(r.end, End::Error { line: 3 });
    // #3000 cannot be read.
    let (code, line, _, _) = the_error(&run("#1 = #3000\n", &mill(&[])));
    assert_eq!((code, line), ("macro-system-variable", 1));
}

#[test]
fn behaviour20_16_message_stop_3006_is_a_stop_and_the_run_goes_on() {
    let text = "G00 X1.\n#3006 = 1 (TURN THE PART OVER)\nX2.\nM30\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.block_count, 4);
    assert_eq!(
        r.blocks[1].explanation(),
        "#3006 = 1.000: the control stops with the message \"TURN THE PART OVER\" and waits for cycle start; the run goes on."
    );
    assert!(
        r.events
            .iter()
            .any(|e| e.line == 2 && e.kind == EventKind::ProgramStop)
    );
}

#[test]
fn behaviour20_15_a_checkpoint_inside_a_loop_gives_the_same_report() {
    let nested = "#1 = 0\nWHILE [#1 LT 3] DO1\n#2 = 0\nWHILE [#2 LT 2] DO2\nG01 X[#1*10] Y[#2*20] F200\n#2 = #2 + 1\nEND2\n#1 = #1 + 1\nEND1\nM30\n";
    let setup = mill(&[]);
    for text in [programs::WHILE_BOLT_CIRCLE, nested] {
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
}

#[test]
fn behaviour20_15_a_program_with_loops_runs_the_same_on_two_threads() {
    let setup = mill(&[]);
    let one = run_with(programs::WHILE_BOLT_CIRCLE, &setup, RunOptions::default());
    match offsetlab::run_on_two_threads(programs::WHILE_BOLT_CIRCLE, &setup, RunOptions::default())
    {
        Some(two) => assert_eq!(two, one),
        None => assert_eq!(
            offsetlab::run_pipelined(programs::WHILE_BOLT_CIRCLE, &setup, RunOptions::default()),
            one
        ),
    }
}

/// A line of a random program: moves, counters, jumps and loops.
fn line() -> impl Strategy<Value = String> {
    prop_oneof![
        (1u32..6).prop_map(|n| format!("N{n} G91 G01 X1. F100")),
        Just("#1 = #1 + 1".to_string()),
        Just("#1 = 0".to_string()),
        (1u32..7).prop_map(|n| format!("GOTO {n}")),
        (0u32..5, 1u32..7).prop_map(|(c, n)| format!("IF [#1 LT {c}] GOTO {n}")),
        (0u32..5, 1u8..4).prop_map(|(c, m)| format!("WHILE [#1 LT {c}] DO{m}")),
        (1u8..4).prop_map(|m| format!("DO{m}")),
        (1u8..4).prop_map(|m| format!("END{m}")),
        (1u32..6).prop_map(|n| format!("N{n} #1 = #1 - 1")),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// behaviour 20.15: whatever its jumps and loops, no program runs past
    /// the block limit, none panics, and a stop is an error with its line.
    #[test]
    fn behaviour20_15_no_program_of_jumps_and_loops_runs_past_the_limit(
        lines in prop::collection::vec(line(), 1..14)
    ) {
        let text = lines.join("\n");
        let r = run_with(&text, &Setup::default(), limited(500));
        prop_assert!(r.block_count as usize <= 500);
        prop_assert_eq!(r.blocks.len(), r.block_count as usize);
        if let End::Error { line } = r.end {
            prop_assert!(line >= 1 && line as usize <= lines.len());
            prop_assert!(r.diagnostics.iter().any(|d| d.is_error()));
        }
        // The page's way: checkpoints and reports made again agree.
        let options = RunOptions {
            keep_blocks: false,
            checkpoint_every: 7,
            max_blocks: 500,
            ..RunOptions::default()
        };
        let (light, checkpoints) = run_observed(&text, &Setup::default(), options, &mut ());
        prop_assert_eq!(light.block_count, r.block_count);
        let last = r.block_count.saturating_sub(1);
        if r.block_count > 0 && r.block_count < 500 {
            let again = report_at(&text, &Setup::default(), &checkpoints, last);
            prop_assert_eq!(again.as_ref(), r.blocks.last());
        }
    }
}

#[test]
fn behaviour20_19_fanuc_reads_the_abbreviations_of_the_macro_words() {
    // WH … DO1 / EN1 loops while #1 <= 3: #1 = 0, 1, 2, 3, four passes of
    // X+1 (X4); #1 = 4 > 3, so GO20 passes over the G00 X50.; #3 = SQRT 16
    // + ABS -2 = 6; TH sets #4 = ROUND 2.6 = 3; #5 = 3 XOR 3 = 0, so the
    // last block ends at X4 Y3 Z0.
    let text = "#1=0\n#2=3\nWH[[#1LT#2]OR[#1EQ#2]]DO1\nG91 G01 X1. F100\n#1=#1+1\nEN1\n\
                IF[#1GT3]GO20\nG00 X50.\nN20 #3=SQ[16]+AB[-2]\nIF[#3EQ6]TH#4=RO[2.6]\n\
                #5=[#4XO3]\nG90 G00 Y#4 Z#5\nM30\n";
    let mut fanuc = Setup::default();
    fanuc.settings.control = offsetlab::setup::Control::Fanuc;
    let r = ok(text, &fanuc);
    assert_eq!(on_line(&r, 4).len(), 4);
    assert!(on_line(&r, 8).is_empty());
    same(r.moves.last().unwrap().to, [4.0, 3.0, 0.0]);
    // Haas and YASNAC write the words in full: the first abbreviation
    // stops the run, its message naming the word it stands for.
    for control in [
        offsetlab::setup::Control::Haas,
        offsetlab::setup::Control::Yasnac,
    ] {
        let mut s = Setup::default();
        s.settings.control = control;
        let r = run(text, &s);
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!((d.code, d.line, d.column), ("macro-expression", 3, 1));
        assert!(
            d.message.contains("`WH` is Fanuc's abbreviation of WHILE"),
            "{}",
            d.message
        );
        assert_eq!(r.moves.len(), 0);
    }
    // The setting wins over the profile.
    let mut s = Setup::default();
    s.settings.macro_abbreviations = Some(offsetlab::setup::MacroAbbreviations::Fanuc);
    same(ok(text, &s).moves.last().unwrap().to, [4.0, 3.0, 0.0]);
}
