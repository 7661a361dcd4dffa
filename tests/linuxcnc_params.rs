//! Behaviour 22.10 (`docs/behaviour.md`): LinuxCNC's numbered parameters
//! under the linuxcnc profile — #31 on global and 0 never set, a line's
//! settings made after its values are read, and the control's parameters
//! read from the machine's state. The comparison with rs274 is
//! `tests/linuxcnc/44_numbered_params.ngc`, `p01`–`p06` and
//! `refused/r30`–`r33` (`make test`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::Position;

#[test]
fn behaviour22_10_linuxcnc_parameters_past_30_are_global_and_read_0_unset() {
    // #31, #250, #4999 never set read 0 (Fanuc: #250 is no variable, #31
    // a local, #4999 a system variable). The sub adds its #1 = 10 to
    // #31 = 5: 15, and sets #2000 = 40 + 7.5; its #1 = 40 is gone at
    // the return, the caller's 3 back.
    let text = "G21 G90\nG0 X#31 Y#250 Z[#4999 + 1]\n#31 = 5\n#4000 = 7.5\no100 sub\n  #31 = [#31 + #1]\n  #1 = 40\n  #2000 = [#1 + #4000]\no100 endsub\n#1 = 3\no100 call [10]\nG0 X#31 Y#2000 Z#1\n#3000 = 2\nG0 Z#3000\nM2\n";
    let r = ok(text, &linuxcnc());
    same(r.moves[0].to, [0.0, 0.0, 1.0]);
    same(r.moves[1].to, [15.0, 47.5, 3.0]);
    // #3000 is a parameter like any other here (Fanuc's alarm number).
    same(r.moves[2].to, [15.0, 47.5, 2.0]);
    // #0 and #5602 are out of LinuxCNC's range, read or set.
    let s = linuxcnc();
    assert_eq!(
        error_line("G21\nG0 X[#0 + 1]\nM2\n", &s),
        ("macro-variable-number", 2)
    );
    assert_eq!(
        error_line("G21\n#5000 = 1\n#5602 = 1\nM2\n", &s),
        ("macro-variable-number", 3)
    );
}

#[test]
fn behaviour22_10_linuxcnc_settings_take_effect_after_the_line() {
    // `#1 = 8` beside `X#1` leaves X the old 2; `#4 = 6 Y#4` Y the old 0;
    // `#5 = 1 #6 = #5` gives #6 the old #5, 0. `#7 = [#1 + #2] #1 = #7`:
    // #7 = 8 + 3 = 11 and #1 the old #7, 0.
    let text = "G21 G90\n#1 = 2 #2 = 3\nG0 X#1 Y#2 #1 = 8\nG0 #4 = 6 Y#4 X#1\n#5 = 1 #6 = #5\nG0 X#6 Y#4\n#7 = [#1 + #2] #1 = #7\nG0 X#1 Y#7\n#<side> = 12.5\n#<side> = 20 G1 X#<side> F300\nG1 Y#<side>\nM2\n";
    let r = ok(text, &linuxcnc());
    same(r.moves[0].to, [2.0, 3.0, 0.0]);
    same(r.moves[1].to, [8.0, 0.0, 0.0]);
    same(r.moves[2].to, [0.0, 6.0, 0.0]);
    same(r.moves[3].to, [0.0, 11.0, 0.0]);
    same(r.moves[4].to, [12.5, 11.0, 0.0]);
    same(r.moves[5].to, [12.5, 20.0, 0.0]);
    // A setting's value is one operand, as rs274 reads it: `1 + 2` needs
    // brackets.
    assert_eq!(error_line("G21\n#1 = 1 + 2\nM2\n", &linuxcnc()).1, 2);
}

#[test]
fn behaviour22_10_linuxcnc_control_parameters_read_the_machine_in_its_units() {
    // A mm setup: G54's X 10, G55's Y −4, the G28 position Z 50.
    let mut s = linuxcnc();
    s.work_offsets.g54 = Position {
        x: 10.0,
        y: 0.0,
        z: 0.0,
    };
    s.work_offsets.g55 = Position {
        x: 0.0,
        y: -4.0,
        z: 0.0,
    };
    s.reference = Position {
        x: 0.0,
        y: 0.0,
        z: 50.0,
    };
    // In a G20 program the stored positions read in the machine's mm
    // (rs274 keeps them in machine units): X#5221 is 10 in, Y#5242 −4 in,
    // Z[#5163 / 10] 5 in; the run's moves are in mm: 254, −101.6, 127.
    let text = "G20 G90\nG0 X#5221 Y#5242 Z[#5163 / 10]\nM2\n";
    let r = ok(text, &s);
    same(r.moves[0].to, [254.0, -101.6, 127.0]);
    // The G92 offset: at X10 (mm), G92 X1 shifts 9 mm; #5210 is 1; #5420
    // reads the current X in the program's units, 1 mm. After the move to
    // X9, in G20 #5420 is 9/25.4 in, ×25.4 = 9: Y9 in, 228.6 mm. #5220 is
    // 2 in G55.
    let text = "G21 G90\nG0 X10 Y5\nG92 X1\nG0 X#5211 Y#5210 Z#5420\nG20\nG0 Y[#5420 * 25.4]\nG21 G55\nG0 X#5220\nM2\n";
    let r = ok(text, &linuxcnc());
    same(r.moves[1].to, [9.0, 1.0, 1.0]);
    same(r.moves[2].to, [9.0, 228.6, 1.0]);
    same(r.moves[3].to, [2.0, 228.6, 1.0]);
    // #5161 = 20 moves G28's target to machine X 20; G54's zero at X 10
    // makes it work X 10. #5241 (G55, not in use) = 3: G55 (its Y −4)
    // then puts machine X 20, Y 0 at work X 17, Y 4.
    let text = "G21 G90\n#5161 = 20\nG28\n#5241 = 3\nG55\nG0 Y1\nM2\n";
    let r = ok(text, &s);
    let n = r.moves.len();
    same(r.moves[n - 2].to, [10.0, 0.0, 50.0]);
    same(r.moves[n - 1].from, [17.0, 4.0, 50.0]);
    same(r.moves[n - 1].to, [17.0, 1.0, 50.0]);
    // #5400 the tool in the spindle.
    let r = ok("G21\nT3 M6\nG0 X#5400\nM2\n", &linuxcnc());
    same(r.moves[0].to, [3.0, 0.0, 0.0]);
}

#[test]
fn behaviour22_10_linuxcnc_refuses_settings_it_cannot_honour() {
    let s = linuxcnc();
    let e = |t: &str| error_line(t, &s);
    // Read only in LinuxCNC ("Parameter is readonly").
    assert_eq!(e("G21\n#5420 = 1\nM2\n"), ("macro-system-variable", 2));
    assert_eq!(e("G21\n#5400 = 1\nM2\n"), ("macro-system-variable", 2));
    // Kept by LinuxCNC for later, which offsetlab does not model: the G92
    // offset while it is on (22.14), the system in use, a G54 origin while
    // G54 is in use.
    assert_eq!(
        e("G21\nG92 X1\n#5211 = 1\nM2\n"),
        ("macro-system-variable", 3)
    );
    assert_eq!(e("G21\n#5220 = 2\nM2\n"), ("macro-system-variable", 2));
    assert_eq!(
        e("G21\nG0 X1\n#5221 = 1\nM2\n"),
        ("macro-system-variable", 3)
    );
    // An axis the machine does not have: an A of 0 is taken, 1 is not.
    assert_eq!(
        e("G21\n#5164 = 0\n#5164 = 1\nM2\n"),
        ("macro-system-variable", 3)
    );
    // What offsetlab does not model, read: the probe's result.
    assert_eq!(e("G21\nG0 X#5061\nM2\n"), ("macro-system-variable", 2));
}
