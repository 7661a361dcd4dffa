//! Behaviour 2 (`docs/behaviour.md`): the machine — modes, coordinates,
//! arcs, canned cycles, G28, mirror image, M codes, and stopping at the first
//! error. Each test is named after the rule it checks (`behaviour2_12_…`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::EventKind;
use offsetlab::report::End;
use offsetlab::setup::{Mirror, Position};
use offsetlab::{MoveKind, Setup, run};
use std::f64::consts::{FRAC_PI_2, PI};

#[test]
fn behaviour2_3_start_state_and_absolute_incremental() {
    let r = ok("X10. Y5.\nG91 X10.\nG90 X0", &mill(&[]));
    same(programmed(&r, 0), [10.0, 5.0, 0.0]);
    same(programmed(&r, 1), [20.0, 5.0, 0.0]);
    same(programmed(&r, 2), [0.0, 5.0, 0.0]);
    assert_eq!(r.moves[0].kind, MoveKind::Rapid, "G00 at start");
    let m = r.blocks[0].state.modal.codes(offsetlab::MachineKind::Mill);
    assert_eq!(
        (
            m.plane,
            m.distance,
            m.units,
            m.length,
            m.cycle,
            m.work,
            m.feed_mode
        ),
        (
            "G17",
            Some("G90"),
            "G21",
            Some("G49"),
            Some("G80"),
            "G54",
            "G94"
        )
    );
}

#[test]
fn behaviour2_6_units_g20_g21() {
    let text = "G20\nG01 X1. F10.\nG21\nG01 X50.8";
    let r = ok(text, &mill(&[]));
    same(programmed(&r, 1), [25.4, 0.0, 0.0]);
    assert_eq!(at_line(&r, text, 2).programmed.x, 1.0);
    assert_eq!(at_line(&r, text, 4).programmed.x, 50.8);
    // Drawn in the units of the first move.
    assert_eq!(r.units, offsetlab::Units::Inch);
}

#[test]
fn behaviour2_7_work_offsets_g54_to_g59_from_the_setup() {
    let mut s = mill(&[]);
    s.work_offsets.g55 = Position {
        x: 100.0,
        y: 50.0,
        z: 0.0,
    };
    let text = "G54 G00 X10. Y10.\nG55 X10. Y10.\nG54";
    let r = ok(text, &s);
    let m = r.moves.last().unwrap();
    // In G55 the same coordinates are 100/50 further in machine terms: in
    // G54 terms the tool went from (10,10) to (110,60).
    same(m.programmed_from, [-90.0, -40.0, 0.0]);
    same(m.to, [10.0, 10.0, 0.0]);
    same(programmed(&r, 2), [110.0, 60.0, 0.0]);
}

#[test]
fn behaviour2_8_g92_sets_the_programmed_position_without_motion() {
    let r = ok("G00 X10. Y10.\nG92 X0 Y0\nG01 X5. F100.", &mill(&[]));
    same(programmed(&r, 1), [0.0, 0.0, 0.0]);
    assert_eq!(r.blocks[1].move_count, 0);
    same(programmed(&r, 2), [5.0, 0.0, 0.0]);
}

#[test]
fn behaviour2_9_g04_dwell_p_milliseconds_and_x_seconds() {
    let r = ok("G04 P1500\nG04 X2.5\nG04 X2500", &mill(&[]));
    let secs: Vec<f64> = r
        .events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Dwell { seconds } => Some(seconds),
            _ => None,
        })
        .collect();
    assert_eq!(secs, vec![1.5, 2.5, 2.5]);
    assert!(r.moves.is_empty(), "a dwell does not move");
    assert_eq!(errors("G04 P1000 X1.", &mill(&[])), vec!["dwell-words"]);
}

#[test]
fn behaviour2_10_g28_clears_the_offset_vectors_and_g43_applies_again_at_the_next_z_move() {
    let mut s = mill(&[(1, 5.0), (2, 15.0)]);
    s.reference = Position {
        x: 0.0,
        y: 0.0,
        z: 100.0,
    };
    let text = "G90 G00 G43 Z50. H02\nG91 G45 X10. D01\nG91 G28 Z0\nG90 G00 Z20.";
    let r = ok(text, &s);
    same(actual(&r, 0), [0.0, 0.0, 65.0]);
    // Through the intermediate point (here the current position) to Z100.
    same(actual(&r, 2), [15.0, 0.0, 100.0]);
    same(programmed(&r, 2), [10.0, 0.0, 100.0]);
    assert_eq!(r.blocks[2].state.length.vector, 0.0);
    assert_eq!(r.blocks[2].state.length.target, 15.0, "G43 stays modal");
    assert_eq!(
        r.blocks[2].state.position.vector[0], 5.0,
        "X did not return"
    );
    same(actual(&r, 3), [15.0, 0.0, 35.0]);
    assert!(
        explain(&r, 2).contains("stays active"),
        "{}",
        explain(&r, 2)
    );
}

#[test]
fn behaviour2_10_g28_intermediate_point_then_reference() {
    let mut s = mill(&[]);
    s.reference = Position {
        x: 200.0,
        y: 100.0,
        z: 50.0,
    };
    let r = ok("G90 G28 X10. Y20.", &s);
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [10.0, 20.0, 0.0]);
    same(r.moves[1].to, [200.0, 100.0, 0.0]);
}

#[test]
fn behaviour2_12_arcs_in_g17_with_i_j_and_with_r() {
    let s = mill(&[]);
    let r = ok("G00 X10. Y0\nG03 X0 Y10. I-10. J0 F100.", &s);
    let a = r.moves.last().unwrap().arc.unwrap();
    same(a.center, [0.0, 0.0, 0.0]);
    assert!((a.sweep - FRAC_PI_2).abs() < 1e-9);
    let r = ok("G00 X10. Y0\nG03 X0 Y10. R10. F100.", &s);
    same(r.moves.last().unwrap().arc.unwrap().center, [0.0, 0.0, 0.0]);
    // R < 0: more than 180°.
    let r = ok("G00 X10. Y0\nG03 X0 Y10. R-10. F100.", &s);
    let a = r.moves.last().unwrap().arc.unwrap();
    same(a.center, [10.0, 10.0, 0.0]);
    assert!((a.sweep - 3.0 * FRAC_PI_2).abs() < 1e-9);
    assert_eq!(r.moves.last().unwrap().kind, MoveKind::ArcCcw);
}

#[test]
fn behaviour2_12_arcs_in_g18_and_g19_and_helix() {
    let s = mill(&[]);
    // G18: the ZX plane, CW seen from +Y with Z to the right and X up.
    // From (Z10, X0) clockwise to (Z0, X10): the centre is at Z10 X10.
    let r = ok("G18 G00 X0 Z10.\nG02 X10. Z0 R10. F100.", &s);
    let a = r.moves.last().unwrap().arc.unwrap();
    same(a.center, [10.0, 0.0, 10.0]);
    assert!((a.sweep + FRAC_PI_2).abs() < 1e-9);
    let r = ok("G19 G00 Y10. Z0\nG03 Y0 Z10. J-10. K0 F100.", &s);
    same(r.moves.last().unwrap().arc.unwrap().center, [0.0, 0.0, 0.0]);
    // Helix: the third axis moves linearly.
    let r = ok("G00 X10. Y0 Z0\nG03 X10. Y0 Z-5. I-10. F100.", &s);
    let m = r.moves.last().unwrap();
    same(m.to, [10.0, 0.0, -5.0]);
    assert!(
        (m.arc.unwrap().sweep - 2.0 * PI).abs() < 1e-9,
        "full circle with I/J"
    );
}

#[test]
fn behaviour2_13_radius_check_and_r_too_small_are_errors() {
    let s = mill(&[]);
    assert_eq!(
        errors("G00 X10.\nG03 X0 Y10.05 I-10. F100.", &s),
        vec!["arc-radius"]
    );
    assert!(errors("G00 X10.\nG03 X0 Y10.005 I-10. F100.", &s).is_empty());
    assert_eq!(errors("G02 X30. R10. F100.", &s), vec!["arc-radius"]);
    assert_eq!(errors("G02 X30. F100.", &s), vec!["arc-without-center"]);
}

#[test]
fn behaviour2_14_g81_drilling_with_g98_and_g99_returns() {
    let text = "G90 G00 X0 Y0 Z50.\nG98 G81 X10. Y10. Z-5. R2. F100.\nG99 X20.\nG80";
    let r = ok(text, &mill(&[]));
    let hole1: Vec<(MoveKind, f64)> = r
        .moves
        .iter()
        .filter(|m| m.line == 2)
        .map(|m| (m.kind, m.programmed_to[2]))
        .collect();
    assert_eq!(
        hole1,
        vec![
            (MoveKind::Rapid, 50.0),
            (MoveKind::Rapid, 2.0),
            (MoveKind::Feed, -5.0),
            (MoveKind::Rapid, 50.0)
        ]
    );
    let hole2: Vec<f64> = r
        .moves
        .iter()
        .filter(|m| m.line == 3)
        .map(|m| m.programmed_to[2])
        .collect();
    assert_eq!(hole2.last(), Some(&2.0), "G99 returns to R");
    same(programmed(&r, 2), [20.0, 10.0, 2.0]);
}

#[test]
fn behaviour2_14_cycles_in_g91_r_from_initial_and_z_from_r_with_k_repeats() {
    let text = "G90 G00 X0 Y0 Z50.\nG91 G99 G81 X10. R-48. Z-7. K3 F100.";
    let r = ok(text, &mill(&[]));
    let bottoms: Vec<[f64; 3]> = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Feed)
        .map(|m| m.programmed_to)
        .collect();
    assert_eq!(bottoms.len(), 3);
    same(bottoms[0], [10.0, 0.0, -5.0]);
    same(bottoms[2], [30.0, 0.0, -5.0]);
}

#[test]
fn behaviour2_14_length_offset_applies_to_the_cycle_levels() {
    let text = "G90 G00 G43 Z50. H01\nG98 G81 X10. Y10. Z-5. R2. F100.";
    let r = ok(text, &mill(&[(1, 10.0)]));
    let feed = r.moves.iter().find(|m| m.kind == MoveKind::Feed).unwrap();
    same(feed.to, [10.0, 10.0, 5.0]);
    same(feed.programmed_to, [10.0, 10.0, -5.0]);
}

#[test]
fn behaviour2_15_g83_pecks_out_to_r_and_g73_backs_off() {
    let s = mill(&[]);
    let r = ok("G90 G00 Z10.\nG83 X0 Y0 Z-10. R1. Q4. F100.", &s);
    let feeds: Vec<f64> = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Feed)
        .map(|m| m.programmed_to[2])
        .collect();
    assert_eq!(feeds, vec![-3.0, -7.0, -10.0]);
    let outs = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Rapid && m.programmed_to[2] == 1.0)
        .count();
    assert!(outs >= 3, "back to R after each peck");
    let r = ok("G90 G00 Z10.\nG73 X0 Y0 Z-10. R1. Q4. F100.", &s);
    let backs: Vec<f64> = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Rapid)
        .map(|m| m.programmed_to[2])
        .collect();
    // Back off by d = 1 mm after each peck, then the retract to the initial level.
    assert_eq!(backs, vec![10.0, 1.0, -2.0, -6.0, 10.0]);
    assert_eq!(errors("G83 X0 Y0 Z-10. R1. F100.", &s), vec!["cycle-q"]);
}

#[test]
fn behaviour2_15_tapping_boring_and_dwell_cycles() {
    let s = mill(&[]);
    for (code, feeds_up) in [
        (84, true),
        (74, true),
        (85, true),
        (89, true),
        (86, false),
        (82, false),
        (88, false),
    ] {
        let text = format!("G90 G00 Z10.\nG{code} X0 Y0 Z-10. R1. P500 F100.");
        let r = ok(&text, &s);
        let up = r
            .moves
            .iter()
            .any(|m| m.kind == MoveKind::Feed && m.programmed_to[2] == 1.0);
        assert_eq!(up, feeds_up, "G{code}");
    }
    let r = ok("G90 G00 Z10.\nG84 X0 Y0 Z-10. R1. P500 F100.", &s);
    let kinds: Vec<&EventKind> = r.events.iter().map(|e| &e.kind).collect();
    assert!(
        kinds.contains(&&EventKind::SpindleCcw)
            && kinds.contains(&&EventKind::Dwell { seconds: 0.5 })
    );
    // G76: oriented stop and a shift by Q before the retract.
    let r = ok("G90 G00 Z10.\nG76 X0 Y0 Z-10. R1. Q0.5 F100.", &s);
    assert!(
        r.moves
            .iter()
            .any(|m| m.programmed_to[0] == 0.5 && m.programmed_to[2] == -10.0)
    );
    // G87: back boring from R below the part up to Z.
    let r = ok("G90 G00 Z10.\nG98 G87 X0 Y0 Z-5. R-20. Q0.5 F100.", &s);
    let feed = r.moves.iter().find(|m| m.kind == MoveKind::Feed).unwrap();
    assert_eq!(
        (feed.programmed_from[2], feed.programmed_to[2]),
        (-20.0, -5.0)
    );
    assert_eq!(
        errors("G99 G87 X0 Y0 Z-5. R-20. Q0.5 F100.", &s),
        vec!["cycle-return"]
    );
}

#[test]
fn behaviour2_14_g80_and_group_01_cancel_the_cycle() {
    let r = ok(
        "G90 G00 Z10.\nG81 X0 Y0 Z-5. R1. F100.\nG80\nX10.",
        &mill(&[]),
    );
    assert_eq!(r.moves.last().unwrap().kind, MoveKind::Rapid);
    assert_eq!(r.moves.last().unwrap().programmed_to, [10.0, 0.0, 10.0]);
    let r = ok(
        "G90 G00 Z10.\nG81 X0 Y0 Z-5. R1. F100.\nG00 X10.",
        &mill(&[]),
    );
    assert_eq!(r.blocks[2].move_count, 1);
    assert_eq!(
        errors("G01 G81 X0 Y0 Z-5. R1. F100.", &mill(&[])),
        vec!["motion-and-cycle"]
    );
    assert_eq!(
        errors("G81 X0 Y0 R1. F100.", &mill(&[])),
        vec!["cycle-without-depth"]
    );
}

#[test]
fn behaviour2_17_mirror_image_reverses_movements_about_the_start() {
    let mut s = mill(&[]);
    s.start = Position {
        x: 10.0,
        y: 0.0,
        z: 0.0,
    };
    s.settings.mirror = Mirror { x: true, y: false };
    let r = ok("G90 G01 X30. Y5. F100.\nG91 X5.\nG90 G02 X20. Y5. R10.", &s);
    same(actual(&r, 0), [-10.0, 5.0, 0.0]);
    same(actual(&r, 1), [-15.0, 5.0, 0.0]);
    // One mirrored axis in the plane turns G02 into a counter-clockwise arc.
    assert_eq!(r.moves.last().unwrap().kind, MoveKind::ArcCcw);
    same(actual(&r, 2), [0.0, 5.0, 0.0]);
}

#[test]
fn behaviour2_18_m_codes_are_events_and_m30_ends_the_program() {
    let text = "M03 S1000\nM08\nM06 T2\nM01\nM123\nM05 M09\nM30\nG00 X10.";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.end, End::ProgramEnd { line: 7 });
    assert_eq!(r.block_count, 7, "nothing after M30 runs");
    let kinds: Vec<EventKind> = r.events.iter().map(|e| e.kind.clone()).collect();
    assert!(kinds.contains(&EventKind::SpindleCw));
    assert!(kinds.contains(&EventKind::CoolantOn { m: 8 }));
    assert!(kinds.contains(&EventKind::OptionalStop));
    assert!(kinds.contains(&EventKind::Auxiliary { m: 123 }));
    assert!(kinds.contains(&EventKind::ProgramEnd { m: 30 }));
    assert_eq!(errors("M03 M04", &mill(&[])), vec!["modal-conflict"]);
}

#[test]
fn behaviour2_18_t_in_the_m06_block_is_the_tool_put_in_the_spindle() {
    // Issue 23's defect: `T1 M06` showed tool 0, and `T2 M06` tool 1.
    let r = ok("T1 M06\nG00 X1.\nT2 M06\nG00 X2.", &mill(&[]));
    let tools: Vec<u32> = r.blocks.iter().map(|b| b.state.tool).collect();
    assert_eq!(tools, vec![1, 1, 2, 2]);
    let changes: Vec<&EventKind> = r.events.iter().map(|e| &e.kind).collect();
    assert_eq!(
        changes,
        vec![
            &EventKind::ToolChange { tool: 1 },
            &EventKind::ToolChange { tool: 2 }
        ]
    );
}

#[test]
fn behaviour2_18_m06_changes_to_the_selected_tool() {
    let r = ok("T5\nM06", &mill(&[]));
    assert_eq!(r.blocks[1].state.tool, 5);
    assert!(
        r.events
            .iter()
            .any(|e| e.kind == EventKind::ToolChange { tool: 5 })
    );
}

#[test]
fn behaviour2_20_feed_move_before_any_f_word_warns_once() {
    let r = run("G01 X10.\nG01 X20.\nG01 X30. F100.", &mill(&[]));
    let w: Vec<_> = r
        .diagnostics
        .iter()
        .filter(|d| d.code == "missing-feed")
        .collect();
    assert_eq!(w.len(), 1);
    assert_eq!(w[0].line, 1);
    assert!(!r.has_errors());
}

#[test]
fn behaviour2_1_execution_stops_at_the_first_error_and_every_parse_error_is_reported() {
    let text = "G00 X10.\nG01 X20. F100.\nG01 X1.2.3\nG00 X40.\nG00 Y1.2.3";
    let r = run(text, &mill(&[]));
    assert_eq!(
        r.block_count, 2,
        "blocks before the error keep their motion"
    );
    assert_eq!(r.moves.len(), 2);
    assert_eq!(r.end, End::Error { line: 3 });
    let lines: Vec<u32> = r.diagnostics.iter().map(|d| d.line).collect();
    assert_eq!(lines, vec![3, 5]);
}

#[test]
fn behaviour2_1_run_time_error_stops_too() {
    let r = run("G00 X10.\nG02 X30. R5. F100.\nG00 X0", &mill(&[]));
    assert_eq!(r.block_count, 1);
    assert_eq!(r.end, End::Error { line: 2 });
}

#[test]
fn behaviour2_21_unsupported_g_codes_are_errors_not_skips() {
    for code in ["G22 X10. Y10.", "G11", "G66.1 P9000"] {
        assert_eq!(
            errors(code, &mill(&[])),
            vec!["unsupported-g-code"],
            "{code}"
        );
    }
    assert_eq!(errors("G00 U10.", &mill(&[])), vec!["lathe-address"]);
}

#[test]
fn behaviour2_2_block_skip_setting() {
    let text = "G00 X10.\n/G00 X20.\nG00 Y5.";
    let r = ok(text, &mill(&[]));
    same(programmed(&r, 2), [20.0, 5.0, 0.0]);
    let mut s = mill(&[]);
    s.settings.block_skip = true;
    let r = ok(text, &s);
    assert_eq!(r.block_count, 2);
    same(programmed(&r, 1), [10.0, 5.0, 0.0]);
}

#[test]
fn behaviour2_3_a_setup_start_position_and_bad_setup() {
    let mut s = Setup {
        start: Position {
            x: 1.0,
            y: 2.0,
            z: 3.0,
        },
        ..Setup::default()
    };
    let r = ok("G91 X1.", &s);
    same(programmed(&r, 0), [2.0, 2.0, 3.0]);
    s.table_size = 0;
    let r = run("G91 X1.", &s);
    assert!(r.has_errors());
    assert_eq!(r.diagnostics[0].code, "setup-range");
    assert_eq!(r.block_count, 0);
}

#[test]
fn limits_a_block_that_would_make_too_many_moves_stops_with_an_error() {
    let options = offsetlab::RunOptions {
        max_moves: 100,
        ..offsetlab::RunOptions::default()
    };
    let text = "G90 G00 Z10.\nG91 G81 X1. Z-5. R-8. K9999 F100.\nG00 X0";
    let r = offsetlab::run_with(text, &mill(&[]), options);
    assert_eq!(r.end, End::Error { line: 2 });
    assert!(r.moves.len() <= 100);
    assert_eq!(r.diagnostics.last().unwrap().code, "too-many-moves");
    // Pecks are limited per hole as well.
    assert_eq!(
        errors(
            "G90 G00 Z10.\nG83 X0 Y0 Z-99999. R1. Q0.001 F100.",
            &mill(&[])
        ),
        vec!["cycle-pecks"]
    );
}

#[test]
fn behaviour1_14_a_feed_rate_is_0_to_999999() {
    // Program text (behaviour 1.14), checked where the machine is given it.
    assert!(errors("G01 X1. F999999.", &mill(&[])).is_empty());
    assert_eq!(
        errors("G01 X1. F1000000.", &mill(&[])),
        vec!["out-of-range"]
    );
    assert_eq!(errors("G01 X1. F-1.", &mill(&[])), vec!["out-of-range"]);
}

#[test]
fn behaviour2_8_g92_needs_an_axis() {
    assert_eq!(errors("G92", &mill(&[])), vec!["g92-without-axis"]);
    // G28 without an axis word is setting 7.20 (tests/coordinates.rs).
}

#[test]
fn behaviour2_9_the_lathe_dwells_u_seconds() {
    let r = ok("G04 U1.5", &lathe(&[]));
    assert_eq!(r.events[0].kind, EventKind::Dwell { seconds: 1.5 });
    assert!(r.moves.is_empty());
}

#[test]
fn behaviour2_13_r_wins_over_centre_words_and_a_centre_word_off_the_plane_is_ignored() {
    let s = mill(&[]);
    let r = run("G00 X10.\nG03 X0 Y10. R10. I-10. F100.", &s);
    assert!(!r.has_errors());
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, vec!["arc-r-and-center"]);
    same(r.moves.last().unwrap().arc.unwrap().center, [0.0, 0.0, 0.0]);
    let r = run("G00 X10.\nG03 X0 Y10. I-10. K5. F100.", &s);
    assert!(!r.has_errors());
    let codes: Vec<&str> = r.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, vec!["arc-center-word"]);
    // An R arc that ends where it starts moves like G01, with a warning.
    let r = run("G17 G02 Z-5. R10. F100.", &s);
    assert!(!r.has_errors());
    assert_eq!(r.diagnostics[0].code, "arc-r-no-motion");
    assert_eq!(r.moves[0].kind, MoveKind::Feed);
    same(r.moves[0].to, [0.0, 0.0, -5.0]);
}

#[test]
fn behaviour2_18_m19_m07_and_a_t_word_in_the_m06_block() {
    let r = ok("M19\nM07\nT5\nM06 T2\nM06", &mill(&[]));
    let kinds: Vec<EventKind> = r.events.iter().map(|e| e.kind.clone()).collect();
    assert_eq!(
        kinds,
        vec![
            EventKind::SpindleOrient,
            EventKind::CoolantOn { m: 7 },
            EventKind::ToolChange { tool: 2 },
            EventKind::ToolChange { tool: 2 },
        ]
    );
    // A T in the M06 block is the tool M06 changes to (Haas `T1 M06`); a
    // later M06 without T changes to the same tool again.
    assert_eq!(r.blocks[3].state.tool, 2);
    assert_eq!(r.blocks[4].state.tool, 2);
    // M00 is reported, and the run goes on.
    let r = ok("M00\nG00 X1.", &mill(&[]));
    assert_eq!(r.events[0].kind, EventKind::ProgramStop);
    assert_eq!((r.block_count, r.end), (2, End::Completed));
    // On the lathe M06 is an auxiliary function (the turret indexes on T).
    let r = ok("M06", &lathe(&[]));
    assert_eq!(r.events[0].kind, EventKind::Auxiliary { m: 6 });
}

#[test]
fn behaviour2_19_feed_spindle_and_their_modes() {
    let r = ok("G95 G01 X1. F0.1 S1200\nX2.", &mill(&[]));
    let s = &r.blocks[1].state;
    assert_eq!((s.feed, s.spindle), (Some(0.1), Some(1200.0)));
    let m = s.modal.codes(offsetlab::MachineKind::Mill);
    assert_eq!(m.feed_mode, "G95");
    let r = ok("G50 X100. Z50. S3000\nG96 G98 S200", &lathe(&[]));
    assert_eq!(r.blocks[0].state.spindle, None, "G50 S is the speed limit");
    let s = &r.blocks[1].state;
    assert_eq!(s.spindle, Some(200.0));
    let m = s.modal.codes(offsetlab::MachineKind::Lathe);
    assert_eq!((m.feed_mode, m.surface_speed), ("G98", Some("G96")));
    // The lathe starts in G99 (feed per revolution) and G97.
    let m = r.blocks[0].state.modal.codes(offsetlab::MachineKind::Lathe);
    assert_eq!(
        (m.feed_mode, m.surface_speed, m.plane),
        ("G99", Some("G97"), "G18")
    );
}

#[test]
fn behaviour7_5_mirror_image_is_for_the_mill_only() {
    let mut s = lathe(&[]);
    s.settings.mirror = Mirror { x: true, y: false };
    let r = run("G00 X10.", &s);
    assert_eq!(r.diagnostics[0].code, "setup-mirror");
    assert_eq!(r.block_count, 0);
}

#[test]
fn behaviour7_6_peck_retract_sets_the_back_off_of_g73_and_g83() {
    let mut s = mill(&[]);
    s.settings.peck_retract = Some(0.5);
    let r = ok("G90 G00 Z10.\nG73 X0 Y0 Z-10. R1. Q4. F100.", &s);
    let backs: Vec<f64> = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Rapid)
        .map(|m| m.programmed_to[2])
        .collect();
    assert_eq!(backs, vec![10.0, 1.0, -2.5, -6.5, 10.0]);
}

#[test]
fn behaviour2_14_k0_keeps_the_cycle_data_and_drills_nothing() {
    let text = "G90 G00 Z10.\nG81 X5. Y5. Z-5. R2. K0 F100.\nX10.";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.blocks[1].move_count, 0);
    same(programmed(&r, 1), [0.0, 0.0, 10.0]);
    // The next block drills with the R and Z the K0 block gave.
    let bottom = r.moves.iter().find(|m| m.kind == MoveKind::Feed).unwrap();
    same(bottom.programmed_to, [10.0, 0.0, -5.0]);
}

#[test]
fn behaviour7_8_an_inch_setup_positions_the_tool_in_inches() {
    let s = Setup {
        units: offsetlab::Units::Inch,
        start: Position {
            x: 1.0,
            y: 2.0,
            z: 3.0,
        },
        ..Setup::default()
    };
    let r = ok("G91 G00 X1.", &s);
    // Kept in millimetres; the start and the word both in inches.
    same(programmed(&r, 0), [50.8, 50.8, 76.2]);
    assert_eq!(r.units, offsetlab::Units::Inch);
}
