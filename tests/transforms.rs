//! Behaviour 13.7–13.14 (`docs/behaviour.md`): the mill's programmable
//! transformations — mirror image G51.1, scaling G51, rotation G68 — and
//! polar coordinates G16, G90.1/G91.1 and the rotary axes: where each sends
//! a move and an arc, what they do to G43 and G45–G48, the codes they
//! forbid. Positions are worked out by hand in the comments.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::RotationAngle;
use offsetlab::{MoveKind, run};

const R3: f64 = 1.732_050_807_568_877_2; // √3

fn arc(r: &offsetlab::Run, i: usize) -> offsetlab::machine::ArcInfo {
    r.moves[i].arc.expect("an arc move")
}

// ----- 13.7 the order of the transformations -------------------------------------

#[test]
fn behaviour13_7_mirror_then_scaling_then_rotation() {
    let text = "G17 G90 G00 X0 Y0\nG51.1 X10.\nG51 X0 Y0 P2000\nG68 X0 Y0 R90.\nG01 X12. Y1. F100.";
    let r = ok(text, &mill(&[]));
    // Mirror X about 10: (12, 1) → (8, 1). The scaling centre, written
    // (0, 0), is mirrored too: (20, 0); ×2 about it: (20 + 2·(8 − 20),
    // 2·1) = (−4, 2). The rotation centre goes through both: (20, 0);
    // 90° about it: (20 − 2, 0 + (−4 − 20)) = (18, −24).
    same(programmed(&r, 4), [18.0, -24.0, 0.0]);
    // The drawn (programmed) path is the transformed one.
    let m = r.moves.last().unwrap();
    same(m.programmed_to, [18.0, -24.0, 0.0]);
    assert!(explain(&r, 4).contains("G51.1, G51, G68: X12.000 Y1.000 goes to X18.000 Y-24.000"));
}

#[test]
fn behaviour13_7_offsets_are_added_after_the_transformations() {
    // H01 = 100, D02 = 3. Scaling ×2 about the origin.
    let s = mill(&[(1, 100.0), (2, 3.0)]);
    let text = "G51 X0 Y0 Z0 P2000\nG43 Z5. H01\nG91 G01 G45 X10. D02 F100.";
    let r = ok(text, &s);
    // Z5 scaled is 10; the length offset is not scaled: 10 + 100.
    same(programmed(&r, 1), [0.0, 0.0, 10.0]);
    same(actual(&r, 1), [0.0, 0.0, 110.0]);
    // G91 X10 is a movement of 20 once scaled; G45 extends it by D02 = 3,
    // not by 6: the tool travels 23.
    same(programmed(&r, 2), [20.0, 0.0, 10.0]);
    same(actual(&r, 2), [23.0, 0.0, 110.0]);
}

#[test]
fn behaviour13_7_canned_cycle_holes_are_transformed_not_their_levels() {
    let text = "G90 G00 X0 Y0 Z10.\nG68 X0 Y0 R90.\nG81 X10. Y0 Z-5. R2. F100.\nG80";
    let r = ok(text, &mill(&[]));
    // The hole (10, 0) turns to (0, 10); the levels stay: R2, Z-5, back
    // to the initial 10 (G98).
    let rapid = r.moves.iter().find(|m| m.block == 2).unwrap();
    same(rapid.programmed_to, [0.0, 10.0, 10.0]);
    let bottom = r
        .moves
        .iter()
        .find(|m| m.block == 2 && m.kind == MoveKind::Feed)
        .unwrap();
    same(bottom.programmed_to, [0.0, 10.0, -5.0]);
    same(programmed(&r, 2), [0.0, 10.0, 10.0]);
}

// ----- 13.8 G50.1/G51.1 ------------------------------------------------------------

#[test]
fn behaviour13_8_g51_1_mirrors_moves_and_turns_arcs() {
    let text =
        "G17 G90 G00 X0 Y0\nG51.1 X50.\nG01 X10. Y0 F100.\nG02 X20. Y10. R10.\nG50.1 X0\nG00 X0";
    let r = ok(text, &mill(&[]));
    // X10 mirrored about X50 is X90.
    same(programmed(&r, 2), [90.0, 0.0, 0.0]);
    // G02 from (10, 0) to (20, 10), R10, turns clockwise about (20, 0);
    // mirrored: from (90, 0) to (80, 10) about (80, 0), counter-clockwise.
    same(programmed(&r, 3), [80.0, 10.0, 0.0]);
    let a = arc(&r, 1);
    assert_eq!(r.moves[1].kind, MoveKind::ArcCcw);
    same(a.programmed_center, [80.0, 0.0, 0.0]);
    assert!((a.sweep - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    // G50.1 X0 cancels: X0 is X0.
    same(programmed(&r, 5), [0.0, 10.0, 0.0]);
    assert_eq!(errors("G51.1", &mill(&[])), vec!["mirror-without-axis"]);
}

#[test]
fn behaviour13_8_g45_follows_the_mirrored_movement() {
    // D01 = 5. G91 X0 with G45 is a movement of +5 (behaviour 4.4);
    // mirrored in X it goes −5.
    let s = mill(&[(1, 5.0)]);
    let r = ok("G51.1 X0\nG91 G01 G45 X0 D01 F100.", &s);
    same(actual(&r, 1), [-5.0, 0.0, 0.0]);
    let r = ok("G91 G01 G45 X0 D01 F100.", &s);
    same(actual(&r, 0), [5.0, 0.0, 0.0]);
}

// ----- 13.9 G50/G51 ----------------------------------------------------------------

#[test]
fn behaviour13_9_g51_scales_about_its_centre() {
    let r = ok(
        "G90 G00 X0 Y0\nG51 X10. Y10. P2000\nG01 X20. Y10. F100.\nG50\nG00 X0",
        &mill(&[]),
    );
    // ×2 about (10, 10): (20, 10) → (10 + 2·10, 10) = (30, 10).
    same(programmed(&r, 2), [30.0, 10.0, 0.0]);
    same(programmed(&r, 4), [0.0, 10.0, 0.0]);
    // I and J scale each axis; without a point they are thousandths.
    let r = ok("G51 X0 Y0 I2000 J1000\nG01 X10. Y10. F100.", &mill(&[]));
    same(programmed(&r, 1), [20.0, 10.0, 0.0]);
    let r = ok("G51 X0 Y0 I2. J0.5\nG01 X10. Y10. F100.", &mill(&[]));
    same(programmed(&r, 1), [20.0, 5.0, 0.0]);
    // In inches too: I2000 is ×2, not 0.2.
    let r = ok("G20\nG51 X0 Y0 I2000\nG01 X1. F10.", &mill(&[]));
    same(programmed(&r, 2), [50.8, 0.0, 0.0]);
    assert_eq!(errors("G51 X0 Y0", &mill(&[])), vec!["scaling-factor"]);
    assert_eq!(errors("G51 X0 Y0 P0", &mill(&[])), vec!["scaling-factor"]);
    assert_eq!(errors("G51 P2000 I2.", &mill(&[])), vec!["scaling-factor"]);
}

#[test]
fn behaviour13_9_scaled_arcs_and_negative_factors() {
    // ×2: the R5 half circle from (0, 0) to (10, 0) becomes R10 from
    // (0, 0) to (20, 0), centre (10, 0).
    let r = ok("G51 X0 Y0 P2000\nG02 X10. Y0 R5. F100.", &mill(&[]));
    let a = arc(&r, 0);
    assert!((a.programmed_radius - 10.0).abs() < 1e-9);
    same(a.programmed_center, [10.0, 0.0, 0.0]);
    // I−1: X mirrored, so G02 turns counter-clockwise: from (0, 0) to
    // (−10, 0) about (−5, 0).
    let r = ok("G51 X0 Y0 I-1. J1.\nG02 X10. Y0 I5. J0 F100.", &mill(&[]));
    assert_eq!(r.moves[0].kind, MoveKind::ArcCcw);
    same(arc(&r, 0).programmed_center, [-5.0, 0.0, 0.0]);
    same(programmed(&r, 1), [-10.0, 0.0, 0.0]);
    // Different factors: R takes the larger (Fanuc), ×2 on X, ×1 on Y: the
    // quarter R10 from (0, 10) to (10, 0) goes from (0, 10) to (20, 0)
    // with R20 — an arc whose centre is 20 from both ends.
    let r = ok(
        "G00 X0 Y10.\nG51 X0 Y0 I2. J1.\nG02 X10. Y0 R10. F100.",
        &mill(&[]),
    );
    assert!((arc(&r, 1).programmed_radius - 20.0).abs() < 1e-9);
}

// ----- 13.10 G68/G69 ---------------------------------------------------------------

#[test]
fn behaviour13_10_g68_rotates_about_its_centre() {
    let text = "G17 G90 G00 X0 Y0\nG68 X10. Y10. R30.\nG01 X20. Y10. F100.\nG69\nG00 X0 Y0";
    let r = ok(text, &mill(&[]));
    // 30° about (10, 10): (20, 10) → (10 + 10 cos 30°, 10 + 10 sin 30°)
    // = (18.660254, 15).
    same(programmed(&r, 2), [10.0 + 5.0 * R3, 15.0, 0.0]);
    let b = at_line(&r, text, 3);
    assert_eq!((b.programmed.x, b.programmed.y), (18.660254, Some(15.0)));
    same(programmed(&r, 4), [0.0, 0.0, 0.0]);
    assert_eq!(errors("G68 X0 Y0", &mill(&[])), vec!["rotation-angle"]);
    assert_eq!(
        errors("G68 X0 Y0 Z1. R10.", &mill(&[])),
        vec!["rotation-words"]
    );
}

#[test]
fn behaviour13_10_incremental_moves_before_the_first_absolute_one() {
    // The tool at (0, 0) when G68 turns the coordinates 90° about (10, 10):
    // G91 X10 moves by the turned movement (0, 10), from where the tool
    // is (Fanuc: the centre of such a move is the tool's place at G68).
    let text = "G00 X0 Y0\nG68 X10. Y10. R90.\nG91 G01 X10. F100.\nG90 X20. Y10.";
    let r = ok(text, &mill(&[]));
    same(programmed(&r, 2), [0.0, 10.0, 0.0]);
    // The absolute X20 Y10 turns about (10, 10): (10, 20).
    same(programmed(&r, 3), [10.0, 20.0, 0.0]);
}

#[test]
fn behaviour13_10_rotated_arcs_and_the_zx_plane() {
    // 90° about the origin: the quarter from (10, 0) to (0, 10) about the
    // origin becomes the one from (0, 10) to (−10, 0), still G03.
    let r = ok(
        "G68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG03 X0 Y10. I-10. J0",
        &mill(&[]),
    );
    same(programmed(&r, 2), [-10.0, 0.0, 0.0]);
    let a = arc(&r, 1);
    assert_eq!(r.moves[1].kind, MoveKind::ArcCcw);
    same(a.programmed_center, [0.0, 0.0, 0.0]);
    assert!((a.programmed_radius - 10.0).abs() < 1e-9);
    // G18: the plane's first axis is Z. X10 Z0 is (Z 0, X 10); turned 90°
    // from Z toward X it is (Z −10, X 0).
    let r = ok("G18 G68 X0 Z0 R90.\nG01 X10. Z0 F100.", &mill(&[]));
    same(programmed(&r, 1), [0.0, 0.0, -10.0]);
    // An arc of another plane while G68 turns the XY plane: Fanuc PS0144.
    assert_eq!(
        errors("G68 X0 Y0 R10.\nG18 G02 X1. Z1. R1.", &mill(&[])),
        vec!["rotation-plane"]
    );
}

#[test]
fn behaviour13_10_r_in_g91_is_a_setting() {
    let text = "G68 X0 Y0 R30.\nG91 G68 R15.\nG90 G01 X10. Y0 F100.";
    // Fanuc RIN = 0: R is the angle: 15°.
    let r = ok(text, &mill(&[]));
    assert_eq!(
        r.blocks[1].state.modal.transforms.rotation.unwrap().degrees,
        15.0
    );
    // RIN = 1: in G91 R adds: 45°: X10 goes to (5√2, 5√2).
    let mut s = mill(&[]);
    s.settings.rotation_angle = RotationAngle::DistanceMode;
    let r = ok(text, &s);
    let h = 10.0 / 2f64.sqrt();
    same(programmed(&r, 2), [h, h, 0.0]);
}

#[test]
fn behaviour13_10_g45_to_g48_are_refused_under_rotation() {
    assert_eq!(
        errors(
            "G68 X0 Y0 R30.\nG91 G01 G45 X10. D01 F100.",
            &mill(&[(1, 2.0)])
        ),
        vec!["position-offset-rotation"]
    );
}

#[test]
fn behaviour13_10_the_length_offset_stays_on_z() {
    let r = ok(
        "G68 X0 Y0 R90.\nG43 Z10. H01\nG01 X10. F100.",
        &mill(&[(1, 100.0)]),
    );
    // Z10 + 100; X10 turned 90° is Y10.
    same(actual(&r, 2), [0.0, 10.0, 110.0]);
}

// ----- 13.11 G15/G16 ---------------------------------------------------------------

#[test]
fn behaviour13_11_a_bolt_circle_in_polar_coordinates() {
    let text = "G17 G90 G00 X0 Y0 Z10.\nG16\nG81 X50. Y0 Z-5. R2. F100.\nY120.\nY240.\nG80 G15";
    let r = ok(text, &mill(&[]));
    // Three holes 50 from the zero at 0°, 120°, 240°: (50, 0),
    // (−25, 25√3), (−25, −25√3); each ends back at the initial level.
    same(programmed(&r, 2), [50.0, 0.0, 10.0]);
    same(programmed(&r, 3), [-25.0, 25.0 * R3, 10.0]);
    same(programmed(&r, 4), [-25.0, -25.0 * R3, 10.0]);
    let b = at_line(&r, text, 4);
    assert_eq!(b.modal.polar_coordinates, Some("G16"));
    assert!(
        b.explanation
            .contains("G16: Y120.000° goes to X-25.000 Y43.301"),
        "{}",
        b.explanation
    );
}

#[test]
fn behaviour13_11_g90_and_g91_radius_and_angle() {
    // Fanuc's example: radius 100 at 30°, then G91 Y120 twice: the angle
    // adds, the radius stays.
    let text = "G16\nG90 G00 X100. Y30.\nG91 Y120.\nY120.";
    let r = ok(text, &mill(&[]));
    same(programmed(&r, 1), [50.0 * R3, 50.0, 0.0]);
    same(programmed(&r, 2), [-50.0 * R3, 50.0, 0.0]);
    same(programmed(&r, 3), [0.0, -100.0, 0.0]);
    // G91 with a radius: measured from the current point (20, 0), the
    // angle added to the point's 0°: (20, 10).
    let r = ok("G00 X20. Y0\nG16\nG91 G01 X10. Y90. F100.", &mill(&[]));
    same(programmed(&r, 2), [20.0, 10.0, 0.0]);
    // The centre in G90 is the local zero of G52.
    let r = ok("G52 X100. Y100.\nG16\nG00 X10. Y90.", &mill(&[]));
    same(programmed(&r, 2), [0.0, 10.0, 0.0]);
    // G18: Z is the radius, X the angle: Z10 at 90° is X10 Z0.
    let r = ok("G18 G16\nG00 Z10. X90.", &mill(&[]));
    same(programmed(&r, 1), [10.0, 0.0, 0.0]);
}

#[test]
fn behaviour13_11_polar_arcs_take_r() {
    // From (0, 50) (50 at 90°) to (50, 0) (50 at 0°), G02 R50: the quarter
    // about the zero.
    let r = ok("G16\nG00 X50. Y90.\nG02 X50. Y0 R50. F100.", &mill(&[]));
    same(programmed(&r, 2), [50.0, 0.0, 0.0]);
    same(arc(&r, 1).programmed_center, [0.0, 0.0, 0.0]);
    assert_eq!(
        errors("G16\nG02 X50. Y0 I10. F100.", &mill(&[])),
        vec!["polar-arc-center"]
    );
}

// ----- 13.12 G90.1/G91.1 -----------------------------------------------------------

#[test]
fn behaviour13_12_absolute_and_incremental_arc_centres() {
    let text = "G17 G90 G00 X10. Y0\nG90.1\nG03 X0 Y10. I0 J0 F100.\nG91.1 G02 X10. Y0 I0 J-10.";
    let r = run(text, &mill(&[]));
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    // G90.1: I0 J0 is the centre (0, 0) itself.
    let a = arc(&r, 1);
    same(a.programmed_center, [0.0, 0.0, 0.0]);
    assert!((a.sweep - std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    // G91.1: J-10 from the start (0, 10) is (0, 0) again.
    same(arc(&r, 2).programmed_center, [0.0, 0.0, 0.0]);
    // One warning for the program: the codes are not the manuals'.
    let w: Vec<_> = r.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(w, vec!["arc-center-mode"]);
    assert_eq!(
        r.blocks[3].state.modal.codes(r.machine).arc_center,
        Some("G91.1")
    );
    assert_eq!(
        errors("G90.1\nG03 X0 Y10. I0 F100.", &mill(&[])),
        vec!["arc-without-center"]
    );
}

// ----- 13.13 what the transformations forbid ---------------------------------------

#[test]
fn behaviour13_13_coordinate_codes_and_order_while_transforming() {
    let m = mill(&[]);
    for text in [
        "G68 X0 Y0 R10.\nG28 Z0",
        "G51 X0 Y0 P2000\nG92 X0",
        "G51.1 X0\nG55",
        "G68 X0 Y0 R10.\nG53 Z0",
        "G51 X0 Y0 P2000\nG52 X1.",
        "G68 X0 Y0 R10.\nG30 Z0",
        "G51.1 X0\nG27 X0",
    ] {
        assert_eq!(errors(text, &m), vec!["code-in-transform"], "{text}");
    }
    assert_eq!(
        errors("G51 X0 Y0 P2000\nG51.1 X0", &m),
        vec!["transform-order"]
    );
    assert_eq!(
        errors("G68 X0 Y0 R10.\nG51 X0 Y0 P2000", &m),
        vec!["transform-order"]
    );
    assert_eq!(errors("G68 X0 Y0 R10.\nG50", &m), vec!["transform-order"]);
    assert_eq!(errors("G68 X0 Y0 R10.\nG18", &m), vec!["rotation-plane"]);
    // Cancelled in the same block, the code is allowed.
    assert!(errors("G68 X0 Y0 R10.\nG69 G91 G28 Z0", &m).is_empty());
}

// ----- 13.14 rotary axes -----------------------------------------------------------

#[test]
fn behaviour13_14_rotary_words_are_reported_not_drawn() {
    let text = "G00 X10. A90.\nG91 A45.\nG90 B30. C10.\nG92 A0";
    let r = run(text, &mill(&[]));
    assert!(!r.has_errors(), "{:?}", r.diagnostics);
    assert_eq!(r.blocks[1].state.rotary, [Some(135.0), None, None]);
    assert_eq!(
        r.blocks[2].state.rotary,
        [Some(135.0), Some(30.0), Some(10.0)]
    );
    // G92 A0 sets A without motion.
    assert_eq!(r.blocks[3].state.rotary[0], Some(0.0));
    // Only the X move is drawn, and one warning says why.
    assert_eq!(r.moves.len(), 1);
    let w: Vec<_> = r
        .diagnostics
        .iter()
        .map(|d| (d.code, d.message.clone()))
        .collect();
    assert_eq!(w.len(), 1);
    assert_eq!(w[0].0, "rotary-axis");
    assert!(w[0].1.starts_with("rotary axis A is reported, not drawn"));
    assert!(explain(&r, 1).contains("rotary axis A at 135.000°"));
    // G28 returns the rotary axes it names, to 0° (our convention); a Haas
    // G28 without axis words returns every axis, the rotary ones too.
    let r = run("G00 A90. B10.\nG91 G28 X0 A0", &mill(&[]));
    assert_eq!(r.blocks[1].state.rotary, [Some(0.0), Some(10.0), None]);
    let mut haas = mill(&[]);
    haas.settings.control = offsetlab::setup::Control::Haas;
    let r = run("G00 A90. B10.\nG28", &haas);
    assert_eq!(r.blocks[1].state.rotary, [Some(0.0), Some(0.0), None]);
    // The lathe refuses them (its C is the chamfer word of some controls).
    assert_eq!(errors("G00 A10.", &lathe(&[])), vec!["unsupported-word"]);
}
