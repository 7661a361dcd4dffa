//! Behaviour 21 (`docs/behaviour.md`): macro calls and system variables —
//! G65 with argument specification I and II, a level of local variables
//! per call, nesting, the G66 modal call and G67, and the system variables
//! of modal information, positions, the additional work systems, the
//! lathe's tool offsets and the clocks. Values are worked out by hand in
//! the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use std::collections::BTreeMap;

use common::*;
use offsetlab::report::Run;
use offsetlab::view::block_view;
use offsetlab::{RunOptions, report_at, run, run_with};

/// The last value the run gave each variable (None: vacant).
fn variables(r: &Run, text: &str) -> BTreeMap<u32, Option<f64>> {
    let mut m = BTreeMap::new();
    for b in &r.blocks {
        for v in block_view(b, text).variables_set {
            m.insert(v.variable, v.value);
        }
    }
    m
}

/// The end points of the moves, X and Y.
fn ends(r: &Run) -> Vec<[f64; 2]> {
    r.moves.iter().map(|m| [m.to[0], m.to[1]]).collect()
}

#[track_caller]
fn near(got: &[[f64; 2]], want: &[[f64; 2]]) {
    assert_eq!(got.len(), want.len(), "{got:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            (g[0] - w[0]).abs() < 1e-9 && (g[1] - w[1]).abs() < 1e-9,
            "got {got:?}, want {want:?}"
        );
    }
}

#[test]
fn behaviour21_1_a_bolt_circle_by_g65() {
    let r = ok(programs::G65_BOLT_CIRCLE, &mill(&[]));
    // 20 cos 45° = 20 sin 45° = 14.1421356 → 14.142 (the least increment):
    // (10 ± 14.142, 5 ± 14.142) (the rapid to (0, 0) where the tool
    // stands makes no move).
    near(
        &ends(&r),
        &[
            [24.142, 19.142],
            [-4.142, 19.142],
            [-4.142, -9.142],
            [24.142, -9.142],
        ],
    );
    // The caller's #1 (7) is back after the calls.
    assert_eq!(variables(&r, programs::G65_BOLT_CIRCLE)[&101], Some(7.0));
    // The call's sentence names the arguments and their locals.
    let v = at_line(&r, programs::G65_BOLT_CIRCLE, 4);
    assert!(
        v.explanation.contains(
            "G65 P9010: calls O9010 with X=#24=10.000, Y=#25=5.000, R=#18=20.000, A=#1=45.000"
        ),
        "{}",
        v.explanation
    );
    assert!(
        v.explanation
            .contains("local variable level 1; it returns to line 5")
    );
    // Inside the macro the stack shows the call and its level.
    let inside = r
        .blocks
        .iter()
        .find(|b| b.span.line == 11)
        .map(|b| block_view(b, programs::G65_BOLT_CIRCLE))
        .unwrap();
    assert_eq!(inside.stack, vec!["O1000 N40 (G65, level 1)", "O9010"]);
}

#[test]
fn behaviour21_1_g65_l_repeats_with_the_same_arguments() {
    // L3: the macro runs three times; its locals start from the arguments
    // each time, a common variable counts: X = #24 + 10 (#100 − 1), 0 to 20.
    let text = "G90 G00 X0 Y0\nG65 P9011 L3 X5.\nM30\nO9011\n#100 = #100 + 1\n#24 = #24 + 10 * [#100 - 1]\nG00 X#24\nM99\n";
    let r = ok(text, &mill(&[]));
    // X 5, 15, 25: #24 is 5. again at each repeat (not 15 + 10).
    near(&ends(&r), &[[5.0, 0.0], [15.0, 0.0], [25.0, 0.0]]);
}

#[test]
fn behaviour21_2_argument_specification_i() {
    let text = "G65 P9000 A1. B2. C3. I4. J5. K6. D7. E8. F9. H11. M13. Q17. R18. S19. T20. U21. V22. W23. X24. Y25. Z26.
M30
O9000
#100 = #1 + #2 + #3
#101 = #4 * 100 + #5 * 10 + #6
#102 = #7 + #8 + #9
#103 = #11 + #13
#104 = #17 + #18 + #19 + #20
#105 = #21 + #22 + #23
#106 = #24 + #25 + #26
#107 = #10
M99
";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    // Each letter's number is its variable's: 1+2+3 = 6; 456; 7+8+9 = 24;
    // 11+13 = 24; 17+18+19+20 = 74; 21+22+23 = 66; 24+25+26 = 75; #10 (no
    // letter) vacant.
    assert_eq!(v[&100], Some(6.0));
    assert_eq!(v[&101], Some(456.0));
    assert_eq!(v[&102], Some(24.0));
    assert_eq!(v[&103], Some(24.0));
    assert_eq!(v[&104], Some(74.0));
    assert_eq!(v[&105], Some(66.0));
    assert_eq!(v[&106], Some(75.0));
    assert_eq!(v[&107], None);
}

#[test]
fn behaviour21_2_an_argument_without_a_point_is_in_least_increments() {
    // G21, increment input: X25 is 0.025 mm, D2 (a whole-number address) is 2.
    let text = "G21\nG65 P9000 X25 D2\nM30\nO9000\n#100 = #24\n#101 = #7\nM99\n";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    assert_eq!(v[&100], Some(0.025));
    assert_eq!(v[&101], Some(2.0));
}

#[test]
fn behaviour21_2_argument_specification_ii_and_the_mixture() {
    // II: A #1, then sets of I, J, K: I2. J3. K4. to #4–#6, I5. J6. K7. to
    // #7–#9, I8. (set 3) to #10.
    let text = "G65 P9000 A1. I2. J3. K4. I5. J6. K7. I8.
G65 P9001 A1.0 B2.0 I-3.0 I4.0 D5.0
M30
O9000
#100 = #4 + #5 + #6
#101 = #7 * 100 + #8 * 10 + #9
#102 = #10
#103 = #11
M99
O9001
#110 = #1
#111 = #2
#112 = #3
#113 = #4
#114 = #5
#115 = #7
M99
";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    // 2+3+4 = 9; 5·100 + 6·10 + 7 = 567; #10 = 8; #11 vacant.
    assert_eq!(v[&100], Some(9.0));
    assert_eq!(v[&101], Some(567.0));
    assert_eq!(v[&102], Some(8.0));
    assert_eq!(v[&103], None);
    // The manual's mixture: I-3.0 is #4, the second I (set 2) is #7, and D
    // (#7) written after it holds: #7 = 5; #3 and #5 vacant.
    assert_eq!(v[&110], Some(1.0));
    assert_eq!(v[&111], Some(2.0));
    assert_eq!(v[&112], None);
    assert_eq!(v[&113], Some(-3.0));
    assert_eq!(v[&114], None);
    assert_eq!(v[&115], Some(5.0));
}

#[test]
fn behaviour21_2_arguments_from_variables_and_expressions() {
    // A#100 and R[#100*2] are evaluated at the call: #1 = 3, #18 = 6.
    let text = "#100 = 3.\nG65 P9000 A#100 R[#100*2]\nM30\nO9000\n#101 = #1\n#102 = #18\nM99\n";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    assert_eq!(v[&101], Some(3.0));
    assert_eq!(v[&102], Some(6.0));
}

#[test]
fn behaviour21_3_locals_are_vacant_at_entry_and_come_back_at_m99() {
    let text = "#1 = 7.\n#5 = 9.\nG65 P9000 A1.\n#102 = #1\n#103 = #5\nM30\nO9000\n#100 = #5\n#101 = #1\n#5 = 4.\nM99\n";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    // In the macro: #5 vacant (no argument), #1 = 1; it sets its own #5 = 4.
    assert_eq!(v[&100], None);
    assert_eq!(v[&101], Some(1.0));
    // Back in the main program: #1 = 7 and #5 = 9, as before the call.
    assert_eq!(v[&102], Some(7.0));
    assert_eq!(v[&103], Some(9.0));
}

#[test]
fn behaviour21_3_the_words_of_a_g65_block_are_no_motion() {
    // X and Z after G65 are arguments: the tool does not move at the call.
    let text = "G90 G00 X1. Y0 Z0\nG65 P9000 X50. Z-10.\nM30\nO9000\nM99\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.moves.len(), 1);
    // A G code after G65 is refused, never run or passed over.
    let bad = "G65 P9000 G01 X1.\nM30\nO9000\nM99\n";
    let r = run(bad, &mill(&[]));
    assert_eq!(first_error(&r), ("call-words", 1, 11));
    // G65 without P; P of no program (PS0076).
    assert_eq!(first_error(&run("G65 A1.\n", &mill(&[]))).0, "missing-word");
    let r = run("G65 P9999 A1.\n", &mill(&[]));
    assert_eq!(first_error(&r), ("program-not-found", 1, 5));
}

#[test]
fn behaviour21_4_macro_calls_nest_four_deep_then_ps0077() {
    // O9000 counts its level in #100 and calls itself: levels 1 to 4 open,
    // the call at level 4 is the fifth: PS0077 at its G65 (line 5, column 1).
    let text = "G65 P9000\nM30\nO9000\n#100 = #100 + 1\nG65 P9000\nM99\n";
    let r = run(text, &mill(&[]));
    assert_eq!(first_error(&r), ("nesting-too-deep", 5, 1));
    assert_eq!(variables(&r, text)[&100], Some(4.0));
    // Setting 7.45 raises it: with 6, the sixth call fails at level 6.
    let mut s = mill(&[]);
    s.settings.macro_nesting = Some(6);
    let r = run(text, &s);
    assert_eq!(variables(&r, text)[&100], Some(6.0));
}

#[test]
fn behaviour21_4_subprograms_inside_macros_count_apart() {
    // Four macro levels (O9000 → O9001 → O9002 → O9003), and an M98 in the
    // deepest: with setting 7.37 at 1, the M98 nesting counts M98 calls
    // only, so the one M98 is allowed at level 4.
    let text = "G65 P9000\nM30\nO9000\nG65 P9001\nM99\nO9001\nG65 P9002\nM99\nO9002\nG65 P9003\nM99\nO9003\n#100 = 4.\nM98 P2000\nM99\nO2000\n#102 = #100\nM99\n";
    let mut s = mill(&[]);
    s.settings.subprogram_nesting = Some(1);
    let r = ok(text, &s);
    assert_eq!(variables(&r, text)[&102], Some(4.0));
}

#[test]
fn behaviour21_5_g66_calls_after_each_move_until_g67() {
    let text = "G90 G00 X0 Y0 Z10.
G66 P9020 Z-5. R2.
G00 X10.
X20.
M05
G04 X1.
G67
X30.
M30
O9020
G01 Z#26 F100.
G00 Z#18
M99
";
    let r = ok(text, &mill(&[]));
    // The G66 block does not move or call; X10. and X20. move, then the
    // macro drills (Z−5, back to Z2) — its own moves call nothing; M05
    // (no axis) and G04 X1. (X a time) call nothing; after G67 X30. moves
    // only.
    let z: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    let want = [
        [0.0, 0.0, 10.0],
        [10.0, 0.0, 10.0],
        [10.0, 0.0, -5.0],
        [10.0, 0.0, 2.0],
        [20.0, 0.0, 2.0],
        [20.0, 0.0, -5.0],
        [20.0, 0.0, 2.0],
        [30.0, 0.0, 2.0],
    ];
    assert_eq!(z.len(), want.len(), "{z:?}");
    for (g, w) in z.iter().zip(want) {
        same(*g, w);
    }
    let v = at_line(&r, text, 3);
    assert!(
        v.explanation
            .contains("G66 (line 2): after this move, calls O9020 with Z=#26=-5.000, R=#18=2.000")
    );
    assert!(
        at_line(&r, text, 7)
            .explanation
            .contains("G67: the modal call of O9020 (G66 at line 2) ends")
    );
}

#[test]
fn behaviour21_7_modal_information_reads_the_codes_in_force() {
    let text = "G91 G01 X10. Y5. F200.
#100 = #4001
#101 = #4003
#102 = #4109
#103 = #4014
#104 = #4006
#105 = #4012
G66 P9000
#106 = #4012
G67
M30
O9000
M99
";
    let r = ok(text, &mill(&[]));
    let v = variables(&r, text);
    // G01, G91, F200, G54, G21 (the setup's mm), G67; in G66 #4012 is 66.
    assert_eq!(v[&100], Some(1.0));
    assert_eq!(v[&101], Some(91.0));
    assert_eq!(v[&102], Some(200.0));
    assert_eq!(v[&103], Some(54.0));
    assert_eq!(v[&104], Some(21.0));
    assert_eq!(v[&105], Some(67.0));
    assert_eq!(v[&106], Some(66.0));
}

#[test]
fn behaviour21_8_positions_in_work_and_machine_coordinates() {
    // G55 at machine X100 Y-50; H1 = 25 (G43).
    let mut s = mill(&[(1, 25.0)]);
    s.work_offsets.by_p_mut(2).x = 100.0;
    s.work_offsets.by_p_mut(2).y = -50.0;
    let text = "G90 G55 G00 X10. Y5.
G43 H1 Z2.
#100 = #5001
#101 = #5002
#102 = #5021
#103 = #5022
#104 = #5043
#105 = #5023
#106 = #5083
#107 = #4111
#5001 = 1.
";
    let r = run(text, &s);
    let v = variables(&r, text);
    // Work (10, 5); machine X 100 + 10 = 110, Y −50 + 5 = −45; Z: the tool
    // point at 2, its reference point 2 + 25 = 27 (work = machine: G55 Z 0),
    // the length offset 25, H1.
    assert_eq!(v[&100], Some(10.0));
    assert_eq!(v[&101], Some(5.0));
    assert_eq!(v[&102], Some(110.0));
    assert_eq!(v[&103], Some(-45.0));
    assert_eq!(v[&104], Some(27.0));
    assert_eq!(v[&105], Some(27.0));
    assert_eq!(v[&106], Some(25.0));
    assert_eq!(v[&107], Some(1.0));
    // A position is read only: PS0116.
    assert_eq!(first_error(&r), ("macro-write-protected", 11, 1));
}

#[test]
fn behaviour21_9_the_additional_work_systems() {
    // #7001 + 20 (P − 1) + axis: #7021 is G54.1 P2 X. In force, its zero
    // moves at once: X10. in P2 with its zero at 40 is machine X 50, then
    // X 60 once the zero is 50.
    let text = "G54.1 P2 G90 G00 X10. Y0\n#100 = #7021\n#7021 = 50.\nX10.\n";
    let mut s = mill(&[]);
    s.extended_work_offsets.insert(
        2,
        offsetlab::setup::Position {
            x: 40.0,
            ..Default::default()
        },
    );
    let r = ok(text, &s);
    assert_eq!(variables(&r, text)[&100], Some(40.0));
    let last = r.blocks.last().unwrap();
    assert!((block_view(last, text).machine.x - 60.0).abs() < 1e-9);
}

#[test]
fn behaviour21_10_lathe_offsets_written_are_read_by_the_next_t_code() {
    // #2001 X wear, #2701 X geometry of offset 01: 0.6 + 1.0 = 1.6 on X,
    // Z wear 0.1 by G10 before: T0101 then moves X +1.6, Z +0.1.
    let text = "G21 G00
G10 P1 Z0.1
#2001 = 0.6
#2701 = 1.
#100 = #2001
#101 = #2101
T0101
G00 X50. Z0
";
    let r = ok(text, &lathe(&[]));
    let v = variables(&r, text);
    assert_eq!(v[&100], Some(0.6));
    assert_eq!(v[&101], Some(0.1));
    let last = r.blocks.last().unwrap();
    same(last.state.actual, [51.6, 0.0, 0.1]);
}

#[test]
fn behaviour21_15_lathe_work_offsets_are_x_first_and_z_second() {
    // A two-axis lathe: #5221 G54 X, #5222 G54 Z, #5242 G55 Z (20 numbers
    // a system). G54 Z at −100 in the setup.
    let mut s = lathe(&[]);
    s.work_offsets.by_p_mut(1).z = -100.0;
    let text = "G54 G00 X20. Z0
#100 = #5221
#101 = #5222
#5221 = 10.
X20. Z0
#102 = #5021
#103 = #5022
#5242 = -50.
G55 X20. Z0
#104 = #5021
#105 = #5022
#106 = #5242
#5223 = 1.
";
    let r = run(text, &s);
    let v = variables(&r, text);
    assert_eq!(v[&100], Some(0.0));
    assert_eq!(v[&101], Some(-100.0));
    // G54 in force: its X zero moves to 10 at once (the tool stays, its
    // work X reads 10), so X20. Z0 after it is machine X 10 + 20 = 30,
    // Z −100 + 0 = −100.
    assert_eq!(v[&102], Some(30.0));
    assert_eq!(v[&103], Some(-100.0));
    // G55 (X 0, Z −50 as written): X 20, Z −50.
    assert_eq!(v[&104], Some(20.0));
    assert_eq!(v[&105], Some(-50.0));
    assert_eq!(v[&106], Some(-50.0));
    // A third axis number of a two-axis lathe is no variable offsetlab has.
    assert_eq!(first_error(&r), ("macro-system-variable", 13, 1));
}

#[test]
fn behaviour21_11_clocks_stand_still_and_the_date_is_refused() {
    // #3001 reads 0 at the start, keeps what is written; #3011 (the date) is
    // no value a run has.
    let text = "#100 = #3001\n#3001 = 500.\n#101 = #3001\n#102 = #3011\n";
    let r = run(text, &mill(&[]));
    let v = variables(&r, text);
    assert_eq!(v[&100], Some(0.0));
    assert_eq!(v[&101], Some(500.0));
    assert_eq!(first_error(&r).0, "macro-system-variable");
}

/// Drilling by G66 at three places (the macro drills to Z−5, back to Z2).
const MODAL_DRILL: &str = "G90 G00 X0 Y0 Z10.
G66 P9020 Z-5. R2.
X10.
X20.
Y10.
G67
X0 Y0
M30
O9020
G01 Z#26 F100.
G00 Z#18
M99
";

#[test]
fn behaviour21_6_a_checkpoint_inside_a_macro_gives_the_same_report() {
    let setup = mill(&[]);
    for text in [programs::G65_BOLT_CIRCLE, MODAL_DRILL] {
        let full = run(text, &setup);
        assert!(!full.has_errors());
        for every in [1, 2, 3, 7] {
            let (light, checkpoints) = checkpointed(text, &setup, every);
            assert_eq!(light.moves, full.moves);
            for (i, kept) in full.blocks.iter().enumerate() {
                let again = report_at(text, &setup, &checkpoints, i as u32);
                assert_eq!(again.as_ref(), Some(kept), "block {i}, every {every}");
            }
        }
        // The run on two threads hands a program with macro calls to one
        // thread: the same run (G66's calls included).
        let one = run_with(text, &setup, RunOptions::default());
        match offsetlab::run_on_two_threads(text, &setup, RunOptions::default()) {
            Some(two) => assert_eq!(two, one),
            None => assert_eq!(
                offsetlab::run_pipelined(text, &setup, RunOptions::default()),
                one
            ),
        }
    }
    // Three holes: each drills to Z−5 (9 moves with the three positions),
    // plus the first rapid to Z10 and the last to (0, 0).
    assert_eq!(run(MODAL_DRILL, &setup).moves.len(), 11);
}
