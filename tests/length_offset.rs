//! Behaviour 3 (`docs/behaviour.md`): tool length offset G43, G44, G49
//! (seed 001), one test or more per numbered rule.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::MoveKind;
use offsetlab::setup::LengthOffsetWithoutZ;

#[test]
fn behaviour3_1_g43_adds_the_register_to_z() {
    let r = ok("G90 G00 G43 Z50. H02", &mill(&[(2, 15.0)]));
    same(actual(&r, 0), [0.0, 0.0, 65.0]);
    same(programmed(&r, 0), [0.0, 0.0, 50.0]);
}

#[test]
fn behaviour3_1_g44_subtracts_the_register_from_z() {
    let r = ok("G90 G00 G44 Z50. H02", &mill(&[(2, 15.0)]));
    same(actual(&r, 0), [0.0, 0.0, 35.0]);
}

#[test]
fn behaviour3_1_negative_value_reverses_the_direction() {
    let r = ok("G90 G00 G43 Z50. H02", &mill(&[(2, -15.0)]));
    same(actual(&r, 0), [0.0, 0.0, 35.0]);
    let r = ok("G90 G00 G44 Z50. H02", &mill(&[(2, -15.0)]));
    same(actual(&r, 0), [0.0, 0.0, 65.0]);
}

#[test]
fn behaviour3_1_geometry_plus_wear_is_used() {
    let mut s = mill(&[]);
    s.set_register("02=15.0,W-0.25").unwrap();
    let r = ok("G90 G00 G43 Z50. H02", &s);
    same(actual(&r, 0), [0.0, 0.0, 64.75]);
}

#[test]
fn behaviour3_1_g49_and_h00_cancel() {
    let s = mill(&[(2, 15.0)]);
    let r = ok("G90 G00 G43 Z50. H02\nG49 Z50.", &s);
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    let r = ok("G90 G00 G43 Z50. H02\nH00 Z50.", &s);
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    assert!(explain(&r, 1).contains("H00 cancels"), "{}", explain(&r, 1));
}

#[test]
fn behaviour3_1_a_register_holding_zero_is_a_new_h_not_h00_and_is_warned_about() {
    // Issue 23's defect: with G43 H01 = 6 on, `G43 Z50. H02` with H02 = 0
    // was explained as "H00 cancels". It is a change of H (6 → 0): Z50.
    // lands at 50 + 0 = 50, and the empty register is warned about.
    let s = mill(&[(1, 6.0)]);
    let r = ok("G90 G00 G43 Z50. H01\nG43 Z50. H02", &s);
    same(actual(&r, 0), [0.0, 0.0, 56.0]);
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    let e = explain(&r, 1);
    assert!(
        e.starts_with("H01 → H02 while G43 is active (6.000 → 0.000)"),
        "{e}"
    );
    assert!(!e.contains("H00"), "{e}");
    let w: Vec<_> = r
        .diagnostics
        .iter()
        .filter(|d| d.code == "length-offset-zero")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", r.diagnostics);
    assert_eq!((w[0].line, w[0].column), (2, 10), "at the H word");
    // H00 keeps its own warning and sentence.
    let r = ok("G90 G00 G43 Z50. H01\nG43 Z50. H00", &s);
    assert!(explain(&r, 1).contains("H00 cancels"), "{}", explain(&r, 1));
    assert!(r.diagnostics.iter().any(|d| d.code == "length-offset-h00"));
}

#[test]
fn behaviour3_2_worked_example() {
    // `G90 G00 G43 Z50. H02` with register 02 = 15. → Z65.
    let text = "G90 G00 G43 Z50. H02";
    let r = ok(text, &mill(&[(2, 15.0)]));
    let b = at_line(&r, text, 1);
    assert_eq!(b.actual.z, 65.0);
    let l = b.length_offset.unwrap();
    assert_eq!((l.mode, l.h, l.value, l.vector), ("G43", 2, 15.0, 15.0));
    assert_eq!(
        b.explanation,
        "G43 adds H02 (15.000): Z target 50.000 lands at 65.000."
    );
}

#[test]
fn behaviour3_3_no_z_word_moves_z_by_the_offset() {
    let text = "G90 G00 Z50.\nG43 H02";
    let r = ok(text, &mill(&[(2, 15.0)]));
    same(actual(&r, 1), [0.0, 0.0, 65.0]);
    same(programmed(&r, 1), [0.0, 0.0, 50.0]);
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    assert!(!m.at_feed, "made in the current G00 mode");
    assert!(
        explain(&r, 1).contains("Z moves by +15.000"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour3_3_offset_motion_in_g01_mode_is_at_feed() {
    let r = ok("G90 G01 Z50. F100.\nG43 H02", &mill(&[(2, 15.0)]));
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    assert!(m.at_feed);
}

#[test]
fn behaviour3_3_setting_next_z_waits_for_the_next_z_move() {
    let mut s = mill(&[(2, 15.0)]);
    s.settings.length_offset_without_z = Some(LengthOffsetWithoutZ::NextZ);
    let text = "G90 G00 Z50.\nG43 H02\nX10.\nZ20.";
    let r = ok(text, &s);
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    assert_eq!(r.blocks[1].move_count, 0, "no motion");
    assert!(explain(&r, 1).contains("next Z move"), "{}", explain(&r, 1));
    same(actual(&r, 2), [10.0, 0.0, 50.0]);
    same(actual(&r, 3), [10.0, 0.0, 35.0]);
    let b = at_line(&r, text, 2).length_offset.unwrap();
    assert_eq!((b.vector, b.target), (0.0, 15.0));
}

#[test]
fn behaviour3_3_h_with_xy_move_and_no_z_shifts_z_in_the_same_move() {
    let r = ok("G90 G00 Z50.\nG43 H02 X10. Y5.", &mill(&[(2, 15.0)]));
    assert_eq!(r.blocks[1].move_count, 1);
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Rapid);
    same(m.to, [10.0, 5.0, 65.0]);
}

#[test]
fn behaviour3_4_new_h_moves_by_the_difference() {
    let text = "G90 G00 G43 Z50. H02\nH03";
    let r = ok(text, &mill(&[(2, 15.0), (3, 12.0)]));
    same(actual(&r, 1), [0.0, 0.0, 62.0]);
    let m = r.moves.last().unwrap();
    same(m.from, [0.0, 0.0, 65.0]);
    same(m.to, [0.0, 0.0, 62.0]);
    let e = explain(&r, 1);
    assert!(
        e.contains("H02 → H03") && e.contains("difference, -3.000"),
        "{e}"
    );
    assert_eq!(at_line(&r, text, 2).length_offset.unwrap().value, 12.0);
}

#[test]
fn behaviour3_4_switching_g43_to_g44_moves_by_the_difference() {
    let r = ok("G90 G00 G43 Z50. H02\nG44", &mill(&[(2, 15.0)]));
    same(actual(&r, 1), [0.0, 0.0, 35.0]);
    assert_eq!(r.moves.last().unwrap().kind, MoveKind::Offset);
}

#[test]
fn behaviour3_5_in_g91_the_offset_is_added_to_the_incremental_move() {
    // `G91 G43 Z-20. H03` with register 03 = -2. moves Z by -22.
    let r = ok("G91 G00 G43 Z-20. H03", &mill(&[(3, -2.0)]));
    let m = r.moves.last().unwrap();
    assert!((m.to[2] - m.from[2] + 22.0).abs() < 1e-9);
    same(programmed(&r, 0), [0.0, 0.0, -20.0]);
    assert!(
        explain(&r, 0).contains("the Z move -20.000 becomes -22.000"),
        "{}",
        explain(&r, 0)
    );
}

#[test]
fn behaviour3_6_cancel_with_z_in_g90_goes_to_the_uncompensated_target() {
    let r = ok("G90 G00 G43 Z50. H02\nG49 Z30.", &mill(&[(2, 15.0)]));
    same(actual(&r, 1), [0.0, 0.0, 30.0]);
}

#[test]
fn behaviour3_6_cancel_with_z_in_g91_moves_by_the_move_minus_the_old_vector() {
    let r = ok("G90 G00 G43 Z50. H02\nG91 G49 Z-10.", &mill(&[(2, 15.0)]));
    let m = r.moves.last().unwrap();
    assert!((m.to[2] - m.from[2] + 25.0).abs() < 1e-9);
    same(actual(&r, 1), [0.0, 0.0, 40.0]);
}

#[test]
fn behaviour3_6_cancel_without_z_moves_back_by_the_old_vector() {
    let r = ok("G90 G00 G43 Z50. H02\nG49", &mill(&[(2, 15.0)]));
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    assert!((m.to[2] - m.from[2] + 15.0).abs() < 1e-9);
    assert!(explain(&r, 1).contains("G49 cancels"), "{}", explain(&r, 1));
}

#[test]
fn behaviour3_7_length_offset_in_arc_mode_is_an_error() {
    let s = mill(&[(2, 15.0)]);
    assert_eq!(
        errors("G17 G02 X10. Y10. I10. F100.\nG43 H02", &s),
        vec!["length-offset-in-arc"]
    );
    assert_eq!(
        errors("G43 G02 X10. Y10. I10. H02 F100.", &s),
        vec!["length-offset-in-arc"]
    );
    assert_eq!(
        errors("G43 Z5. H02\nG03 X10. Y10. J10. F100.\nG49", &s),
        vec!["length-offset-in-arc"]
    );
    // Blocks before the error keep their motion (behaviour 2.1).
    let r = offsetlab::run("G43 Z5. H02\nG03 X10. Y10. J10. F100.\nG49", &s);
    assert_eq!(r.block_count, 2);
}

#[test]
fn behaviour3_8_h_number_beyond_the_table_is_an_error() {
    assert_eq!(errors("G43 Z50. H100", &mill(&[])), vec!["out-of-range"]);
    let mut s = mill(&[]);
    s.table_size = 10;
    assert_eq!(errors("G43 Z50. H11", &s), vec!["out-of-range"]);
    assert!(errors("G43 Z50. H10", &s).is_empty());
}

#[test]
fn behaviour3_offset_values_are_read_in_the_current_unit() {
    // Behaviour 2.6 and 3.9: G20/G21 — offset values are read in the current
    // unit, not converted.
    let text = "G20 G90 G00 G43 Z1. H02";
    let r = ok(text, &mill(&[(2, 0.5)]));
    let b = at_line(&r, text, 1);
    assert_eq!(b.units, "inch");
    assert_eq!(b.actual.z, 1.5);
    same(actual(&r, 0), [0.0, 0.0, 1.5 * 25.4]);
}

#[test]
fn behaviour3_g43_with_h00_warns() {
    let r = offsetlab::run("G43 Z10.", &mill(&[]));
    assert!(r.diagnostics.iter().any(|d| d.code == "length-offset-h00"));
    assert!(!r.has_errors());
}

#[test]
fn behaviour3_3_with_next_z_a_z_less_h_change_or_cancel_waits_too() {
    let mut s = mill(&[(2, 15.0), (3, 10.0)]);
    s.settings.length_offset_without_z = Some(LengthOffsetWithoutZ::NextZ);
    let r = ok("G90 G00 G43 Z50. H02\nH03\nZ20.", &s);
    assert_eq!(r.blocks[1].move_count, 0);
    same(actual(&r, 1), [0.0, 0.0, 65.0]);
    same(actual(&r, 2), [0.0, 0.0, 30.0]);
    let r = ok("G90 G00 G43 Z50. H02\nG49\nZ20.", &s);
    assert_eq!(r.blocks[1].move_count, 0);
    same(actual(&r, 1), [0.0, 0.0, 65.0]);
    same(actual(&r, 2), [0.0, 0.0, 20.0]);
}

#[test]
fn behaviour3_11_the_offset_is_on_z_whatever_the_plane() {
    for plane in ["G17", "G18", "G19"] {
        let text = format!("{plane} G90 G00 G43 Z50. H02");
        let r = ok(&text, &mill(&[(2, 15.0)]));
        same(actual(&r, 0), [0.0, 0.0, 65.0]);
    }
}

#[test]
fn behaviour3_12_an_h_given_in_g49_applies_at_the_next_g43() {
    let r = ok("G90 G00 Z50.\nH02\nG43 Z50.", &mill(&[(2, 15.0)]));
    same(actual(&r, 1), [0.0, 0.0, 50.0]);
    same(actual(&r, 2), [0.0, 0.0, 65.0]);
}

#[test]
fn behaviour3_13_a_change_in_a_cycle_block_without_a_hole_moves_at_rapid() {
    let text = "G90 G01 Z50. F100.\nG81 X0 Y0 Z-5. R2.\nG43 H02\nG80";
    let r = ok(text, &mill(&[(2, 15.0)]));
    let m = r.moves.last().unwrap();
    assert_eq!((m.kind, m.at_feed, m.line), (MoveKind::Offset, false, 3));
    same(m.to, [0.0, 0.0, 65.0]);
}
