//! Behaviour 22.12 and 22.13 (`docs/behaviour.md`): LinuxCNC's polar
//! coordinates `@` `^`, and the small stops where rs274 reads a word
//! differently from the Fanuc family (G4 with axis words, F over 999999).
//! The oracle programs `tests/linuxcnc/q*.ngc`, `s*.ngc` and
//! `tests/linuxcnc/refused/rq*.ngc`, `rs*.ngc` compare the same with rs274.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::MoveKind;

use offsetlab::{Setup, run};

fn first_error_of(text: &str) -> (&'static str, u32, u32) {
    first_error(&run(text, &linuxcnc()))
}

#[test]
fn behaviour22_12_linuxcnc_polar_g90_gives_distance_and_angle_about_the_origin() {
    // From (3, 4), 5 from the origin at atan2(4, 3) = 53.13°: @10 keeps the
    // angle, (6, 8); ^90 keeps the distance 10, (0, 10); @5 ^180, (-5, 0);
    // @2.5 ^-45 with Z, (1.76777, -1.76777, -1).
    let r = ok(
        "G21 G17 G90\nG0 X3 Y4 Z1\nG1 F200 @10\nG1 ^90\nG1 @5 ^180\nG1 @2.5 ^-45 Z-1\nM2\n",
        &linuxcnc(),
    );
    let to: Vec<_> = r.moves.iter().map(|m| m.to).collect();
    same(to[1], [6.0, 8.0, 1.0]);
    same(to[2], [0.0, 10.0, 1.0]);
    same(to[3], [-5.0, 0.0, 1.0]);
    let h = 2.5 / 2f64.sqrt();
    same(to[4], [h, -h, -1.0]);
    assert!(r.moves[1..].iter().all(|m| m.kind == MoveKind::Feed));
    // A block of polar words alone moves in the motion mode: G0 X10, then
    // @5 rapids to (5, 0).
    let r = ok("G21 G90\nG0 X10 Y0\n@5\nM2\n", &linuxcnc());
    same(r.moves[1].to, [5.0, 0.0, 0.0]);
    assert_eq!(r.moves[1].kind, MoveKind::Rapid);
}

#[test]
fn behaviour22_12_linuxcnc_polar_g91_adds_the_distance_then_the_angle() {
    // From (3, 4), distance 5: @5 makes it 10, (6, 8); ^90 turns (6, 8)
    // about the origin to (-8, 6); @-5 ^-90: distance 5 first, (-4, 3),
    // then -90°, (3, 4). The pole stays the origin, not the current point.
    let r = ok(
        "G21 G90\nG0 X3 Y4\nG91\nG1 F100 @5\nG1 ^90\nG1 @-5 ^-90\nM2\n",
        &linuxcnc(),
    );
    let to: Vec<_> = r.moves.iter().map(|m| m.to).collect();
    same(to[1], [6.0, 8.0, 0.0]);
    same(to[2], [-8.0, 6.0, 0.0]);
    same(to[3], [3.0, 4.0, 0.0]);
}

#[test]
fn behaviour22_12_linuxcnc_polar_g91_cycle_turns_again_at_each_hole() {
    // G91 ^90 L4 from (10, 0): holes at (0, 10), (-10, 0), (0, -10),
    // (10, 0); R-2 from Z5 is Z3, Z-3 below it Z0. Each hole: a rapid over
    // it at the clearance Z3 (the first at Z5, then down to 3), feed to 0.
    let r = ok(
        "G21 G17 G90\nG0 X10 Y0 Z5\nG91 G81 R-2 Z-3 ^90 L4 F100\nG80\nM2\n",
        &linuxcnc(),
    );
    let bottoms: Vec<_> = r
        .moves
        .iter()
        .filter(|m| m.kind == MoveKind::Feed)
        .map(|m| m.to)
        .collect();
    assert_eq!(bottoms.len(), 4);
    for (got, want) in bottoms.iter().zip([
        [0.0, 10.0, 0.0],
        [-10.0, 0.0, 0.0],
        [0.0, -10.0, 0.0],
        [10.0, 0.0, 0.0],
    ]) {
        same(*got, want);
    }
    // G90: `^120` in the G81 mode keeps the distance 25, the hole at
    // (-12.5, 21.65064).
    let r = ok(
        "G21 G90\nG0 X25 Y0 Z5\nG81 R1 Z-3 F100\n^120\nG80\nM2\n",
        &linuxcnc(),
    );
    let last = r
        .moves
        .iter()
        .rev()
        .find(|m| m.kind == MoveKind::Feed)
        .unwrap();
    same(last.to, [-12.5, 25.0 * 3f64.sqrt() / 2.0, -3.0]);
}

#[test]
fn behaviour22_12_linuxcnc_polar_words_take_expressions_units_and_the_last_of_two() {
    // #1 = 3: @[#1*2] ^[#1*10] is 6 at 30°, (5.19615, 3).
    let r = ok(
        "G21 G90\n#1 = 3\nG0 X10 Y0\nG1 F100 @[#1*2] ^[#1*10]\nM2\n",
        &linuxcnc(),
    );
    same(r.moves[1].to, [3.0 * 3f64.sqrt(), 3.0, 0.0]);
    // G20: @2 is 2 in (50.8 mm), ^90 degrees whatever the units.
    let r = ok("G20 G90\nG0 X1 Y0\nG1 F10 @2 ^90\nM2\n", &linuxcnc());
    same(r.moves[1].to, [0.0, 50.8, 0.0]);
    // ^10 ^60: rs274 takes the last, and the run says so.
    let r = ok("G21 G90\nG0 X10 Y0\nG1 F100 ^10 ^60\nM2\n", &linuxcnc());
    same(r.moves[1].to, [5.0, 5.0 * 3f64.sqrt(), 0.0]);
    assert!(r.diagnostics.iter().any(|d| d.code == "polar-repeated"));
}

#[test]
fn behaviour22_12_linuxcnc_polar_words_are_refused_where_rs274_refuses_them() {
    for (text, want) in [
        // Outside G17 (the plane before the block).
        ("G21 G18\nG0 X1\nG1 F100 @10\nM2\n", ("polar-words", 3, 9)),
        // With X or Y: at the X or Y word.
        ("G21\nG0 X1 Y1\nG1 F100 @4 X1\nM2\n", ("polar-words", 3, 12)),
        ("G21\nG0 X1 Y1\nG1 F100 ^4 Y1\nM2\n", ("polar-words", 3, 12)),
        // G53, G92, G28: no polar end point.
        ("G21\nG0 X10\nG53 G0 @5\nM2\n", ("polar-words", 3, 8)),
        ("G21\nG0 X10\nG92 @5\nM2\n", ("polar-words", 3, 5)),
        ("G21\nG0 X10\nG28 ^90\nM2\n", ("polar-words", 3, 5)),
        // At the origin: G90 @ alone, G91 @ or ^.
        (
            "G21 G90\nG0 X0 Y0\nG1 F100 @10\nM2\n",
            ("polar-origin", 3, 9),
        ),
        (
            "G21 G91\nG0 X0 Y0\nG1 F100 ^45\nM2\n",
            ("polar-origin", 3, 9),
        ),
        (
            "G21 G91\nG0 X0 Y0\nG1 F100 @4\nM2\n",
            ("polar-origin", 3, 9),
        ),
        // Under cutter compensation: not read yet (its look-ahead reads X
        // and Y), an error rather than a wrong path.
        (
            "G21\nG0 X10 Y0\nG41 G1 F100 D1 ^90\nM2\n",
            ("polar-words", 3, 16),
        ),
    ] {
        assert_eq!(first_error_of(text), want, "{text}");
    }
    // The Fanuc family reads no `@` or `^`.
    let r = run("G21\nG0 X10 Y0\nG1 F100 @5\nM30\n", &Setup::default());
    assert_eq!(first_error(&r), ("unexpected-character", 3, 9));
}

#[test]
fn behaviour22_13_linuxcnc_g4_dwells_then_moves_by_its_axis_words() {
    // G0 X1, then G4 P0.5 X5: half a second, then a rapid to X5; in G1,
    // G4 P1 X6 Y1 feeds there after a second.
    let r = ok(
        "G21 G90\nG0 X1\nG4 P0.5 X5\nG1 F200\nG4 P1 X6 Y1\nM2\n",
        &linuxcnc(),
    );
    assert_eq!(dwells(&r), vec![0.5, 1.0]);
    same(r.moves[1].to, [5.0, 0.0, 0.0]);
    assert_eq!(r.moves[1].kind, MoveKind::Rapid);
    same(r.moves[2].to, [6.0, 1.0, 0.0]);
    assert_eq!(r.moves[2].kind, MoveKind::Feed);
    // A LinuxCNC G4 needs P (rs274: "Dwell time missing with g4"), at G4.
    assert_eq!(
        first_error_of("G21\nG0 X1\nG4\nM2\n"),
        ("dwell-words", 3, 1)
    );
    // The Fanuc family's G4 X is the dwell time: X and P together refused.
    assert_eq!(
        errors("G21\nG4 P1 X5\nM30\n", &Setup::default()),
        vec!["dwell-words"]
    );
}

#[test]
fn behaviour22_13_linuxcnc_takes_a_feed_over_999999_and_refuses_i_on_g0() {
    // rs274 runs F1000000 as written; the Fanuc family stops at 999999.
    let r = ok("G21\nG1 X1 F1000000\nM2\n", &linuxcnc());
    assert_eq!(r.moves.len(), 1);
    assert_eq!(
        first_error(&run("G21\nG1 X1 F1000000\nM30\n", &Setup::default())),
        ("out-of-range", 2, 7)
    );
    // A negative F is refused by both (rs274: "Negative f word used").
    assert_eq!(first_error_of("G21\nG1 X1 F-1\nM2\n").0, "out-of-range");
    // `G0 X2 I1`: no code of the line reads I (rs274: "I word with no G2,
    // G3 … to use it").
    assert_eq!(first_error_of("G21\nG0 X2 I1\nM2\n"), ("unused-word", 2, 7));
}
