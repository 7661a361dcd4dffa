//! Behaviour 14 (`docs/behaviour.md`): modal codes without geometry — each
//! kept in the modal state, its words read or refused, its sentence — and the
//! skip function G31. Each test is named after the rule it checks.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::{MachineKind, MoveKind, run};

fn modal(
    r: &offsetlab::report::Run,
    i: usize,
    m: MachineKind,
) -> offsetlab::machine::modal::ModalCodes {
    r.blocks[i].state.modal.codes(m)
}

#[test]
fn behaviour14_1_the_codes_are_read_by_machine_and_group() {
    // Mill: G61 (group 15) with G01 (01) and G17 (02) in one block is fine;
    // two codes of group 15 are not.
    let r = ok("G61 G01 G17 X1. F100.", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).cutting_mode, Some("G61"));
    assert_eq!(
        errors("G61 G64 X1.", &mill(&[])),
        vec!["modal-conflict"],
        "G61 and G64 are both group 15"
    );
    // G61.1 is no Fanuc, Haas or YASNAC code: refused with the reason.
    let r = run("G61.1", &mill(&[]));
    assert_eq!(r.diagnostics[0].code, "unsupported-g-code");
    assert!(r.diagnostics[0].message.contains("G61 for exact stop"));
    // The lathe's drilling cycles are refused with their reason, its G80 is read.
    let r = run("G83 X0 Z-10.", &lathe(&[]));
    assert!(r.diagnostics[0].message.contains("drilling canned cycles"));
    // Mill codes on the lathe are refused.
    for code in ["G61", "G09", "G93", "G187", "G05.1 Q1", "G08 P1"] {
        let r = run(code, &lathe(&[]));
        assert_eq!(
            r.diagnostics[0].code, "unsupported-g-code",
            "{code} on the lathe"
        );
    }
}

#[test]
fn behaviour14_2_cutting_modes_and_exact_stop_change_no_path() {
    let text = "G61\nG01 X10. F100.\nG62\nG63\nG64\nG64\nG09 X20.";
    let r = ok(text, &mill(&[]));
    let m = |i| modal(&r, i, MachineKind::Mill).cutting_mode;
    assert_eq!(
        [m(0), m(1), m(2), m(3), m(4), m(5), m(6)],
        [
            Some("G61"),
            Some("G61"),
            Some("G62"),
            Some("G63"),
            Some("G64"),
            Some("G64"),
            Some("G64")
        ]
    );
    assert!(
        explain(&r, 0).starts_with("G61 exact stop mode"),
        "{}",
        explain(&r, 0)
    );
    assert!(explain(&r, 2).starts_with("G62 automatic corner override"));
    assert!(explain(&r, 3).starts_with("G63 tapping mode"));
    assert!(explain(&r, 4).starts_with("G64 cutting mode"));
    // A G64 in G64 changes nothing and says nothing.
    assert_eq!(explain(&r, 5), "No offset applies: actual = programmed.");
    // G09 stops at this block's end: the move is the G01's, from X10 to X20.
    assert!(explain(&r, 6).starts_with("G09 exact stop"));
    let last = r.moves.last().unwrap();
    assert_eq!(last.kind, MoveKind::Feed);
    same(last.from, [10.0, 0.0, 0.0]);
    same(last.to, [20.0, 0.0, 0.0]);
    // The start state is G64 (Fanuc's initial cutting mode).
    let r = ok("X1.", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).cutting_mode, Some("G64"));
}

#[test]
fn behaviour14_3_mode_codes_of_group_00_stand_alone() {
    for (text, letter) in [
        ("G05.1 Q1 X10.", "X"),
        ("G08 P1 Z5.", "Z"),
        ("G08 P1 Q1", "Q"),
        ("G187 P2 R1.", "R"),
    ] {
        let r = run(text, &mill(&[]));
        let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!(e.code, "mode-words", "{text}");
        assert!(
            e.message.contains(&format!("{letter} is not read")),
            "{text}: {}",
            e.message
        );
    }
    // Other modal codes, M, S and F may share the block.
    let r = ok("G90 G17 G05.1 Q1 M08 S1000", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
}

#[test]
fn behaviour14_4_g05_1_switches_ai_contour_control_with_q1_or_q0() {
    // Q1 is a whole number here (no integer-dimension warning, not 0.001).
    let text = "G05.1 Q1\nG01 X5. F100.\nG05.1 Q0";
    let r = ok(text, &mill(&[]));
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(modal(&r, 0, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
    assert_eq!(modal(&r, 1, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
    assert_eq!(modal(&r, 2, MachineKind::Mill).ai_contour, None);
    assert!(explain(&r, 0).starts_with("G05.1 Q1 AI contour control on"));
    assert!(explain(&r, 2).starts_with("G05.1 Q0 AI contour control off"));
    // The Q before the code is read the same way.
    let r = ok("Q1 G05.1", &mill(&[]));
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(modal(&r, 0, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
    // Anything but Q0/Q1, or no Q, is refused; elsewhere Q stays a dimension.
    assert_eq!(errors("G05.1 Q2", &mill(&[])), vec!["mode-words"]);
    assert_eq!(errors("G05.1", &mill(&[])), vec!["mode-words"]);
    // With a point Q1. is 1 too; in calculator input Q1 is 1.
    let r = ok("G05.1 Q1.", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
    let mut s = mill(&[]);
    s.settings.decimal_input = Some(offsetlab::setup::DecimalInput::Calculator);
    let r = ok("G05.1 Q1", &s);
    assert_eq!(modal(&r, 0, MachineKind::Mill).ai_contour, Some("G05.1 Q1"));
    let r = ok("G83 X0 Z-5. R1. Q2500 F100.", &mill(&[]));
    assert_eq!(
        r.diagnostics[0].code, "integer-dimension",
        "Q of G83 is a dimension"
    );
}

#[test]
fn behaviour14_5_g08_switches_look_ahead() {
    let r = ok("G08 P1\nG08 P0", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).look_ahead, Some("G08 P1"));
    assert_eq!(modal(&r, 1, MachineKind::Mill).look_ahead, None);
    assert!(explain(&r, 0).starts_with("G08 P1 look-ahead"));
    assert!(explain(&r, 1).starts_with("G08 P0 look-ahead off"));
    assert_eq!(errors("G08 P3", &mill(&[])), vec!["mode-words"]);
    assert_eq!(errors("G08", &mill(&[])), vec!["mode-words"]);
}

#[test]
fn behaviour14_6_g187_sets_the_haas_smoothness() {
    let r = ok("G187 P1\nG187 P3\nG187", &mill(&[]));
    let m = |i| modal(&r, i, MachineKind::Mill).smoothness;
    assert_eq!(
        [m(0), m(1), m(2)],
        [Some("G187 P1"), Some("G187 P3"), Some("G187")]
    );
    assert!(explain(&r, 0).starts_with("G187 P1 smoothness rough"));
    assert!(explain(&r, 2).contains("Setting 191"));
    assert_eq!(errors("G187 P4", &mill(&[])), vec!["mode-words"]);
    // Before any G187 the panel shows none.
    let r = ok("X1.", &mill(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Mill).smoothness, None);
}

#[test]
fn behaviour14_7_g31_moves_as_g01_and_says_a_skip_would_stop_earlier() {
    // From X0 Y0 in G00 mode: G31 feeds to X30 Y5 (not a rapid), and the
    // mode stays G00 for the next block.
    let text = "G31 X30. Y5. F50.\nX40.";
    let r = ok(text, &mill(&[]));
    assert_eq!(r.moves[0].kind, MoveKind::Feed);
    same(r.moves[0].to, [30.0, 5.0, 0.0]);
    assert_eq!(r.moves[1].kind, MoveKind::Rapid, "G31 is one-shot");
    assert_eq!(modal(&r, 0, MachineKind::Mill).motion, "G00");
    let s = explain(&r, 0);
    assert!(s.starts_with("G31 skip: moves at the feed"), "{s}");
    assert!(s.contains("may stop earlier"), "{s}");
    // P1–P4 select the multi-step skip signal; others are refused.
    let r = ok("G31 P3 Z-10. F20.", &mill(&[]));
    assert!(explain(&r, 0).contains("skip signal 3"));
    assert_eq!(errors("G31 P5 Z-10. F20.", &mill(&[])), vec!["skip-words"]);
    // No axis, an arc word, or a canned cycle: refused.
    assert_eq!(errors("G31 F20.", &mill(&[])), vec!["skip-words"]);
    assert_eq!(errors("G31 X1. R2. F20.", &mill(&[])), vec!["skip-words"]);
    assert_eq!(
        errors("G81 X0 Z-5. R1. F10.\nG31 X1.", &mill(&[])),
        vec!["skip-words"]
    );
    // With a length offset, the actual end carries it: H01 = 10., G43 Z5 →
    // actual Z 15; G31 Z-2. ends at actual Z 8.
    let r = ok("G43 Z5. H01\nG31 Z-2. F20.", &mill(&[(1, 10.0)]));
    same(actual(&r, 1), [0.0, 0.0, 8.0]);
    // The lathe: G31 U-4. from X20 Z0 feeds to X16 (a diameter), in G00 mode.
    let r = ok("G00 X20. Z0\nG31 U-4. F0.1", &lathe(&[]));
    assert_eq!(r.moves[1].kind, MoveKind::Feed);
    same(r.moves[1].to, [16.0, 0.0, 0.0]);
    assert_eq!(modal(&r, 1, MachineKind::Lathe).motion, "G00");
}

#[test]
fn behaviour14_8_feed_modes_and_surface_speed_on_the_mill() {
    // G93: F is 1 / minutes and every feed block needs its own F.
    let text = "G93\nG01 X10. F2.\nG94\nG95\nG96 S200\nG97 S1000";
    let r = ok(text, &mill(&[]));
    let m = |i| modal(&r, i, MachineKind::Mill);
    assert_eq!(m(0).feed_mode, "G93");
    assert!(explain(&r, 0).starts_with("G93 inverse time feed"));
    assert!(explain(&r, 0).contains("does not simulate time"));
    same(actual(&r, 1), [10.0, 0.0, 0.0]);
    assert!(explain(&r, 2).starts_with("G94 feed per minute"));
    assert!(explain(&r, 3).starts_with("G95 feed per revolution"));
    assert_eq!(m(4).surface_speed, Some("G96"));
    assert!(explain(&r, 4).starts_with("G96 constant surface speed"));
    assert_eq!(m(5).surface_speed, Some("G97"));
    assert!(explain(&r, 5).starts_with("G97"));
    // A G01 in G93 without F, a plain move block too, is refused.
    assert_eq!(
        errors("G93 G01 X1. F1.\nX2.", &mill(&[])),
        vec!["inverse-time-feed"]
    );
    assert_eq!(
        errors("G93 G01 X1. F0", &mill(&[])),
        vec!["inverse-time-feed"]
    );
    // Rapids need none; back in G94 F is modal again.
    ok("G93\nG00 X5.\nG94 G01 X6. F100.\nX7.", &mill(&[]));
}

#[test]
fn behaviour14_9_the_lathe_reads_g80() {
    let r = ok("G18 G20 G40 G80 G99\nG00 X1. Z0.1", &lathe(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Lathe).cycle, Some("G80"));
    assert_eq!(r.moves.len(), 1);
    // It does not cancel a turning cycle of group 01: the next X makes a pass.
    let r = ok("G00 X60. Z2.\nG90 X50. Z-20. F0.2\nG80\nX46.", &lathe(&[]));
    assert_eq!(modal(&r, 2, MachineKind::Lathe).motion, "G90");
    assert_eq!(r.moves.len(), 1 + 4 + 4);
}

#[test]
fn behaviour14_6_g187_e_is_the_corner_tolerance() {
    let r = ok("G187 P2 E0.05", &mill(&[]));
    let s = explain(&r, 0);
    assert!(
        s.starts_with("G187 P2 smoothness medium; E0.050: the control may round each corner"),
        "{s}"
    );
    let st = r.blocks[0].state.modal.smoothness.unwrap();
    assert_eq!(st.corner, Some(0.05));
    assert_eq!(errors("G187 P1 E-0.1", &mill(&[])), vec!["mode-words"]);
    // E elsewhere stays refused.
    assert_eq!(
        errors("G01 X1. E0.1 F10.", &mill(&[])),
        vec!["unsupported-word"]
    );
}

#[test]
fn behaviour14_10_g07_1_cylindrical_interpolation_is_reported_not_drawn() {
    // Lathe: G07.1 C20. turns it on; in the mode a C word is an angle, 30° on
    // a radius of 20 is 20 × π/6 = 10.472 mm of surface; Z is drawn.
    let text = "G07.1 C20.\nG01 Z-5. C30. F0.1\nG07.1 C0\nG01 C10.";
    let r = run(text, &lathe(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Lathe).cylindrical, Some("G07.1"));
    assert!(
        explain(&r, 0)
            .starts_with("G07.1 cylindrical interpolation on, about a cylinder of radius 20.000")
    );
    assert_eq!(
        explain(&r, 1),
        "C30° on the cylinder of radius 20.000 (10.472 along its surface from 0°, G07.1): not drawn."
    );
    same(r.moves[0].to, [0.0, 0.0, -5.0]);
    assert_eq!(modal(&r, 2, MachineKind::Lathe).cylindrical, None);
    // Out of the mode, C is refused again.
    let e: Vec<_> = r.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert_eq!((e.len(), e[0].code, e[0].line), (1, "unsupported-word", 4));
    // The mill's rotary word may be A, B or C; one of them, not negative.
    ok("G07.1 A30.\nG01 X5. A90. F100.\nG07.1 A0", &mill(&[]));
    assert_eq!(errors("G07.1", &mill(&[])), vec!["mode-words"]);
    assert_eq!(errors("G07.1 A-3.", &mill(&[])), vec!["mode-words"]);
    assert_eq!(errors("G07.1 C20. X5.", &lathe(&[])), vec!["mode-words"]);
}

#[test]
fn behaviour14_11_polar_interpolation_is_kept_shown_and_stands_in_blocks_of_its_own() {
    for (on, off) in [("G12.1", "G13.1"), ("G112", "G113")] {
        let text = format!("{on}\n{off}\nG01 X10. F0.1");
        let r = ok(&text, &lathe(&[]));
        assert_eq!(modal(&r, 0, MachineKind::Lathe).polar, Some(on));
        assert!(explain(&r, 0).starts_with(&format!("{on} polar coordinate interpolation on")));
        assert_eq!(modal(&r, 1, MachineKind::Lathe).polar, Some(off));
        assert!(explain(&r, 1).starts_with(&format!("{off} polar coordinate interpolation off")));
        // G12.1 and G13.1 stand in blocks of their own (Fanuc).
        let r = run(&format!("{on} X20. C5."), &lathe(&[]));
        let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!(
            (e.code, e.column),
            ("polar-interpolation", on.len() as u32 + 2)
        );
        assert!(e.message.contains("blocks of their own"), "{}", e.message);
    }
    // The start state is G13.1; the mill refuses the codes with the reason.
    let r = ok("G00 X1.", &lathe(&[]));
    assert_eq!(modal(&r, 0, MachineKind::Lathe).polar, Some("G13.1"));
    let r = run("G12.1", &mill(&[]));
    assert!(r.diagnostics[0].message.contains("lathe only"));
}

#[test]
fn behaviour14_2_a_cutting_mode_takes_no_p_or_q() {
    let r = run("G64 P5", &mill(&[]));
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(e.code, "mode-words");
    assert!(e.message.contains("LinuxCNC"), "{}", e.message);
}

#[test]
fn behaviour14_14_g09_may_share_a_corner_block_and_g31_may_not() {
    // G09 G01 X50. ,C5. then Y40.: the chamfer is cut as without G09.
    let r = ok("G01 F100.\nG09 G01 X50. ,C5.\nY40.", &mill(&[]));
    assert!(
        r.moves
            .iter()
            .any(|m| { (m.to[0] - 50.0).abs() < 1e-9 && (m.to[1] - 5.0).abs() < 1e-9 })
    );
    assert_eq!(
        errors("G01 F100.\nG31 X50. ,C5.\nY40.", &mill(&[])),
        vec!["corner-words"]
    );
}

#[test]
fn behaviour14_22_haas_g103_limits_the_look_ahead_and_changes_no_path() {
    // G103 P1, G103 P0 and G103 alone between two moves: the moves end
    // where they would without them, each block saying what it does.
    let text = "G01 X5. F100.\nG103 P1\nG01 X10.\nG103 P0\nG103\nG01 Y3.";
    let r = ok(text, &mill(&[]));
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.moves.len(), 3);
    same(r.moves[2].to, [10.0, 3.0, 0.0]);
    assert!(explain(&r, 1).starts_with("G103 P1: the control looks at most one block ahead"));
    assert!(explain(&r, 3).starts_with("G103 P0: the control's look-ahead is no longer limited"));
    assert!(explain(&r, 4).starts_with("G103 without P"));
    // P outside 0–15 and a word not its own are refused; P with a point is
    // the parser's (P takes none, behaviour 1.13).
    for text in ["G103 P16", "G103 P2 X1."] {
        assert_eq!(errors(text, &mill(&[])), vec!["mode-words"], "{text}");
    }
    assert_eq!(errors("G103 P1.5", &mill(&[])), vec!["decimal-point"]);
}
