//! Behaviour 13 (`docs/behaviour.md`), where a program's coordinates lie:
//! G53 machine coordinates, G52 local coordinates, the additional work
//! systems G54.1/G154, G92.1, the reference returns G28/G30 and the check
//! G27, with what each does to the length, position and T offset vectors.
//! The transformations (13.7–13.13) and the rotary axes (13.14) are
//! `tests/transforms.rs`. Positions are worked out by hand in the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Control, ExtendedWork, Position, ReturnWithoutAxes};
use offsetlab::view::block_view;
use offsetlab::{MoveKind, Setup, run};

fn pos(x: f64, y: f64, z: f64) -> Position {
    Position { x, y, z }
}

fn with_control(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

fn warnings(r: &offsetlab::Run) -> Vec<&'static str> {
    r.diagnostics
        .iter()
        .filter(|d| !d.is_error())
        .map(|d| d.code)
        .collect()
}

// ----- 13.1 G53 ---------------------------------------------------------------

#[test]
fn behaviour13_1_g53_moves_to_machine_coordinates_whatever_the_work_offset() {
    let mut s = mill(&[]);
    s.work_offsets.g54 = pos(-400.0, -200.0, -300.0);
    let text = "G54 G90 G00 X10. Y20. Z5.\nG53 X-100. Y-50.\nX0";
    let r = ok(text, &s);
    // G54 puts the zero at machine (-400, -200, -300): X10 Y20 Z5 is
    // machine (-390, -180, -295).
    let b = at_line(&r, text, 1);
    assert_eq!(
        (b.machine.x, b.machine.y, b.machine.z),
        (-390.0, Some(-180.0), -295.0)
    );
    // G53 X-100 Y-50: machine X-100 is G54 X300 (-100 + 400), Y-50 is Y150;
    // Z stays. One rapid.
    same(programmed(&r, 1), [300.0, 150.0, 5.0]);
    let b = at_line(&r, text, 2);
    assert_eq!(
        (b.machine.x, b.machine.y, b.machine.z),
        (-100.0, Some(-50.0), -295.0)
    );
    assert_eq!(r.blocks[1].move_count, 1);
    assert_eq!(r.moves[1].kind, MoveKind::Rapid);
    assert!(
        b.explanation.contains("G53: to machine X-100.000 Y-50.000"),
        "{}",
        b.explanation
    );
    // G53 is one-shot: X0 is G54's X0 again, machine X-400.
    same(programmed(&r, 2), [0.0, 150.0, 5.0]);
    assert_eq!(at_line(&r, text, 3).machine.x, -400.0);
}

#[test]
fn behaviour13_1_g53_suspends_the_length_offset_on_z_until_the_next_z_move() {
    let mut s = mill(&[(1, 150.0)]);
    s.work_offsets.g54 = pos(0.0, 0.0, -300.0);
    let text = "G54 G90 G00 X0 Y0\nG43 Z20. H01\nG53 Z0\nX10.\nZ50.";
    let r = ok(text, &s);
    // G43 Z20 H01: Z lands at 20 + 150 = 170 (machine 170 - 300 = -130).
    same(actual(&r, 1), [0.0, 0.0, 170.0]);
    // G53 Z0: machine Z0 without the offset: G54 Z = 0 + 300 = 300, the
    // actual Z too; G43 H01 stays the mode.
    same(programmed(&r, 2), [0.0, 0.0, 300.0]);
    same(actual(&r, 2), [0.0, 0.0, 300.0]);
    assert_eq!(r.blocks[2].state.length.vector, 0.0);
    assert_eq!(r.blocks[2].state.length.target, 150.0);
    let b = at_line(&r, text, 3);
    assert_eq!(b.modal.length, Some("G43"));
    assert_eq!(b.machine.z, 0.0);
    assert!(
        b.explanation.contains("applies again at the next Z move"),
        "{}",
        b.explanation
    );
    // X10 moves no Z: the offset waits.
    same(actual(&r, 3), [10.0, 0.0, 300.0]);
    // Z50 lands on the offset again: 50 + 150.
    same(actual(&r, 4), [10.0, 0.0, 200.0]);
}

#[test]
fn behaviour13_1_g53_keeps_the_position_offset_vector() {
    // D01 = 5: G91 G45 X10. moves X by 15, leaving a vector of +5 on X.
    let text = "G91 G00 G45 X10. D01\nG90 G53 X0";
    let r = ok(text, &mill(&[(1, 5.0)]));
    same(actual(&r, 0), [15.0, 0.0, 0.0]);
    // Fanuc: the machine moves by the offsets left on: machine X0 + 5.
    same(programmed(&r, 1), [0.0, 0.0, 0.0]);
    same(actual(&r, 1), [5.0, 0.0, 0.0]);
    assert!(explain(&r, 1).contains("G45–G48 vector is carried"));
}

#[test]
fn behaviour13_1_g53_with_g49_and_without_axes() {
    let s = mill(&[(1, 150.0)]);
    // G53 G49 Z0: Z to machine 0 and the offset cancelled.
    let r = ok("G43 Z20. H01\nG53 G49 Z0", &s);
    same(actual(&r, 1), [0.0, 0.0, 0.0]);
    assert_eq!(r.blocks[1].state.modal.codes(r.machine).length, Some("G49"));
    // G53 G49 M05 names no axis: nothing moves by G53; the cancel moves Z
    // back by the old vector as any G49 without Z does (behaviour 3.6):
    // from 170 to 20.
    let text = "G43 Z20. H01\nG53 G49 M05";
    let r = ok(text, &s);
    same(actual(&r, 1), [0.0, 0.0, 20.0]);
    assert_eq!(r.moves.last().unwrap().kind, MoveKind::Offset);
    assert!(explain(&r, 1).contains("G53 without axis words"));
}

#[test]
fn behaviour13_1_g53_in_g91_is_ignored_with_a_warning() {
    let r = ok("G91 G53 X10.\nX5.", &mill(&[]));
    // Fanuc ignores G53 in G91: X moves by 10, then 5 more.
    same(programmed(&r, 0), [10.0, 0.0, 0.0]);
    same(programmed(&r, 1), [15.0, 0.0, 0.0]);
    assert_eq!(warnings(&r), vec!["g53-incremental"]);
}

#[test]
fn behaviour13_1_lathe_g53_and_the_t_offset() {
    let mut s = lathe(&[(1, 0.4, -0.2)]);
    s.work_offsets.g54 = pos(0.0, 0.0, -200.0);
    let text = "T0101\nG00 X50. Z10.\nG53 Z0\nW-10.";
    let r = ok(text, &s);
    same(actual(&r, 1), [50.4, 0.0, 9.8]);
    // G53 Z0: machine Z0 is G54 Z200; Z goes there without its T vector,
    // X keeps its vector (Fanuc 0i-TC 14.1.6).
    same(programmed(&r, 2), [50.0, 0.0, 200.0]);
    same(actual(&r, 2), [50.4, 0.0, 200.0]);
    assert_eq!(at_line(&r, text, 3).machine.z, 0.0);
    // W-10: Z moves and carries the offset again: 190 - 0.2.
    same(actual(&r, 3), [50.4, 0.0, 189.8]);
    assert_eq!(errors("G53 U10.", &lathe(&[])), vec!["g53-words"]);
}

#[test]
fn behaviour13_1_the_report_shows_machine_and_work_positions() {
    let mut s = mill(&[(1, 150.0)]);
    s.work_offsets.g55 = pos(100.0, 50.0, -300.0);
    let text = "G55 G90 G00 X10. Y10.\nG43 Z0 H01";
    let r = ok(text, &s);
    let b = at_line(&r, text, 2);
    // Work: programmed Z0, actual Z150; machine: actual + the G55 zero.
    assert_eq!((b.actual.x, b.actual.z), (10.0, 150.0));
    assert_eq!(
        (b.machine.x, b.machine.y, b.machine.z),
        (110.0, Some(60.0), -150.0)
    );
    assert_eq!(
        (b.coordinates.zero.x, b.coordinates.zero.z),
        (100.0, -300.0)
    );
    let json = serde_json::to_value(&b).unwrap();
    assert_eq!(json["machine"]["z"], -150.0);
    assert_eq!(json["coordinates"]["zero"]["y"], 50.0);
}

// ----- 13.2 G52 ---------------------------------------------------------------

#[test]
fn behaviour13_2_g52_sets_a_local_zero_in_every_work_system() {
    let mut s = mill(&[]);
    s.work_offsets.g54 = pos(100.0, 50.0, 0.0);
    s.work_offsets.g55 = pos(200.0, 0.0, 0.0);
    let text = "G90 G54 G00 X0 Y0\nG52 X10. Y5.\nG00 X0 Y0\nG55\nG52 X0 Y0";
    let r = ok(text, &s);
    // The tool at machine (100, 50); the local zero at G54 (10, 5) =
    // machine (110, 55): the tool's coordinates become (-10, -5).
    same(programmed(&r, 1), [-10.0, -5.0, 0.0]);
    assert_eq!(r.blocks[1].move_count, 0);
    // X0 Y0 is the local zero: machine (110, 55).
    same(programmed(&r, 2), [0.0, 0.0, 0.0]);
    assert_eq!(at_line(&r, text, 3).machine.x, 110.0);
    // G55 keeps the local offset: zero at machine (210, 5); the tool at
    // (110, 55) is (-100, 50).
    same(programmed(&r, 3), [-100.0, 50.0, 0.0]);
    // G52 X0 Y0 cancels it: zero at (200, 0), the tool at (-90, 55).
    same(programmed(&r, 4), [-90.0, 55.0, 0.0]);
    let b = at_line(&r, text, 5);
    assert_eq!(b.coordinates.local.x, 0.0);
    assert!(
        b.explanation.contains("G52: no local offset"),
        "{}",
        b.explanation
    );
    assert_eq!(errors("G52", &mill(&[])), vec!["g52-without-axis"]);
}

#[test]
fn behaviour13_2_g92_cancels_the_local_offset_on_the_axes_it_sets() {
    let text = "G52 X10. Y5.\nG92 X5.\nG52 X0 Y0";
    let r = ok(text, &mill(&[]));
    // The tool at machine 0: local (-10, -5).
    same(programmed(&r, 0), [-10.0, -5.0, 0.0]);
    // G92 X5: the tool's X is 5; the zero at machine X-5, all of it G92's
    // shift (the local X offset is gone); Y keeps its local offset.
    let b = at_line(&r, text, 2);
    assert_eq!((b.coordinates.shift.x, b.coordinates.local.x), (-5.0, 0.0));
    assert_eq!(b.coordinates.local.y, Some(5.0));
    // G52 X0 Y0: only Y changes (to machine 0 - 0).
    same(programmed(&r, 2), [5.0, 0.0, 0.0]);
}

#[test]
fn behaviour13_2_lathe_g52() {
    let r = ok("G52 Z-50.\nG00 X20. Z0", &lathe(&[]));
    // The local zero at Z-50: Z0 is machine Z-50.
    same(programmed(&r, 0), [0.0, 0.0, 50.0]);
    let text = "G52 Z-50.\nG00 X20. Z0";
    assert_eq!(at_line(&r, text, 2).machine.z, -50.0);
    assert_eq!(errors("G52 W5.", &lathe(&[])), vec!["g52-words"]);
}

// ----- 13.3 additional work systems ------------------------------------------

#[test]
fn behaviour13_3_g54_1_and_g54_p_on_fanuc() {
    let mut s = with_control(mill(&[]), Control::Fanuc);
    s.extended_work_offsets.insert(2, pos(50.0, 60.0, -10.0));
    let text = "G90 G54.1 P2 G00 X0 Y0\nG54 X0 Y0\nG54 P2 X1. Y1.\nG54.1 P7";
    let r = ok(text, &s);
    // P2's zero is machine (50, 60, -10).
    let b = at_line(&r, text, 1);
    assert_eq!((b.machine.x, b.machine.y), (50.0, Some(60.0)));
    assert_eq!(b.modal.work, "G54.1 P2");
    assert_eq!(at_line(&r, text, 2).machine.x, 0.0);
    // G54 P2 is G54.1 P2: X1 Y1 is machine (51, 61).
    let b = at_line(&r, text, 3);
    assert_eq!((b.machine.x, b.machine.y), (51.0, Some(61.0)));
    assert_eq!(b.modal.work, "G54.1 P2");
    // P7 is not in the setup: its zero is machine zero, and the sentence
    // says so.
    assert!(explain(&r, 3).contains("the setup leaves it out"));
    assert_eq!(errors("G54.1 P49", &s), vec!["work-offset-number"]);
    assert_eq!(errors("G54.1", &s), vec!["work-offset-number"]);
    assert_eq!(errors("G154 P1", &s), vec!["work-offset-code"]);
    assert_eq!(errors("G55 P1", &s), vec!["work-offset-number"]);
    assert_eq!(errors("G04 G54.1 P1", &s), vec!["p-conflict"]);
}

#[test]
fn behaviour13_3_haas_g110_to_g129_are_g154_p1_to_p20() {
    // G110 is G154 P1 (zero at machine X5 Y7), G129 is G154 P20 (X-3):
    // X1. after each lands at machine X6, then X-2.
    let mut s = with_control(mill(&[]), Control::Haas);
    s.extended_work_offsets.insert(1, pos(5.0, 7.0, 0.0));
    s.extended_work_offsets.insert(20, pos(-3.0, 0.0, 0.0));
    let text = "G110 G00 X1. Y0\nG129 X1.";
    let r = ok(text, &s);
    let b = at_line(&r, text, 1);
    assert_eq!(
        (b.machine.x, b.machine.y, b.modal.work),
        (6.0, Some(7.0), "G154 P1")
    );
    let b = at_line(&r, text, 2);
    assert_eq!((b.machine.x, b.modal.work), (-2.0, "G154 P20"));
    assert_eq!(errors("G110 P3", &s), vec!["work-offset-number"]);
    // Fanuc and YASNAC number their systems G54.1 Pn: G110 is refused there.
    let f = with_control(mill(&[]), Control::Fanuc);
    assert_eq!(errors("G110", &f), vec!["work-offset-code"]);
}

#[test]
fn behaviour13_3_g154_p_on_haas() {
    let mut s = with_control(mill(&[]), Control::Haas);
    s.extended_work_offsets.insert(12, pos(5.0, 5.0, 0.0));
    let text = "G154 P12 G00 X0 Y0";
    let r = ok(text, &s);
    let b = at_line(&r, text, 1);
    assert_eq!((b.machine.x, b.modal.work), (5.0, "G154 P12"));
    assert_eq!(errors("G154 P100", &s), vec!["work-offset-number"]);
    assert_eq!(errors("G54.1 P1", &s), vec!["work-offset-code"]);
    assert_eq!(errors("G54 P1", &s), vec!["work-offset-number"]);
    // The setting wins over the profile.
    s.settings.extended_work_offsets = Some(ExtendedWork::G54_1);
    assert!(errors("G54.1 P1", &s).is_empty());
}

#[test]
fn behaviour13_3_the_setup_keys_the_additional_systems_by_p() {
    let s =
        Setup::from_json(r#"{"extended_work_offsets": {"03": {"x": 1, "y": 2, "z": 3}}}"#).unwrap();
    assert_eq!(s.extended_work_offsets[&3], pos(1.0, 2.0, 3.0));
    assert!(s.to_json().contains("\"03\""));
    let e = Setup::from_json(r#"{"extended_work_offsets": {"100": {"x": 1}}}"#).unwrap_err();
    assert!(e.to_string().contains("outside 01 to 99"), "{e}");
}

// ----- 13.4 G92.1 ---------------------------------------------------------------

#[test]
fn behaviour13_4_g92_1_undoes_the_g92_shift_of_the_named_axes() {
    let text = "G00 X10. Y10.\nG92 X0 Y0\nG92.1 X0";
    let r = ok(text, &mill(&[]));
    same(programmed(&r, 1), [0.0, 0.0, 0.0]);
    // X's shift is undone: the tool at machine 10 is X10 again; Y keeps
    // the shift.
    same(programmed(&r, 2), [10.0, 0.0, 0.0]);
    assert_eq!(r.blocks[2].move_count, 0);
    assert_eq!(errors("G92.1 X5.", &mill(&[])), vec!["g92-1-value"]);
    assert_eq!(errors("G92.1", &mill(&[])), vec!["g92-1-without-axis"]);
}

// ----- 13.5 G28, G30 --------------------------------------------------------------

#[test]
fn behaviour13_5_g28_without_axes_as_each_control_does_it() {
    let text = "G00 X10. Y20. Z30.\nG28";
    // Haas: every axis returns, straight from where it is, to the Haas
    // profile's reference (setting 7.49, behaviour 13.15): X0 Y0 and the
    // top of the VF-2's Z travel, 508 mm above the work zero.
    let r = ok(text, &with_control(mill(&[]), Control::Haas));
    same(programmed(&r, 1), [0.0, 0.0, 508.0]);
    assert_eq!(r.blocks[1].move_count, 1);
    // Fanuc returns the axes named: none; a warning says so.
    for control in [Control::Fanuc, Control::Yasnac] {
        let r = ok(text, &with_control(mill(&[]), control));
        same(programmed(&r, 1), [10.0, 20.0, 30.0]);
        assert_eq!(r.blocks[1].move_count, 0);
        assert_eq!(warnings(&r), vec!["reference-without-axes"], "{control:?}");
    }
    // The setting wins over the profile.
    let mut s = with_control(mill(&[]), Control::Fanuc);
    s.settings.reference_return_without_axes = Some(ReturnWithoutAxes::AllAxes);
    same(programmed(&ok(text, &s), 1), [0.0, 0.0, 508.0]);
    // The Haas lathe returns X and Z.
    let mut l = lathe(&[]);
    l.settings.control = Control::Haas;
    l.reference = pos(200.0, 0.0, 100.0);
    let r = ok("G00 X50. Z10.\nG28", &l);
    same(programmed(&r, 1), [200.0, 0.0, 100.0]);
}

#[test]
fn behaviour13_5_g91_g28_x0_y0_z0_goes_straight_to_the_reference() {
    let mut s = mill(&[]);
    s.reference = pos(10.0, 20.0, 30.0);
    let r = ok("G00 X5. Y5. Z5.\nG91 G28 X0 Y0 Z0", &s);
    // The intermediate point is where the tool is: one move, to machine
    // (10, 20, 30).
    same(programmed(&r, 1), [10.0, 20.0, 30.0]);
    assert_eq!(r.blocks[1].move_count, 1);
}

#[test]
fn behaviour13_5_g30_returns_to_the_second_third_or_fourth_reference() {
    let mut s = mill(&[(1, 150.0)]);
    s.third_reference = Some(pos(0.0, 0.0, -50.0));
    s.second_reference = Some(pos(-10.0, -20.0, 0.0));
    let text = "G90 G00 X0 Y0\nG43 Z20. H01\nG91 G30 P3 Z0\nG90 G00 Z20.\nG91 G30 X0 Y0";
    let r = ok(text, &s);
    same(actual(&r, 1), [0.0, 0.0, 170.0]);
    // G30 P3: Z to machine -50; the length vector is cleared there.
    same(programmed(&r, 2), [0.0, 0.0, -50.0]);
    same(actual(&r, 2), [0.0, 0.0, -50.0]);
    assert!(explain(&r, 2).contains("G30 P3: to reference position 3"));
    // The next Z move lands on the offset again.
    same(actual(&r, 3), [0.0, 0.0, 170.0]);
    // G30 without P is the second reference position.
    same(programmed(&r, 4), [-10.0, -20.0, 20.0]);
    // An unset reference position is the first.
    let r = ok("G91 G30 P4 X0", &mill(&[]));
    same(programmed(&r, 0), [0.0, 0.0, 0.0]);
    assert_eq!(errors("G30 P5 Z0", &s), vec!["reference-number"]);
    assert_eq!(errors("G28 P2 Z0", &s), vec!["reference-number"]);
}

#[test]
fn behaviour13_5_lathe_g28_u0_w0_and_g30() {
    let mut s = lathe(&[(1, 0.4, -0.2)]);
    s.reference = pos(200.0, 0.0, 100.0);
    s.second_reference = Some(pos(150.0, 0.0, 80.0));
    let text = "T0101\nG00 X50. Z10.\nG28 U0 W0\nG00 X60.\nG30 U0 W0";
    let r = ok(text, &s);
    same(actual(&r, 1), [50.4, 0.0, 9.8]);
    // Straight to the reference (X200 Z100), the T vector off on both.
    same(actual(&r, 2), [200.0, 0.0, 100.0]);
    // X moves and carries its offset again; Z waits for its own move.
    same(actual(&r, 3), [60.4, 0.0, 100.0]);
    // G30 without P: the second reference position.
    same(actual(&r, 4), [150.0, 0.0, 80.0]);
    assert_eq!(errors("G30 T0101 U0", &s), vec!["t-in-positioning"]);
}

// ----- 13.6 G27 -------------------------------------------------------------------

#[test]
fn behaviour13_6_g27_checks_the_reference_position() {
    let mut s = mill(&[(1, 150.0)]);
    s.reference = pos(0.0, 0.0, 100.0);
    // At machine Z100 the check passes.
    let r = ok("G00 X10.\nG27 X0 Z100.", &s);
    same(programmed(&r, 1), [0.0, 0.0, 100.0]);
    assert!(explain(&r, 1).contains("G27: X, Z at the reference position"));
    // X5 is not the reference: the control's alarm.
    let r = run("G27 X5.", &s);
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(e.code, "reference-check");
    assert!(e.message.contains("reached machine 5.000"), "{}", e.message);
    // With G43 the tool stops 150 above Z100: the check fails and says why.
    let r = run("G43 Z0 H01\nG27 Z100.", &s);
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(e.code, "reference-check");
    assert!(
        e.message.contains("reached machine 250.000"),
        "{}",
        e.message
    );
    assert!(
        e.message.contains("cancel them before G27"),
        "{}",
        e.message
    );
    assert_eq!(errors("G27", &s), vec!["g27-without-axis"]);
    // The lathe: U0 W0 after G28 is at the reference.
    let mut l = lathe(&[]);
    l.reference = pos(200.0, 0.0, 100.0);
    assert!(errors("G28 U0 W0\nG27 U0 W0", &l).is_empty());
}

// ----- the JSON ---------------------------------------------------------------------

#[test]
fn behaviour13_1_the_json_of_a_block_has_machine_coordinates_and_transforms() {
    let text = "G52 X1.\nG68 X0 Y0 R90.\nG00 X1. A30.";
    let r = run(text, &mill(&[]));
    let b = r.blocks.last().unwrap();
    let v = serde_json::to_value(block_view(b, text)).unwrap();
    assert_eq!(v["coordinates"]["local"]["x"], 1.0);
    assert_eq!(v["transforms"]["rotation"]["degrees"], 90.0);
    assert_eq!(v["transforms"]["rotation"]["plane"], "G17");
    assert!(v["transforms"].get("scaling").is_none());
    assert_eq!(v["rotary"]["a"], 30.0);
    assert!(v["rotary"].get("b").is_none());
    assert_eq!(v["modal"]["rotation"], "G68");
    assert_eq!(v["modal"]["scaling"], "G50");
    assert_eq!(v["modal"]["polar_coordinates"], "G15");
    assert_eq!(v["modal"]["mirror"], "G50.1");
    assert!(v["modal"].get("arc_center").is_none());
    // X1 rotated 90° about the origin is Y1; the local zero adds X1 in
    // machine coordinates.
    assert_eq!(v["programmed"]["y"], 1.0);
    assert_eq!(v["machine"]["x"], 1.0);
    // The lathe's block has no transforms and no rotary key.
    let l = run("G00 X10.", &lathe(&[]));
    let v = serde_json::to_value(block_view(&l.blocks[0], "G00 X10.")).unwrap();
    assert!(v.get("transforms").is_none() && v.get("rotary").is_none());
    assert!(v["modal"].get("rotation").is_none());
}
