//! Behaviour 16.12–16.19 (`docs/behaviour.md`): cutter radius
//! compensation's alarms (interference PS0041, no intersection PS0033,
//! arc centre PS0038, start-up or cancel in an arc PS0034, plane change
//! PS0037, G45–G48 PS0042, chamfers PS0039), what a block reports, G39 and
//! I/J/K, mirror image, the length offset, G28 and canned cycles. The
//! corners themselves are `tests/cutter.rs`. Positions worked out by hand
//! in the comments; register 01 = 5, G17, G41 unless said.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::report::End;
use offsetlab::setup::{CutterInterference, Mirror};
use offsetlab::{MoveKind, Run, Setup, run};

const S: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// From (-20, 0), a start-up along +X to (0, 0), ending at (0, 5); the
/// block after is line 3.
const UP: &str = "G00 X-20.\nG01 G41 D01 X0 F100.\n";

fn r5() -> Setup {
    mill(&[(1, 5.0)])
}

#[track_caller]
fn end(r: &Run, line: u32) -> [f64; 3] {
    r.blocks
        .iter()
        .rev()
        .find(|b| b.span.line == line)
        .unwrap_or_else(|| panic!("no block on line {line}: {:#?}", r.diagnostics))
        .state
        .actual
}

/// The first error: its code, line and message.
#[track_caller]
fn alarm(text: &str, setup: &Setup) -> (&'static str, u32, String) {
    let r = run(text, setup);
    let d = r
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .unwrap_or_else(|| panic!("no error in {text}: {:#?}", r.diagnostics));
    (d.code, d.span.line, d.message.clone())
}

// ----- 16.12 interference, no intersection, arc centre --------------------

/// A groove 8 wide and 10 deep in the path, the tool 10 across: X50. to
/// the wall, Y-10. down, X58. along the bottom, Y0 up, X100.
fn groove() -> String {
    format!("{UP}X50.\nY-10.\nX58.\nY0\nX100.\nG40 X120.")
}

#[test]
fn behaviour16_12_a_block_whose_offset_runs_backwards_is_an_interference_alarm() {
    // X50. then down: an outside corner, y = 5 and x = 55 meet at (55, 5).
    // Y-10. then +X: inside, x = 55 and y = -5 meet at (55, -5). X58. then
    // up: inside, y = -5 and x = 53 at (53, -5): the bottom's offset runs
    // from x 55 back to 53, against its programmed +X: PS0041 at line 5,
    // the path drawn up to the block before.
    let (code, line, message) = alarm(&groove(), &r5());
    assert_eq!((code, line), ("cutter-interference", 5));
    assert!(message.contains("PS0041"), "{message}");
    let r = run(&groove(), &r5());
    assert_eq!(r.end, End::Error { line: 5 });
    assert_eq!(r.block_count, 4);
    same(end(&r, 4), [55.0, -5.0, 0.0]);
}

#[test]
fn behaviour16_12_with_the_check_off_the_overcut_is_drawn_with_a_warning() {
    // cutter_interference_check = off: the bottom runs back from (55, -5)
    // to (53, -5), a warning says so, and Y0 goes on from there to the
    // outside corner x = 53, y = 5.
    let mut s = r5();
    s.settings.cutter_interference_check = CutterInterference::Off;
    let r = ok(&groove(), &s);
    let m = r.moves.iter().find(|m| m.line == 5).unwrap();
    same(m.from, [55.0, -5.0, 0.0]);
    same(m.to, [53.0, -5.0, 0.0]);
    assert!(
        r.diagnostics
            .iter()
            .any(|d| d.code == "cutter-interference" && !d.is_error() && d.span.line == 5)
    );
    same(end(&r, 6), [53.0, 5.0, 0.0]);
}

#[test]
fn behaviour16_12_an_inside_arc_smaller_than_the_tool_is_an_interference() {
    // G03 of radius 3 after X50., the tool (radius 5) inside it: its offset
    // radius is 3 - 5 = -2, the tool would run round it the other way.
    let text = format!("{UP}X50.\nG03 X53. Y3. R3.\nG01 Y30.\nG40 X0");
    let (code, line, _) = alarm(&text, &r5());
    assert_eq!((code, line), ("cutter-interference", 4));
}

#[test]
fn behaviour16_12_an_arc_of_the_tool_radius_has_its_offset_at_the_centre() {
    // G03 of radius 5 inside a tool of radius 5: the offset arc's ends are
    // its centre (50, 5): PS0038.
    let text = format!("{UP}X50.\nG03 X55. Y5. R5.\nG01 Y30.\nG40 X0");
    let (code, line, message) = alarm(&text, &r5());
    assert_eq!((code, line), ("cutter-arc-center", 4));
    assert!(message.contains("PS0038"), "{message}");
}

#[test]
fn behaviour16_12_offsets_that_do_not_meet_at_an_inside_corner_are_an_alarm() {
    // X50. then a G03 of radius 2 about (48, 0) heading up: inside, the
    // offset line y = 5 passes 5 from the centre, the offset circle has
    // radius |2 - 5| = 3: no intersection, PS0033 at X50.
    let text = format!("{UP}X50.\nG03 X46. Y0 I-2. J0\nG01 Y-30.\nG40 X0");
    let (code, line, message) = alarm(&text, &r5());
    assert_eq!((code, line), ("cutter-no-intersection", 3));
    assert!(message.contains("PS0033"), "{message}");
}

// ----- 16.10 (alarm) start-up and cancel in an arc -------------------------

#[test]
fn behaviour16_10_start_up_or_cancel_in_an_arc_is_an_alarm() {
    let (code, line, message) = alarm("G02 G41 D01 X20. Y0 R10. F100.", &r5());
    assert_eq!((code, line), ("cutter-arc", 1));
    assert!(message.contains("PS0034"), "{message}");
    let text = format!("{UP}X50.\nG02 G40 X60. Y-10. R10.");
    assert_eq!(alarm(&text, &r5()).0, "cutter-arc");
}

// ----- 16.13 what a block reports ---------------------------------------

#[test]
fn behaviour16_13_every_block_reports_the_mode_d_radius_phase_and_vector() {
    let text = "G01 G41 D01 X50. F100.\nM08\nX100.\nG40 X150.";
    let r = ok(text, &r5());
    let v = at_line(&r, text, 1);
    let c = v.cutter.unwrap();
    assert_eq!(
        (c.mode, c.d, c.radius, c.phase),
        ("G41", 1, 5.0, "start_up")
    );
    assert_eq!((c.vector.x, c.vector.y, c.vector.z), (0.0, Some(5.0), 0.0));
    assert_eq!(v.modal.cutter, Some("G41"));
    assert_eq!(
        v.explanation,
        "G41 D01 (5.000 left) start-up (type A): the tool centre goes 5.000 left of the next block's start, perpendicular to its direction."
    );
    // M08 carries the vector: the start-up read past it to X100.
    assert_eq!(
        at_line(&r, text, 2).explanation,
        "Offsets carried: Y +5.000 (G41 D01)."
    );
    let last = at_line(&r, text, 4);
    assert_eq!(last.cutter.unwrap().phase, "cancelling");
    assert_eq!(last.modal.cutter, Some("G40"));
    // The JSON has the same fields.
    let json = serde_json::to_value(at_line(&r, text, 3)).unwrap();
    assert_eq!(json["cutter"]["mode"], "G41");
    assert_eq!(json["cutter"]["phase"], "offset");
    assert_eq!(json["cutter"]["vector"]["y"], 5.0);
    assert_eq!(json["modal"]["cutter"], "G41");
}

#[test]
fn behaviour16_13_the_lathe_reports_its_nose_radius_compensation() {
    // The lathe reports group 07 too (behaviour 18.9): G40, no tip read
    // outside compensation.
    let text = "G00 X10. Z5.";
    let r = ok(text, &lathe(&[]));
    let v = at_line(&r, text, 1);
    let c = v.cutter.expect("the lathe reports its compensation");
    assert_eq!(c.mode, "G40");
    assert_eq!(c.phase, "cancel");
    assert_eq!(v.modal.cutter, Some("G40"));
}

// ----- 16.14 G39 and I/J/K ----------------------------------------------

#[test]
fn behaviour16_14_g39_turns_the_corner_on_an_arc_of_the_radius() {
    // X50. sees G39 next: it ends perpendicular to itself, (50, 5). G39
    // turns about the corner (50, 0) clockwise (G41) to 5 left of the next
    // move (-Y): (55, 0), a quarter turn. Y-30. starts there.
    let text = format!("{UP}X50.\nG39\nY-30.\nG40 X0");
    let r = ok(&text, &r5());
    same(end(&r, 3), [50.0, 5.0, 0.0]);
    let m = r.moves.iter().find(|m| m.line == 4).unwrap();
    assert_eq!(m.kind, MoveKind::ArcCw);
    let arc = m.arc.unwrap();
    same(arc.center, [50.0, 0.0, 0.0]);
    assert!((arc.radius - 5.0).abs() < 1e-9);
    assert!((arc.sweep + std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    same(m.to, [55.0, 0.0, 0.0]);
    same(m.programmed_from, m.programmed_to);
    let next = r.moves.iter().find(|m| m.line == 5).unwrap();
    same(next.from, [55.0, 0.0, 0.0]);
    // With I1. J-1. the end is 5 left of (s, -s): (50 + 5s, 5s), 45° on.
    let text = format!("{UP}X50.\nG39 I1. J-1.\nY-30.\nG40 X0");
    let r = ok(&text, &r5());
    same(end(&r, 4), [50.0 + 5.0 * S, 5.0 * S, 0.0]);
}

#[test]
fn behaviour16_14_g39_outside_offset_mode_or_with_a_move_is_refused() {
    assert_eq!(alarm("G39", &r5()).0, "cutter-g39");
    let text = format!("{UP}X50.\nG39 X60.\nY-30.");
    assert_eq!(alarm(&text, &r5()).0, "cutter-g39");
}

#[test]
fn behaviour16_14_g41_with_i_j_and_no_move_sets_the_vector_from_their_direction() {
    // G41 I1. J0 in G01 from (0, 0): the vector is 5 left of +X, (0, 5),
    // made at once as offset motion at the feed (the start-up). X50. then
    // runs on its offset line y = 5.
    let text = "G01 G41 D01 I1. J0 F100.\nX50.\nX100.\nG40 X150.";
    let r = ok(text, &r5());
    let m = r.moves.iter().find(|m| m.line == 1).unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    same(m.to, [0.0, 5.0, 0.0]);
    assert_eq!(at_line(&r, text, 1).cutter.unwrap().phase, "start_up");
    same(end(&r, 2), [50.0, 5.0, 0.0]);
    // Not in a G40 block without a move.
    let (code, line, _) = alarm("G01 G41 D01 X50. F100.\nX100.\nG40 I1. J0", &r5());
    assert_eq!((code, line), ("cutter-ijk", 3));
}

#[test]
fn behaviour16_14_a_g41_block_with_a_move_and_i_j_ends_perpendicular_to_their_direction() {
    // Fanuc 15i-MA, the IJ-type vector: G41 X0 Y0 I1. J1. from (−20, 0)
    // ends 5 left of the direction (1, 1)/√2, at (−5/√2, 5/√2), whatever
    // the next block (X50. would have made it (0, 5)), and without the
    // start-up type. The next block runs from there to its own corner.
    let h = 5.0 * std::f64::consts::FRAC_1_SQRT_2;
    let text = "G00 X-20.\nG01 G41 D01 X0 I1. J1. F100.\nX50.\nY-40.\nG40 X0";
    let r = ok(text, &r5());
    same(end(&r, 2), [-h, h, 0.0]);
    assert_eq!(at_line(&r, text, 2).cutter.unwrap().phase, "start_up");
    let m = r.moves.iter().find(|m| m.line == 3).unwrap();
    same(m.from, [-h, h, 0.0]);
    same(m.to, [55.0, 5.0, 0.0]);
    // In offset mode G42 Y−40. I0 J−1. after X50.: the side changes; the
    // block ends 5 right of −Y, at (45, −40), with no corner to the next.
    let text = "G00 X-20.\nG01 G41 D01 X0 F100.\nX50.\nG42 Y-40. I0 J-1.\nX100. Y-60.\nG40 X120.";
    let r = ok(text, &r5());
    same(end(&r, 4), [45.0, -40.0, 0.0]);
    let m = r.moves.iter().find(|m| m.line == 5).unwrap();
    same(m.from, [45.0, -40.0, 0.0]);
}

#[test]
fn behaviour16_14_a_g40_block_with_i_j_gives_the_direction_the_block_before_ends_on() {
    // G42 along +X at y = −45 (X100. from (50, −40)); G40 X120. Y−60. I1.
    // J−1.: the block before ends where y = −45 meets the offset of the
    // direction (1, −1) from (100, −40), 5 to its right: the line
    // x + y = 60 − 5√2, at x = 105 − 5√2. Without I/J (type A) it ends at
    // (100, −45).
    let x = 105.0 - 5.0 * std::f64::consts::SQRT_2;
    let base = "G00 X50. Y-20.\nG01 G42 D01 Y-40. F100.\nX100.\n";
    let r = ok(&format!("{base}G40 X120. Y-60. I1. J-1.\nM30"), &r5());
    same(end(&r, 3), [x, -45.0, 0.0]);
    same(end(&r, 4), [120.0, -60.0, 0.0]);
    let text = explain(&r, 3);
    assert!(text.contains("with I/J/K"), "{text}");
    let plain = ok(&format!("{base}G40 X120. Y-60.\nM30"), &r5());
    same(end(&plain, 3), [100.0, -45.0, 0.0]);
}

// ----- 16.15 mirror image -------------------------------------------------

#[test]
fn behaviour16_15_mirror_image_turns_g41_into_g42() {
    // Mirror X about the start (0, 0): X50. goes to -50, and G41 cuts on
    // the mirrored side: the path is the unmirrored one, (50, 5), mirrored,
    // (-50, 5) — what G42 gives on the mirrored program.
    let mut s = r5();
    s.settings.mirror = Mirror { x: true, y: false };
    let text = "G01 G41 D01 X50. F100.\nX100.\nG40 X150.";
    let r = ok(text, &s);
    same(end(&r, 1), [-50.0, 5.0, 0.0]);
    same(end(&r, 2), [-100.0, 5.0, 0.0]);
    let g42 = ok("G01 G42 D01 X-50. F100.\nX-100.\nG40 X-150.", &r5());
    same(end(&g42, 1), end(&r, 1));
    // Programmable mirror image G51.1 X0 does the same (behaviour 13.8).
    let r = ok(
        "G51.1 X0\nG01 G41 D01 X50. F100.\nX100.\nG40 X150.\nG50.1 X0",
        &r5(),
    );
    same(end(&r, 2), [-50.0, 5.0, 0.0]);
}

// ----- 16.16 the plane ------------------------------------------------------

#[test]
fn behaviour16_16_the_plane_cannot_change_in_compensation() {
    let (code, line, message) = alarm("G01 G41 D01 X50. F100.\nG18 X100.", &r5());
    assert_eq!((code, line), ("cutter-plane", 2));
    assert!(message.contains("PS0037"), "{message}");
    // Once cancelled, the next block is in cancel mode again: a new plane,
    // a canned cycle, G45 and a chamfer all run (16.2).
    for after in [
        "G18 G01 Z-5.",
        "G81 X10. Y10. Z-5. R2.\nG80",
        "G91 G45 X10. D01\nG90",
        "G01 X200. ,C2.\nY50.",
    ] {
        let text = format!("G01 G41 D01 X50. F100.\nX100.\nG40 X150.\n{after}\nM30");
        let r = ok(&text, &r5());
        assert_eq!(
            at_line(&r, &text, 4).cutter.unwrap().phase,
            "cancel",
            "{after}"
        );
    }
}

// ----- 16.17 the length offset and G45–G48 ------------------------------

#[test]
fn behaviour16_17_the_length_offset_is_independent_and_g45_to_g48_are_refused() {
    // H02 = 100: G43 lifts Z by 100 in the block that moves on in G41:
    // (100, 5, -5 + 100).
    let s = mill(&[(1, 5.0), (2, 100.0)]);
    let r = ok(
        "G01 G41 D01 X50. F100.\nG43 H02 X100. Z-5.\nX150.\nG40 X200.",
        &s,
    );
    same(end(&r, 2), [100.0, 5.0, 95.0]);
    let (code, line, message) = alarm("G01 G41 D01 X50. F100.\nG91 G45 X10.", &r5());
    assert_eq!((code, line), ("cutter-position-offset", 2));
    assert!(message.contains("PS0042"), "{message}");
}

// ----- 16.18 G28 and canned cycles ------------------------------------------

#[test]
fn behaviour16_18_g28_cancels_for_the_return_and_the_next_move_starts_up_again() {
    // X100. sees G28 X Y next: it ends perpendicular, (100, 5). G28 goes
    // from there to the intermediate point (100, 50) without the vector,
    // then to the reference (0, 0). G01 X150. Y50. starts up again (type
    // A, the next move +X): (150, 55).
    let text = "G01 G41 D01 X50. F100.\nX100.\nG28 X100. Y50.\nG01 X150. Y50.\nX200.\nG40 X250.";
    let r = ok(text, &r5());
    same(end(&r, 2), [100.0, 5.0, 0.0]);
    let g28: Vec<_> = r.moves.iter().filter(|m| m.line == 3).collect();
    assert_eq!(g28.len(), 2);
    same(g28[0].from, [100.0, 5.0, 0.0]);
    same(g28[0].to, [100.0, 50.0, 0.0]);
    same(g28[1].to, [0.0, 0.0, 0.0]);
    same(end(&r, 4), [150.0, 55.0, 0.0]);
    assert_eq!(at_line(&r, text, 4).cutter.unwrap().phase, "start_up");
}

#[test]
fn behaviour16_18_canned_cycles_ignore_the_compensation() {
    // G41 not started yet: the holes are drilled where programmed.
    let text = "G41 D01\nG81 X10. Y10. Z-5. R2. F100.\nG80\nM30";
    let r = ok(text, &r5());
    same(r.blocks[1].state.actual, [10.0, 10.0, 0.0]);
    assert!(
        r.blocks[1]
            .explanation()
            .contains("ignored in a canned cycle")
    );
    // With the vector on: refused.
    let (code, line, _) = alarm("G01 G41 D01 X50. F100.\nG81 X60. Y0 Z-5. R2.", &r5());
    assert_eq!((code, line), ("cutter-in-cycle", 2));
}
