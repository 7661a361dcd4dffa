//! Behaviour 4 (`docs/behaviour.md`): tool position offset G45–G48 (seeds
//! 000 and 003), one test or more per numbered rule, and the worked example
//! of seed 000's square.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::Mirror;

/// Seed 000's square (comment line, seven blocks, M30), register 01 = 6.
const SQUARE: &str = include_str!("data/seed000_square.nc");

#[test]
fn behaviour4_worked_example_seed000_square() {
    let text = SQUARE;
    let r = ok(text, &mill(&[(1, 6.0)]));
    let want = [
        [-30.0, -20.0],
        [-6.0, -6.0],
        [86.0, -6.0],
        [86.0, 56.0],
        [-6.0, 56.0],
        [-6.0, -6.0],
        [-30.0, -20.0],
        // M30 ends the program where the last block left the tool.
        [-30.0, -20.0],
    ];
    assert_eq!(r.blocks.len(), want.len());
    for (i, w) in want.iter().enumerate() {
        same(actual(&r, i), [w[0], w[1], 0.0]);
    }
    // The cutter (radius 6) runs around the rectangle (0,0)–(80,50).
    same(programmed(&r, 5), [0.0, 0.0, 0.0]);
    assert_eq!(
        explain(&r, 2),
        "G47 (double extension): X move 80.000 extended by 2 × D01 (6.000) to 92.000."
    );
}

#[test]
fn behaviour4_1_g91_amount_is_the_word() {
    let r = ok("G91 G01 G45 X50. D01 F100.", &mill(&[(1, 6.0)]));
    same(actual(&r, 0), [56.0, 0.0, 0.0]);
    same(programmed(&r, 0), [50.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_1_g90_amount_is_from_the_preceding_end_point() {
    let r = ok("G90 G00 X10.\nG45 X30. D01", &mill(&[(1, 6.0)]));
    // Movement 20 extended by 6 → 26, from 10: actual 36.
    same(actual(&r, 1), [36.0, 0.0, 0.0]);
    same(programmed(&r, 1), [30.0, 0.0, 0.0]);
    let r = ok("G90 G00 X10.\nG45 X-30. D01", &mill(&[(1, 6.0)]));
    same(actual(&r, 1), [-36.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_1_double_codes_use_twice_the_value() {
    let s = mill(&[(1, 6.0)]);
    same(actual(&ok("G91 G47 X50. D01", &s), 0), [62.0, 0.0, 0.0]);
    same(actual(&ok("G91 G48 X50. D01", &s), 0), [38.0, 0.0, 0.0]);
    same(actual(&ok("G91 G46 X-50. D01", &s), 0), [-44.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_2_negative_register_turns_reduction_into_extension() {
    // `G91 G46 X30. D02` with register 02 = -4. moves X by +34.
    let r = ok("G91 G46 X30. D02", &mill(&[(2, -4.0)]));
    same(actual(&r, 0), [34.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_3_reduction_larger_than_the_movement_reverses_it() {
    // `G91 G48 X8. D03` with register 03 = 6. moves X by -4.
    let r = ok("G91 G48 X8. D03", &mill(&[(3, 6.0)]));
    same(actual(&r, 0), [-4.0, 0.0, 0.0]);
    assert!(explain(&r, 0).contains("reverses"), "{}", explain(&r, 0));
}

#[test]
fn behaviour4_4_g91_zero_movement_seed003() {
    // `G91 G01 G45 X0 Y0 D10 F…` moves +v along X and Y.
    let r = ok("G91 G01 G45 X0 Y0 D10 F100.", &mill(&[(10, 2.5)]));
    same(actual(&r, 0), [2.5, 2.5, 0.0]);
    same(programmed(&r, 0), [0.0, 0.0, 0.0]);
    // `G91 G00 G46 X0 D11` moves -v along X.
    let r = ok("G91 G00 G46 X0 D11", &mill(&[(11, 3.0)]));
    same(actual(&r, 0), [-3.0, 0.0, 0.0]);
    // A sign on the zero means nothing.
    let r = ok("G91 G00 G46 X-0 D11", &mill(&[(11, 3.0)]));
    same(actual(&r, 0), [-3.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_5_g90_zero_movement_changes_nothing() {
    let r = ok("G90 G00 X10.\nG45 X10. Y5. D01", &mill(&[(1, 6.0)]));
    same(actual(&r, 1), [10.0, 11.0, 0.0]);
    assert!(
        // The machine's own sentence, which still cites the rule by the
        // number it has in docs/behaviour.md.
        explain(&r, 1).contains("not changed (behaviour 4.5)"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour4_6_each_axis_changed_on_its_own() {
    // A 45° move is changed on both axes (overcut is the user's problem).
    let r = ok("G91 G01 G45 X10. Y10. D01 F100.", &mill(&[(1, 2.0)]));
    same(actual(&r, 0), [12.0, 12.0, 0.0]);
    // Z too, and the plane does not matter.
    let r = ok("G18\nG91 G45 Z-10. D01", &mill(&[(1, 2.0)]));
    same(actual(&r, 1), [0.0, 0.0, -12.0]);
    let r = ok("G19\nG91 G45 X10. D01", &mill(&[(1, 2.0)]));
    same(actual(&r, 1), [12.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_7_the_vector_stays_until_an_opposite_code_removes_it() {
    let text = "G91 G45 X10. D01\nX5.\nG90 X40.\nG91 G46 X5.";
    let r = ok(text, &mill(&[(1, 2.0)]));
    same(actual(&r, 1), [17.0, 0.0, 0.0]);
    same(actual(&r, 2), [42.0, 0.0, 0.0]);
    same(actual(&r, 3), [45.0, 0.0, 0.0]);
    same(programmed(&r, 3), [45.0, 0.0, 0.0]);
    // The vector is reported (seed 003: offset distance from the programmed end point).
    let v = at_line(&r, text, 2).position_offset.unwrap();
    assert_eq!((v.d, v.value, v.vector.x), (1, 2.0, 2.0));
    assert!(
        explain(&r, 1).contains("Offsets carried: X +2.000"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour4_7_g92_clears_the_vector_on_the_named_axes() {
    let text = "G91 G45 X10. Y10. D01\nG92 X0\nG90 X5. Y20.";
    let r = ok(text, &mill(&[(1, 2.0)]));
    same(programmed(&r, 1), [0.0, 10.0, 0.0]);
    same(actual(&r, 1), [0.0, 12.0, 0.0]);
    same(r.blocks[1].state.position.vector, [0.0, 2.0, 0.0]);
    // The tool did not move; X's coordinate changed.
    assert_eq!(r.blocks[1].move_count, 0);
    same(actual(&r, 2), [5.0, 22.0, 0.0]);
    assert_eq!(
        r.moves.last().unwrap().to[0] - r.moves.last().unwrap().from[0],
        5.0
    );
}

#[test]
fn behaviour4_8_quarter_circle_gives_the_concentric_arc() {
    // The Fanuc manual's pattern: the tool carries (0, -5) from a G46 Y move,
    // then G45 G03 X30 Y30 J30 cuts a quarter circle with radius 30 + 5.
    let text = "G90 G00 X0 Y-10.\nG91 G46 Y10. D01\nG45 G03 X30. Y30. J30. F100.";
    let r = ok(text, &mill(&[(1, 5.0)]));
    same(actual(&r, 1), [0.0, -5.0, 0.0]);
    same(actual(&r, 2), [35.0, 30.0, 0.0]);
    let arc = r.moves.last().unwrap().arc.unwrap();
    same(arc.center, arc.programmed_center);
    same(arc.center, [0.0, 30.0, 0.0]);
    assert!((arc.radius - 35.0).abs() < 1e-9);
    assert!((arc.programmed_radius - 30.0).abs() < 1e-9);
    assert!(
        explain(&r, 2).contains("J 30.000 becomes 35.000"),
        "{}",
        explain(&r, 2)
    );
}

#[test]
fn behaviour4_8_an_explicit_zero_centre_word_stays_zero() {
    // Register 01 = 5. From X15 Y0, G45 X5. moves 5 + 5 = 10: programmed
    // (20, 0), actual (25, 0), vector (+5, 0). Then a G91 quarter circle
    // about the programmed centre (0, 0), from (20, 0) to (0, 20):
    //   X -20 -> -20 - 5 = -25, Y +20 -> +20 + 5 = +25,
    //   I -20 -> -25, J 0 stays 0 (a zero centre word has no direction).
    // Actual centre = (25, 0) + (-25, 0) = (0, 0); actual end = (25 - 25,
    // 0 + 25) = (0, 25): both 25 from the centre, the concentric arc of
    // radius 20 + 5. (Extending J0 by +5 put the centre at (0, 5), 25.5
    // from the start and 20 from the end: an arc-radius error.)
    let text = "G90 G00 X15. Y0\nG91 G01 G45 X5. D01 F100.\nG03 G45 X-20. Y20. I-20. J0";
    let r = ok(text, &mill(&[(1, 5.0)]));
    same(actual(&r, 1), [25.0, 0.0, 0.0]);
    same(programmed(&r, 2), [0.0, 20.0, 0.0]);
    same(actual(&r, 2), [0.0, 25.0, 0.0]);
    let arc = r.moves.last().unwrap().arc.unwrap();
    same(arc.center, [0.0, 0.0, 0.0]);
    same(arc.programmed_center, [0.0, 0.0, 0.0]);
    assert!((arc.radius - 25.0).abs() < 1e-9);
    assert!((arc.programmed_radius - 20.0).abs() < 1e-9);
    let why = explain(&r, 2);
    assert!(why.contains("J 0 stays 0"), "{why}");
    assert!(why.contains("I -20.000 becomes -25.000"), "{why}");
}

#[test]
fn behaviour4_9_a_full_circle_takes_g45_with_centre_words_alone() {
    // Register 01 = 5, the tool offset (+5, 0) as above: programmed (20, 0),
    // actual (25, 0). G02 G45 I-20. (YASNAC PC NC: "1/4, 3/4 or full
    // circle"): no axis word, so the end is the start; I -20 -> -25 puts the
    // actual centre at (25 - 25, 0) = (0, 0): a full circle of radius
    // 20 + 5 = 25 about the programmed centre, ending where it started.
    let text = "G90 G00 X15. Y0\nG91 G01 G45 X5. D01 F100.\nG02 G45 I-20.";
    let r = ok(text, &mill(&[(1, 5.0)]));
    same(programmed(&r, 2), [20.0, 0.0, 0.0]);
    same(actual(&r, 2), [25.0, 0.0, 0.0]);
    let m = r.moves.last().unwrap();
    same(m.from, m.to);
    let arc = m.arc.unwrap();
    same(arc.center, [0.0, 0.0, 0.0]);
    assert!((arc.radius - 25.0).abs() < 1e-9);
    assert!((arc.programmed_radius - 20.0).abs() < 1e-9);
    assert!((arc.sweep + std::f64::consts::TAU).abs() < 1e-9);
    // In G90 the block is the same full circle. A straight move still needs
    // an axis word, and reads no centre word (behaviour 2.22).
    let g90 = "G90 G00 X15. Y0\nG91 G01 G45 X5. D01 F100.\nG90 G02 G45 I-20.";
    same(actual(&ok(g90, &mill(&[(1, 5.0)])), 2), [25.0, 0.0, 0.0]);
    assert_eq!(
        errors("G01 G45 I-20. D01 F100.", &mill(&[(1, 5.0)])),
        vec!["unused-word"]
    );
    assert_eq!(
        errors("G01 G45 D01 F100.", &mill(&[(1, 5.0)])),
        vec!["position-offset-without-axis"]
    );
}

#[test]
fn behaviour4_8_r_is_changed_as_a_radius() {
    let text = "G90 G00 X0 Y-10.\nG91 G46 Y10. D01\nG45 G03 X30. Y30. R30. F100.";
    let r = ok(text, &mill(&[(1, 5.0)]));
    let arc = r.moves.last().unwrap().arc.unwrap();
    assert!((arc.radius - 35.0).abs() < 1e-9);
    same(actual(&r, 2), [35.0, 30.0, 0.0]);
    assert!(
        explain(&r, 2).contains("R 30.000 becomes 35.000"),
        "{}",
        explain(&r, 2)
    );
}

#[test]
fn behaviour4_8_other_arcs_fail_the_radius_check() {
    // A 45° arc is not a quarter circle on the axes: seed 003, build the arc
    // from quarter circles.
    let e = errors(
        "G91 G45 G03 X-2.9289 Y7.0711 I-10. F100. D01",
        &mill(&[(1, 5.0)]),
    );
    assert_eq!(e, vec!["arc-radius"]);
    let r = offsetlab::run(
        "G91 G45 G03 X-2.9289 Y7.0711 I-10. F100. D01",
        &mill(&[(1, 5.0)]),
    );
    assert!(
        r.diagnostics[0].message.contains("seed 003"),
        "{}",
        r.diagnostics[0].message
    );
}

#[test]
fn behaviour4_9_only_g00_to_g03_and_g90_g91_may_share_the_block() {
    let s = mill(&[(1, 5.0), (2, 10.0)]);
    assert!(errors("G90 G01 G45 X10. D01 F100.", &s).is_empty());
    assert_eq!(
        errors("G43 G45 X10. D01 H02", &s),
        vec!["position-offset-g-code"]
    );
    assert_eq!(
        errors("G17 G45 X10. D01", &s),
        vec!["position-offset-g-code"]
    );
    assert_eq!(
        errors("G21 G45 X10. D01", &s),
        vec!["position-offset-g-code"]
    );
}

#[test]
fn behaviour4_9_two_position_offset_codes_in_a_block_is_an_error() {
    assert_eq!(
        errors("G45 G46 X10. D01", &mill(&[(1, 5.0)])),
        vec!["modal-conflict"]
    );
}

#[test]
fn behaviour4_9_position_offset_without_an_axis_word_is_an_error() {
    assert_eq!(
        errors("G45 D01", &mill(&[(1, 5.0)])),
        vec!["position-offset-without-axis"]
    );
}

#[test]
fn behaviour4_10_position_offset_in_a_canned_cycle_is_an_error() {
    let text = "G90 G00 Z10.\nG81 X0 Y0 Z-5. R2. F100.\nG45 X10. D01";
    assert_eq!(
        errors(text, &mill(&[(1, 5.0)])),
        vec!["position-offset-in-cycle"]
    );
    let text = "G90 G00 Z10.\nG81 X0 Y0 Z-5. R2. F100.\nG80\nG45 X10. D01";
    assert!(errors(text, &mill(&[(1, 5.0)])).is_empty());
}

#[test]
fn behaviour4_11_length_and_position_offsets_add_up_on_z() {
    let text = "G90 G00 G43 Z50. H02\nG91 G45 Z-10. D01";
    let r = ok(text, &mill(&[(1, 6.0), (2, 15.0)]));
    // Programmed 40, + length 15, + position -6 (extension along the -Z move).
    same(programmed(&r, 1), [0.0, 0.0, 40.0]);
    same(actual(&r, 1), [0.0, 0.0, 49.0]);
    let b = at_line(&r, text, 2);
    assert_eq!(b.length_offset.unwrap().vector, 15.0);
    assert_eq!(b.position_offset.unwrap().vector.z, -6.0);
}

#[test]
fn behaviour4_12_the_register_is_read_when_the_block_runs() {
    // D is modal; a later block reads the register's value of the run.
    let text = "G91 G45 X10. D01\nG45 X10.";
    let a = ok(text, &mill(&[(1, 1.0)]));
    let b = ok(text, &mill(&[(1, 2.0)]));
    same(actual(&a, 1), [22.0, 0.0, 0.0]);
    same(actual(&b, 1), [24.0, 0.0, 0.0]);
}

#[test]
fn behaviour4_d00_reads_zero_and_d_is_modal() {
    let r = ok("G91 G45 X10. D00\nG45 Y10.", &mill(&[(1, 5.0)]));
    same(actual(&r, 1), [10.0, 10.0, 0.0]);
}

#[test]
fn behaviour4_mirror_image_reverses_the_offset_with_the_movement() {
    // Seed 003: mirror image can be applied to tool position offset.
    let mut s = mill(&[(1, 6.0)]);
    s.settings.mirror = Mirror { x: true, y: false };
    let text = SQUARE;
    let r = ok(text, &s);
    let want = [
        [30.0, -20.0],
        [6.0, -6.0],
        [-86.0, -6.0],
        [-86.0, 56.0],
        [6.0, 56.0],
    ];
    for (i, w) in want.iter().enumerate() {
        same(actual(&r, i), [w[0], w[1], 0.0]);
    }
    // A zero move follows the mirrored direction too.
    let r = ok("G91 G45 X0 D01", &s);
    same(actual(&r, 0), [-6.0, 0.0, 0.0]);
}

#[test]
fn behaviour1_18_d_and_h_read_one_table() {
    // One offset memory (YASNAC; Fanuc memory type A): H01 and D01 are the
    // same register.
    let text = "G90 G00 G43 Z10. H01\nG91 G45 X10. D01";
    let r = ok(text, &mill(&[(1, 5.0)]));
    same(actual(&r, 1), [15.0, 0.0, 15.0]);
}
