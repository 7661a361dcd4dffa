//! Behaviour 2.30–2.34 (`docs/behaviour.md`): chamfer `,C` and corner
//! rounding `,R` at the end of a G01 block on the mill, cut between its move
//! and the next block's (Fanuc 0i-MF "optional angle chamfering and corner
//! R"; alarms PS0051, PS0052, PS0055).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::Mirror;
use offsetlab::{MoveKind, Setup, run};

fn error_of(text: &str, setup: &Setup) -> (String, String) {
    let r = run(text, setup);
    let d = r
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .unwrap_or_else(|| panic!("no error in {text}: {:#?}", r.diagnostics));
    (d.code.to_string(), d.message.clone())
}

#[test]
fn behaviour2_30_a_chamfer_cuts_the_corner_between_two_g01_moves() {
    // The fixture's N50 X60. ,C5. then N60 Y40.: the corner is (60, 0); the
    // chamfer starts 5 before it on the first move, (55, 0), and ends 5
    // along the second, (60, 5). H01 = 10 keeps the actual path 10 above.
    let (text, setup) = fixture("corners");
    let r = ok(&text, &setup);
    let on = |line: u32| -> Vec<_> { r.moves.iter().filter(|m| m.line == line).collect() };
    let n50 = on(8);
    assert_eq!(n50.len(), 2);
    same(n50[0].programmed_from, [0.0, 0.0, -2.0]);
    same(n50[0].programmed_to, [55.0, 0.0, -2.0]);
    assert_eq!(n50[1].kind, MoveKind::Feed);
    same(n50[1].programmed_from, [55.0, 0.0, -2.0]);
    same(n50[1].programmed_to, [60.0, 5.0, -2.0]);
    same(n50[1].to, [60.0, 5.0, 8.0]);
    // The block ends where the chamfer does; the next move starts there.
    same(programmed(&r, 5), [60.0, 5.0, -2.0]);
    same(on(9)[0].programmed_from, [60.0, 5.0, -2.0]);
    assert!(explain(&r, 5).contains("a chamfer from X55.000 Y0.000 to X60.000 Y5.000"));
}

#[test]
fn behaviour2_30_a_corner_round_is_an_arc_tangent_to_both_moves() {
    // N60 Y40. ,R8. then N70 X0: the path turns left by 90° at (60, 40);
    // the tangent length is 8·tan(45°) = 8, so the arc runs from (60, 32)
    // to (52, 40) about (52, 32), counter-clockwise.
    let (text, setup) = fixture("corners");
    let r = ok(&text, &setup);
    let n60: Vec<_> = r.moves.iter().filter(|m| m.line == 9).collect();
    assert_eq!(n60.len(), 2);
    same(n60[0].programmed_to, [60.0, 32.0, -2.0]);
    assert_eq!(n60[1].kind, MoveKind::ArcCcw);
    let arc = n60[1].arc.unwrap();
    same(arc.programmed_center, [52.0, 32.0, -2.0]);
    assert!((arc.programmed_radius - 8.0).abs() < 1e-9);
    assert!((arc.programmed_sweep - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    same(n60[1].programmed_to, [52.0, 40.0, -2.0]);
}

#[test]
fn behaviour2_30_a_round_at_a_45_degree_turn() {
    // X50. then X100. Y50.: the path turns left by 45° at (50, 0); the
    // tangent length is 5·tan(22.5°) = 2.071068; the arc runs from
    // (47.928932, 0) to (50 + 2.071068·cos 45°, 2.071068·sin 45°) =
    // (51.464466, 1.464466) about (47.928932, 5).
    let r = ok("G01 X50. ,R5. F100.\nX100. Y50.", &Setup::default());
    let d = 5.0 * (std::f64::consts::PI / 8.0).tan();
    same(r.moves[0].programmed_to, [50.0 - d, 0.0, 0.0]);
    let arc = r.moves[1].arc.unwrap();
    same(arc.programmed_center, [50.0 - d, 5.0, 0.0]);
    let h = d * std::f64::consts::FRAC_1_SQRT_2;
    same(r.moves[1].programmed_to, [50.0 + h, h, 0.0]);
    same(r.moves[2].programmed_from, [50.0 + h, h, 0.0]);
    same(r.moves[2].programmed_to, [100.0, 50.0, 0.0]);
}

#[test]
fn behaviour2_30_a_right_turn_rounds_clockwise() {
    // X50. then Y-30.: a right turn at (50, 0); the arc about (45, -5) runs
    // from (45, 0) to (50, -5) clockwise.
    let r = ok("G01 X50. ,R5. F100.\nY-30.", &Setup::default());
    assert_eq!(r.moves[1].kind, MoveKind::ArcCw);
    same(r.moves[1].arc.unwrap().programmed_center, [45.0, -5.0, 0.0]);
    same(r.moves[1].programmed_to, [50.0, -5.0, 0.0]);
}

#[test]
fn behaviour2_32_the_next_block_counts_its_words_from_the_corner() {
    // The fixture's N80 G91 Y-20. ,R6. after the chamfer of N70 at (0, 40):
    // Y-20 from the corner, not from the chamfer's end (0, 36), is (0, 20);
    // N90 X20. likewise from (0, 20) is (20, 20).
    let (text, setup) = fixture("corners");
    let r = ok(&text, &setup);
    let n80: Vec<_> = r.moves.iter().filter(|m| m.line == 11).collect();
    same(n80[0].programmed_from, [0.0, 36.0, -2.0]);
    same(n80[0].programmed_to, [0.0, 26.0, -2.0]);
    same(n80[1].arc.unwrap().programmed_center, [6.0, 26.0, -2.0]);
    let n90 = r.moves.iter().find(|m| m.line == 12).unwrap();
    same(n90.programmed_from, [6.0, 20.0, -2.0]);
    same(n90.programmed_to, [20.0, 20.0, -2.0]);
}

#[test]
fn behaviour2_31_the_next_move_must_be_a_feed_move_in_the_plane() {
    let s = Setup::default();
    let (code, msg) = error_of("G01 X50. ,C5. F100.", &s);
    assert_eq!(code, "corner-next-move");
    assert!(
        msg.contains("program ends") && msg.contains("PS0051"),
        "{msg}"
    );
    let (code, msg) = error_of("G01 X50. ,C5. F100.\nM08\nY40.", &s);
    assert_eq!(code, "corner-next-move");
    assert!(msg.contains("line 2") && msg.contains("PS0051"), "{msg}");
    let (code, msg) = error_of("G01 X50. ,C5. F100.\nG00 Y40.", &s);
    assert_eq!(code, "corner-next-move");
    assert!(msg.contains("PS0052"), "{msg}");
    let (code, msg) = error_of("G01 X50. ,C5. F100.\nZ-5.", &s);
    assert_eq!(code, "corner-next-move");
    assert!(msg.contains("G17 plane"), "{msg}");
    // An arc next (behaviour 2.36) that leaves the corner tangentially.
    let (code, msg) = error_of("G01 X50. ,C5. F100.\nG03 X60. Y10. R10.", &s);
    assert_eq!(code, "corner-angle");
    assert!(msg.contains("tangentially"), "{msg}");
    let (code, _) = error_of("G01 X50. ,R5. F100.\nX80.", &s);
    assert_eq!(code, "corner-angle");
    // Nothing moves past the block before the one refused.
    let r = run("G01 X10. F100.\nX50. ,C5.\nG00 Y40.", &s);
    assert_eq!(r.moves.len(), 1);
}

#[test]
fn behaviour2_31_the_next_block_is_the_next_one_that_runs() {
    // With the block skip switch on, /X100. does not run: the chamfer is cut
    // towards Y40.; with it off X100. is the next move, along the same line.
    let text = "G01 X50. ,C5. F100.\n/X100.\nY40.";
    let mut s = Setup::default();
    s.settings.block_skip = true;
    let r = ok(text, &s);
    same(r.moves[1].programmed_to, [50.0, 5.0, 0.0]);
    assert_eq!(error_of(text, &Setup::default()).0, "corner-angle");
}

#[test]
fn behaviour2_33_the_corner_words_are_refused_where_no_corner_is_cut() {
    let s = Setup::default();
    let cases = [
        (
            "G01 X50. ,C5. ,R2. F100.\nY40.",
            "corner-words",
            "either chamfered or rounded",
        ),
        (
            "G00 X50. ,C5.\nG01 Y40. F100.",
            "corner-motion",
            "not in G00",
        ),
        ("G01 X50. ,C0 F100.\nY40.", "corner-words", "positive"),
        (
            "G91 G01 G45 X50. ,C5. D01 F100.\nY40.",
            "corner-words",
            "G45",
        ),
        ("G01 X50. Z-5. ,C5. F100.\nY40.", "corner-move", "G17"),
        ("G01 X4. ,C5. F100.\nY40.", "corner-too-long", "PS0055"),
        ("G01 X50. ,C5. F100.\nY4.", "corner-too-long", "line 2"),
        // A half circle that ends going down, then up: no corner (2.36).
        (
            "G02 X50. R25. ,C5. F100.\nG01 Y40.",
            "corner-angle",
            "backwards",
        ),
    ];
    for (text, code, says) in cases {
        let (got, msg) = error_of(text, &s);
        assert_eq!(got, code, "{text}: {msg}");
        assert!(msg.contains(says), "{text}: {msg}");
    }
    // The lathe cuts them too (2.35), with the same refusals.
    let (code, _) = error_of("G01 U10. ,C1. ,R1. F0.1\nW-10.", &lathe(&[]));
    assert_eq!(code, "corner-words");
}

#[test]
fn behaviour2_34_the_corner_follows_mirror_image_and_the_offsets() {
    // Mirror X about the start: X60. goes to X-60; the chamfer runs from
    // (-55, 0) to (-60, 5). G43 H01 = 10 lifts both ends by 10.
    let mut s = mill(&[(1, 10.0)]);
    s.settings.mirror = Mirror { x: true, y: false };
    let r = ok("G43 Z0 H01\nG01 X60. ,C5. F100.\nY40.", &s);
    let m = &r.moves[2];
    same(m.programmed_from, [-55.0, 0.0, 0.0]);
    same(m.programmed_to, [-60.0, 5.0, 0.0]);
    same(m.to, [-60.0, 5.0, 10.0]);
}

#[test]
fn behaviour2_30_inch_words_are_inches() {
    // G20: ,C0.2 is 5.08 mm along each move.
    let r = ok("G20 G01 X2. ,C0.2 F10.\nY2.", &Setup::default());
    same(r.moves[0].programmed_to, [(2.0 - 0.2) * 25.4, 0.0, 0.0]);
    same(r.moves[1].programmed_to, [50.8, 5.08, 0.0]);
}

// ----- 2.35 the lathe ----------------------------------------------------

/// A lathe with offset 01 at zero, and with a nose of R0.8, tip 3.
fn lathe_setup(nose: bool) -> Setup {
    let mut s = lathe(&[(1, 0.0, 0.0)]);
    if nose {
        s.set_register("01=R0.8,T3").unwrap();
    }
    s
}

/// A face up to X50. with `face`'s word, then Z−20. with `turn`'s, then up
/// to X60.
fn lathe_profile(face: &str, turn: &str, code: &str) -> String {
    format!("T0101\nG00 X40. Z2.\n{code}G01 Z0 F0.2\nX50. {face}\nZ-20. {turn}\nG40 X60.\nM30\n")
}

/// The moves of line `line` as (kind, X, Z of the actual end).
fn ends(r: &offsetlab::Run, line: u32) -> Vec<(MoveKind, [f64; 3])> {
    r.moves
        .iter()
        .filter(|m| m.line == line)
        .map(|m| (m.kind, m.to))
        .collect()
}

#[test]
fn behaviour2_35_the_lathe_cuts_a_chamfer_and_a_corner_r_in_radius() {
    // ,C1. at (X50 Z0): 1 on the part along each move, so the chamfer runs
    // from X48. (radius 24) to Z−1. on X50. ,R2. at (X50 Z−20), the turn
    // from −Z to +X: from Z−18. to X54. (radius 25 + 2), about X54. Z−18.,
    // clockwise in the ZX view.
    let r = ok(&lathe_profile(",C1.", ",R2.", ""), &lathe_setup(false));
    let face = ends(&r, 4);
    assert_eq!(face.len(), 2);
    same(face[0].1, [48.0, 0.0, 0.0]);
    same(face[1].1, [50.0, 0.0, -1.0]);
    let turn = ends(&r, 5);
    same(turn[0].1, [50.0, 0.0, -18.0]);
    assert_eq!(turn[1].0, MoveKind::ArcCw);
    same(turn[1].1, [54.0, 0.0, -20.0]);
    let arc = r
        .moves
        .iter()
        .filter(|m| m.line == 5)
        .nth(1)
        .unwrap()
        .arc
        .unwrap();
    same(arc.center, [54.0, 0.0, -18.0]);
    assert!((arc.radius - 2.0).abs() < 1e-9, "{arc:?}");
    // The next block starts at the round's end.
    same(
        r.moves.iter().find(|m| m.line == 6).unwrap().from,
        [54.0, 0.0, -20.0],
    );
}

#[test]
fn behaviour2_35_with_nose_radius_compensation_the_cut_path_is_compensated() {
    // G42, R0.8, tip 3 (behaviour 16.19, 18.5). In radius space (z, r),
    // k = 0.8√2: the face's offset line is z = 0.8; the chamfer from
    // (0, 24) to (−1, 25), its offset 0.8 to its right, z + r = 24 + k;
    // the diameter's, r = 25.8. The nose centre stops at (0.8, 23.2 + k)
    // (a 135° outside corner: the intersection) and at (k − 1.8, 25.8);
    // the imaginary nose (tip 3) is 0.8 less in both: X = 2·(22.4 + k) at
    // Z0, then X50. at Z = k − 2.6.
    let k = 0.8 * std::f64::consts::SQRT_2;
    let r = ok(&lathe_profile(",C1.", "", "G42 "), &lathe_setup(true));
    let face = ends(&r, 4);
    assert_eq!(face.len(), 2, "{face:?}");
    same(face[0].1, [2.0 * (22.4 + k), 0.0, 0.0]);
    same(face[1].1, [50.0, 0.0, k - 2.6]);
}

#[test]
fn behaviour2_35_not_in_a_g70_to_g73_contour() {
    let text = "T0101\nG00 X60. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X40.\nG01 Z0\nX50. ,C1.\nN20 Z-20.\nG70 P10 Q20\nM30\n";
    let r = run(text, &lathe_setup(false));
    let (code, line, _) = first_error(&r);
    assert_eq!((code, line), ("unsupported-word", 7));
}

// ----- 2.36 at an arc ----------------------------------------------------

/// Along +X to the corner (20, 0); then G02 X40. Y0 R10., a half circle
/// about (30, 0) that leaves the corner going up (+Y), ending at (40, 0)
/// going down; then +X.
const LINE_ARC: &str =
    "G90 G17\nG00 X-10. Y0\nG01 X0 Y0 F100.\nX20. ,R2.\nG02 X40. Y0 R10. ,C2.\nG01 X60.\nM30\n";

#[test]
fn behaviour2_36_a_round_between_a_line_and_an_arc_is_tangent_to_both() {
    // The path turns left at (20, 0). ,R2.: the round's centre is 2 left
    // of the line (y = 2) and 2 outside the arc's circle (12 from
    // (30, 0)): Q = (30 − √140, 2); it touches the line at (30 − √140, 0)
    // and the arc at (30, 0) + 10·(Q − (30, 0))/12.
    let r = ok(LINE_ARC, &Setup::default());
    let s = 140f64.sqrt();
    let m: Vec<_> = r.moves.iter().filter(|m| m.line == 4).collect();
    assert_eq!(m.len(), 2);
    same(m[0].to, [30.0 - s, 0.0, 0.0]);
    assert_eq!(m[1].kind, MoveKind::ArcCcw);
    let arc = m[1].arc.unwrap();
    same(arc.center, [30.0 - s, 2.0, 0.0]);
    same(m[1].to, [30.0 - s * 10.0 / 12.0, 2.0 * 10.0 / 12.0, 0.0]);
    // The arc block runs on from there on its own circle.
    let g02 = r.moves.iter().find(|m| m.line == 5).unwrap();
    same(g02.from, m[1].to);
    same(g02.arc.unwrap().center, [30.0, 0.0, 0.0]);
}

#[test]
fn behaviour2_36_a_chamfer_at_an_arcs_end_is_a_chord_from_the_corner() {
    // The half circle ends at (40, 0) going down; +X next: a left turn.
    // ,C2.: the point of the circle 2 in a straight line from (40, 0),
    // back along it, the angle a = 2·asin(0.1) from it about (30, 0):
    // (30 + 10 cos a, 10 sin a); on the line, (42, 0). The arc is cut
    // short there (its sweep from its start, the round's end, shrinks).
    let r = ok(LINE_ARC, &Setup::default());
    let a = 2.0 * 0.1f64.asin();
    let m: Vec<_> = r.moves.iter().filter(|m| m.line == 5).collect();
    assert_eq!(m.len(), 2);
    same(m[0].to, [30.0 + 10.0 * a.cos(), 10.0 * a.sin(), 0.0]);
    same(m[1].to, [42.0, 0.0, 0.0]);
    let arc = m[0].arc.unwrap();
    let start = (m[0].from[1] - 0.0).atan2(m[0].from[0] - 30.0);
    let sweep = (10.0 * a.sin()).atan2(10.0 * a.cos()) - start;
    assert!((arc.sweep - sweep).abs() < 1e-9, "{} vs {sweep}", arc.sweep);
    assert!((arc.programmed_sweep - sweep).abs() < 1e-9);
}

#[test]
fn behaviour2_36_with_cutter_compensation_the_round_at_an_arc_is_offset() {
    // G42, D5 (behaviour 16.19): the tool is right of the path, outside
    // the round. The line's move ends 5 right of its tangent point, at
    // (30 − √140, −5); the round, about Q with radius 2 + 5, ends where
    // the arc's offset circle (radius 10 − 5) begins:
    // Q + 7·(√140, −2)/12 = (30 − 5√140/12, 5/6).
    let text = LINE_ARC
        .replace("G01 X0 Y0 F100.", "G01 G42 D01 X0 Y0 F100.")
        .replace("M30", "G40 X80.\nM30");
    let r = ok(&text, &mill(&[(1, 5.0)]));
    let s = 140f64.sqrt();
    let m: Vec<_> = r.moves.iter().filter(|m| m.line == 4).collect();
    assert_eq!(m.len(), 2, "{m:?}");
    same(m[0].to, [30.0 - s, -5.0, 0.0]);
    same(m[1].to, [30.0 - 5.0 * s / 12.0, 5.0 / 6.0, 0.0]);
    assert!((m[1].arc.unwrap().radius - 7.0).abs() < 1e-9);
}

#[test]
fn behaviour2_36_tangent_paths_have_no_corner() {
    // G03 X70. Y10. R10. from (60, 0) ends going up (+Y); Y30. goes on
    // tangentially: no corner to round.
    let text = "G01 X60. Y0 F100.\nG03 X70. Y10. R10. ,R3.\nG01 Y30.\n";
    let (code, msg) = error_of(text, &Setup::default());
    assert_eq!(code, "corner-angle", "{msg}");
}

#[test]
fn behaviour2_36_the_lathe_chamfers_an_arc_in_radius() {
    // Up the face to the corner (X50 Z0), then G02 to X60. Z−5. R5.: the
    // chamfer's ends are 1 (on the part, X as a radius) in a straight line
    // from the corner.
    let text = "T0101\nG00 X40. Z2.\nG01 Z0 F0.2\nX50. ,C1.\nG02 X60. Z-5. R5.\nG01 Z-20.\nM30\n";
    let r = ok(text, &lathe(&[(1, 0.0, 0.0)]));
    let m: Vec<_> = r.moves.iter().filter(|m| m.line == 4).collect();
    assert_eq!(m.len(), 2, "{m:?}");
    let on_part = |p: [f64; 3]| ((p[0] / 2.0 - 25.0).hypot(p[2])).abs();
    assert!((on_part(m[1].from) - 1.0).abs() < 1e-9, "{:?}", m[1].from);
    assert!((on_part(m[1].to) - 1.0).abs() < 1e-9, "{:?}", m[1].to);
    same(m[1].from, [48.0, 0.0, 0.0]);
    let arc = r.moves.iter().find(|m| m.line == 5).unwrap();
    same(arc.from, m[1].to);
}
