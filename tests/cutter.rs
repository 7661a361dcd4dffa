//! Behaviour 16.1–16.11 (`docs/behaviour.md`): cutter radius compensation
//! C on the mill — the codes and the register, start-up types A and B,
//! the corners of offset mode (inside, outside at 90° or more, outside
//! under 90°, lines and arcs), a new D and a change of side, blocks without
//! a move in the plane, and the cancel. Each program reproduces a figure of
//! the Fanuc 0i-MF/30i "Details of cutter compensation C" (start-up, offset
//! mode, cancel), with the tool centre's positions worked out by hand in
//! the comments. The alarms, G39 and the interactions are in
//! `tests/cutter_rules.rs`.
//!
//! Conventions: register 01 = 5 (the radius), G17, G41 (the tool left of
//! the path); s = √½ = 0.70711.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{CutterCancelWithoutMotion, CutterOutsideCorner, CutterStartUp, Settings};
use offsetlab::{MoveKind, Run, Setup, run};

const S: f64 = std::f64::consts::FRAC_1_SQRT_2;

fn setup(registers: &[(u16, f64)], settings: impl FnOnce(&mut Settings)) -> Setup {
    let mut s = mill(registers);
    settings(&mut s.settings);
    s
}

fn r5() -> Setup {
    mill(&[(1, 5.0)])
}

fn type_b() -> Setup {
    setup(&[(1, 5.0)], |s| s.cutter_start_up = Some(CutterStartUp::B))
}

/// The actual position after the block on `line` (the last block there).
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

/// The actual end points of the moves of the block on `line`, in order.
fn ends(r: &Run, line: u32) -> Vec<[f64; 3]> {
    r.moves
        .iter()
        .filter(|m| m.line == line)
        .map(|m| m.to)
        .collect()
}

#[track_caller]
fn points(got: Vec<[f64; 3]>, want: &[[f64; 3]]) {
    assert_eq!(got.len(), want.len(), "got {got:?}, want {want:?}");
    for (g, w) in got.iter().zip(want) {
        same(*g, *w);
    }
}

fn sentence(r: &Run, line: u32) -> String {
    r.blocks
        .iter()
        .rev()
        .find(|b| b.span.line == line)
        .map(|b| b.explanation())
        .unwrap_or_default()
}

/// From (-20, 0), a start-up along +X to (0, 0) (type A, the next block
/// going on along +X: it ends at (0, 5)); the block after is line 3.
const UP: &str = "G00 X-20.\nG01 G41 D01 X0 F100.\n";

// ----- 16.1 codes, register, plane -------------------------------------

#[test]
fn behaviour16_1_g41_is_left_and_g42_right_in_g17_g18_g19() {
    // Straight on along the first axis of each plane, the tool centre is
    // 5 to the left (G41) of the direction, seen from the normal's positive
    // side: G17 +X → +Y; G18 (Z, X) +Z → +X; G19 (Y, Z) +Y → +Z. The block
    // before G40 ends perpendicular to itself (type A), the G40 block on
    // the programmed point.
    let r = ok("G17 G01 G41 D01 X50. F100.\nX100.\nG40 X150.\nM30", &r5());
    same(end(&r, 1), [50.0, 5.0, 0.0]);
    same(end(&r, 2), [100.0, 5.0, 0.0]);
    same(end(&r, 3), [150.0, 0.0, 0.0]);
    let r = ok("G17 G01 G42 D01 X50. F100.\nX100.\nG40 X150.", &r5());
    same(end(&r, 1), [50.0, -5.0, 0.0]);
    let r = ok("G18 G01 G41 D01 Z50. F100.\nZ100.\nG40 Z150.", &r5());
    same(end(&r, 1), [5.0, 0.0, 50.0]);
    same(end(&r, 3), [0.0, 0.0, 150.0]);
    let r = ok("G19 G01 G41 D01 Y50. F100.\nY100.\nG40 Y150.", &r5());
    same(end(&r, 1), [0.0, 50.0, 5.0]);
}

#[test]
fn behaviour16_1_the_radius_is_geometry_plus_wear_and_a_negative_value_swaps_the_side() {
    // Register 01 = 5 - 0.2 = 4.8: (50, 4.8). Register 01 = -5 with G41:
    // the tool goes right, (50, -5), as G42 with +5 would.
    let mut s = Setup::default();
    s.set_register("1=5,W-0.2").unwrap();
    let r = ok("G01 G41 D01 X50. F100.\nX100.", &s);
    same(end(&r, 1), [50.0, 4.8, 0.0]);
    let r = ok("G01 G41 D01 X50. F100.\nX100.", &mill(&[(1, -5.0)]));
    same(end(&r, 1), [50.0, -5.0, 0.0]);
    assert!(sentence(&r, 1).contains("negative value swaps the side"));
}

#[test]
fn behaviour16_1_the_axis_across_the_plane_is_not_compensated() {
    // A helical line in G17: Z moves as programmed, only X and Y are
    // offset: (50, 5, -10).
    let r = ok("G01 G41 D01 X50. Z-10. F100.\nX100.", &r5());
    same(end(&r, 1), [50.0, 5.0, -10.0]);
}

// ----- 16.2 the modes --------------------------------------------------

#[test]
fn behaviour16_2_g41_without_a_move_in_the_plane_starts_up_at_the_next_one() {
    // G41 D01 alone and a Z move leave the tool on the programmed path
    // (cancel mode); X50. is the start-up block.
    let text = "G41 D01\nG01 Z-5. F100.\nX50.\nX100.";
    let r = ok(text, &r5());
    same(end(&r, 1), [0.0, 0.0, 0.0]);
    same(end(&r, 2), [0.0, 0.0, -5.0]);
    same(end(&r, 3), [50.0, 5.0, -5.0]);
    let phase = |line| at_line(&r, text, line).cutter.unwrap().phase;
    assert_eq!(phase(1), "cancel");
    assert_eq!(phase(3), "start_up");
    assert_eq!(phase(4), "offset");
    assert!(sentence(&r, 1).contains("starts up with the next move in the plane"));
}

#[test]
fn behaviour16_2_d00_gives_no_compensation() {
    // G41 with D00: register 00 reads 0, the tool stays on the path.
    let r = ok("G01 G41 D00 X50. F100.\nX100.", &r5());
    same(end(&r, 1), [50.0, 0.0, 0.0]);
    assert!(sentence(&r, 1).contains("no radius"));
}

// ----- 16.3 start-up type A ---------------------------------------------

/// The start-up block X50. from (0,0), then `next`.
fn start_up(next: &str, s: &Setup) -> Run {
    ok(&format!("G01 G41 D01 X50. F100.\n{next}\nG40 X0 Y-40."), s)
}

#[test]
fn behaviour16_3_type_a_start_up_ends_perpendicular_to_the_next_block() {
    // Fanuc start-up, type A, for the three corners of the manual: the
    // vector at the end is 5 left of the next block's direction at its
    // start, whatever the corner.
    // Inside (α = 270°): next +Y; left of +Y is -X: (45, 0).
    let r = start_up("Y30.", &r5());
    points(ends(&r, 1), &[[45.0, 0.0, 0.0]]);
    // Outside, obtuse (α = 135°): next along (s, -s); left of it is
    // (s, s): (50 + 5s, 5s) = (53.536, 3.536).
    let r = start_up("G91 X20. Y-20.", &r5());
    points(ends(&r, 1), &[[50.0 + 5.0 * S, 5.0 * S, 0.0]]);
    // Outside, acute (α = 45°): next along (-s, -s); left of it is
    // (s, -s): (50 + 5s, -5s) = (53.536, -3.536), in one move.
    let r = start_up("G91 X-20. Y-20.", &r5());
    points(ends(&r, 1), &[[50.0 + 5.0 * S, -5.0 * S, 0.0]]);
    assert!(sentence(&r, 1).contains("start-up (type A)"));
}

#[test]
fn behaviour16_3_the_next_block_starts_where_the_start_up_ends() {
    // After the type A start-up at the inside corner, Y30. runs on its
    // offset line x = 45 from (45, 0) to (45, 30) (the cancel follows, so
    // it ends perpendicular to itself).
    let r = start_up("Y30.", &r5());
    let m = r.moves.iter().find(|m| m.line == 2).unwrap();
    same(m.from, [45.0, 0.0, 0.0]);
    same(m.to, [45.0, 30.0, 0.0]);
}

// ----- 16.4 start-up type B ---------------------------------------------

#[test]
fn behaviour16_4_type_b_start_up_compensates_the_corner() {
    // Inside: the intersection of the offset lines y = 5 and x = 45.
    let r = start_up("Y30.", &type_b());
    points(ends(&r, 1), &[[45.0, 5.0, 0.0]]);
    // Outside, obtuse (turn of 45°): the intersection of y = 5 with the
    // offset of the line along (s, -s) through (50 + 5s, 5s): x = 50 +
    // 5·tan(22.5°) = 52.071.
    let r = start_up("G91 X20. Y-20.", &type_b());
    let t = (std::f64::consts::PI / 8.0).tan();
    points(ends(&r, 1), &[[50.0 + 5.0 * t, 5.0, 0.0]]);
    // Outside, acute: a vector perpendicular to each block: (50, 5), then
    // (50 + 5s, -5s), two moves of the start-up block.
    let r = start_up("G91 X-20. Y-20.", &type_b());
    points(
        ends(&r, 1),
        &[[50.0, 5.0, 0.0], [50.0 + 5.0 * S, -5.0 * S, 0.0]],
    );
    assert!(sentence(&r, 1).contains("type B"));
}

// ----- 16.5 inside corners --------------------------------------------

#[test]
fn behaviour16_5_inside_corner_line_to_line() {
    // Start-up along +X to (0,0) (type A: next +X, so (0, 5)), then X50.,
    // then Y30. (a left turn: inside for G41): the tool stops at the
    // intersection of y = 5 and x = 45.
    let text = "G00 X-20.\nG01 G41 D01 X0 F100.\nX50.\nY30.\nG40 X0";
    let r = ok(text, &r5());
    same(end(&r, 2), [0.0, 5.0, 0.0]);
    points(ends(&r, 3), &[[45.0, 5.0, 0.0]]);
    assert!(sentence(&r, 3).contains(
        "inside corner (270.0°): the tool stops at the intersection of the two offset lines"
    ));
}

#[test]
fn behaviour16_5_inside_corners_line_to_arc_arc_to_line_and_arc_to_arc() {
    // X50. then G03 about (30, 0), radius 20, from (50, 0) to (30, 20):
    // it starts heading +Y, a left turn of 90° (inside). The tool is inside
    // the arc: offset radius 20 - 5 = 15. Line to arc: y = 5 meets the
    // circle (x - 30)² + y² = 15² at x = 30 + √200 = 44.142.
    // Arc to line: the arc ends heading -X; G01 X0? no: Y0 heads -Y from
    // (30, 20), a left turn (inside); its offset line is x = 35, which
    // meets the circle at y = √(225 - 25) = 14.142.
    let text = format!("{UP}X50.\nG03 X30. Y20. I-20. J0\nG01 Y0\nG40 X0");
    let r = ok(&text, &r5());
    let root200 = 200f64.sqrt();
    points(ends(&r, 3), &[[30.0 + root200, 5.0, 0.0]]);
    points(ends(&r, 4), &[[35.0, root200, 0.0]]);
    let arc = r.moves.iter().find(|m| m.line == 4).unwrap().arc.unwrap();
    assert!((arc.radius - 15.0).abs() < 1e-9);
    same(arc.center, [30.0, 0.0, 0.0]);
    assert!(sentence(&r, 3).contains("this block's offset line and the next block's offset arc"));
    // Arc to arc: the same first arc, then G03 about (50, 20), radius 20,
    // from (30, 20) heading -Y (a left turn). Offset circles: radius 15
    // about (30, 0) and 15 about (50, 20), centres 28.284 apart: they
    // meet at (40, 10) ± 5·(-s, s); the one near the corner is
    // (40 - 5s, 10 + 5s) = (36.464, 13.536).
    // The second arc ends heading +X before the cancel: 5 left of that,
    // (50, 5), on its offset circle (15 from (50, 20)).
    let text = format!("{UP}X50.\nG03 X30. Y20. I-20. J0\nX50. Y0 I20. J0\nG01 G40 X80.");
    let r = ok(&text, &r5());
    points(ends(&r, 4), &[[40.0 - 5.0 * S, 10.0 + 5.0 * S, 0.0]]);
    points(ends(&r, 5), &[[50.0, 5.0, 0.0]]);
    assert!(sentence(&r, 4).contains("the two offset arcs"));
}

// ----- 16.6 outside corners of 90° or more ------------------------------

#[test]
fn behaviour16_6_outside_corners_of_90_degrees_or_more_end_at_the_intersection() {
    // A square gone round clockwise with G41: every corner is outside, at
    // 90°; the offset lines meet 5 out on both axes.
    let text = "G00 X-20. Y-20.\nG01 G41 D01 X0 Y0 F100.\nY40.\nX60.\nY0\nX0\nG40 X-20. Y-20.";
    let r = ok(text, &r5());
    // The start-up (type A) ends 5 left of +Y at (0, 0): (-5, 0).
    same(end(&r, 2), [-5.0, 0.0, 0.0]);
    same(end(&r, 3), [-5.0, 45.0, 0.0]);
    same(end(&r, 4), [65.0, 45.0, 0.0]);
    same(end(&r, 5), [65.0, -5.0, 0.0]);
    // X0 before the cancel (type A): perpendicular to itself, (0, -5).
    same(end(&r, 6), [0.0, -5.0, 0.0]);
    same(end(&r, 7), [-20.0, -20.0, 0.0]);
    assert!(sentence(&r, 3).contains("outside corner (90.0°): the tool goes to the intersection"));
}

#[test]
fn behaviour16_6_line_to_arc_at_an_obtuse_outside_corner() {
    // X50. then G02 about (44, -8), radius 10, from (50, 0): it starts
    // heading (0.8, -0.6), a right turn of 36.87° (α = 143.13°, outside).
    // The tool is outside the arc: radius 15. y = 5 meets the circle where
    // (x - 44)² = 225 - 13² = 56: x = 44 + √56 = 51.483.
    // The arc ends at (50, -16) heading (-0.8, -0.6); the cancel follows
    // (type A): 5 left of that, (50, -16) + 5·(0.6, -0.8) = (53, -20).
    let text = format!("{UP}X50.\nG02 X50. Y-16. I-6. J-8.\nG01 G40 X80. Y-16.");
    let r = ok(&text, &r5());
    points(ends(&r, 3), &[[44.0 + 56f64.sqrt(), 5.0, 0.0]]);
    points(ends(&r, 4), &[[53.0, -20.0, 0.0]]);
    let m = r.moves.iter().find(|m| m.line == 4).unwrap();
    assert_eq!(m.kind, MoveKind::ArcCw);
    assert!((m.arc.unwrap().radius - 15.0).abs() < 1e-9);
}

// ----- 16.7 outside corners under 90° -------------------------------------

#[test]
fn behaviour16_7_an_acute_outside_corner_takes_the_extra_vectors() {
    // X50. then along (-s, -s): α = 45°. The first vector (0, 5) is
    // stretched by 5 along +X: (55, 5); the second, 5 left of (-s, -s) =
    // (5s, -5s), pulled back by 5 along (-s, -s): (50 + 10s, 0) =
    // (57.071, 0). The next block starts there, on its offset line.
    let text = format!("{UP}X50.\nG91 X-20. Y-20.\nG90 G40 X0 Y-50.");
    let r = ok(&text, &r5());
    points(
        ends(&r, 3),
        &[[55.0, 5.0, 0.0], [50.0 + 10.0 * S, 0.0, 0.0]],
    );
    let second = r.moves.iter().filter(|m| m.line == 3).nth(1).unwrap();
    assert_eq!(second.kind, MoveKind::Feed);
    same(second.programmed_from, [50.0, 0.0, 0.0]);
    same(second.programmed_to, [50.0, 0.0, 0.0]);
    let next = r.moves.iter().find(|m| m.line == 4).unwrap();
    same(next.from, [50.0 + 10.0 * S, 0.0, 0.0]);
    assert!(sentence(&r, 3).contains("outside corner (45.0°, under 90°)"));
}

#[test]
fn behaviour16_7_an_outside_corner_whose_offset_paths_do_not_meet_takes_the_extra_vectors() {
    // X50. then G03 about (58, 0) with R8, starting down -Y: a right turn
    // of 90° (α = 90°, 16.6's case), but the offset line y = 5 and the
    // offset circle (radius 8 − 5 = 3 about (58, 0), y within ±3) do not
    // meet. The extra vectors: (50, 5) stretched 5 along +X is (55, 5); the
    // arc's start vector, 5 left of -Y = (55, 0), pulled back 5 along -Y is
    // (55, 5) as well (that move goes nowhere and is not recorded); then on
    // to (55, 0), on the offset circle. The arc ends 5 toward its centre
    // from (58, -8): (58, -3).
    let text = format!(
        "{UP}X50.
G03 X58. Y-8. R8.
G01 X70.
G40 X80. Y-20."
    );
    let r = ok(&text, &r5());
    points(ends(&r, 3), &[[55.0, 5.0, 0.0], [55.0, 0.0, 0.0]]);
    points(ends(&r, 4), &[[58.0, -3.0, 0.0]]);
    let s = sentence(&r, 3);
    assert!(
        s.contains("outside corner (90.0°, the offset paths do not meet)"),
        "{s}"
    );
}

#[test]
fn behaviour16_7_arc_to_line_at_an_acute_corner() {
    // G02 from (40, 10) about (40, 0) to (50, 0): it ends heading -Y, the
    // tool outside (radius 15). Then along (-s, s): a right turn of 135°
    // (α = 45°). The arc ends 5 left of -Y, (55, 0); the vector is
    // stretched 5 along -Y, (55, -5); then the next block's, 5 left of
    // (-s, s) = (-5s, -5s), pulled back 5 along (-s, s): (50, -10s) =
    // (50, -7.071). Three moves: the arc and two lines.
    let text = "G00 X40. Y-10.\nG01 G41 D01 Y10. F100.\nG02 X50. Y0 I0 J-10.\nG91 G01 X-20. Y20.\nG90 G40 X0";
    let r = ok(text, &r5());
    points(
        ends(&r, 3),
        &[[55.0, 0.0, 0.0], [55.0, -5.0, 0.0], [50.0, -10.0 * S, 0.0]],
    );
}

#[test]
fn behaviour16_7_setting_arc_goes_round_an_outside_corner_on_an_arc() {
    // cutter_outside_corner = arc: at the same 45° corner the tool ends 5
    // left of X50. at (50, 5), then turns about the corner (50, 0)
    // clockwise (the tool on the left) to 5 left of the next block,
    // (50 + 5s, -5s).
    let s = setup(&[(1, 5.0)], |s| {
        s.cutter_outside_corner = Some(CutterOutsideCorner::Arc);
    });
    let r = ok(&format!("{UP}X50.\nG91 X-20. Y-20.\nG90 G40 X0 Y-50."), &s);
    points(
        ends(&r, 3),
        &[[50.0, 5.0, 0.0], [50.0 + 5.0 * S, -5.0 * S, 0.0]],
    );
    let arc = r.moves.iter().filter(|m| m.line == 3).nth(1).unwrap();
    assert_eq!(arc.kind, MoveKind::ArcCw);
    let info = arc.arc.unwrap();
    same(info.center, [50.0, 0.0, 0.0]);
    assert!((info.radius - 5.0).abs() < 1e-9);
    // 135° of turn, clockwise.
    assert!((info.sweep + 0.75 * std::f64::consts::PI).abs() < 1e-9);
}

// ----- 16.8 a new D, a change of side ------------------------------------

#[test]
fn behaviour16_8_a_new_d_takes_effect_at_the_end_of_its_block() {
    // Registers 01 = 5, 02 = 8. D02 X100. starts 5 above the path, at
    // (50, 5), where the block before ended, and ends 8 above it,
    // (100, 8): the Fanuc figure of a compensation value changed in offset
    // mode.
    let s = mill(&[(1, 5.0), (2, 8.0)]);
    let r = ok("G01 G41 D01 X50. F100.\nD02 X100.\nX150.\nG40 X200.", &s);
    same(end(&r, 1), [50.0, 5.0, 0.0]);
    let m = r.moves.iter().find(|m| m.line == 2).unwrap();
    same(m.from, [50.0, 5.0, 0.0]);
    same(m.to, [100.0, 8.0, 0.0]);
    same(end(&r, 3), [150.0, 8.0, 0.0]);
}

#[test]
fn behaviour16_8_g41_to_g42_crosses_at_the_intersection_of_the_two_offsets() {
    // X100. in G41, then G42 Y50.: the offsets y = 5 (left of +X) and
    // x = 105 (right of +Y) meet at (105, 5).
    let r = ok("G01 G41 D01 X50. F100.\nX100.\nG42 Y50.\nG40 X0", &r5());
    points(ends(&r, 2), &[[105.0, 5.0, 0.0]]);
    // G42 Y50. ends 5 right of +Y before the cancel: (105, 50).
    same(end(&r, 3), [105.0, 50.0, 0.0]);
    assert!(sentence(&r, 2).contains("changes to the right side"));
    // Straight on, the offsets y = 5 and y = -5 never meet: the tool ends
    // 5 left of X100.'s end, then moves to 5 right of the next start.
    let r = ok("G01 G41 D01 X50. F100.\nX100.\nG42 X150.\nG40 X200.", &r5());
    points(ends(&r, 2), &[[100.0, 5.0, 0.0], [100.0, -5.0, 0.0]]);
}

// ----- 16.9 blocks without a move in the plane ----------------------------

#[test]
fn behaviour16_9_blocks_without_a_move_are_read_past() {
    // Two blocks without a move in the plane (an M code and a Z move)
    // between X50. and Y30.: the control still finds the inside corner,
    // (45, 5); the Z move carries the vector.
    let text = format!("{UP}X50.\nM08\nZ-2.\nY30.\nG40 X0");
    let r = ok(&text, &r5());
    same(end(&r, 3), [45.0, 5.0, 0.0]);
    same(end(&r, 5), [45.0, 5.0, -2.0]);
    assert!(r.diagnostics.is_empty(), "{:#?}", r.diagnostics);
}

#[test]
fn behaviour16_9_more_blocks_than_the_control_reads_leave_the_vector_perpendicular() {
    // Three blocks without a move: the control cannot see Y30., so X50.
    // ends perpendicular to itself, (50, 5), with a warning; Y30. then
    // runs from (50, 5) to (45, 30) across the corner: the overcut the
    // manual warns of.
    let text = format!("{UP}X50.\nM08\nG04 P100\nM09\nY30.\nG40 X0");
    let r = run(&text, &r5());
    assert!(!r.has_errors());
    same(end(&r, 3), [50.0, 5.0, 0.0]);
    assert!(
        r.diagnostics
            .iter()
            .any(|d| d.code == "cutter-look-ahead" && d.span.line == 3)
    );
    let m = r.moves.iter().find(|m| m.line == 7).unwrap();
    same(m.from, [50.0, 5.0, 0.0]);
    same(m.to, [45.0, 30.0, 0.0]);
    // With three blocks read past (setting), the corner is found again.
    let s = setup(&[(1, 5.0)], |s| s.cutter_blocks_without_motion = Some(3));
    let r = ok(&text, &s);
    same(end(&r, 3), [45.0, 5.0, 0.0]);
}

// ----- 16.10 cancel with a move -------------------------------------------

#[test]
fn behaviour16_10_cancel_type_a_starts_perpendicular_to_the_block_before() {
    // X50. then G40 Y-30.: type A ends X50. 5 left of its end, (50, 5), and
    // the cancel block goes from there to the programmed (50, -30).
    let r = ok(&format!("{UP}X50.\nG40 Y-30."), &r5());
    points(ends(&r, 3), &[[50.0, 5.0, 0.0]]);
    let m = r.moves.iter().find(|m| m.line == 4).unwrap();
    same(m.from, [50.0, 5.0, 0.0]);
    same(m.to, [50.0, -30.0, 0.0]);
    assert!(sentence(&r, 4).contains("G40 cancel"));
}

#[test]
fn behaviour16_10_cancel_type_b_compensates_the_corner() {
    // Outside 90° (G40 Y-30.): the intersection of y = 5 and x = 55.
    let r = ok(&format!("{UP}X50.\nG40 Y-30."), &type_b());
    points(ends(&r, 3), &[[55.0, 5.0, 0.0]]);
    // Inside (G40 Y30.): y = 5 and x = 45.
    let r = ok(&format!("{UP}X50.\nG40 Y30."), &type_b());
    points(ends(&r, 3), &[[45.0, 5.0, 0.0]]);
    // Outside, acute: a vector perpendicular to each block, (50, 5) then
    // (50 + 5s, -5s); the cancel runs from there.
    let r = ok(&format!("{UP}X50.\nG91 G40 X-20. Y-20."), &type_b());
    points(
        ends(&r, 3),
        &[[50.0, 5.0, 0.0], [50.0 + 5.0 * S, -5.0 * S, 0.0]],
    );
    same(end(&r, 4), [30.0, -20.0, 0.0]);
}

#[test]
fn behaviour16_10_d00_cancels_like_g40() {
    // D00 X100. Y-20. in G41: the cancel block (G41 stays the mode); X50.
    // before it ends perpendicular to itself (type A).
    let text = format!("{UP}X50.\nD00 X100. Y-20.\nX150.");
    let r = ok(&text, &r5());
    same(end(&r, 3), [50.0, 5.0, 0.0]);
    same(end(&r, 4), [100.0, -20.0, 0.0]);
    let v = at_line(&r, &text, 4);
    assert_eq!(v.cutter.unwrap().phase, "cancelling");
    assert_eq!(v.modal.cutter, Some("G41"));
}

// ----- 16.11 G40 without a move -------------------------------------------

#[test]
fn behaviour16_11_g40_alone_takes_the_vector_off_in_its_block_on_fanuc() {
    // X100. sees the G40 without a move next: it ends perpendicular,
    // (100, 5); G40 moves the tool back to (100, 0) as offset motion.
    let text = "G01 G41 D01 X50. F100.\nX100.\nG40\nX150.";
    // The positions are not the point: the tool starts at the work zero
    // (setting 7.49), not at the Fanuc profile's typical home.
    let s = setup(&[(1, 5.0)], |s| {
        s.control = offsetlab::setup::Control::Fanuc;
        s.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    });
    let r = ok(text, &s);
    same(end(&r, 2), [100.0, 5.0, 0.0]);
    let m = r.moves.iter().find(|m| m.line == 3).unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    assert!(m.at_feed);
    same(m.from, [100.0, 5.0, 0.0]);
    same(m.to, [100.0, 0.0, 0.0]);
    same(end(&r, 4), [150.0, 0.0, 0.0]);
}

#[test]
fn behaviour16_11_g40_alone_waits_for_the_next_move_on_haas() {
    // Haas: no change until the next X/Y move, which cancels: X100. ends
    // perpendicular before it (type A), G40 leaves the tool at (100, 5),
    // X150. goes from there to (150, 0).
    let text = "G01 G41 D01 X50. F100.\nX100.\nG40\nX150.";
    // The tool starts at the work zero (setting 7.49), as on Fanuc above.
    let s = setup(&[(1, 5.0)], |s| {
        s.control = offsetlab::setup::Control::Haas;
        s.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    });
    assert_eq!(
        s.settings.cutter_cancel_without_motion(),
        CutterCancelWithoutMotion::NextMove
    );
    let r = ok(text, &s);
    same(end(&r, 2), [100.0, 5.0, 0.0]);
    same(end(&r, 3), [100.0, 5.0, 0.0]);
    assert!(ends(&r, 3).is_empty());
    let m = r.moves.iter().find(|m| m.line == 4).unwrap();
    same(m.from, [100.0, 5.0, 0.0]);
    same(m.to, [150.0, 0.0, 0.0]);
}
