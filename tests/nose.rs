//! Behaviour 18 (`docs/behaviour.md`): tool nose radius compensation on the
//! lathe, G40/G41/G42 with the T code's nose radius R and tip direction.
//! The profiles are worked out by hand in the comments, in the plane's
//! coordinates (Z, X as a radius); the program and the reports write X as a
//! diameter. G42 is the tool right of the path seen with +X up and +Z to
//! the right (the Fanuc and Haas figures): above an outside profile cut
//! toward the chuck.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::{Run, Setup, run};

/// A lathe setup whose register `n` has nose radius `r` and tip `t` (and
/// X/Z geometry `x`, `z`).
fn nose(n: u16, x: f64, z: f64, r: f64, t: u8) -> Setup {
    let mut s = lathe(&[]);
    s.set_register(&format!("{n:02}=X{x},Z{z},R{r},T{t}"))
        .unwrap();
    s
}

/// The actual position at the end of the block on `line`.
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

/// The first error: code, line and column.
#[track_caller]
fn alarm(text: &str, setup: &Setup) -> (&'static str, u32, u32, String) {
    let r = run(text, setup);
    let d = r
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .unwrap_or_else(|| panic!("no error in {text}: {:#?}", r.diagnostics));
    (d.code, d.line, d.column, d.message.clone())
}

/// A face, a 45° taper, a diameter, a concave R10 arc and a diameter, cut
/// with G42 from the centre outward and toward the chuck (lines 1–9).
const PROFILE: &str = "T0101
G00 X0 Z1.
G42 G01 Z0 F0.1
X20.
X30. Z-5.
Z-15.
G02 X50. Z-25. R10.
G01 Z-35.
G40 G00 X60. Z5.
";

/// The nose centre at the end of lines 3–8 of [`PROFILE`] with R 0.5, as
/// (X diameter, Z): what tips 0 and 9 report, the other tips moved by
/// their vector.
///
/// - 3, start-up (type A): the next block faces along +X at Z0; right of
///   +X is +Z, so the centre goes to (Z 0.5, X 0).
/// - 4, face → taper: +X (90°) then (−1, +1) (135°) turns left, away from
///   the tool: an outside corner of 135°, the intersection of the offset
///   face z = 0.5 and the offset taper z + x = 10 + 0.5·√2 = 10.70711:
///   x = 10.20711, X 20.41421.
/// - 5, taper → diameter: the offset diameter x = 15.5 meets z + x =
///   10.70711 at z = −4.79289.
/// - 6, diameter → arc: the arc starts along −Z too (centre (−15, 25),
///   start at −90°): tangent, the centre ends 0.5 above (−15, 15.5).
/// - 7, arc → diameter: the arc ends along +X, the line goes −Z: a left
///   turn, outside, 90°; the offset arc (inside it, 10 − 0.5 = 9.5 about
///   (−15, 25)) meets x = 25.5 at z + 15 = −√(9.5² − 0.5²) = −√90 =
///   −9.48683: z = −24.48683.
/// - 8, before the cancel (type A): perpendicular to its end, (−35, 25.5).
const CENTRES: [(u32, f64, f64); 6] = [
    (3, 0.0, 0.5),
    (4, 20.414214, 0.5),
    (5, 31.0, -4.792893),
    (6, 31.0, -15.0),
    (7, 51.0, -24.486833),
    (8, 51.0, -35.0),
];

#[test]
fn behaviour18_1_g42_on_a_face_a_taper_and_an_arc_offsets_the_nose_centre_by_r() {
    // Tip 0: the program's points are the nose centre (18.2), so the actual
    // path is the centre's.
    let r = ok(PROFILE, &nose(1, 0.0, 0.0, 0.5, 0));
    for (line, x, z) in CENTRES {
        same(end(&r, line), [x, 0.0, z]);
    }
    // The cancel block ends on the programmed point.
    same(end(&r, 9), [60.0, 0.0, 5.0]);
    // The offset arc: about the programmed centre (X50 diameter, Z−15),
    // radius 9.5 in radius space.
    let arc = r.moves.iter().find(|m| m.line == 7).unwrap().arc.unwrap();
    same(arc.center, [50.0, 0.0, -15.0]);
    assert!((arc.radius - 9.5).abs() < 1e-9, "{}", arc.radius);
}

#[test]
fn behaviour18_2_each_tip_moves_the_path_by_its_imaginary_nose() {
    // Tip t reports the nose centre plus R times the tip's vector (Z, X
    // radius): 1 (+, +), 2 (−, +), 3 (−, −), 4 (+, −), 5 (+, 0), 6 (0, +),
    // 7 (−, 0), 8 (0, −), 0 and 9 none. In X (a diameter) that is twice.
    let v: [(f64, f64); 10] = [
        (0.0, 0.0),
        (1.0, 1.0),
        (-1.0, 1.0),
        (-1.0, -1.0),
        (1.0, -1.0),
        (1.0, 0.0),
        (0.0, 1.0),
        (-1.0, 0.0),
        (0.0, -1.0),
        (0.0, 0.0),
    ];
    for (t, (vz, vx)) in v.into_iter().enumerate() {
        let r = ok(PROFILE, &nose(1, 0.0, 0.0, 0.5, t as u8));
        for (line, x, z) in CENTRES {
            same(end(&r, line), [x + 2.0 * 0.5 * vx, 0.0, z + 0.5 * vz]);
        }
        // Before the start-up and after the cancel there is no vector.
        same(end(&r, 2), [0.0, 0.0, 1.0]);
        same(end(&r, 9), [60.0, 0.0, 5.0]);
    }
    // Tip 3, the outside turning tool: on the face (line 4) its imaginary
    // nose is at Z 0.5 − 0.5 = 0, on the face; on the diameter (line 6) at
    // X 31 − 1 = 30, on the diameter: the faces and diameters are cut on
    // the programmed line, the taper and arc by the nose circle.
    let r = ok(PROFILE, &nose(1, 0.0, 0.0, 0.5, 3));
    assert!((end(&r, 4)[2]).abs() < 1e-9);
    assert!((end(&r, 6)[0] - 30.0).abs() < 1e-9);
}

#[test]
fn behaviour18_1_x_is_a_diameter_and_the_t_offset_still_applies() {
    // Tip 0, R 0.4, the register's X 0.4 (diameter) and Z −0.2. A straight
    // turn at X40 toward the chuck with G42: the centre 0.4 above in
    // radius, X 40.8 as a diameter, plus the T offset: X 41.2, Z −20.2.
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-20.\nG40 G00 X50.\n";
    let r = ok(text, &nose(1, 0.4, -0.2, 0.4, 0));
    // Start-up: the next block goes −Z; its start offset 0.4 up: X 40.8,
    // Z 0, with the T offset X 41.2 Z −0.2.
    same(end(&r, 3), [41.2, 0.0, -0.2]);
    // Line 4 ends perpendicular to itself (the next block cancels, type A).
    same(end(&r, 4), [41.2, 0.0, -20.2]);
    // The cancel block lands on the programmed point plus the T offset.
    same(end(&r, 5), [50.4, 0.0, -20.2]);
}

#[test]
fn behaviour18_3_g41_is_left_of_the_path_the_boring_bar_below_the_bore() {
    // Boring toward the chuck at X20 (radius 10), G41: left of −Z is −X, so
    // the centre runs at radius 10 − 0.4 = 9.6; tip 2 (−Z, +X) puts the
    // imaginary nose back at radius 10: X 20, Z moved by −0.4.
    let text = "T0101\nG00 X20. Z2.\nG41 G01 Z0 F0.1\nZ-20.\nG40 G00 X15.\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.4, 2));
    same(end(&r, 3), [20.0, 0.0, -0.4]);
    same(end(&r, 4), [20.0, 0.0, -20.4]);
    // G42 on the same bore would put the centre outside it, in the wall:
    // radius 10.4, the imaginary nose at 10.8 (X 21.6).
    let r = ok(&text.replace("G41", "G42"), &nose(1, 0.0, 0.0, 0.4, 2));
    same(end(&r, 4), [21.6, 0.0, -20.4]);
}

#[test]
fn behaviour18_4_start_up_waits_for_a_move_and_cancel_ends_on_the_programmed_point() {
    // G42 alone sets the mode; the start-up is the next move (line 4).
    let text = "T0101\nG00 X40. Z2.\nG42\nG01 Z0 F0.1\nZ-20.\nG40 X50.\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.4, 3));
    let phase = |line| at_line(&r, text, line).cutter.unwrap().phase;
    assert_eq!(phase(3), "cancel");
    assert_eq!(phase(4), "start_up");
    assert_eq!(phase(5), "offset");
    assert_eq!(phase(6), "cancelling");
    same(end(&r, 3), [40.0, 0.0, 2.0]);
    // Line 4: the next block goes −Z at X40: the centre 0.4 above its start
    // (X 40.8, Z 0), tip 3 back by (−0.4, −0.4): X 40.0, Z −0.4.
    same(end(&r, 4), [40.0, 0.0, -0.4]);
    // The cancel (G01 G40 X50.) runs from there to the programmed point.
    same(end(&r, 6), [50.0, 0.0, -20.0]);
    let m = r.moves.iter().find(|m| m.line == 6).unwrap();
    same(m.from, [40.0, 0.0, -20.4]);
    // Offset 00 or a nose radius of 0: no compensation, with a sentence.
    let r = ok(text, &nose(1, 0.0, 0.0, 0.0, 3));
    same(end(&r, 5), [40.0, 0.0, -20.0]);
    assert!(
        explain(&r, 2).contains("nose radius is 0"),
        "{}",
        explain(&r, 2)
    );
}

#[test]
fn behaviour18_4_k_and_i_give_the_vector_of_a_start_up_and_the_exit_of_a_cancel() {
    // The KI-type vector (16.14 in G18), R0.8, tip 3, in radius (z, r):
    // G42 X40. Z0 K−1. I1. ends 0.8 right of (−1, 1)/√2, the centre at
    // (0.4√2, 20 + 0.4√2), the imaginary nose 0.8 back in both: X
    // 2·(19.2 + 0.4√2), Z 0.4√2 − 0.8 (the next block, −Z, would have put
    // it at X40. Z−0.8). G40 ... K1. I1. after Z−20.: that block ends where
    // r = 20.8 meets the offset of (1, 1)/√2 from (−20, 20), 0.8 to its
    // right, z − r = −40 + 0.8√2: the centre at z = −19.2 + 0.8√2, the
    // nose at Z −20 + 0.8√2, X40.
    let k = 0.4 * std::f64::consts::SQRT_2;
    let text =
        "T0101\nG00 X40. Z2.\nG42 G01 X40. Z0 K-1. I1. F0.2\nZ-20.\nG40 X60. Z-25. K1. I1.\nM30\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.8, 3));
    same(end(&r, 3), [2.0 * (19.2 + k), 0.0, k - 0.8]);
    same(end(&r, 4), [40.0, 0.0, -20.0 + 2.0 * k]);
    same(end(&r, 5), [60.0, 0.0, -25.0]);
}

#[test]
fn behaviour18_5_the_corners_are_the_mills_inside_outside_and_acute() {
    // Inside corner: Z−20. at X40 then up the face to X60 (G42, R 0.5,
    // tip 0): heading −Z then +X turns right, toward the tool: inside, the
    // offset lines x = 20.5 and z = −20 + 0.5 meet at (−19.5, 20.5).
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-20.\nX60.\nG40 G00 X70.\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.5, 0));
    same(end(&r, 4), [41.0, 0.0, -19.5]);
    assert!(
        explain(&r, 3).contains("inside corner"),
        "{}",
        explain(&r, 3)
    );
    // Acute outside corner: −Z along X40, then back toward +Z and down a
    // 30° flank (radius 20 − 5, Z −20 + 5·√3 = −11.33975): heading 180°
    // then −30°, a left turn of 150° away from the tool, the corner 30° —
    // the extra vectors: the first ends 0.5 past the corner along −Z at
    // radius 20.5, (−20.5, 20.5).
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-20.\nX30. Z-11.33975\nG40 G00 X70.\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.5, 0));
    let moves: Vec<_> = r.moves.iter().filter(|m| m.line == 4).collect();
    assert!(moves.len() >= 2, "{moves:#?}");
    same(moves[0].to, [41.0, 0.0, -20.5]);
    assert!(explain(&r, 3).contains("under 90°"), "{}", explain(&r, 3));
}

#[test]
fn behaviour18_6_an_interference_is_the_mills_alarm() {
    // A groove 0.6 wide (Z−10 to Z−10.6) and 2 deep in a diameter of 40,
    // the nose 0.5: the offset of its bottom runs backwards (PS0041).
    let text =
        "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-10.\nX36.\nZ-10.6\nX40.\nZ-20.\nG40 G00 X50.\n";
    let (code, line, _, _) = alarm(text, &nose(1, 0.0, 0.0, 0.5, 3));
    assert_eq!((code, line), ("cutter-interference", 6));
}

#[test]
fn behaviour18_7_a_cycle_in_the_g41_g42_block_itself_is_refused() {
    let s = nose(1, 0.0, 0.0, 0.4, 3);
    // G42 and G90 in one block: the cycle compensates from the mode in
    // force, so G42 goes in a block before (18.15).
    let text = "T0101\nG00 X42. Z2.\nG42 G90 X38. Z-20. F0.2\n";
    let (code, line, _, msg) = alarm(text, &s);
    assert_eq!((code, line), ("nose-in-cycle", 3));
    assert!(msg.contains("G90 with G42"), "{msg}");
    // G42 before the cycle: it runs compensated.
    ok(
        "T0101\nG00 X42. Z2.\nG42\nG90 X38. Z-20. F0.2\nG40 G00 X50.\n",
        &s,
    );
}

#[test]
fn behaviour18_8_g74_to_g76_in_compensation_are_refused() {
    let s = nose(1, 0.0, 0.0, 0.4, 3);
    let text = "T0101\nG00 X42. Z2.\nG42\nG75 R0.5\nG75 X30. Z-10. P1000 Q2000 F0.1\n";
    assert_eq!(alarm(text, &s).0, "nose-in-cycle");
    // G70 while G42 is the mode now compensates its contour (18.12).
    let text = "T0101\nG00 X42. Z2.\nG42\nG70 P10 Q20\nN10 G00 X20.\nG01 Z-20.\nN20 X42.\nG40\n";
    ok(text, &s);
}

#[test]
fn behaviour18_9_a_new_offset_number_for_the_tool_ends_its_block_on_the_new_nose() {
    // Offset 01 R0.8 and 02 R0.4, both tip 3 at zero geometry. Z−10. ends
    // 0.8 above its end (the next block goes on along −Z): X40. Z−10.8.
    // T0102 Z−20. (16.8: the block's corner with the new radius on both
    // sides) meets X60.'s offset at the inside corner: the centre at
    // (z −19.6, r 20.4), the imaginary nose 0.4 back in both: X40. Z−20.
    // X60. then ends 0.4 right of its end before the cancel: X59.2 Z−20.
    let mut s = nose(1, 0.0, 0.0, 0.8, 3);
    s.set_register("02=X0,Z0,R0.4,T3").unwrap();
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.2\nZ-10.\nT0102 Z-20.\nX60.\nG40 X70.\nM30\n";
    let r = ok(text, &s);
    same(end(&r, 4), [40.0, 0.0, -10.8]);
    same(end(&r, 5), [40.0, 0.0, -20.0]);
    same(end(&r, 6), [59.2, 0.0, -20.0]);
    assert!(
        explain(&r, 4).contains("the radius changed from 0.800 to 0.400"),
        "{}",
        explain(&r, 4)
    );
}

#[test]
fn behaviour18_9_what_the_mode_refuses() {
    let s = nose(1, 0.0, 0.0, 0.4, 3);
    // Another tool in compensation.
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-20. T0202\n";
    let (code, line, column, _) = alarm(text, &s);
    assert_eq!((code, line, column), ("nose-t-change", 4, 7));
    // Another plane than ZX (G17 is polar interpolation's face plane).
    let (code, line, _, _) = alarm("G17\nT0101\nG42 G01 X10. Z0 F0.1\n", &s);
    assert_eq!((code, line), ("nose-plane", 3));
    // Start-up in an arc (Fanuc PS0034).
    let text = "T0101\nG00 X40. Z2.\nG42 G02 X50. Z-3. R5. F0.1\n";
    assert_eq!(alarm(text, &s).0, "cutter-arc");
}

#[test]
fn behaviour18_10_every_block_reports_r_tip_mode_and_vector() {
    let text = "T0101\nG00 X40. Z2.\nG42 G01 Z0 F0.1\nZ-20.\nG40 G00 X50.\n";
    let r = ok(text, &nose(1, 0.0, 0.0, 0.4, 3));
    let v = at_line(&r, text, 4);
    let c = v.cutter.unwrap();
    assert_eq!((c.mode, c.d, c.tip, c.phase), ("G42", 1, Some(3), "offset"));
    assert!((c.radius - 0.4).abs() < 1e-12);
    // Line 4 ends perpendicular (the cancel follows, type A): centre 0.4
    // above, tip 3 back by (−0.4, −0.4): X +0.8 − 0.8 = 0, Z −0.4.
    assert!(c.vector.x.abs() < 1e-9 && (c.vector.z + 0.4).abs() < 1e-9);
    assert_eq!(v.modal.cutter, Some("G42"));
    let start = explain(&r, 2);
    assert!(
        start.contains("G42 offset 01 (nose R 0.400 right, tip 3) start-up (type A)"),
        "{start}"
    );
    assert!(start.contains("the imaginary tool nose (tip 3)"), "{start}");
    let cancel = explain(&r, 4);
    assert!(cancel.contains("G40 cancel"), "{cancel}");
}

#[test]
fn behaviour18_11_the_nose_fixture_turns_a_profile_and_bores_with_two_tools() {
    // tests/data/nose.nc: offset 01 X0.4 Z−0.2 R0.8 tip 3, offset 02 X−0.3
    // Z0.15 R0.4 tip 2 (also run by tests/rerun.rs and tests/checkpoints.rs).
    let (text, setup) = fixture("nose");
    let r = ok(&text, &setup);
    // N20 (line 5), start-up: the face N25 goes +X at Z0, the centre 0.8 to
    // its right (+Z): (Z 0.8, X 0); tip 3 moves it by (−0.8, −0.8): Z 0,
    // X −1.6 as a diameter; the T offset adds X 0.4, Z −0.2.
    same(end(&r, 5), [-1.2, 0.0, -0.2]);
    // N35 (line 8) ends tangent to the arc N40: the centre 0.8 above
    // (Z −20, X radius 20.8), tip 3: (Z −20.8, X radius 20), + T: X 40.4,
    // Z −21.
    same(end(&r, 8), [40.4, 0.0, -21.0]);
    // N70 (line 15), the bore at X20 then in to X16 at Z−20 (G41, tip 2):
    // heading −Z then (−5, −2): a left turn toward the tool, inside; the
    // offset line x = 10 − 0.4 = 9.6 meets the taper's offset line. The
    // taper from (−15, 10) to (−20, 8), direction (−5, −2)/√29, left
    // normal (2, −5)/√29: points with (z + 15)·2 − (x − 10)·5 = 0.4·√29 =
    // 2.154066; at x = 9.6: 2z + 30 + 2 = 2.154066, z = −14.922967. Tip 2
    // moves by (−0.4, +0.4): Z −15.322967, X radius 10, + T: X 19.7,
    // Z −15.172967.
    same(end(&r, 15), [19.7, 0.0, -15.172967]);
    assert!(explain(&r, 13).contains("tip 2"), "{}", explain(&r, 13));
}
