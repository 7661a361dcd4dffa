//! Behaviour 15 (`docs/behaviour.md`): the lathe's multiple repetitive
//! cycles G70–G76. Every program is our own; the positions each cycle
//! makes are worked out by hand in the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::EventKind;
use offsetlab::setup::{Control, DepthWord, GCodeSystem};
use offsetlab::{MoveKind, Run, RunOptions, Setup, run, run_with};

use MoveKind::{Feed, Rapid};

/// The programmed end (X diameter, Z) and kind of each move of block `i`.
fn path(r: &Run, i: usize) -> Vec<(MoveKind, f64, f64)> {
    let b = &r.blocks[i];
    let first = b.first_move as usize;
    r.moves[first..first + b.move_count as usize]
        .iter()
        .map(|m| (m.kind, m.programmed_to[0], m.programmed_to[2]))
        .collect()
}

#[track_caller]
fn same_path(got: &[(MoveKind, f64, f64)], want: &[(MoveKind, f64, f64)]) {
    assert_eq!(got.len(), want.len(), "got {got:#?}");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            g.0 == w.0 && (g.1 - w.1).abs() < 1e-6 && (g.2 - w.2).abs() < 1e-6,
            "move {k}: got {g:?}, want {w:?}\n{got:#?}"
        );
    }
}

/// The index of the block on `line`.
fn index_at(r: &Run, line: u32) -> usize {
    r.blocks.iter().position(|b| b.span.line == line).unwrap()
}

fn with_control(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

/// Stock Ø50 turned to Ø30/Ø40 (Fanuc two-block G71, type I), register 01
/// X0.4 Z-0.2 active.
const G71_TYPE_I: &str = "\
T0101
G00 X50. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.2
N10 G00 X30.
G01 Z-20.
X40. Z-30.
Z-50.
N20 X50.
G70 P10 Q20
M30
";

#[test]
fn behaviour15_7_g71_type_i_roughs_down_to_the_finishing_allowance() {
    let r = ok(G71_TYPE_I, &lathe(&[(1, 0.4, -0.2)]));
    // The contour shifted by U0.4 W0.1: X30.4 from Z2.1 to Z-19.9, the taper
    // to X40.4 Z-29.9, X40.4 to Z-49.9, up to X50.4. From A (X50 Z2), Δd 2
    // (radius): levels X46, X42, X38, X34, then the last at X30.4 ((25 −
    // 15.2) / 2 = 4.9 → 5 levels). At X46 and X42 the cut meets the wall at
    // Z-49.9; at X38 the taper (19 − 15.2) / 5 · 10 = 7.6 past Z-19.9, so
    // Z-27.5; at X34 3.6 past, Z-23.5; at X30.4 the end of the flat, Z-19.9.
    // After each cut the escape R0.5 at 45°: X +1.0 (diameter), Z +0.5, then
    // rapid back to Z2 and down in the P block's G00 to the next level.
    let mut want = Vec::new();
    for (x, z_end) in [
        (46.0, -49.9),
        (42.0, -49.9),
        (38.0, -27.5),
        (34.0, -23.5),
        (30.4, -19.9),
    ] {
        want.extend([
            (Rapid, x, 2.0),
            (Feed, x, z_end),
            (Rapid, x + 1.0, z_end + 0.5),
            (Rapid, x + 1.0, 2.0),
        ]);
    }
    // The finishing-allowance contour, then back to A.
    want.extend([
        (Rapid, 30.4, 2.1),
        (Feed, 30.4, -19.9),
        (Feed, 40.4, -29.9),
        (Feed, 40.4, -49.9),
        (Feed, 50.4, -49.9),
        (Rapid, 50.0, 2.0),
    ]);
    let i = index_at(&r, 4);
    same_path(&path(&r, i), &want);
    let e = explain(&r, i);
    assert!(e.contains("G71 type I: 5 cuts at 5 levels Δd 2.000"), "{e}");
    assert!(e.contains("toward X30.400"), "{e}");
}

#[test]
fn behaviour15_13_every_cycle_move_carries_the_t_offset_and_the_cycle_block() {
    let r = ok(G71_TYPE_I, &lathe(&[(1, 0.4, -0.2)]));
    for line in [4, 10] {
        let i = index_at(&r, line);
        let b = &r.blocks[i];
        assert!(b.move_count > 5);
        let first = b.first_move as usize;
        for m in &r.moves[first..first + b.move_count as usize] {
            // Actual = programmed + (X0.4, Z-0.2), move by move.
            same(
                m.to,
                [m.programmed_to[0] + 0.4, 0.0, m.programmed_to[2] - 0.2],
            );
            assert_eq!((m.block, m.line), (i as u32, line));
        }
    }
}

#[test]
fn behaviour15_5_the_contour_after_g71_is_passed_over_and_the_run_goes_on_after_q() {
    let r = ok(G71_TYPE_I, &lathe(&[(1, 0.4, -0.2)]));
    for line in 5..=9 {
        let i = index_at(&r, line);
        assert_eq!(r.blocks[i].move_count, 0, "line {line}");
        same(programmed(&r, i), [50.0, 0.0, 2.0]);
        let e = explain(&r, i);
        assert!(e.starts_with("not run: the G71 at line 4"), "{e}");
    }
    // After N20 the G70 runs.
    assert!(r.blocks[index_at(&r, 10)].move_count > 0);
}

#[test]
fn behaviour15_5_a_contour_before_the_cycle_is_not_passed_over_again() {
    // The contour first (run as ordinary moves), then a G71 of it: the run
    // goes on with the block after the G71.
    let text = "G00 X50. Z2.\nN10 G00 X30.\nN20 G01 Z-10. F0.2\nG00 X50. Z2.\nG71 P10 Q20 D5. U0 W0\nG00 X60.\n";
    let r = ok(text, &lathe(&[]));
    let e = explain(&r, 4);
    assert!(e.contains("is before this block"), "{e}");
    same(programmed(&r, 5), [60.0, 0.0, 2.0]);
}

#[test]
fn behaviour15_11_g70_runs_the_contour_as_programmed_with_its_feeds() {
    let text =
        "G00 X50. Z2. F0.3\nG70 P10 Q20\nN10 G00 X30.\nG01 Z-20. F0.1\nN20 X50. F0.15\nG00 X60.\n";
    let r = ok(text, &lathe(&[]));
    // A (X50 Z2) → N10 X30 at rapid → Z-20 and X50 at feed → back to A.
    same_path(
        &path(&r, 1),
        &[
            (Rapid, 30.0, 2.0),
            (Feed, 30.0, -20.0),
            (Feed, 50.0, -20.0),
            (Rapid, 50.0, 2.0),
        ],
    );
    // The contour's last F stays in effect.
    assert_eq!(r.blocks[1].state.feed, Some(0.15));
    // G70 does not pass over the contour after it: those blocks run.
    assert_eq!(r.blocks[2].move_count, 1);
}

#[test]
fn behaviour15_15_g70_with_the_roughing_words_warns_on_haas_and_is_ps0066_on_fanuc() {
    // The G71 line's U W copied onto the G70: Haas finishes the contour as
    // programmed (A X50 Z2 → X30 rapid → Z-20, X50 feed → A), the words
    // named in one warning; Fanuc and YASNAC stop at U (PS0066).
    let text = "G00 X50. Z2. F0.3\nG70 P10 Q20 U0.4 W0.1\nN10 G00 X30.\nG01 Z-20. F0.1\nN20 X50.\nG00 X60.\n";
    let r = ok(text, &with_control(lathe(&[]), Control::Haas));
    same_path(
        &path(&r, 1),
        &[
            (Rapid, 30.0, 2.0),
            (Feed, 30.0, -20.0),
            (Feed, 50.0, -20.0),
            (Rapid, 50.0, 2.0),
        ],
    );
    let w: Vec<_> = r
        .diagnostics
        .iter()
        .filter(|d| d.code == "mrc-ignored-word")
        .collect();
    assert_eq!(w.len(), 1);
    assert_eq!((w[0].line, w[0].column), (2, 13));
    assert!(
        w[0].message
            .starts_with("G70: U W are the roughing cycle's"),
        "{}",
        w[0].message
    );
    for control in [Control::Fanuc, Control::Yasnac] {
        let r = run(text, &with_control(lathe(&[]), control));
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!((d.code, d.line, d.column), ("mrc-word", 2, 13));
    }
    // A word G70 never reads (A, G76's tool angle) stays an error on Haas too.
    let stray = text.replace("W0.1", "A5");
    assert_eq!(
        errors(&stray, &with_control(lathe(&[]), Control::Haas)),
        vec!["unsupported-word"]
    );
}

#[test]
fn behaviour15_8_g72_type_i_faces_in_z_levels() {
    // Facing from A (X62 Z1) with W1.5 R0.5, allowance U0.2 W0.1: the
    // shifted contour is X62.2 Z-4.9 → X40.2 Z-4.9 → X30.2 Z-1.9 → X30.2
    // Z0.1 → X0.2 Z0.1. Levels Z-0.5, -2.0, -3.5, then -4.9 (5.9 / 1.5 →
    // 4). Each cut runs along -X from X62 to the contour: at Z-0.5 the
    // shoulder X30.2; at Z-2.0 the taper (radius 20.1 − 5·2.9/3 =
    // 15.2667, X30.5333); at Z-3.5 (20.1 − 5·1.4/3 = 17.7667, X35.5333);
    // at Z-4.9 the face to X40.2. Escape: X +1.0, Z +0.5; back to X62.
    let text = "G00 X62. Z1.\nG72 W1.5 R0.5\nG72 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 Z-5.\nG01 X40.\nX30. Z-2.\nZ0.\nN20 X0.\n";
    let r = ok(text, &lathe(&[]));
    let mut want = Vec::new();
    for (z, x_end) in [
        (-0.5, 30.2),
        (-2.0, 2.0 * (20.1 - 5.0 * 2.9 / 3.0)),
        (-3.5, 2.0 * (20.1 - 5.0 * 1.4 / 3.0)),
        (-4.9, 40.2),
    ] {
        want.extend([
            (Rapid, 62.0, z),
            (Feed, x_end, z),
            (Rapid, x_end + 1.0, z + 0.5),
            (Rapid, 62.0, z + 0.5),
        ]);
    }
    want.extend([
        (Rapid, 62.2, -4.9),
        (Feed, 40.2, -4.9),
        (Feed, 30.2, -1.9),
        (Feed, 30.2, 0.1),
        (Feed, 0.2, 0.1),
        (Rapid, 62.0, 1.0),
    ]);
    same_path(&path(&r, 2), &want);
}

#[test]
fn behaviour15_8_g71_type_ii_roughs_the_pocket() {
    // The P block names X and Z: type II. Contour X20 Z2 → Z-10 → X36 Z-18
    // → X24 Z-24 (the pocket) → Z-30 → X40 Z-34, from A (X40 Z2), Δd 3
    // (radius), R0.5, no allowance. Levels X34, X28, X24 (the pocket's
    // bottom), X22, X20. At X34 (radius 17) the first cut meets the taper
    // at Z-17, the pocket is cut from Z-19 to Z-32.5; at X28 from Z-14 and
    // Z-22 to Z-31; at X24 from Z-12 and along the pocket bottom Z-24 to
    // Z-30; at X22 and X20 only the first stretch, to Z-11 and Z-10.
    let text = "G00 X40. Z2.\nG71 U3. R0.5\nG71 P10 Q20 U0 W0 F0.2\nN10 G00 X20. Z2.\nG01 Z-10.\nX36. Z-18.\nX24. Z-24.\nZ-30.\nN20 X40. Z-34.\n";
    let r = ok(text, &lathe(&[]));
    let pocket = |x: f64, x_before: f64, z0: f64, z1: f64| {
        // Up to the start's X, over the pocket, down to the level before,
        // in at the feed, along, and the 45° escape.
        vec![
            (Rapid, 40.0, 0.0),
            (Rapid, 40.0, z0),
            (Rapid, x_before, z0),
            (Feed, x, z0),
            (Feed, x, z1),
            (Rapid, x + 1.0, z1 + 0.5),
            (Rapid, 40.0, z1 + 0.5),
            (Rapid, 40.0, 2.0),
        ]
    };
    let mut want = vec![
        (Rapid, 34.0, 2.0),
        (Feed, 34.0, -17.0),
        (Rapid, 35.0, -16.5),
    ];
    let mut p = pocket(34.0, 40.0, -19.0, -32.5);
    p[0].2 = -16.5;
    p.remove(2); // from X40 to X40: no move
    want.extend(p);
    want.extend([
        (Rapid, 28.0, 2.0),
        (Feed, 28.0, -14.0),
        (Rapid, 29.0, -13.5),
    ]);
    let mut p = pocket(28.0, 34.0, -22.0, -31.0);
    p[0].2 = -13.5;
    want.extend(p);
    want.extend([
        (Rapid, 24.0, 2.0),
        (Feed, 24.0, -12.0),
        (Rapid, 25.0, -11.5),
    ]);
    let mut p = pocket(24.0, 28.0, -24.0, -30.0);
    p[0].2 = -11.5;
    want.extend(p);
    want.extend([
        (Rapid, 22.0, 2.0),
        (Feed, 22.0, -11.0),
        (Rapid, 23.0, -10.5),
        (Rapid, 23.0, 2.0),
        (Rapid, 20.0, 2.0),
        (Feed, 20.0, -10.0),
        (Rapid, 21.0, -9.5),
        (Rapid, 21.0, 2.0),
        // The contour, then back to A.
        (Rapid, 20.0, 2.0),
        (Feed, 20.0, -10.0),
        (Feed, 36.0, -18.0),
        (Feed, 24.0, -24.0),
        (Feed, 24.0, -30.0),
        (Feed, 40.0, -34.0),
        (Rapid, 40.0, 2.0),
    ]);
    same_path(&path(&r, 2), &want);
    assert!(explain(&r, 2).starts_with("G71 type II"));
}

#[test]
fn behaviour15_9_g73_repeats_the_contour_closing_in_on_it() {
    // Δi 3 (radius), Δk 2, 3 divisions, allowance U0.4 W0.1: the shifts
    // are X 0.4 + 2·3·(3−k)/2 and Z 0.1 + 2·(3−k)/2: (6.4, 2.1), (3.4,
    // 1.1), (0.4, 0.1); each pass from A (X60 Z5) and back to it.
    let text = "G00 X60. Z5.\nG73 U3. W2. R3\nG73 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X30. Z2.\nG01 Z-20.\nX50. Z-30.\nN20 X60.\n";
    let r = ok(text, &lathe(&[]));
    let mut want = Vec::new();
    for (dx, dz) in [(6.4, 2.1), (3.4, 1.1), (0.4, 0.1)] {
        want.extend([
            (Rapid, 30.0 + dx, 2.0 + dz),
            (Feed, 30.0 + dx, -20.0 + dz),
            (Feed, 50.0 + dx, -30.0 + dz),
            (Feed, 60.0 + dx, -30.0 + dz),
            (Rapid, 60.0, 5.0),
        ]);
    }
    same_path(&path(&r, 2), &want);
}

#[test]
fn behaviour15_10_g74_pecks_along_z_at_each_x() {
    // Fanuc two blocks: e 0.5; X from 20 to 10 in steps of P2500 = 2.5 mm
    // (radius: X20, X15, X10), pecks of Q3000 = 3 mm from Z1 to Z-6 (Z-2,
    // Z-5, Z-6), back 0.5 between pecks, out to Z1 after each hole.
    let text = "G00 X20. Z1.\nG74 R0.5\nG74 X10. Z-6. P2500 Q3000 F0.1\n";
    let r = ok(text, &lathe(&[]));
    let mut want = Vec::new();
    for x in [20.0, 15.0, 10.0] {
        if x != 20.0 {
            want.push((Rapid, x, 1.0));
        }
        want.extend([
            (Feed, x, -2.0),
            (Rapid, x, -1.5),
            (Feed, x, -5.0),
            (Rapid, x, -4.5),
            (Feed, x, -6.0),
            (Rapid, x, 1.0),
        ]);
    }
    want.push((Rapid, 20.0, 1.0));
    // The last rapid goes nowhere (the tool is at X10 Z1): the back to X20.
    let got = path(&r, 2);
    same_path(&got, &want);
}

#[test]
fn behaviour15_10_g75_one_block_pecks_along_x() {
    // Haas/Series 10 form: I2. is the X peck (radius); no Z, one groove.
    // From X40 (radius 20) to X30 (15): pecks to radius 18, 16, 15, back by
    // the default return 1 mm (setting peck_retract) between them.
    let text = "G00 X40. Z-10.\nG75 X30. I2. F0.1\n";
    let r = ok(text, &lathe(&[]));
    same_path(
        &path(&r, 1),
        &[
            (Feed, 36.0, -10.0),
            (Rapid, 38.0, -10.0),
            (Feed, 32.0, -10.0),
            (Rapid, 34.0, -10.0),
            (Feed, 30.0, -10.0),
            (Rapid, 40.0, -10.0),
        ],
    );
}

#[test]
fn behaviour15_12_g76_two_blocks_cut_at_the_square_root_depths() {
    // P010060: m 1, no chamfer, 60°; Q100: Δdmin 0.1; R0.05: d. Second
    // block: root X22, Z-14, k P2000 = 2.0, Δd Q800 = 0.8, lead 2.
    // Depths 0.8·√n: 0.8, 1.1314, 1.3856, 1.6, 1.7889, then 0.8·√6 =
    // 1.9596 ≥ k − d = 1.95 → 1.95, and one finishing pass at 2.0. The
    // crest is X26 (radius 11 + 2); a pass at depth δ cuts at X26 − 2δ and
    // starts δ·tan 30° toward the cut (−Z) from Z5.
    let text = "G00 X30. Z5.\nG76 P010060 Q100 R0.05\nG76 X22. Z-14. P2000 Q800 F2.\n";
    let r = ok(text, &lathe(&[]));
    let tan30 = 30f64.to_radians().tan();
    let mut want = Vec::new();
    for d in [
        0.8,
        0.8 * 2f64.sqrt(),
        0.8 * 3f64.sqrt(),
        1.6,
        0.8 * 5f64.sqrt(),
        1.95,
        2.0,
    ] {
        want.extend([
            (Rapid, 26.0 - 2.0 * d, 5.0 - d * tan30),
            (Feed, 26.0 - 2.0 * d, -14.0),
            (Rapid, 30.0, -14.0),
            (Rapid, 30.0, 5.0),
        ]);
    }
    same_path(&path(&r, 2), &want);
    let e = explain(&r, 2);
    assert!(e.contains("7 passes"), "{e}");
}

#[test]
fn behaviour15_12_g76_one_block_haas_reads_d_as_a_length() {
    // Haas: G76 X Z K D F, D0.8 a length; no A: a radial infeed; m 1.
    // Depths 0.8·√n to 2.0: 0.8, 1.1314, 1.3856, 1.6, 1.7889, 1.9596,
    // then 0.8·√7 = 2.117 → 2.0, and the finishing pass at 2.0: 8 passes.
    let text = "G00 X30. Z5.\nG76 X22. Z-14. K2. D0.8 F2.\n";
    let r = ok(text, &with_control(lathe(&[]), Control::Haas));
    let got = path(&r, 1);
    assert_eq!(got.len(), 8 * 4);
    // Pass 2 at X26 − 2·0.8·√2, straight in from Z5.
    same_path(
        &got[4..6],
        &[
            (Rapid, 26.0 - 1.6 * 2f64.sqrt(), 5.0),
            (Feed, 26.0 - 1.6 * 2f64.sqrt(), -14.0),
        ],
    );
    // With A60 the passes go in along the flank: pass 1 from Z5 − 0.8·tan 30°.
    let r = ok(
        "G00 X30. Z5.\nG76 X22. Z-14. K2. D0.8 F2. A60\n",
        &with_control(lathe(&[]), Control::Haas),
    );
    let tan30 = 30f64.to_radians().tan();
    same_path(&path(&r, 1)[..1], &[(Rapid, 24.4, 5.0 - 0.8 * tan30)]);
}

#[test]
fn behaviour7_24_depth_word_reads_d_by_the_control() {
    // Fanuc's Series 10/11 format: D in least increments, D800 = 0.8 mm;
    // a decimal point there is an error.
    let fanuc = with_control(lathe(&[]), Control::Fanuc);
    let r = ok("G00 X30. Z5.\nG76 X22. Z-14. K2. D800 F2.\n", &fanuc);
    same_path(&path(&r, 1)[..1], &[(Rapid, 24.4, 5.0)]);
    assert_eq!(
        errors("G00 X30. Z5.\nG76 X22. Z-14. K2. D0.8 F2.\n", &fanuc),
        vec!["decimal-point"]
    );
    // The setting wins over the control.
    let mut s = fanuc;
    s.settings.depth_word = Some(DepthWord::Dimension);
    ok("G00 X30. Z5.\nG76 X22. Z-14. K2. D0.8 F2.\n", &s);
}

#[test]
fn behaviour15_2_p_and_q_are_sequence_numbers_and_d_a_length() {
    // No integer-dimension warning for P, Q (sequence numbers) or D with a
    // point; a decimal point in P is refused.
    let r = ok(G71_TYPE_I, &lathe(&[(1, 0.4, -0.2)]));
    assert!(r.diagnostics.is_empty(), "{:#?}", r.diagnostics);
    assert_eq!(errors("G70 P10. Q20\n", &lathe(&[])), vec!["decimal-point"]);
    // Q stays a dimension outside the cycles' blocks.
    let r = run("G00 X10. Q5\n", &lathe(&[]));
    assert!(r.diagnostics.iter().any(|d| d.code == "integer-dimension"));
    // A D is still the mill's outside a cycle block.
    assert_eq!(errors("G00 X10. D01\n", &lathe(&[])), vec!["mill-address"]);
    // G73's R is a count: R3 is three divisions, not 0.003 mm.
    let text =
        "G00 X60. Z5.\nG73 U3. W2. R3\nG73 P10 Q20 U0 W0\nN10 G00 X30.\nN20 G01 Z-10. F0.2\n";
    assert!(explain(&ok(text, &lathe(&[])), 1).contains("over 3 divisions"));
}

#[test]
fn behaviour15_1_system_c_numbers_the_cycles_g72_to_g78() {
    // In G-code system C, G71 is metric and G73 the stock removal in turning.
    let mut s = lathe(&[]);
    s.settings.gcode_system = Some(GCodeSystem::C);
    let text =
        "G71 G00 X50. Z2.\nG73 U2. R0.5\nG73 P10 Q20 U0 W0 F0.2\nN10 G00 X30.\nN20 G01 Z-10.\n";
    let r = ok(text, &s);
    let e = explain(&r, 2);
    assert!(e.starts_with("G73 type I"), "{e}");
    // G72 is G70's number there.
    let r = ok(
        "G71 G00 X50. Z2.\nG72 P10 Q20\nN10 G00 X30.\nN20 G01 Z-10. F0.2\n",
        &s,
    );
    assert!(
        explain(&r, 1).starts_with("G72: the contour"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour15_6_the_contour_is_checked_with_the_controls_alarms() {
    let s = lathe(&[]);
    let check = |text: &str, code: &str, alarm: &str| {
        let r = run(text, &s);
        let d = r
            .diagnostics
            .iter()
            .find(|d| d.is_error())
            .unwrap_or_else(|| panic!("no error for {text}"));
        assert_eq!(d.code, code, "{text}: {}", d.message);
        assert!(d.message.contains(alarm), "{text}: {}", d.message);
    };
    let head = "G00 X50. Z2.\nG71 U2. R0.5\n";
    // PS0061: Q missing; PS0063: no N20 after N10, no N30 at all.
    check("G70 P10\n", "mrc-sequence", "PS0061");
    check(
        &format!("{head}G71 P10 Q20\nN10 G00 X30.\n"),
        "mrc-sequence",
        "PS0063",
    );
    check(
        &format!("{head}G71 P30 Q20\nN10 G00 X30.\n"),
        "mrc-sequence",
        "PS0063",
    );
    // PS0065: the first block is not G00/G01.
    check(
        &format!("{head}G71 P10 Q20\nN10 X30.\nN20 G01 Z-10.\n"),
        "mrc-first-block",
        "PS0065",
    );
    // Type I: X goes up and down (PS0329, X is the plane's second axis).
    check(
        &format!("{head}G71 P10 Q20\nN10 G00 X30.\nG01 Z-10.\nX40. Z-15.\nX30. Z-20.\nN20 X50.\n"),
        "mrc-monotonic",
        "PS0329",
    );
    // Z turns back (PS0064, the first axis), even in type II.
    check(
        &format!("{head}G71 P10 Q20\nN10 G00 X30. Z2.\nG01 Z-10.\nX40. Z-5.\nN20 X50. Z-20.\n"),
        "mrc-monotonic",
        "PS0064",
    );
    // PS0322: the contour goes beyond the start's X.
    check(
        &format!("{head}G71 P10 Q20\nN10 G00 X30.\nG01 Z-10.\nN20 X60.\n"),
        "mrc-over-start",
        "PS0322",
    );
    // PS0325: a G28 inside the contour.
    check(
        &format!("{head}G71 P10 Q20\nN10 G00 X30.\nG28 U0\nN20 G01 Z-10.\n"),
        "mrc-shape",
        "PS0325",
    );
    // PS0062: no depth of cut; a G73 with no divisions.
    check("G00 X50. Z2.\nG71 U0 R1.\n", "mrc-value", "PS0062");
    check(
        "G00 X50. Z2.\nG71 P10 Q20\nN10 G00 X30.\nN20 G01 Z-10.\n",
        "mrc-value",
        "PS0062",
    );
    check(
        "G00 X40. Z5.\nG76 X30. Z-10. K0 D1. F1.\n",
        "mrc-value",
        "PS0062",
    );
    // A word the cycle does not read is refused, never passed over.
    check("G70 P10 Q20 X5.\n", "mrc-word", "PS0066");
}

#[test]
fn behaviour15_14_absurd_values_are_errors_never_hangs() {
    let s = lathe(&[]);
    // Δd 0.0001 mm over 25 mm of radius: 250,000 levels.
    assert_eq!(
        errors(
            "G00 X50. Z2.\nG71 U0.0001 R0.5\nG71 P10 Q20\nN10 G00 X0.\nN20 G01 Z-10. F0.2\n",
            &s
        ),
        vec!["mrc-passes"]
    );
    // A thread of height 50 with a first depth of one micrometre.
    assert_eq!(
        errors("G00 X200. Z5.\nG76 X100. Z-10. K50. D0.001 F1.\n", &s),
        vec!["mrc-passes"]
    );
    // 10⁶ pecks.
    assert_eq!(
        errors("G00 X40. Z5.\nG74 Z-995. K0.001 F0.1\n", &s),
        vec!["mrc-passes"]
    );
    // A cycle's moves count against the run's move budget.
    let options = RunOptions {
        max_moves: 10,
        ..RunOptions::default()
    };
    let r = run_with(G71_TYPE_I, &lathe(&[(1, 0.4, -0.2)]), options);
    assert!(r.diagnostics.iter().any(|d| d.code == "too-many-moves"));
}

#[test]
fn behaviour15_4_first_blocks_are_kept_for_the_cycles_after() {
    // One G71 U… R… serves two G71 cycles.
    let text = "G00 X50. Z2.\nG71 U5. R1.\nG71 P10 Q20\nN10 G00 X30.\nN20 G01 Z-10. F0.2\nG00 X50. Z2.\nG71 P10 Q20\nG00 X60.\n";
    let r = ok(text, &lathe(&[]));
    // Levels X40, X30 (radius 25 → 20 → 15): 2 cuts each time.
    for i in [2, 6] {
        assert!(
            explain(&r, i).contains("2 cuts at 2 levels Δd 5.000"),
            "{}",
            explain(&r, i)
        );
    }
    // The second G71's contour lies before it: nothing is passed over.
    same(programmed(&r, 7), [60.0, 0.0, 2.0]);
}

#[test]
fn behaviour15_11_g70_dwell_in_the_contour_is_an_event() {
    let text = "G00 X50. Z2.\nG70 P10 Q20\nN10 G00 X30.\nG04 P500\nN20 G01 Z-10. F0.2\n";
    let r = ok(text, &lathe(&[]));
    assert!(
        r.events
            .iter()
            .any(|e| e.block == 1 && e.kind == EventKind::Dwell { seconds: 0.5 })
    );
}

#[test]
fn behaviour7_25_trailing_rapids_are_the_exit_on_haas_and_the_shape_on_fanuc() {
    // The contour ends `G00 Z2.` back at the start, as Haas school programs
    // write it.
    let text = "G00 X50. Z2.\nG71 P10 Q20 U0 W0 D5. F0.2\nN10 G00 X30. Z2.\nG01 Z-10.\nX50.\nN20 G00 Z2.\n";
    let fanuc = with_control(lathe(&[]), Control::Fanuc);
    let r = run(&text.replace("D5.", "D5000"), &fanuc);
    assert_eq!(
        r.diagnostics[0].code, "mrc-monotonic",
        "{:#?}",
        r.diagnostics
    );
    let r = ok(text, &with_control(lathe(&[]), Control::Haas));
    assert_eq!(r.diagnostics[0].code, "mrc-exit");
    // Without the exit: levels X40 and X30 (D5. radius from X50) to Z-10
    // (the wall at X30–X50), escaping by e = 1 mm (no first block: setting
    // peck_retract) — X +2.0, Z +1.0; then the shape X30 Z2 → Z-10 → X50,
    // back to A.
    same_path(
        &path(&r, 1),
        &[
            (Rapid, 40.0, 2.0),
            (Feed, 40.0, -10.0),
            (Rapid, 42.0, -9.0),
            (Rapid, 42.0, 2.0),
            (Rapid, 30.0, 2.0),
            (Feed, 30.0, -10.0),
            (Rapid, 32.0, -9.0),
            (Rapid, 32.0, 2.0),
            (Rapid, 30.0, 2.0),
            (Feed, 30.0, -10.0),
            (Feed, 50.0, -10.0),
            (Rapid, 50.0, 2.0),
        ],
    );
}

#[test]
fn behaviour15_5_blocks_between_the_cycle_and_p_are_passed_over_too() {
    // Fanuc goes on after N20: the M08 between the G71 and N10 is not run.
    let text = "G00 X50. Z2.\nG71 P10 Q20 U0 W0 D5. F0.2\nM08\nN10 G00 X30.\nN20 G01 Z-10.\nM09\n";
    let r = ok(text, &lathe(&[]));
    assert_eq!(r.blocks[2].move_count, 0);
    assert!(explain(&r, 2).starts_with("not run"));
    // Only the M09 after N20 is an event.
    let events: Vec<_> = r.events.iter().map(|e| e.line).collect();
    assert_eq!(events, vec![6]);
}

#[test]
fn behaviour15_7_an_inch_program_reads_the_haas_d_in_inches() {
    // G20, D.05 = 0.05 in (radius) from X1.0 down to X0.8: levels X0.9,
    // X0.8 (0.1 in of radius over 0.05 → 2), cut to Z-0.5; escape by the
    // default 1 mm (0.03937 in) at 45°.
    let text =
        "G20\nG00 X1.0 Z0.1\nG71 P10 Q20 U0 W0 D.05 F0.01\nN10 G00 X0.8\nG01 Z-0.5\nN20 X1.0\n";
    let r = ok(text, &with_control(lathe(&[]), Control::Haas));
    let mm = |v: f64| v * 25.4;
    let got = path(&r, 2);
    same_path(
        &got[..3],
        &[
            (Rapid, mm(0.9), mm(0.1)),
            (Feed, mm(0.9), mm(-0.5)),
            (Rapid, mm(0.9) + 2.0, mm(-0.5) + 1.0),
        ],
    );
    assert!(
        explain(&r, 2).contains("2 cuts at 2 levels Δd 0.0500"),
        "{}",
        explain(&r, 2)
    );
}
