//! A machine that starts where machines start (behaviour 13.15, setting
//! 7.49): with `start` and `reference` left out, the Fanuc and Haas
//! profiles put the reference position where a typical machine has it and
//! start the tool there; YASNAC keeps the seeds' work zero.

mod common;
use common::{lathe, mill, ok, programmed, same};
use offsetlab::setup::{Control, MachinePositions, Position};
use offsetlab::{Setup, Units};

fn with(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

/// The Haas mill: the tool starts homed at X0 Y0 Z508 (a VF-2's 20 in of
/// Z travel above the work zero) and `G91 G28 Z0.` rises back there.
#[test]
fn behaviour13_15_g91_g28_z0_rises_to_the_top_of_the_travel() {
    let s = with(mill(&[]), Control::Haas);
    assert_eq!(s.settings.machine_positions(), MachinePositions::Typical);
    // Line 1 from the start (0, 0, 508) down to (10, 20, 5): one rapid.
    // Line 2: G91 G28 Z0. — the intermediate point is where the tool is
    // (Z + 0), so one move, straight up from Z5 to Z508.
    let r = ok("G90 G00 X10. Y20. Z5.\nG91 G28 Z0.\n", &s);
    same(r.moves[0].from, [0.0, 0.0, 508.0]);
    same(r.moves[0].to, [10.0, 20.0, 5.0]);
    assert_eq!(r.blocks[1].move_count, 1);
    let up = &r.moves[1];
    same(up.from, [10.0, 20.0, 5.0]);
    same(up.to, [10.0, 20.0, 508.0]);
    // X and Y did not move: only Z returned.
    same(programmed(&r, 1), [10.0, 20.0, 508.0]);
    // Fanuc is the same machine.
    let r = ok(
        "G90 G00 X10. Y20. Z5.\nG91 G28 Z0.\n",
        &with(mill(&[]), Control::Fanuc),
    );
    same(programmed(&r, 1), [10.0, 20.0, 508.0]);
}

/// The Haas lathe starts at the turret's home, X406.4 (diameter: the
/// ST-10's 8 in of X travel as a radius, 203.2 mm) Z355.6 (its 14 in of Z
/// travel), not on the centre line, and `G28 U0. W0.` goes back there.
#[test]
fn behaviour13_15_the_lathe_starts_at_the_turret_home() {
    let s = with(lathe(&[]), Control::Haas);
    // Line 1: rapid from home to X40 Z2. Line 2: G28 U0. W0. — the
    // intermediate point is where the tool is: one move back home.
    let r = ok("G00 X40. Z2.\nG28 U0. W0.\n", &s);
    same(r.moves[0].from, [406.4, 0.0, 355.6]);
    same(r.moves[0].to, [40.0, 0.0, 2.0]);
    assert_eq!(r.blocks[1].move_count, 1);
    same(programmed(&r, 1), [406.4, 0.0, 355.6]);
}

/// YASNAC keeps the seeds' start — the tool at the work zero — under a
/// typical machine's reference position, so a return to it goes up and
/// never into the part: `G91 G28 Z0.` from Z5 rises to Z508 (issue 32).
#[test]
fn behaviour13_15_yasnac_starts_at_the_work_zero_and_g28_goes_up() {
    let s = mill(&[]);
    assert_eq!(
        s.settings.machine_positions(),
        MachinePositions::WorkZeroStart
    );
    let r = ok("G90 G00 X10. Y20. Z5.\nG91 G28 Z0.\n", &s);
    same(r.moves[0].from, [0.0, 0.0, 0.0]);
    same(programmed(&r, 1), [10.0, 20.0, 508.0]);
    // Its rapid goes straight up from Z5 to Z508: X and Y stay.
    let up = r.moves.last().unwrap();
    same(up.from, [10.0, 20.0, 5.0]);
    same(up.to, [10.0, 20.0, 508.0]);
    // The lathe: the tool starts on the centre line at the face, and
    // `G28 U0. W0.` goes to the turret home, X406.4 Z355.6 (Haas ST-10).
    let r = ok("G00 X20. Z2.\nG28 U0. W0.\n", &lathe(&[]));
    same(r.moves[0].from, [0.0, 0.0, 0.0]);
    same(programmed(&r, 1), [406.4, 0.0, 355.6]);
    // The setting wins over the profile every way.
    let mut typical = mill(&[]);
    typical.settings.machine_positions = Some(MachinePositions::Typical);
    let r = ok("G91 G28 Z0.\n", &typical);
    same(programmed(&r, 0), [0.0, 0.0, 508.0]);
    let mut zero = with(mill(&[]), Control::Haas);
    zero.settings.machine_positions = Some(MachinePositions::WorkZero);
    let r = ok("G00 Z5.\nG91 G28 Z0.\n", &zero);
    same(r.moves[0].from, [0.0, 0.0, 0.0]);
    // `work_zero`: the reference is machine zero, the work zero: down.
    same(programmed(&r, 1), [0.0, 0.0, 0.0]);
}

/// `start` and `reference` set in the setup win; an inch setup's typical
/// positions are in inches (20 in, exactly 508 mm); with G54 away from
/// machine zero the tool still starts at the reference, so its G54
/// coordinates are the reference less G54's zero.
#[test]
fn behaviour13_15_set_positions_win_and_g54_moves_the_start() {
    let mut s = with(mill(&[]), Control::Haas);
    s.reference = Position {
        x: 100.0,
        y: 0.0,
        z: 300.0,
    };
    // The start left out is the reference (100, 0, 300), G54 at machine zero.
    let r = ok("G00 X1.\nG91 G28 Z0.\n", &s);
    same(r.moves[0].from, [100.0, 0.0, 300.0]);
    same(programmed(&r, 1), [1.0, 0.0, 300.0]);
    s.start = Position {
        x: 5.0,
        y: 5.0,
        z: 5.0,
    };
    let r = ok("G00 X1.\n", &s);
    same(r.moves[0].from, [5.0, 5.0, 5.0]);

    let mut inch = with(mill(&[]), Control::Haas);
    inch.units = Units::Inch;
    assert_eq!(inch.start_position().z, 20.0);
    assert_eq!(inch.reference_point(1).z, 20.0);
    let r = ok("G00 X1.\n", &inch);
    // Positions are kept in mm: 20 in = 508 mm.
    same(r.moves[0].from, [0.0, 0.0, 508.0]);

    // G54 at machine X-300 Y-200 Z-400: the tool starts at machine
    // (0, 0, 508), which is G54 (300, 200, 908); G91 G28 Z0. brings Z back
    // to machine 508, G54 908.
    let mut g54 = with(mill(&[]), Control::Haas);
    g54.work_offsets.g54 = Position {
        x: -300.0,
        y: -200.0,
        z: -400.0,
    };
    let start = g54.start_position();
    assert_eq!((start.x, start.y, start.z), (300.0, 200.0, 908.0));
    let r = ok("G00 X0 Y0 Z10.\nG91 G28 Z0.\n", &g54);
    same(programmed(&r, 1), [0.0, 0.0, 908.0]);
    assert_eq!(r.blocks[1].state.machine_position()[2], 508.0);
}

/// The setting and the positions travel with the document (behaviour 9):
/// left out, nothing is written; set, the JSON carries them.
#[test]
fn behaviour13_15_the_document_carries_the_setting() {
    let s = Setup::from_json(r#"{"settings":{"machine_positions":"typical"}}"#).unwrap();
    assert_eq!(
        s.settings.machine_positions,
        Some(MachinePositions::Typical)
    );
    assert!(s.to_json().contains("\"machine_positions\": \"typical\""));
    assert!(!Setup::default().to_json().contains("machine_positions"));
    assert!(Setup::from_json(r#"{"settings":{"machine_positions":"home"}}"#).is_err());
}
