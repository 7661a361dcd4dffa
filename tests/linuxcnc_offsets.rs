//! Behaviour 22.14 (`docs/behaviour.md`): LinuxCNC's work coordinates
//! under the linuxcnc profile — G59.1–G59.3, G10 L2/L20 with P0–P9,
//! G92.2/G92.3 and #5210–#5213, G28.1/G30.1. Each worked by hand; the
//! move-by-move comparison with rs274 is `tests/linuxcnc/25`, `26`, `29`,
//! `32`, `33`, `w01`–`w10` and `tests/linuxcnc/refused/rw1`–`rw9`
//! (`scripts/oracle-linuxcnc.py`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Position, ToolTable};
use offsetlab::{Setup, Units};

fn inch_linuxcnc() -> Setup {
    Setup {
        units: Units::Inch,
        ..linuxcnc()
    }
}

/// The zero of the coordinate system in use after the block on `line`
/// (machine coordinates, mm).
fn zero_at(r: &offsetlab::report::Run, line: u32) -> [f64; 3] {
    let b = r.blocks.iter().rev().find(|b| b.span.line == line).unwrap();
    b.state.coords.zero
}

#[test]
fn behaviour22_14_g59_1_to_g59_3_are_the_seventh_to_ninth_systems() {
    // G10 L2 P7–P9 set G59.1–G59.3; selecting one puts its zero in force
    // and #5220 reads 7, 8, 9.
    let text = "G21 G90\nG10 L2 P7 X11 Y12 Z13\nG10 L2 P8 X-21\nG10 L2 P9 Y31\n\
                G59.1 G0 X1 Y1 Z1\nG0 X#5220\nG59.2 G0 X#5220\nG59.3 G0 X#5220\nM2\n";
    let r = ok(text, &linuxcnc());
    same(zero_at(&r, 5), [11.0, 12.0, 13.0]);
    same(zero_at(&r, 7), [-21.0, 0.0, 0.0]);
    same(zero_at(&r, 8), [0.0, 31.0, 0.0]);
    // A line's #5220 is read before its G59.x (behaviour 22.10).
    same(r.moves[1].to, [7.0, 1.0, 1.0]);
    same(r.moves[2].to, [7.0, 12.0 + 1.0, 13.0 + 1.0]);
    same(r.moves[3].to, [8.0, 12.0 + 1.0 - 31.0, 14.0]);
    let set = r.set_by_program();
    assert_eq!(set.len(), 5);
    assert_eq!((set[0].set.key.as_str(), set[0].set.field), ("G59.1", "x"));
    assert_eq!((set[4].set.key.as_str(), set[4].set.field), ("G59.3", "y"));
    // The setup keeps their rows (in its units: 1 in is 25.4 mm), and
    // #5341 reads G59.1's X in them.
    let mut s = inch_linuxcnc();
    s.work_offsets.g59_1 = Position {
        x: 1.0,
        y: 2.0,
        z: 0.5,
    };
    let r = ok("G20 G90\nG59.1 G0 Z0\nG0 X#5341 Y#5343\nM2\n", &s);
    same(zero_at(&r, 2), [25.4, 50.8, 12.7]);
    same(r.moves[1].to, [25.4, 12.7, 0.0]);
    // Setting #5361 (G59.2's X) outside G59.2 takes effect at G59.2.
    let r = ok("G20 G90\n#5361 = 2\nG59.2 G0 X0\nM2\n", &s);
    same(zero_at(&r, 3), [50.8, 0.0, 0.0]);
}

#[test]
fn behaviour22_14_g10_l2_p0_is_the_system_in_use_and_g91_changes_nothing() {
    // In G55, G10 L2 P0 X5 sets G55's zero and moves it now: the tool at
    // machine X2 reads 2 − 5 = −3. G91 G10 L2 P2 Y4 is Y4, not added.
    let text = "G21 G90\nG55 G0 X2\nG10 L2 P0 X5\nG91 G10 L2 P2 Y4\nG10 L2 P2 Y4\nM2\n";
    let r = ok(text, &linuxcnc());
    same(zero_at(&r, 3), [5.0, 0.0, 0.0]);
    same(programmed(&r, 2), [-3.0, 0.0, 0.0]);
    same(zero_at(&r, 5), [5.0, 4.0, 0.0]);
    assert_eq!(r.set_by_program()[0].set.key, "G55");
    // G10 L2 without axis words sets nothing and runs, as in rs274.
    ok("G21\nG10 L2 P3\nG10 L2 P1 R0\nM2\n", &linuxcnc());
}

#[test]
fn behaviour22_14_g10_l20_makes_the_current_point_read_the_words() {
    // At machine (10, 20, 5): G10 L20 P1 X0 Y0 puts G54's zero at (10, 20);
    // G91 changes nothing (X1 Y2 → 9, 18 from machine 10, 20).
    let r = ok(
        "G21 G90\nG0 X10 Y20 Z5\nG10 L20 P1 X0 Y0\nG91 G10 L20 P2 X1 Y2\nG55\nM2\n",
        &linuxcnc(),
    );
    same(zero_at(&r, 3), [10.0, 20.0, 0.0]);
    same(zero_at(&r, 5), [9.0, 18.0, 0.0]);
    // With a G92 offset on, the point reads the words with it: at machine
    // X3 in G54 (zero 9) after G92 X0 (offset −6), G10 L20 P1 X5 makes
    // G54's zero 3 − (−6) − 5 = 4; the point reads 5.
    let r = ok(
        "G21 G90\nG10 L2 P1 X9\nG0 X-6\nG92 X0\nG10 L20 P1 X5\nM2\n",
        &linuxcnc(),
    );
    same(zero_at(&r, 5), [4.0 - 6.0, 0.0, 0.0]);
    same(programmed(&r, 4), [5.0, 0.0, 0.0]);
    // A length offset taken without Z: the tip is the machine Z less the
    // offset in force (tool 1, 1 in): at machine Z 2 in, L20 Z0 puts the
    // zero at 2 − 1 = 1 in.
    let mut s = inch_linuxcnc();
    let (table, _) = ToolTable::parse("T1 P1 Z1.0 D0.25\n").unwrap();
    s.tool_table = Some(ToolTable {
        units: Some(Units::Inch),
        ..table
    });
    let r = ok(
        "G20 G90\nG0 Z2\nT1 M6\nG43 H1\nG10 L20 P2 Z0\nG55 G0 Z0.5\nM2\n",
        &s,
    );
    same(zero_at(&r, 6), [0.0, 0.0, 25.4]);
    same(r.moves[1].to, [0.0, 0.0, (0.5 + 1.0) * 25.4]);
}

#[test]
fn behaviour22_14_g10_rotation_and_p_past_nine_are_refused() {
    let l = linuxcnc();
    assert_eq!(
        error_line("G21\nG10 L2 P1 X1 R5\nM2\n", &l),
        ("g10-rotation", 2)
    );
    assert_eq!(
        error_line("G21\nG10 L2 P10 X1\nM2\n", &l),
        ("g10-number", 2)
    );
    assert_eq!(
        error_line("G21\nG10 L2 P-1 X1\nM2\n", &l),
        ("out-of-range", 2)
    );
    assert_eq!(
        error_line("G21\nG10 L2 P1.3 X1\nM2\n", &l),
        ("g10-number", 2)
    );
    assert_eq!(error_line("G21\nG10 L20 X1\nM2\n", &l), ("g10-number", 2));
    assert_eq!(error_line("G21\nG10 L20 P1 R0\nM2\n", &l), ("g10-words", 2));
    assert_eq!(error_line("G21\nG10 L2 P1 I1\nM2\n", &l), ("g10-words", 2));
    // The Fanuc family keeps its P0–P6 and has no G59.1.
    let fanuc = Setup::default();
    assert_eq!(errors("G21\nG10 L2 P7 X1\nM30\n", &fanuc), ["g10-number"]);
    assert_eq!(errors("G21\nG59.1\nM30\n", &fanuc), ["unsupported-g-code"]);
    assert_eq!(errors("G21\nG92.2\nM30\n", &fanuc), ["unsupported-g-code"]);
    assert_eq!(errors("G21\nG28.1\nM30\n", &fanuc), ["unsupported-g-code"]);
}

#[test]
fn behaviour22_14_g92_2_suspends_and_g92_3_restores_the_g92_offset() {
    // Inch machine, mm program: at X10 Y10 G92 X4 Y3 is the offset (6, 7)
    // mm; #5210 reads 1, #5211 6 / 25.4 in.
    let text = "G21 G90\nG0 X10 Y10\nG92 X4 Y3\nG0 X#5210 Y[#5211 * 25.4]\n\
                G92.2\nG0 X#5210 Y[#5212 * 25.4]\nG92.3\nG0 X[#5210 + 1] Y0\n\
                G92.1\nG92.3\nG0 X[#5210 + 2] Y[#5211 + 1]\nM2\n";
    let r = ok(text, &inch_linuxcnc());
    same(zero_at(&r, 3), [6.0, 7.0, 0.0]);
    same(r.moves[1].to, [1.0, 6.0, 0.0]);
    // G92.2: the offset off, #5210 0 and #5212 kept.
    same(zero_at(&r, 5), [0.0, 0.0, 0.0]);
    same(r.moves[2].to, [0.0, 7.0, 0.0]);
    // G92.3: back on from #5211…
    same(zero_at(&r, 7), [6.0, 7.0, 0.0]);
    same(r.moves[3].to, [2.0, 0.0, 0.0]);
    // G92.1 zeroes them: G92.3 then restores 0 and sets #5210.
    same(zero_at(&r, 10), [0.0, 0.0, 0.0]);
    same(r.moves[4].to, [3.0, 1.0, 0.0]);
    // G92 after G92.2 writes every parameter from the offset in force.
    let r = ok(
        "G21 G90\nG0 X10 Y10\nG92 X0 Y0\nG92.2\nG92 X7\nG92.2\nG92.3\nM2\n",
        &linuxcnc(),
    );
    same(zero_at(&r, 7), [3.0, 0.0, 0.0]);
}

#[test]
fn behaviour22_14_g92_parameters_set_while_off_wait_for_g92_3() {
    // #5211 = 0.5 (in) while the offset is off: G92.3 takes it.
    let r = ok(
        "G20 G90\n#5211 = 0.5\n#5212 = -0.25\nG92.3\nG0 X0\nM2\n",
        &inch_linuxcnc(),
    );
    same(zero_at(&r, 4), [12.7, -6.35, 0.0]);
    // While it is on, a setting is refused: rs274 would read it apart
    // from the offset in force. #5210 is never set.
    let l = linuxcnc();
    assert_eq!(
        error_line("G21\nG92 X1\n#5211 = 2\nM2\n", &l),
        ("macro-system-variable", 3)
    );
    assert_eq!(
        error_line("G21\n#5210 = 1\nM2\n", &l),
        ("macro-system-variable", 2)
    );
    ok("G21\n#5214 = 0\nM2\n", &l);
}

#[test]
fn behaviour22_14_g28_1_and_g30_1_store_the_machine_position() {
    // Inch machine, mm program: G54 at (1, 2) in; at X25.4 Y-25.4 Z12.7
    // mm the machine is at (2, 1, 0.5) in, which #5161… then read.
    let text = "G21 G90\nG10 L2 P1 X25.4 Y50.8\nG0 X25.4 Y-25.4 Z12.7\nG28.1\n\
                G0 X#5161 Y#5162 Z#5163\nG0 X0 Y0 Z0\nG28\nM2\n";
    let r = ok(text, &inch_linuxcnc());
    same(r.moves[1].to, [2.0, 1.0, 0.5]);
    // G28: back to machine (50.8, 25.4, 12.7), (25.4, −25.4, 12.7) in G54.
    same(r.moves.last().unwrap().to, [25.4, -25.4, 12.7]);
    // G28.1 leaves the G30 position at machine zero (a setup without it
    // had it at G28's), and G30.1 leaves G28's.
    let text = "G21 G90\nG0 X5 Y6 Z7\nG28.1\nG0 X1\nG30\nG0 X-3 Y-4 Z2\nG30.1\n\
                G0 X0 Y0 Z0\nG28\nG30\nM2\n";
    let r = ok(text, &linuxcnc());
    let ends: Vec<[f64; 3]> = r.moves.iter().map(|m| m.to).collect();
    assert!(ends.contains(&[0.0, 0.0, 0.0]));
    same(
        r.blocks
            .iter()
            .rev()
            .find(|b| b.span.line == 5)
            .unwrap()
            .state
            .programmed,
        [0.0; 3],
    );
    same(
        r.blocks
            .iter()
            .rev()
            .find(|b| b.span.line == 9)
            .unwrap()
            .state
            .programmed,
        [5.0, 6.0, 7.0],
    );
    same(
        r.blocks
            .iter()
            .rev()
            .find(|b| b.span.line == 10)
            .unwrap()
            .state
            .programmed,
        [-3.0, -4.0, 2.0],
    );
    // Axis words are refused: rs274 would move to them in the motion mode
    // (G0 here; under the G80 of the start it refuses them itself).
    assert_eq!(
        error_line("G21\nG0 X0\nG28.1 X1\nM2\n", &linuxcnc()),
        ("stored-code-words", 3)
    );
    assert_eq!(
        error_line("G21\nG0 X0\nG92.3 Z0\nM2\n", &linuxcnc()),
        ("stored-code-words", 3)
    );
    assert_eq!(
        error_line("G21\nG28.1 X1\nM2\n", &linuxcnc()),
        ("axis-without-motion", 2)
    );
}

#[test]
fn behaviour22_14_linuxcnc_refuses_moving_the_zero_under_compensation() {
    let mut s = inch_linuxcnc();
    let (table, _) = ToolTable::parse("T1 P1 Z0 D0.25\n").unwrap();
    s.tool_table = Some(ToolTable {
        units: Some(Units::Inch),
        ..table
    });
    let with = |code: &str| format!("G20 G90\nT1 M6\nG0 X0 Y0\nG41 D1\n{code}\nG40\nM2\n");
    for code in ["G59.1", "G54", "G28.1", "G92 X1", "G10 L2 P0 X1"] {
        assert_eq!(
            error_line(&with(code), &s),
            ("cutter-work-offset", 5),
            "{code}"
        );
    }
    // rs274 runs these under compensation: a system not in use, G92.2.
    ok(&with("G10 L2 P2 X1"), &s);
    ok(&with("G92.2"), &s);
}
