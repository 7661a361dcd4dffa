//! Behaviour 14.11 and 14.15–14.19, 7.33: polar coordinate interpolation on
//! the lathe (Fanuc G12.1/G13.1, Haas G112/G113). Every position below is
//! worked out by hand in the comments: the face plane's point (x, c) is
//! kept as the lathe's X (2x, a diameter-valued coordinate) and Y (c); the
//! machine's X is twice the point's distance from the spindle axis and its
//! C the point's angle, counted from C's place at G12.1.

mod common;
use common::*;
use offsetlab::setup::{Control, PolarInterpolation};
use offsetlab::view::block_view;
use offsetlab::{MoveKind, Setup, run};

const R200: f64 = 14.142_135_623_730_951; // √200, the corner's distance from the axis

/// A 20 × 20 square centred on the spindle axis, Fanuc style: X is a
/// diameter, C the hypothetical axis. The tool starts at X40 (radius 20),
/// which G12.1 makes the face point (20, 0) at C 0°.
const SQUARE: &str = "G98 G00 X40. Z2.
G01 Z-1. F100.
G12.1
G01 X20. C-10.
C10.
X-20.
C-10.
X20.
G13.1
G00 Z5.
M30
";

fn fanuc_lathe(registers: &[(u16, f64, f64)]) -> Setup {
    let mut s = lathe(registers);
    s.settings.control = Control::Fanuc;
    s
}

fn haas_lathe(registers: &[(u16, f64, f64)]) -> Setup {
    let mut s = lathe(registers);
    s.settings.control = Control::Haas;
    s
}

/// The machine's C (degrees) and X (a diameter) after block `i`.
fn machine_c_x(r: &offsetlab::Run, text: &str, i: usize) -> (f64, f64) {
    let p = block_view(&r.blocks[i], text).polar.expect("in the mode");
    (p.c, p.x)
}

#[track_caller]
fn near(got: f64, want: f64) {
    assert!((got - want).abs() < 1e-6, "got {got}, want {want}");
}

#[test]
fn behaviour14_15_a_square_on_the_face_its_x_radius_and_c_angle_at_each_corner() {
    let r = ok(SQUARE, &fanuc_lathe(&[]));
    // Corner by corner (blocks 3 to 7), the face point, the machine's C and
    // X (2 × √200 = 28.284271 at every corner):
    //   X20. C-10.  (10, -10)  C -45°  (atan2(-10, 10); from 0°, -45°)
    //   C10.        (10, 10)   C 45°   (+90°)
    //   X-20.       (-10, 10)  C 135°  (+90°)
    //   C-10.       (-10, -10) C 225°  (+90°: C goes on round, unwound)
    //   X20.        (10, -10)  C 315°  (+90°)
    let corners = [
        ([20.0, -10.0], -45.0),
        ([20.0, 10.0], 45.0),
        ([-20.0, 10.0], 135.0),
        ([-20.0, -10.0], 225.0),
        ([20.0, -10.0], 315.0),
    ];
    for (k, (xy, c)) in corners.iter().enumerate() {
        let i = 3 + k;
        same(programmed(&r, i), [xy[0], xy[1], -1.0]);
        // No offset: actual = programmed.
        same(actual(&r, i), [xy[0], xy[1], -1.0]);
        let (mc, mx) = machine_c_x(&r, SQUARE, i);
        near(mc, *c);
        near(mx, 2.0 * R200);
        // One feed move a block, from the corner before.
        assert_eq!(r.blocks[i].move_count, 1);
    }
    let m = &r.moves[r.blocks[4].first_move as usize];
    assert_eq!(m.kind, MoveKind::Feed);
    same(m.programmed_from, [20.0, -10.0, -1.0]);
    same(m.programmed_to, [20.0, 10.0, -1.0]);
    // The JSON's positions carry the hypothetical axis as y.
    let v = block_view(&r.blocks[4], SQUARE);
    assert_eq!(v.programmed.y, Some(10.0));
    assert_eq!(v.machine.y, None);
    near(v.machine.x, 2.0 * R200);
}

#[test]
fn behaviour14_15_an_arc_in_the_face_plane_with_r_and_with_i_and_j() {
    // From (10, 5) a counter-clockwise quarter of radius 5 to (5, 10): R5.
    // has the centres (5, 5) (a 90° arc, start at 0°, end at 90° about it)
    // and (10, 10) (270°): R > 0 is the short one. I-5. J0 names the same
    // centre, 5 back along X (I a radius value) from the start.
    for arc in ["G03 X10. C10. R5.", "G03 X10. C10. I-5. J0"] {
        let text = format!("G98 G00 X40. Z-1.\nG12.1\nG01 X20. C5. F100.\n{arc}\nG13.1\n");
        let r = ok(&text, &fanuc_lathe(&[]));
        let m = &r.moves[r.blocks[3].first_move as usize];
        assert_eq!(m.kind, MoveKind::ArcCcw, "{arc}");
        let a = m.arc.expect("an arc");
        assert_eq!(a.plane, offsetlab::machine::modal::Plane::XY);
        near(a.programmed_radius, 5.0);
        // The centre as a lathe point: X 2 × 5 = 10, Y 5.
        same(a.programmed_center, [10.0, 5.0, -1.0]);
        near(a.sweep.to_degrees(), 90.0);
        same(programmed(&r, 3), [10.0, 10.0, -1.0]);
        // C turns from atan2(5, 10) = 26.565° to atan2(10, 5) = 63.435°:
        // +36.870°; the machine's X is 2 × √125 = 22.360680.
        let (c, x) = machine_c_x(&r, &text, 3);
        near(c, 63.434_948_822_922_01);
        near(x, 2.0 * 125f64.sqrt());
        assert!(
            explain(&r, 3).contains("a counter-clockwise arc of radius 5.000 about X10.000 C5.000"),
            "{}",
            explain(&r, 3)
        );
        assert!(explain(&r, 3).contains("turns C by +36.870°"));
    }
    // A full circle about the spindle axis (I-10. J10. from (10, -10)):
    // C turns a whole turn, +360°.
    let text = "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C-10. F100.\nG03 X20. C-10. I-10. J10.\n";
    let r = ok(text, &fanuc_lathe(&[]));
    let (c, x) = machine_c_x(&r, text, 3);
    near(c, -45.0 + 360.0);
    near(x, 2.0 * R200);
    // K is along Z, not in the face plane: refused at the word.
    let r = run(
        "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C5. F100.\nG03 X10. C10. I-5. K0\n",
        &fanuc_lathe(&[]),
    );
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line, e.column), ("unused-word", 4, 20));
}

#[test]
fn behaviour14_15_haas_writes_x_as_a_radius_and_y_for_the_hypothetical_axis() {
    // Haas G112 (XY to XC) after G17: X10. is a radius of 10, the same
    // corners as SQUARE's; G00 is allowed in the mode (the manual's example
    // retracts so).
    let text =
        "G17\nG98 G00 X40. Z2.\nG112\nG01 Z-1. F100.\nX10. Y-10.\nY10.\nG00 Z2.\nG113\nG18\n";
    let r = ok(text, &haas_lathe(&[]));
    same(programmed(&r, 4), [20.0, -10.0, -1.0]);
    same(programmed(&r, 5), [20.0, 10.0, -1.0]);
    let (c, x) = machine_c_x(&r, text, 5);
    near(c, 45.0);
    near(x, 2.0 * R200);
    let m = &r.moves[r.blocks[6].first_move as usize];
    assert_eq!(m.kind, MoveKind::Rapid);
    same(m.programmed_to, [20.0, 10.0, 2.0]);
    assert!(
        explain(&r, 5).starts_with("G01 in the XY plane of the face: a line to X10.000 Y10.000")
    );
    // The setting chooses the words whatever the control: Fanuc's words on
    // the Haas profile.
    let mut s = haas_lathe(&[]);
    s.settings.polar_interpolation = Some(PolarInterpolation::Fanuc);
    let r = ok(SQUARE, &s);
    same(programmed(&r, 4), [20.0, 10.0, -1.0]);
}

#[test]
fn behaviour14_15_z_moves_with_the_plane_and_u_is_incremental() {
    // U-20. from X20 (radius 10) is 10 back along X (a diameter amount):
    // (10, 10) → (0, 10), C from 45° to 90°; Z moves to -2. on the way.
    let text = "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C10. F100.\nU-20. Z-2.\nW1.\n";
    let r = ok(text, &fanuc_lathe(&[]));
    same(programmed(&r, 3), [0.0, 10.0, -2.0]);
    let (c, x) = machine_c_x(&r, text, 3);
    near(c, 90.0);
    near(x, 20.0);
    same(programmed(&r, 4), [0.0, 10.0, -1.0]);
    assert!(
        explain(&r, 3).ends_with("and Z to -2.000."),
        "{}",
        explain(&r, 3)
    );
}

#[test]
fn behaviour14_16_g12_1_starts_c_at_zero_and_g13_1_gives_x_back() {
    let r = ok(SQUARE, &fanuc_lathe(&[]));
    // G12.1: the hypothetical axis is 0 and C's place is 0°; the tool's X
    // (40, a radius of 20) is the face point (20, 0).
    let (c, x) = machine_c_x(&r, SQUARE, 2);
    near(c, 0.0);
    near(x, 40.0);
    same(programmed(&r, 2), [40.0, 0.0, -1.0]);
    // G13.1 at (10, -10): the lathe's X is 2 × √200 again, Y 0, no move.
    same(programmed(&r, 8), [2.0 * R200, 0.0, -1.0]);
    assert_eq!(r.blocks[8].move_count, 0);
    assert!(block_view(&r.blocks[8], SQUARE).polar.is_none());
    assert!(
        explain(&r, 8).contains("turned by C315.000°"),
        "{}",
        explain(&r, 8)
    );
    // The next move starts there: G00 Z5. from X28.284271.
    let m = &r.moves[r.blocks[9].first_move as usize];
    same(m.programmed_from, [2.0 * R200, 0.0, -1.0]);
    same(m.programmed_to, [2.0 * R200, 0.0, 5.0]);
}

#[test]
fn behaviour14_16_a_line_through_the_spindle_axis_turns_c_half_a_turn() {
    // (10, -10) to (-10, 10) passes through the axis: C +180° (our
    // convention for the way it turns), X through 0 back to 28.284271.
    let text = "G98 G00 X40. Z-1.\nG12.1\nG01 X20. C-10. F100.\nX-20. C10.\n";
    let r = ok(text, &fanuc_lathe(&[]));
    let (c, x) = machine_c_x(&r, text, 3);
    near(c, -45.0 + 180.0);
    near(x, 2.0 * R200);
    assert!(explain(&r, 3).contains("passes through the spindle axis"));
}

#[test]
fn behaviour14_17_the_t_offset_moves_z_and_pushes_the_tool_out_along_the_radius() {
    // Register 01: X 0.4 (a diameter: 0.2 on the radius), Z -0.2, taken
    // before G12.1. At the corner (10, 10), C 45°, the machine's X carries
    // 0.4 more: 28.284271 + 0.4 = 28.684271; on the face the reference
    // point lies 0.2 further out along the radius: (10 + 0.2 cos 45°,
    // 10 + 0.2 sin 45°) = (10.141421, 10.141421), the lathe's X 20.282843.
    let text = SQUARE.replace("G98 G00 X40. Z2.", "G98 G00 X40. Z2. T0101");
    let r = ok(&text, &fanuc_lathe(&[(1, 0.4, -0.2)]));
    let k = 0.2 * std::f64::consts::FRAC_1_SQRT_2;
    same(programmed(&r, 4), [20.0, 10.0, -1.0]);
    same(actual(&r, 4), [20.0 + 2.0 * k, 10.0 + k, -1.2]);
    let (c, x) = machine_c_x(&r, &text, 4);
    near(c, 45.0);
    near(x, 2.0 * R200 + 0.4);
    // The straight side bends on the actual path: it is drawn in pieces,
    // each turning C by at most 2°, every actual vertex 0.2 farther from
    // the axis than its programmed one, along the same radius.
    let b = &r.blocks[4];
    assert!(b.move_count > 1);
    let moves = &r.moves[b.first_move as usize..(b.first_move + b.move_count) as usize];
    for m in moves {
        assert_eq!(m.kind, MoveKind::Feed);
        let (p, a) = (m.programmed_to, m.to);
        let (rp, ra) = ((p[0] / 2.0).hypot(p[1]), (a[0] / 2.0).hypot(a[1]));
        near(ra, rp + 0.2);
        near((a[1]).atan2(a[0] / 2.0), p[1].atan2(p[0] / 2.0));
        let (f, t) = (m.programmed_from, m.programmed_to);
        let turn = (t[1].atan2(t[0] / 2.0) - f[1].atan2(f[0] / 2.0)).abs();
        assert!(turn <= 2f64.to_radians() + 1e-9, "{}", turn.to_degrees());
    }
    assert!(explain(&r, 4).contains("drawn as"), "{}", explain(&r, 4));
    // Without an X offset (Z only) a block is one move, its actual path
    // the programmed one moved by Z -0.2.
    let r = ok(&text, &fanuc_lathe(&[(1, 0.0, -0.2)]));
    assert_eq!(r.blocks[4].move_count, 1);
    same(actual(&r, 4), [20.0, 10.0, -1.2]);
    // G13.1: the offset is the machine's X again.
    same(actual(&r, 8), [2.0 * R200, 0.0, -1.2]);
}

#[test]
fn behaviour14_18_what_the_mode_refuses() {
    let before = "G98 G00 X40. Z-1. T0101\nG12.1\nG01 X20. C10. F100.\n";
    let s = fanuc_lathe(&[(1, 0.4, -0.2)]);
    for (block, code, column) in [
        // Fanuc moves only with G01–G03 in the mode (PS0146).
        ("G00 X10.", "polar-interpolation", 1),
        ("G28 U0.", "polar-interpolation", 1),
        ("G50 X10. Z0.", "polar-interpolation", 1),
        ("G55", "polar-interpolation", 1),
        ("G90 X10. Z-5.", "polar-interpolation", 1),
        ("G17", "polar-interpolation", 1),
        ("G31 X10.", "polar-interpolation", 1),
        // No offset changes in the mode.
        ("G01 X10. T0202", "polar-interpolation", 10),
        ("H5", "polar-words", 1),
        ("Y5.", "polar-words", 1),
        ("G41 X10.", "nose-polar", 1),
        ("G02 X10. C5.", "arc-without-center", 1),
    ] {
        let text = format!("{before}{block}\n");
        let r = run(&text, &s);
        let e = r
            .diagnostics
            .iter()
            .find(|d| d.is_error())
            .unwrap_or_else(|| panic!("{block}: no error"));
        assert_eq!(
            (e.code, e.line, e.column),
            (code, 4, column),
            "{block}: {}",
            e.message
        );
    }
    // G00 with the mode on but no move yet written after G12.1 (G00 modal
    // from before): the first move block is refused at its first word.
    let r = run("G98 G00 X40. Z-1.\nG12.1\nX20. C10.\n", &s);
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line, e.column), ("polar-interpolation", 3, 1));
    assert!(e.message.contains("PS0146"), "{}", e.message);
    // Haas reads Y and refuses C; its G00 moves.
    let h = haas_lathe(&[]);
    let r = run("G98 G00 X40. Z-1.\nG112\nG01 X10. C5. F100.\n", &h);
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.column), ("polar-words", 10));
    // A T code in the G12.1 block, or G12.1 under G07.1.
    let r = run("G12.1 T0101\n", &s);
    assert_eq!(r.diagnostics[0].code, "polar-interpolation");
    let r = run("G07.1 C20.\nG12.1\n", &s);
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line), ("polar-interpolation", 2));
}

#[test]
fn behaviour14_18_a_turning_arc_in_g17_is_refused() {
    // G17 is the face plane of polar interpolation; outside the mode a lathe
    // arc lies in ZX.
    let r = run("G17\nG00 X40. Z0\nG02 X50. Z-5. R5. F0.2\n", &lathe(&[]));
    let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((e.code, e.line), ("arc-plane", 3));
    // Straight moves are the same in either plane, and G18 turns again.
    ok(
        "G17\nG00 X40. Z0\nG01 X50. Z-5. F0.2\nG18 G02 X60. Z-10. R5.\n",
        &lathe(&[]),
    );
}

#[test]
fn behaviour14_19_each_move_says_what_the_machine_does() {
    let r = ok(SQUARE, &fanuc_lathe(&[]));
    // C10. from (10, -10): +90°, to 45°, X 28.284 (radius 14.142).
    assert_eq!(
        explain(&r, 4),
        "G01 in the XC plane of the face: a line to X20.000 C10.000; the machine turns C by +90.000° (to 45.000° from its place at G12.1) while X moves to 28.284 (radius 14.142)."
    );
}

#[test]
fn behaviour7_33_the_profile_gives_the_words_of_the_face_plane() {
    let mut s = Setup::default();
    assert_eq!(s.settings.polar_interpolation(), PolarInterpolation::Fanuc);
    s.settings.control = Control::Fanuc;
    assert_eq!(s.settings.polar_interpolation(), PolarInterpolation::Fanuc);
    s.settings.control = Control::Haas;
    assert_eq!(s.settings.polar_interpolation(), PolarInterpolation::Haas);
    s.settings.polar_interpolation = Some(PolarInterpolation::Fanuc);
    assert_eq!(s.settings.polar_interpolation(), PolarInterpolation::Fanuc);
    // In documents and plain links by its name.
    let s =
        Setup::from_json(r#"{"machine": "lathe", "settings": {"polar_interpolation": "haas"}}"#)
            .unwrap();
    assert_eq!(s.settings.polar_interpolation(), PolarInterpolation::Haas);
}
