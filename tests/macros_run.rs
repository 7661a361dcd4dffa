//! Behaviour 20.8: macro statements and macro words in a program's run —
//! assignments and `X#1`, `Z-[#3+1.]`, `G#10`, `F[#2*2]` evaluated in
//! program order and what each block's report says (the jumps and loops:
//! `tests/macro_flow.rs`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::machine::{EventKind, VariableSet};
use offsetlab::run;
use offsetlab::view::block_view;

fn block_line(r: &offsetlab::Run, line: u32) -> &offsetlab::report::BlockReport {
    r.blocks
        .iter()
        .rev()
        .find(|b| b.span.line == line)
        .unwrap_or_else(|| panic!("no block on line {line}"))
}

#[test]
fn behaviour20_8_words_take_their_values_in_program_order() {
    // #1 = 25, #2 = 60: X = 25 cos 60 = 12.5, Y = 25 sin 60 = 21.650635 → 21.651;
    // Z = -(25/10 + 1) = -3.5; F = 60 * 2 = 120; then #1 = 10: X = 10.
    let text = "G90 G21\n#1 = 25\n#2 = 60\nG00 X[#1*COS[#2]] Y[#1*SIN[#2]]\nG01 Z-[#1/10+1.] F[#2*2]\n#1 = 10\nX#1\n";
    let r = ok(text, &mill(&[]));
    let b = block_line(&r, 4);
    assert!((b.state.programmed[0] - 12.5).abs() < 1e-9);
    // Rounded to the least input increment, 0.001 mm.
    assert!(
        (b.state.programmed[1] - 21.651).abs() < 1e-9,
        "{:?}",
        b.state.programmed
    );
    let b = block_line(&r, 5);
    assert!((b.state.programmed[2] + 3.5).abs() < 1e-9);
    assert_eq!(b.state.feed, Some(120.0));
    assert!((block_line(&r, 7).state.programmed[0] - 10.0).abs() < 1e-9);
}

#[test]
fn behaviour20_8_a_comma_word_takes_a_macro_value() {
    // ,R#144 with #144 = 2: the corner at X10 Y0 is rounded with R2 — the
    // line stops 2 before the corner (X8), the arc ends 2 past it (X10
    // Y2), then Y10. As ,R2. written out.
    let r = ok(
        "G90 G00 X0 Y0\n#144 = 2.\nG01 X10. ,R#144 F100.\nY10.\n",
        &mill(&[]),
    );
    let feeds: Vec<_> = r.moves.iter().map(|m| m.to).collect();
    assert_eq!(feeds.len(), 3);
    same(feeds[0], [8.0, 0.0, 0.0]);
    same(feeds[1], [10.0, 2.0, 0.0]);
    same(feeds[2], [10.0, 10.0, 0.0]);
    // ,C[#1+1.] with #1 = 2: a chamfer of 3 — the line stops at X7, the
    // chamfer runs to X10 Y3.
    let r = ok(
        "G90 G00 X0 Y0\n#1 = 2.\nG01 X10. ,C[#1+1.] F100.\nY10.\n",
        &mill(&[]),
    );
    same(r.moves[0].to, [7.0, 0.0, 0.0]);
    same(r.moves[1].to, [10.0, 3.0, 0.0]);
    // The next block written with a macro value: the corner's look-ahead
    // does not evaluate it, and says so at the ,R rather than guess.
    let r = offsetlab::run(
        "G90 G00 X0 Y0\n#141 = 10.\nG01 X10. ,R2. F100.\nY#141\n",
        &mill(&[]),
    );
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.code, d.line, d.column), ("corner-not-modelled", 3, 10));
}

#[test]
fn behaviour20_8_cutter_compensation_warns_before_a_block_with_macro_values() {
    // G41 D01 = 5 to X0 Y0, then Y#1 (#1 = 40): the look-ahead does not
    // evaluate Y#1, so the start-up ends perpendicular to its own move
    // (from X-10 Y-10 to X0 Y0, direction (1, 1)/√2, left normal
    // (-1, 1)/√2 × 5 = (-3.536, 3.536)) and says so at line 3, instead of
    // taking the X40 after it for the next move.
    let text = "G90 G00 X-10. Y-10.\n#1 = 40.\nG01 G41 D01 X0 Y0 F100.\nY#1\nX40.\nM30\n";
    let r = ok(text, &mill(&[(1, 5.0)]));
    let w = r
        .diagnostics
        .iter()
        .find(|d| d.code == "cutter-look-ahead-macro")
        .expect("the warning");
    assert_eq!(w.line, 3);
    let h = 5.0 / 2f64.sqrt();
    same(r.moves[1].to, [-h, h, 0.0]);
}

#[test]
fn behaviour20_8_a_g_code_from_a_variable() {
    // #10 = 1: G#10 is G01, a feed move (F100).
    let text = "#10 = 1\nG#10 X5. F100\n";
    let r = ok(text, &mill(&[]));
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, offsetlab::machine::MoveKind::Feed);
    assert!((m.to[0] - 5.0).abs() < 1e-9);
}

#[test]
fn behaviour20_8_the_report_says_what_a_statement_set() {
    // SQRT[3*3 + 4*4] = 5; #101 was vacant, then 5 / 2 = 2.5, was 5.
    let text = "#1 = 3\n#2 = 4\n#101 = SQRT[#1*#1+#2*#2]\n#101 = #101 / 2\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(
        block_line(&r, 3).explanation(),
        "#101 = 5.000 (SQRT[#1*#1+#2*#2]), was vacant."
    );
    assert_eq!(
        block_line(&r, 4).explanation(),
        "#101 = 2.500 (#101 / 2), was 5.000."
    );
    let set = VariableSet {
        variable: 101,
        value: Some(2.5),
        was: Some(5.0),
    };
    assert_eq!(block_line(&r, 4).variables, vec![set]);
    assert!(
        r.events
            .iter()
            .any(|e| e.kind == EventKind::VariableSet(set))
    );
    // The block's JSON lists it.
    let json = serde_json::to_value(block_view(block_line(&r, 4), text)).unwrap();
    assert_eq!(json["variables_set"][0]["variable"], 101);
    assert_eq!(json["variables_set"][0]["was"], 5.0);
}

#[test]
fn behaviour20_4_a_vacant_variable_leaves_its_word_out() {
    // Fanuc: G00 X#1 Y10. with #1 vacant is G00 Y10.; said in the report.
    let text = "G00 X#1 Y10.\n";
    let r = ok(text, &mill(&[]));
    let b = block_line(&r, 1);
    assert_eq!(b.state.programmed, [0.0, 10.0, 0.0]);
    assert!(
        b.explanation()
            .contains("X#1 is vacant: the X word is left out")
    );
}

#[test]
fn behaviour20_8_if_then_sets_only_when_the_condition_holds() {
    let text = "#1 = 3\nIF [#1 GT 2] THEN #2 = 7\nIF [#1 GT 5] THEN #3 = 7\nX#2 Y#3\n";
    let r = ok(text, &mill(&[]));
    // #2 = 7 was set, #3 stayed vacant: X7., Y left out.
    assert_eq!(block_line(&r, 4).state.programmed, [7.0, 0.0, 0.0]);
    assert!(
        block_line(&r, 3)
            .explanation()
            .contains("the condition does not hold")
    );
}

#[test]
fn behaviour20_8_an_if_goto_whose_condition_does_not_hold_goes_on() {
    // #1 = 1: [1 GT 2] is false, no jump; the three blocks run in order.
    let r = ok("#1 = 1\nIF [#1 GT 2] GOTO 10\nX1.\n", &mill(&[]));
    assert_eq!(r.block_count, 3);
    assert_eq!(
        r.blocks[1].notes,
        vec!["IF [#1 GT 2] GOTO 10: the condition does not hold, no jump"]
    );
}

#[test]
fn behaviour20_9_alarms_stop_the_run_at_their_line_and_column() {
    // Division by zero on line 2, the divisor `[#1-1]` at column 10.
    let text = "#1 = 1\n#2 = 5 / [#1-1]\nX1.\n";
    let r = run(text, &mill(&[]));
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line, e.column), ("macro-zero-divide", 2, 10));
    assert_eq!(r.block_count, 1);
    // A format error is a parse error: found whatever runs.
    let r = run("X1.\n#1 = 2 +\nM30\n", &mill(&[]));
    assert!(
        r.diagnostics
            .iter()
            .any(|d| d.code == "macro-expression" && d.line == 2)
    );
    // An expression in a word without brackets: PS0114 at the word.
    let r = run("#1 = 4\nG00 X#1/2 Y1.\n", &mill(&[]));
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line, e.column), ("macro-expression", 2, 5));
    assert!(e.message.contains("`X[#1/…]`"), "{}", e.message);
    // An NC word beside a statement: PS0127.
    assert!(errors("G01 #1 = 2\n", &mill(&[])).contains(&"macro-nc-statement"));
    // A macro word's value still meets the word's checks: H beyond the table.
    let e = errors("#1 = 1000\nG43 H#1 Z1.\n", &mill(&[]));
    assert_eq!(e.len(), 1, "{e:?}");
}

#[test]
fn behaviour20_8_a_bolt_circle_in_straight_line_macro_code() {
    // Four holes on a 40 mm circle about (0, 0) at 45°, 135°, 225°, 315°:
    // X = 20 cos a, Y = 20 sin a = ±14.142136 → ±14.142.
    let mut text = String::from("G90 G21\n#1 = 20\n#2 = 45\n");
    for _ in 0..4 {
        text.push_str("G00 X[#1*COS[#2]] Y[#1*SIN[#2]]\n#2 = #2 + 90\n");
    }
    let r = ok(&text, &mill(&[]));
    let holes: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    let want = [
        [14.142, 14.142],
        [-14.142, 14.142],
        [-14.142, -14.142],
        [14.142, -14.142],
    ];
    assert_eq!(holes.len(), 4);
    for (h, w) in holes.iter().zip(want) {
        assert!(
            (h[0] - w[0]).abs() < 1e-9 && (h[1] - w[1]).abs() < 1e-9,
            "{h:?}"
        );
    }
}

#[test]
fn behaviour20_8_programs_without_macros_read_as_before() {
    // The same program with and without a macro word gives the same path.
    let plain = ok("G01 X10. Y5. F100\n", &mill(&[]));
    let macro_ = ok("#1 = 10\nG01 X#1 Y5. F100\n", &mill(&[]));
    assert_eq!(
        plain.moves.last().unwrap().to,
        macro_.moves.last().unwrap().to
    );
}

#[test]
fn behaviour7_40_the_haas_profile_reads_conditions_as_numbers() {
    // Haas: [1 LT 2] is 1.0, so X[[1 LT 2] * 5] is X5.; Fanuc refuses it (PS0114).
    let mut haas = mill(&[]);
    haas.settings.control = offsetlab::setup::Control::Haas;
    let r = ok("#1 = [1 LT 2] * 5\nX#1\n", &haas);
    assert_eq!(r.moves.last().unwrap().to[0], 5.0);
    assert_eq!(
        errors("#1 = [1 LT 2] * 5\n", &mill(&[])),
        vec!["macro-expression"]
    );
}

#[test]
fn long_macro_lines_read_in_linear_time() {
    // A block of 20,000 macro words (each a duplicate X past the first: one
    // error), and 1,000,000 letters: each once, never a scan to the line's
    // end per word (which took minutes).
    let start = std::time::Instant::now();
    let text = format!(
        "#1 = 1\nG01 {}\n{}\n",
        "X#1 ".repeat(20_000),
        "A".repeat(1_000_000)
    );
    let r = run(&text, &mill(&[]));
    assert!(r.has_errors());
    assert!(start.elapsed().as_secs() < 20, "{:?}", start.elapsed());
}

#[test]
fn behaviour20_10_tool_offsets_read_and_written_through_system_variables() {
    // Memory A (the seeds'): #2001 and #10001 are register 01's one value, 5.
    // Writing #2001 = 12.5 sets it for the blocks after: G43 H01 Z0 then
    // goes to Z 0 + 12.5 = 12.5 (actual).
    let text = "#1 = #2001\n#2 = #10001\n#2001 = 12.5\nG43 H01 Z0\n";
    let r = ok(text, &mill(&[(1, 5.0)]));
    let set = r.set_by_program();
    assert_eq!(
        (set[0].set.table, set[0].set.value, set[0].set.was),
        ("offsets", 12.5, 5.0)
    );
    assert!(
        block_line(&r, 1)
            .explanation()
            .starts_with("#1 = 5.000 (#2001)")
    );
    assert!(
        block_line(&r, 2)
            .explanation()
            .starts_with("#2 = 5.000 (#10001)")
    );
    assert!((r.blocks.last().unwrap().state.actual[2] - 12.5).abs() < 1e-9);
    // Memory C: #2001 H wear, #2201 H geometry, #2401 D wear, #2601 D geometry.
    let mut c = mill(&[]);
    c.settings.offset_memory = Some(offsetlab::setup::OffsetMemory::C);
    let r = ok("#2001 = 1.\n#2201 = 2.\n#2401 = 3.\n#2601 = 4.\n", &c);
    let fields: Vec<_> = r.set_by_program().iter().map(|s| s.set.field).collect();
    assert_eq!(fields, vec!["h_wear", "h_geometry", "d_wear", "d_geometry"]);
    // Past the table (register 200 of a smaller table): PS0115.
    let e = errors("#1 = #2200\n", &mill(&[]));
    assert_eq!(e, vec!["macro-variable-number"]);
}

#[test]
fn behaviour20_10_work_offsets_read_and_written_through_system_variables() {
    // #5221 is G54's X. Set to 100 while G54 is in force: the zero moves and
    // the tool stays, so at machine X 0 it reads X 0 - 100 = -100 in G54.
    let text = "G90 G54\n#5221 = 100.\n#1 = #5221 + 10\nG00 X10.\n";
    let r = ok(text, &mill(&[]));
    assert_eq!(block_line(&r, 3).variables[0].value, Some(110.0));
    assert!((block_line(&r, 2).state.programmed[0] + 100.0).abs() < 1e-9);
    let set = r.set_by_program();
    assert_eq!(
        (set[0].set.table, set[0].set.key.as_str(), set[0].set.field),
        ("work_offsets", "G54", "x")
    );
    // Other system variables are refused, never made up; the lathe's too.
    assert_eq!(
        errors("#1 = #5004\n", &mill(&[])),
        vec!["macro-system-variable"]
    );
    assert_eq!(
        errors("#1 = #2401\n", &lathe(&[])),
        vec!["macro-system-variable"]
    );
}
