//! Behaviour 22.16 (`docs/behaviour.md`): LinuxCNC's arcs under the
//! linuxcnc profile — G2/G3 P (the turns), rs274's arc refusals and
//! tolerances, G61/G61.1/G64, and arcs under cutter compensation. Each
//! worked by hand; the move-by-move comparison with rs274 is
//! `tests/linuxcnc/a*.ngc` and `tests/linuxcnc/refused/ra*.ngc`.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::ToolTable;
use offsetlab::{Setup, Units};
use std::f64::consts::PI;

/// Tool 1: 0.125 in across (radius 0.0625 in), the table in inches.
fn with_tool() -> Setup {
    let mut s = linuxcnc();
    let (mut table, _) = ToolTable::parse("T1 P1 D0.125\n").unwrap();
    table.units = Some(Units::Inch);
    s.tool_table = Some(table);
    s
}

fn sweep(r: &offsetlab::report::Run, i: usize) -> f64 {
    r.moves[i].arc.as_ref().expect("an arc").sweep
}

fn close(got: f64, want: f64) {
    assert!((got - want).abs() < 1e-6, "{got} != {want}");
}

#[test]
fn behaviour22_16_linuxcnc_arc_p_turns_make_the_sweep_and_the_length() {
    // G2 from (10, 0) about the origin back to (10, 0), P3: three clockwise
    // turns, −6π; Z falls 6 mm along them: 3 · 2π · 10 = 188.4956 across,
    // √(188.4956² + 6²) = 188.5911 mm long.
    let r = ok("G21\nG0 X10\nG2 X10 Y0 Z-6 I-10 P3 F300\nM2\n", &linuxcnc());
    close(sweep(&r, 1), -6.0 * PI);
    let across = 3.0 * 2.0 * PI * 10.0;
    close(r.travel.feed, (across * across + 36.0).sqrt());
    // G3 half a circle with P2: one turn and the half, 3π; R takes P too.
    let r = ok(
        "G21\nG0 X10\nG3 X-10 Y0 I-10 P2 F300\nG2 X10 Y0 R10 P2\nM2\n",
        &linuxcnc(),
    );
    close(sweep(&r, 1), 3.0 * PI);
    close(sweep(&r, 2), -3.0 * PI);
    // On a G4 line in G2 mode P is the dwell and the turns: 2 s, 2 turns.
    let r = ok(
        "G21\nG0 X10\nG2 X10 Y0 I-10 F300\nG4 P2 X10 Y0 I-10\nM2\n",
        &linuxcnc(),
    );
    close(sweep(&r, 2), -4.0 * PI);
    assert_eq!(dwells(&r), vec![2.0]);
}

#[test]
fn behaviour22_16_linuxcnc_arc_p_is_a_whole_number_of_one_or_more() {
    let arc = |p: &str| format!("G21\nG0 X10\nG2 X10 Y0 I-10 P{p} F300\nM2\n");
    // Within 0.001 of a whole number it is that number.
    close(sweep(&ok(&arc("1.001"), &linuxcnc()), 1), -2.0 * PI);
    close(sweep(&ok(&arc("1.9995"), &linuxcnc()), 1), -4.0 * PI);
    for p in ["1.5", "1.0011", "0"] {
        assert_eq!(error_line(&arc(p), &linuxcnc()), ("arc-turns", 3), "P{p}");
    }
    // A negative P or one past 99999999 the reading refuses at the word.
    for p in ["-1", "3000000000"] {
        assert_eq!(
            error_line(&arc(p), &linuxcnc()),
            ("out-of-range", 3),
            "P{p}"
        );
    }
    // The Fanuc family's arcs read no P.
    assert_eq!(
        errors("G21\nG0 X10\nG2 X10 Y0 I-10 P2 F300\nM30\n", &mill(&[])),
        vec!["unused-word"]
    );
}

#[test]
fn behaviour22_16_linuxcnc_arc_tolerances_are_rs274s() {
    let end = |e: &str| format!("G21\nG0 X10\nG3 X0 Y[10+{e}] I-10 F100\nM2\n");
    // 2 · 0.01 · √2 = 0.028284 mm: 0.028 runs, 0.0285 (0.28 % of 10 mm) not.
    ok(&end("0.028"), &linuxcnc());
    assert_eq!(error_line(&end("0.0285"), &linuxcnc()), ("arc-radius", 3));
    // Past it, 0.1 % of the radius: a 1000 mm arc takes 0.9 mm, not 1.1.
    let big = |e: &str| format!("G21\nG0 X1000\nG3 X0 Y[1000+{e}] I-1000 F100\nM2\n");
    ok(&big("0.9"), &linuxcnc());
    assert_eq!(error_line(&big("1.1"), &linuxcnc()), ("arc-radius", 3));
    // 100 times it whatever the radius: 2.8284 mm; at 10000 mm 3 mm is 0.03 %.
    let huge = "G21\nG0 X10000\nG3 X0 Y10003 I-10000 F100\nM2\n";
    assert_eq!(error_line(huge, &linuxcnc()), ("arc-radius", 3));
    // In G20 2 · 0.001 · √2 = 0.0028284 in: 0.0028 runs, 0.003 not.
    let inch = |e: &str| format!("G20\nG0 X1\nG3 X0 Y[1+{e}] I-1 F10\nM2\n");
    ok(&inch("0.0028"), &linuxcnc());
    assert_eq!(error_line(&inch("0.003"), &linuxcnc()), ("arc-radius", 3));
    // A centre within 0.00005 in = 0.00127 mm of the start: "Zero-radius arc".
    let zero = |r: &str| format!("G21\nG0 X[2*{r}]\nG3 X0 Y0 I-{r} F100\nM2\n");
    ok(&zero("0.0013"), &linuxcnc());
    assert_eq!(error_line(&zero("0.00126"), &linuxcnc()), ("arc-radius", 3));
    // R short of half the chord (10) by 0.0012 mm runs, by 0.002 not.
    let r = |r: &str| format!("G21\nG0 X0\nG2 X20 Y0 R{r} F100\nM2\n");
    ok(&r("9.9988"), &linuxcnc());
    assert_eq!(error_line(&r("9.998"), &linuxcnc()), ("arc-radius", 3));
}

#[test]
fn behaviour22_16_linuxcnc_refuses_r_with_ijk_a_word_across_the_plane_and_r_to_the_start() {
    let cases = [
        ("G21\nG0 X0\nG2 X10 Y0 R5 I5 F100\nM2\n", "arc-r-and-center"),
        (
            "G21\nG0 X10\nG2 X-10 Y0 I-10 K1 F100\nM2\n",
            "arc-center-word",
        ),
        ("G21\nG0 X5\nG2 X5 Y0 R5 F100\nM2\n", "arc-radius"),
    ];
    for (text, code) in cases {
        assert_eq!(error_line(text, &linuxcnc()), (code, 3), "{text}");
    }
    // An arc with no word of its plane is a full circle about I/J.
    let r = ok("G21\nG0 X10\nG2 Z-1 I-10 F100\nM2\n", &linuxcnc());
    close(sweep(&r, 1), -2.0 * PI);
    same(r.moves[1].to, [10.0, 0.0, -1.0]);
}

#[test]
fn behaviour22_16_linuxcnc_path_modes_are_said_and_refused_with_compensation() {
    let r = ok(
        "G21\nG61\nG61.1\nG64 P0.01 Q0.02\nG64 Q0.5\nG64\nG1 X5 F100\nM2\n",
        &linuxcnc(),
    );
    let note = |line: usize| r.blocks[line - 1].notes.join(" ");
    assert!(note(2).starts_with("G61 exact path"), "{}", note(2));
    assert!(note(3).starts_with("G61.1 exact stop"), "{}", note(3));
    assert!(
        note(4).starts_with("G64 blending tolerance P0.01, naive CAM tolerance Q0.02"),
        "{}",
        note(4)
    );
    assert!(note(5).contains("none (the best speed"), "{}", note(5));
    assert!(note(5).contains("Q0.5"), "{}", note(5));
    assert!(
        note(6).starts_with("G64 blending tolerance none"),
        "{}",
        note(6)
    );
    same(r.moves[0].to, [5.0, 0.0, 0.0]);
    // G41 runs before G61 in a block, so both find compensation on.
    let setup = with_tool();
    for text in [
        "G20\nT1 M6\nG41\nG64 P0.001\nM2\n",
        "G20\nT1 M6\nG41 G61 G1 X1 F10\nM2\n",
    ] {
        let line = if text.contains("G64") { 4 } else { 3 };
        assert_eq!(
            error_line(text, &setup),
            ("cutter-path-mode", line),
            "{text}"
        );
    }
    assert_eq!(
        error_line("G21\nG61 P0.01\nM2\n", &linuxcnc()),
        ("mode-words", 2)
    );
}

#[test]
fn behaviour22_16_linuxcnc_compensation_enters_on_an_arc() {
    // From (1, 0) G41 then G3 to (0, 1) about the origin, tool radius
    // 0.0625 in inside: the arc ends 0.0625 towards the centre, (0, 0.9375),
    // about the point of the Y axis as far from (1, 0) as from there:
    // c² = 1 + (0.9375 − c)², c = 1.87890625 / 1.875 = 1.0020833, the
    // centre (0, 0.9375 − c) = (0, −0.0645833) in.
    let r = ok(
        "G20\nT1 M6\nG0 X1 Y0\nG41\nG3 X0 Y1 I-1 J0 F10\nG1 X-1\nG40 G0 X-1.5 Y0.5\nM2\n",
        &with_tool(),
    );
    let m = &r.moves[1];
    same(m.to, [0.0, 0.9375 * 25.4, 0.0]);
    let arc = m.arc.as_ref().unwrap();
    same(arc.center, [0.0, -0.0645833333 * 25.4, 0.0]);
    close(arc.radius, 1.0020833333 * 25.4);
    // An entry arc ending within the tool radius of the tool is refused.
    let short = "G20\nT1 M6\nG0 X1 Y0\nG41\nG3 X[COS[3]] Y[SIN[3]] I-1 J0 F10\nM2\n";
    assert_eq!(error_line(short, &with_tool()), ("cutter-entry", 5));
    // The Fanuc family refuses the arc entry (PS0034).
    let mut fanuc = mill(&[(1, 0.0625)]);
    fanuc.units = Units::Inch;
    assert!(
        errors("G20\nG0 X1 Y0\nG41 D1\nG3 X0 Y1 I-1 J0 F10\nM30\n", &fanuc).contains(&"cutter-arc")
    );
}

#[test]
fn behaviour22_16_linuxcnc_a_tool_as_big_as_the_arc_stands_on_its_centre() {
    // Hole radius 0.0625 in, tool radius 0.0625 in, G41 inside G3: the
    // compensated arc is the centre itself, a full turn as rs274 sends it,
    // the helix's Z alone.
    let text = "G20\nT1 M6\nG0 X0.5 Y0.5\nG41 G0 X0 Y0.0625\nG3 X0 Y0.0625 I0 J-0.0625 Z-0.1 F10\nG0 Z0.5\nG40 G0 X1\nM2\n";
    let r = ok(text, &with_tool());
    let m = r.moves.iter().find(|m| m.line == 5).unwrap();
    let arc = m.arc.as_ref().unwrap();
    same(m.to, [0.0, 0.0, -0.1 * 25.4]);
    same(arc.center, [0.0, 0.0, 0.0]);
    close(arc.radius, 0.0);
    close(arc.sweep, 2.0 * PI);
    // A smaller hole: "Tool radius not less than arc radius with comp".
    let small = "G20\nT1 M6\nG0 X0.06 Y0\nG41\nG3 X-0.06 Y0 I-0.06 J0 F10\nM2\n";
    assert_eq!(error_line(small, &with_tool()), ("cutter-tool-radius", 5));
}

#[test]
fn behaviour22_16_linuxcnc_the_move_after_g40_leaves_the_offset_path() {
    // G41 to (2, 1) then up to (2, 2): the tool is 0.0625 in left of X2;
    // after G40 alone, G0 Z0.5 brings it back onto (2, 2) on the way up.
    let text = "G20\nT1 M6\nG0 X1 Y1\nG41 G1 X2 Y1 F10\nG1 X2 Y2\nG40\nG0 Z0.5\nM2\n";
    let r = ok(text, &with_tool());
    let last = r.moves.last().unwrap();
    same(last.to, [2.0 * 25.4, 2.0 * 25.4, 0.5 * 25.4]);
}
