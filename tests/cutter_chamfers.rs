//! Behaviour 16.19: `,C` and `,R` (2.30) in cutter compensation's offset
//! mode. The control cuts the corner on the programmed path and
//! compensates that path: the block's move up to the chamfer or the round,
//! then the chamfer or the round, each ending at its corner with what
//! follows. Every point below is worked out by hand; D01 = 5.

mod common;

use common::*;
use offsetlab::{MoveKind, Run, Setup, run};

const R2: f64 = std::f64::consts::SQRT_2;

fn r5() -> Setup {
    mill(&[(1, 5.0)])
}

/// From (−20, 0) a start-up along +X to (0, 0) with `code`, then line 3
/// `corner` (X50. with its comma word: the corner at (50, 0)), then down
/// to Y−40 and away.
fn contour(code: &str, corner: &str, down: &str) -> String {
    format!("G00 X-20.\nG01 {code} D01 X0 F100.\n{corner}\n{down}\nX100.\nG40 X120.\nM30\n")
}

/// The moves of line `line`: (kind, actual from, actual to).
fn moves(r: &Run, line: u32) -> Vec<(MoveKind, [f64; 3], [f64; 3])> {
    r.moves
        .iter()
        .filter(|m| m.line == line)
        .map(|m| (m.kind, m.from, m.to))
        .collect()
}

/// The arc of line 3's round (its second move).
fn round(r: &Run) -> offsetlab::machine::ArcInfo {
    r.moves
        .iter()
        .filter(|m| m.line == 3)
        .nth(1)
        .unwrap()
        .arc
        .unwrap()
}

#[test]
fn behaviour16_19_an_outside_chamfer_is_compensated_with_two_corners() {
    // G41 on a path that turns right at (50, 0): the tool is outside. The
    // chamfer ,C10. runs from (40, 0) to (50, −10), along x + y = 40; its
    // offset line, 5 to its left (the normal (1, 1)/√2), is
    // x + y = 40 + 5√2. The first move's offset line y = 5 meets it at
    // x = 35 + 5√2 (a 135° outside corner: the intersection); the next
    // move's, x = 55, at y = −15 + 5√2.
    let r = ok(&contour("G41", "X50. ,C10.", "Y-40."), &r5());
    let m = moves(&r, 3);
    assert_eq!(m.len(), 2, "{m:?}");
    assert_eq!(m[0].0, MoveKind::Feed);
    same(m[0].1, [0.0, 5.0, 0.0]);
    same(m[0].2, [35.0 + 5.0 * R2, 5.0, 0.0]);
    same(m[1].1, m[0].2);
    same(m[1].2, [55.0, -15.0 + 5.0 * R2, 0.0]);
    // The next block runs from there, down the offset line x = 55.
    let next = moves(&r, 4);
    same(next[0].1, [55.0, -15.0 + 5.0 * R2, 0.0]);
    same(next[0].2, [55.0, -35.0, 0.0]);
    let text = explain(&r, 2);
    assert!(text.contains("where the chamfer starts"), "{text}");
}

#[test]
fn behaviour16_19_an_inside_chamfer_meets_at_both_intersections() {
    // G42 on the same path: the tool is inside, 5 to the right. The
    // chamfer's offset line is x + y = 40 − 5√2; y = −5 meets it at
    // x = 45 − 5√2, and x = 45 at y = −5 − 5√2.
    let r = ok(&contour("G42", "X50. ,C10.", "Y-40."), &r5());
    let m = moves(&r, 3);
    assert_eq!(m.len(), 2, "{m:?}");
    same(m[0].1, [0.0, -5.0, 0.0]);
    same(m[0].2, [45.0 - 5.0 * R2, -5.0, 0.0]);
    same(m[1].2, [45.0, -5.0 - 5.0 * R2, 0.0]);
}

#[test]
fn behaviour16_19_an_outside_round_is_an_arc_of_the_radius_plus_the_tool() {
    // ,R10. at a right angle: the tangent points (40, 0) and (50, −10),
    // the centre (40, −10). G41 keeps the tool outside: the move ends at
    // (40, 5) (tangent: perpendicular), the round is an arc of radius 15
    // about the same centre, clockwise, to (55, −10).
    let r = ok(&contour("G41", "X50. ,R10.", "Y-40."), &r5());
    let m = moves(&r, 3);
    assert_eq!(m.len(), 2, "{m:?}");
    same(m[0].2, [40.0, 5.0, 0.0]);
    assert_eq!(m[1].0, MoveKind::ArcCw);
    same(m[1].2, [55.0, -10.0, 0.0]);
    let arc = round(&r);
    same(arc.center, [40.0, -10.0, 0.0]);
    assert!((arc.radius - 15.0).abs() < 1e-9, "{arc:?}");
}

#[test]
fn behaviour16_19_an_inside_round_is_an_arc_of_the_radius_less_the_tool() {
    // G42: inside, the round's offset radius is 10 − 5 = 5: from (40, −5)
    // to (45, −10) about (40, −10).
    let r = ok(&contour("G42", "X50. ,R10.", "Y-40."), &r5());
    let m = moves(&r, 3);
    same(m[0].2, [40.0, -5.0, 0.0]);
    same(m[1].2, [45.0, -10.0, 0.0]);
    let arc = round(&r);
    assert!((arc.radius - 5.0).abs() < 1e-9, "{arc:?}");
}

#[test]
fn behaviour16_19_an_inside_round_smaller_than_the_tool_is_the_interference_alarm() {
    // ,R4. inside a tool of radius 5: its offset arc would have radius −1
    // (behaviour 16.12, Fanuc PS0041), at the block with the word.
    let r = run(&contour("G42", "X50. ,R4.", "Y-40."), &r5());
    assert_eq!(first_error(&r).0, "cutter-interference");
    assert_eq!(first_error(&r).1, 3);
}

#[test]
fn behaviour16_19_the_next_block_counts_from_the_corner() {
    // Behaviour 2.32 with compensation: G91 Y−40. after the chamfer ends
    // at (50, −40), as the absolute Y−40. does.
    let absolute = ok(&contour("G41", "X50. ,C10.", "Y-40."), &r5());
    let incremental = ok(&contour("G41", "X50. ,C10.", "G91 Y-40.\nG90"), &r5());
    let ends = |r: &Run| moves(r, 4).last().unwrap().2;
    same(ends(&incremental), ends(&absolute));
    same(ends(&absolute), [55.0, -35.0, 0.0]);
}

#[test]
fn behaviour16_19_not_where_the_compensation_starts_ends_or_changes_side() {
    // Fanuc PS0039: the start-up block, G40, D00 and a change of side.
    for (text, line) in [
        ("G01 G41 D01 X50. ,C2. F100.\nY50.", 1),
        ("G01 G41 D01 X50. F100.\nG40 X100. ,C2.\nY50.", 2),
        ("G01 G41 D01 X50. F100.\nD00 X100. ,C2.\nY50.", 2),
        ("G01 G41 D01 X50. F100.\nG42 X100. ,R2.\nY50.", 2),
    ] {
        let r = run(text, &r5());
        let (code, at, _) = first_error(&r);
        assert_eq!((code, at), ("cutter-corner-words", line), "{text}");
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert!(d.message.contains("PS0039"), "{}", d.message);
    }
}

#[test]
fn behaviour16_19_an_inside_chamfer_too_short_for_the_tool_is_the_interference_alarm() {
    // G41 inside a 135° left turn at (30, 0) (X30. then X0 Y30.): the
    // chamfer turns 67.5° at each end, and each inside corner takes
    // 5·tan(33.75°) = 3.341 of it. ,C2. is a chord of 2·2·sin(67.5°) =
    // 3.696 < 6.682: its offset runs backwards (16.12, PS0041) at line 3;
    // ,C10. (18.478) fits.
    let text = |c: &str| {
        format!("G00 X0 Y10.\nG01 G41 D01 X0 Y0 F100.\nX30. {c}\nX0 Y30.\nX-10.\nG40 Y40.\nM30\n")
    };
    let r = run(&text(",C2."), &r5());
    assert_eq!(first_error(&r).0, "cutter-interference");
    assert_eq!(first_error(&r).1, 3);
    ok(&text(",C10."), &r5());
}
