//! Behaviour 18.11–18.16 (`docs/behaviour.md`): tool nose radius
//! compensation inside the lathe's cycles. The worked examples are in the
//! plane's coordinates (Z, X as a radius) in the comments; the program and
//! the moves write X as a diameter. R 0.8, tip 3 (the imaginary nose at
//! (−0.8, −0.8) from the nose centre) unless said.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::Control;
use offsetlab::{Run, Setup, run};

fn nose(r: f64, t: u8, control: Control) -> Setup {
    let mut s = lathe(&[]);
    s.set_register(&format!("01=X0,Z0,R{r},T{t}")).unwrap();
    s.settings.control = control;
    s
}

/// The actual ends (X diameter, Z) of the moves made by the block on `line`.
fn ends(r: &Run, line: u32) -> Vec<[f64; 2]> {
    r.moves
        .iter()
        .filter(|m| m.line == line)
        .map(|m| [m.to[0], m.to[2]])
        .collect()
}

#[track_caller]
fn near(got: [f64; 2], want: [f64; 2]) {
    assert!(
        (got[0] - want[0]).abs() < 1e-4 && (got[1] - want[1]).abs() < 1e-4,
        "got {got:?}, want {want:?}"
    );
}

/// A stepped shaft: a diameter, a taper, a convex R5 arc, a face; G42 in
/// the P block, G40 in the Q block (the Haas form). Lines 4–11.
const SHAFT: &str = "T0101
G00 X60. Z2.
G71 U2. R0.5
G71 P10 Q20 U0. W0. F0.2
N10 G00 G42 X20.
G01 Z-10.
X30. Z-20.
G02 X40. Z-25. R5.
G01 X50.
N20 G40 X60.
G70 P10 Q20
";

#[test]
fn behaviour18_11_g71_roughs_the_compensated_finishing_shape() {
    let r = ok(SHAFT, &nose(0.8, 3, Control::Haas));
    let g71 = ends(&r, 4);
    // The Z leg (r 10, going −Z) offset right by 0.8: the centre at r 10.8.
    // The taper (−10, 10)→(−20, 15): t = (−10, 5)/√125 = (−0.894427,
    // 0.447214); its right offset passes (−10, 10) + 0.8·(0.447214,
    // 0.894427) = (−9.642229, 10.715542). It meets r 10.8 at s = (10.8 −
    // 10.715542)/0.447214 = 0.188854: z = −9.642229 − 0.168916 =
    // −9.811146. The imaginary nose is the centre + (−0.8, −0.8): the
    // corner at (−10.611146, 10), so the last pass (r 10, X20) ends at
    // Z−10.611146 — 0.611146 short of the programmed −10 on the taper side.
    let x20 = g71
        .iter()
        .position(|p| p[0] == 20.0 && p[1] < -10.0)
        .unwrap();
    near(g71[x20], [20.0, -10.611146]);
    // The pass at r 12 (X24) ends where the nose's taper line (through
    // (−10.611146, 10), along t) reaches r 12: s = 2/0.447214 = 4.472136,
    // z = −10.611146 − 4 = −14.611146 (the programmed taper: −14).
    assert!(
        g71.iter()
            .any(|p| (p[0] - 24.0).abs() < 1e-9 && (p[1] + 14.611146).abs() < 1e-5)
    );
    // The contour pass then runs the G70 path below, then back to A.
    near(*g71.last().unwrap(), [60.0, 2.0]);
    let report = r.blocks.iter().find(|b| b.span.line == 4).unwrap();
    let text = report.explanation();
    assert!(text.contains("behaviour 18.11"), "{text}");
}

#[test]
fn behaviour18_12_g70_finishes_the_compensated_contour() {
    let r = ok(SHAFT, &nose(0.8, 3, Control::Haas));
    let g70 = ends(&r, 11);
    // Start-up (type A) on N10: the centre 0.8 right of the Z leg's start,
    // (2, 10.8); the nose (1.2, 10): X20 Z1.2.
    near(g70[0], [20.0, 1.2]);
    // The Z leg to the taper corner worked out above.
    near(g70[1], [20.0, -10.611146]);
    // The concave arc about (−20, 20), R5 shrunk to 4.2 (the nose inside
    // it, on the centre's side), ends
    // at the +X leg's offset z −25 + 0.8: centre (−24.2, 20), nose (−25,
    // 19.2): X38.4 Z−25.
    near(g70[3], [38.4, -25.0]);
    // The X50 leg ends perpendicular before the cancel: centre (−24.2,
    // 25), nose (−25, 24.2): X48.4; the cancel block ends on X60 Z−25.
    near(g70[4], [48.4, -25.0]);
    near(g70[5], [60.0, -25.0]);
    near(g70[6], [60.0, 2.0]);
    // Programmed and actual both drawn: the Z leg's move is programmed to
    // X20 Z−10.
    let m = r.moves.iter().filter(|m| m.line == 11).nth(1).unwrap();
    assert_eq!([m.programmed_to[0], m.programmed_to[2]], [20.0, -10.0]);
    // The arc keeps the programmed circle as its programmed arc.
    let arc = r.moves.iter().filter(|m| m.line == 11).nth(3).unwrap();
    let info = arc.arc.unwrap();
    assert!((info.programmed_radius - 5.0).abs() < 1e-9 && (info.radius - 4.2).abs() < 1e-6);
}

#[test]
fn behaviour18_13_g72_faces_and_g73_repeats_the_compensated_shape() {
    // G72: a face at Z−10 cut toward the axis (G41: the part at −Z is
    // right of −X travel), a taper to (Z−5, r10), a face to r5.
    let text = "T0101
G00 X62. Z2.
G72 W2. R0.5
G72 P10 Q20 U0. W0. F0.2
N10 G00 G41 Z-10.
G01 X40.
X20. Z-5.
N20 X10.
G40 G00 Z5.
";
    let r = ok(text, &nose(0.8, 3, Control::Haas));
    let g72 = ends(&r, 4);
    // The taper t = (5, −10)/√125 = (0.447214, −0.894427), offset left by
    // 0.8: (−10, 20) + 0.8·(0.894427, 0.447214) = (−9.284458, 20.357771);
    // the nose line through (−10.084458, 19.557771). The level Z−6 meets it
    // at s = 4.084458/0.447214 = 9.133122: r = 19.557771 − 8.168916 =
    // 11.388855, X22.77771.
    assert!(
        g72.iter()
            .any(|p| (p[1] + 6.0).abs() < 1e-9 && (p[0] - 22.77771).abs() < 1e-4)
    );
    // The last face (−X at Z−5) ends perpendicular: centre (−4.2, 5),
    // nose (−5, 4.2): X8.4 Z−5.
    assert!(
        g72.iter()
            .any(|p| (p[0] - 8.4).abs() < 1e-9 && (p[1] + 5.0).abs() < 1e-9)
    );
    // G73 twice (Δi 2 in radius): the first pass is the G70 path moved
    // X +4, the last the G70 path itself.
    let g73 = SHAFT
        .replace("G71 U2. R0.5", "G73 U2. W0. R2")
        .replace("G71 P10 Q20 U0. W0. F0.2", "G73 P10 Q20 U0. W0. F0.2");
    let r = ok(&g73, &nose(0.8, 3, Control::Haas));
    let passes = ends(&r, 4);
    near(passes[1], [24.0, -10.611146]);
    near(passes[8], [20.0, -10.611146]);
}

#[test]
fn behaviour18_14_tip_0_and_9_run_the_nose_centre_path() {
    for tip in [0, 9] {
        let r = ok(SHAFT, &nose(0.8, tip, Control::Haas));
        let g70 = ends(&r, 11);
        // The centres of 18.12: (2, 10.8), (−9.811146, 10.8), (−24.2, 20),
        // (−24.2, 25); the cancel block on its programmed point.
        near(g70[0], [21.6, 2.0]);
        near(g70[1], [21.6, -9.811146]);
        near(g70[3], [40.0, -24.2]);
        near(g70[4], [50.0, -24.2]);
        near(g70[5], [60.0, -25.0]);
    }
}

#[test]
fn behaviour18_15_g90_and_g94_are_compensated_on_the_tips_side() {
    // G90 taper from A (Z2, r21) to B (Z2, r10) at rapid, C (Z−20, r15),
    // D (Z−20, r21). The cutting leg t = (−22, 5)/√509 = (−0.975133,
    // 0.221621): tip 3's vector (−1, −1) lies on its left, so the nose
    // centre goes right (G42).
    let text = "T0101\nG00 X42. Z2.\nG42\nG90 X30. Z-20. R-5. F0.2\nG40 G00 X50.\n";
    let r = ok(text, &nose(0.8, 3, Control::Fanuc));
    let legs = ends(&r, 4);
    // Start-up A: centre B + 0.8·(0.221621, 0.975133) = (2.177297,
    // 10.780106); nose (1.377297, 9.980106): X19.960213 Z1.377297.
    near(legs[0], [19.960213, 1.377297]);
    // C: that line meets the face leg's offset z −19.2 at s = 21.922455:
    // r = 10.780106 + 4.858477 = 15.638583; nose (−20, 14.838583).
    near(legs[1], [29.67717, -20.0]);
    // D ends perpendicular before the return: centre (−19.2, 21), nose
    // (−20, 20.2): X40.4; then back to A with no vector.
    near(legs[2], [40.4, -20.0]);
    near(legs[3], [42.0, 2.0]);
    // G41 written: the same path (the tip decides the side).
    let r41 = ok(
        &text.replace("G42\n", "G41\n"),
        &nose(0.8, 3, Control::Fanuc),
    );
    assert_eq!(ends(&r41, 4), legs);
    // G94 taper face: the cutting leg (−5, 21)→(−2, 10), t = (3, −11)/√130
    // = (0.263117, −0.964764); tip 3 lies right of it: the centre goes
    // left by 0.8·(0.964764, 0.263117): start-up end (−4.228189,
    // 21.210494), nose (−5.028189, 20.410494).
    let text = "T0101\nG00 X42. Z2.\nG42\nG94 X20. Z-2. R-3. F0.2\nG40 G00 X50.\n";
    let r = ok(text, &nose(0.8, 3, Control::Fanuc));
    near(ends(&r, 4)[0], [40.820988, -5.028189]);
    // Tip 2 (the boring bar, vector (−1, +1)) on the G90 leg: n = (−0.221621,
    // −0.975133)·(−1, 1) = −0.753512 < 0: the centre goes left (G41), below
    // the cutting leg: start-up centre (2, 10) − 0.8·(0.221621, 0.975133) =
    // (1.822703, 9.219894); nose (1.022703, 10.019894): X20.039787.
    let text = "T0101\nG00 X42. Z2.\nG41\nG90 X30. Z-20. R-5. F0.2\nG40 G00 X50.\n";
    let r = ok(text, &nose(0.8, 2, Control::Fanuc));
    near(ends(&r, 4)[0], [20.039787, 1.022703]);
}

#[test]
fn behaviour18_16_g92_threading_is_not_compensated() {
    let text = "T0101\nG00 X42. Z2.\nG42\nG92 X38. Z-20. F1.5\nG40 G00 X50.\n";
    let r = ok(text, &nose(0.8, 3, Control::Fanuc));
    assert!(r.diagnostics.iter().any(|d| d.code == "nose-thread"));
    // The legs as programmed: X38 Z2, X38 Z−20, X42 Z−20, X42 Z2.
    assert_eq!(
        ends(&r, 4),
        vec![[38.0, 2.0], [38.0, -20.0], [42.0, -20.0], [42.0, 2.0]]
    );
}

#[test]
fn behaviour7_34_fanuc_writes_the_compensation_before_the_cycle() {
    // On Fanuc G42 inside the contour is PS0325 at its word.
    let r = run(SHAFT, &nose(0.8, 3, Control::Fanuc));
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.code, d.line, d.column), ("nose-in-cycle", 5, 9));
    // G42 before the cycle and G40 after it: the same G70 path as the Haas
    // form (the start-up on the P block from A, the return cancelling).
    let fanuc = "T0101
G00 X60. Z2.
G42
G71 U2. R0.5
G71 P10 Q20 U0. W0. F0.2
N10 G00 X20.
G01 Z-10.
X30. Z-20.
G02 X40. Z-25. R5.
G01 X50.
N20 X60.
G70 P10 Q20
G40
";
    let r = ok(fanuc, &nose(0.8, 3, Control::Fanuc));
    let haas = ok(SHAFT, &nose(0.8, 3, Control::Haas));
    let g70: Vec<_> = ends(&r, 12);
    let want = ends(&haas, 11);
    // The Haas form cancels on N20; with G42 the mode N20 ends on the
    // offset and the return to A takes the vector off.
    assert_eq!(g70[..5], want[..5]);
}

#[test]
fn behaviour18_11_a_vector_before_the_cycle_is_taken_off_at_its_start() {
    // G42 starts up on line 3 (−Z); the cycle follows, so the block ends
    // perpendicular: centre (2, 30.8), nose (1.2, 30) — X60 Z1.2.
    let text = "T0101
G00 X60. Z5.
G42 G00 X60. Z2.
G71 U2. R0.5
G71 P10 Q20 U0. W0. F0.2
N10 G00 X20.
G01 Z-10.
N20 X60.
G00 Z5.
G40 G00 X70.
";
    let r = ok(text, &nose(0.8, 3, Control::Fanuc));
    near(ends(&r, 3)[0], [60.0, 1.2]);
    let g71 = ends(&r, 5);
    // The cycle first takes the vector off: to A (X60 Z2) at rapid.
    near(g71[0], [60.0, 2.0]);
    // A square shoulder: the Z leg (centre r 10.8) meets the face leg
    // (+X at Z−10, centre z −9.2) at (−9.2, 10.8): the nose (−10, 10), so
    // the passes end on Z−10 as programmed; the contour's end X60 ends
    // perpendicular: centre (−9.2, 30), nose X58.4 Z−10; back to A.
    assert!(g71.iter().all(|p| p[1] >= -10.0 - 1e-9));
    near(g71[g71.len() - 2], [58.4, -10.0]);
    near(g71[g71.len() - 1], [60.0, 2.0]);
    // G42 is still the mode: the next move starts up again (type A, the
    // G40 block next): the nose X58.4 Z5.
    near(ends(&r, 9)[0], [58.4, 5.0]);
    let after = r.blocks.iter().find(|b| b.span.line == 5).unwrap();
    assert!(after.explanation().contains("behaviour 18.11"));
}

#[test]
fn behaviour18_11_the_compensation_must_face_the_stock() {
    // The shaft's stock lies above the contour (A at X60) and the cut
    // travels −Z: left of the travel is −X, the part; G41 would put the
    // nose on the part's side (Fanuc PS0328).
    let text = SHAFT.replace("G42", "G41");
    let r = run(&text, &nose(0.8, 3, Control::Haas));
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.code, d.line), ("nose-side", 4));
    assert!(d.message.contains("wants G42"), "{}", d.message);
    // A bore: A at X10, the contour from X30 down to X20 going −Z; the
    // stock lies toward A, below the contour (−X), and left of −Z travel
    // is −X: G41 faces the stock, G42 the part.
    let bore = "T0101
G00 X10. Z2.
G71 U1. R0.5
G71 P10 Q20 U0. W0. F0.2
N10 G00 G41 X30.
G01 Z-10.
X20. Z-20.
N20 X10.
";
    ok(bore, &nose(0.4, 2, Control::Haas));
    let wrong = bore.replace("G41", "G42");
    assert_eq!(
        errors(&wrong, &nose(0.4, 2, Control::Haas)),
        vec!["nose-side"]
    );
}
