//! Behaviour 5 (`docs/behaviour.md`): lathe T-code tool position offset
//! (seed 004), machine `lathe`.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::EventKind;
use offsetlab::setup::LatheXOffset;
use offsetlab::{MoveKind, run};

const WORKED: &str = "G50 X120. Z60.;\nG00 S800 M03 T0108;\nX50. Z3.;\nT0100;";

#[test]
fn behaviour5_worked_example_seed004() {
    let r = ok(WORKED, &lathe(&[(8, 0.4, -0.2)]));
    same(actual(&r, 0), [120.0, 0.0, 60.0]);
    same(actual(&r, 1), [120.4, 0.0, 59.8]);
    same(actual(&r, 2), [50.4, 0.0, 2.8]);
    same(actual(&r, 3), [50.0, 0.0, 3.0]);
    let b = at_line(&r, WORKED, 2);
    assert_eq!(b.programmed.y, None, "lathe positions have no Y");
    let t = b.lathe_offset.unwrap();
    assert_eq!(
        (t.tool, t.offset, t.vector.x, t.vector.z),
        (1, 8, 0.4, -0.2)
    );
}

#[test]
fn behaviour5_1_the_offset_starts_in_the_block_with_the_t_code() {
    let r = ok(WORKED, &lathe(&[(8, 0.4, -0.2)]));
    same(r.blocks[0].state.lathe.vector, [0.0; 3]);
    same(r.blocks[1].state.lathe.vector, [0.4, 0.0, -0.2]);
}

#[test]
fn behaviour5_2_t_with_a_move_lands_on_the_end_point_plus_the_offset_in_one_move() {
    let r = ok(
        "G50 X120. Z60.\nG00 X50. Z3. T0108",
        &lathe(&[(8, 0.4, -0.2)]),
    );
    assert_eq!(r.blocks[1].move_count, 1);
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Rapid);
    same(m.from, [120.0, 0.0, 60.0]);
    same(m.to, [50.4, 0.0, 2.8]);
}

#[test]
fn behaviour5_2_t_with_a_single_axis_move_offsets_both_axes() {
    let r = ok("G50 X120. Z60.\nG00 Z3. T0108", &lathe(&[(8, 0.4, -0.2)]));
    same(actual(&r, 1), [120.4, 0.0, 2.8]);
}

#[test]
fn behaviour5_3_t_alone_moves_by_the_difference_at_rapid_in_g00() {
    let r = ok(WORKED, &lathe(&[(8, 0.4, -0.2)]));
    let m = &r.moves[0];
    assert_eq!((m.kind, m.at_feed), (MoveKind::Offset, false));
    same(m.programmed_from, m.programmed_to);
    assert!(
        explain(&r, 1).contains("at rapid (G00)"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour5_3_t_alone_in_g01_moves_at_the_cutting_feed() {
    // Seed 004: "GO1 T0216 ;" — offset motion at the cutting feedrate.
    let text = "G50 X100. Z50.\nG00 T0202\nG01 X60. Z2. F0.2\nG01 T0216";
    let r = ok(text, &lathe(&[(2, 0.2, 0.1), (16, 0.6, -0.3)]));
    let m = r.moves.last().unwrap();
    assert_eq!((m.kind, m.at_feed), (MoveKind::Offset, true));
    same(m.from, [60.2, 0.0, 2.1]);
    same(m.to, [60.6, 0.0, 1.7]);
    assert!(
        explain(&r, 3).contains("at the cutting feed (G01)"),
        "{}",
        explain(&r, 3)
    );
}

#[test]
fn behaviour5_4_new_offset_in_a_feed_move_corrects_the_taper() {
    // Seed 004: G01 U+… W-… F… T0216 ends shifted by the difference of the
    // offsets of T0216 and T0202.
    let text = "G50 X100. Z50.\nG00 T0202\nG01 X60. Z2. F0.2\nG01 U10. W-20. F0.2 T0216";
    let r = ok(text, &lathe(&[(2, 0.2, 0.1), (16, 0.6, -0.3)]));
    same(programmed(&r, 3), [70.0, 0.0, -18.0]);
    same(actual(&r, 3), [70.6, 0.0, -18.3]);
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Feed);
    same(m.from, [60.2, 0.0, 2.1]);
    let e = explain(&r, 3);
    assert!(
        e.contains("X +0.400 Z -0.400") && e.contains("taper"),
        "{e}"
    );
}

#[test]
fn behaviour5_5_cancel_with_a_move_goes_to_the_programmed_position() {
    let text = "G50 X120. Z60.\nG00 T0108\nX50. Z3.\nG00 X100. Z50. T0100";
    let r = ok(text, &lathe(&[(8, 0.4, -0.2)]));
    same(actual(&r, 3), [100.0, 0.0, 50.0]);
    assert_eq!(r.blocks[3].move_count, 1);
}

#[test]
fn behaviour5_5_cancel_alone_makes_only_the_cancel_motion() {
    let r = ok(WORKED, &lathe(&[(8, 0.4, -0.2)]));
    let m = r.moves.last().unwrap();
    assert_eq!(m.kind, MoveKind::Offset);
    same(m.from, [50.4, 0.0, 2.8]);
    same(m.to, [50.0, 0.0, 3.0]);
    assert!(
        explain(&r, 3).contains("only the cancel motion"),
        "{}",
        explain(&r, 3)
    );
}

#[test]
fn behaviour5_6_a_new_tool_number_indexes_the_turret() {
    let r = ok("T0101\nT0102\nT0202", &lathe(&[]));
    let tools: Vec<u32> = r
        .events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::ToolIndex { tool } => Some(tool),
            _ => None,
        })
        .collect();
    assert_eq!(tools, vec![1, 2]);
}

#[test]
fn behaviour5_t108_is_the_same_as_t0108() {
    let a = ok("T108", &lathe(&[(8, 0.4, -0.2)]));
    let b = ok("T0108", &lathe(&[(8, 0.4, -0.2)]));
    same(actual(&a, 0), actual(&b, 0));
}

#[test]
fn behaviour5_geometry_plus_wear() {
    let mut s = lathe(&[]);
    s.set_register("08=X0.4,Z-0.2,XW-0.02,ZW0.01").unwrap();
    let r = ok("T0108", &s);
    same(actual(&r, 0), [0.38, 0.0, -0.19]);
}

#[test]
fn behaviour5_lathe_x_offset_radius_doubles_x() {
    let mut s = lathe(&[(8, 0.2, -0.2)]);
    s.settings.lathe_x_offset = LatheXOffset::Radius;
    let r = ok("G50 X120. Z60.\nT0108", &s);
    same(actual(&r, 1), [120.4, 0.0, 59.8]);
}

#[test]
fn behaviour5_u_and_w_are_incremental_and_x_is_a_diameter() {
    let r = ok("G50 X100. Z10.\nG01 U-20. W-5. F0.2", &lathe(&[]));
    same(programmed(&r, 1), [80.0, 0.0, 5.0]);
    assert_eq!(
        errors("G01 X10. U5. F0.2", &lathe(&[])),
        vec!["axis-conflict"]
    );
}

#[test]
fn behaviour5_arc_with_r_and_with_i_k_in_the_zx_plane() {
    let s = lathe(&[]);
    for text in [
        "G00 X20. Z0\nG02 X40. Z-10. R10. F0.2",
        "G00 X20. Z0\nG02 X40. Z-10. I10. K0 F0.2",
    ] {
        let r = ok(text, &s);
        let m = r.moves.last().unwrap();
        assert_eq!(m.kind, MoveKind::ArcCw);
        let a = m.arc.unwrap();
        // Centre at Z0 and radius 20 (diameter 40); radius 10.
        same(a.center, [40.0, 0.0, 0.0]);
        assert!((a.radius - 10.0).abs() < 1e-9);
        assert!((a.sweep + std::f64::consts::FRAC_PI_2).abs() < 1e-9);
    }
}

#[test]
fn behaviour5_g90_turning_cycle_legs() {
    let text = "G50 X60. Z2.\nG90 X50. Z-30. F0.2\nX45.";
    let r = ok(text, &lathe(&[]));
    let legs: Vec<([f64; 3], MoveKind)> =
        r.moves.iter().map(|m| (m.programmed_to, m.kind)).collect();
    assert_eq!(legs.len(), 8);
    same(legs[0].0, [50.0, 0.0, 2.0]);
    same(legs[1].0, [50.0, 0.0, -30.0]);
    same(legs[2].0, [60.0, 0.0, -30.0]);
    same(legs[3].0, [60.0, 0.0, 2.0]);
    assert_eq!(
        legs[..4].iter().map(|l| l.1).collect::<Vec<_>>(),
        vec![
            MoveKind::Rapid,
            MoveKind::Feed,
            MoveKind::Feed,
            MoveKind::Rapid
        ]
    );
    // The next pass repeats the cycle with the new X.
    same(legs[5].0, [45.0, 0.0, -30.0]);
}

#[test]
fn behaviour5_g90_taper_and_g94_facing_and_g92_threading() {
    let r = ok("G50 X60. Z2.\nG90 X50. Z-30. R-2. F0.2", &lathe(&[]));
    same(r.moves[0].programmed_to, [46.0, 0.0, 2.0]);
    let r = ok("G50 X60. Z2.\nG94 X20. Z-2. F0.2", &lathe(&[]));
    let to: Vec<[f64; 3]> = r.moves.iter().map(|m| m.programmed_to).collect();
    same(to[0], [60.0, 0.0, -2.0]);
    same(to[1], [20.0, 0.0, -2.0]);
    same(to[2], [20.0, 0.0, 2.0]);
    same(to[3], [60.0, 0.0, 2.0]);
    let r = ok("G50 X40. Z5.\nG92 X38.5 Z-20. F1.5", &lathe(&[]));
    let kinds: Vec<MoveKind> = r.moves.iter().map(|m| m.kind).collect();
    assert_eq!(
        kinds,
        vec![
            MoveKind::Rapid,
            MoveKind::Feed,
            MoveKind::Rapid,
            MoveKind::Rapid
        ]
    );
}

#[test]
fn behaviour5_cycles_carry_the_t_offset() {
    let r = ok(
        "G50 X60. Z2.\nT0108\nG90 X50. Z-30. F0.2",
        &lathe(&[(8, 0.4, -0.2)]),
    );
    same(r.moves.last().unwrap().to, [60.4, 0.0, 1.8]);
    same(r.moves[2].to, [50.4, 0.0, -30.2]);
}

#[test]
fn behaviour5_g28_clears_the_vector_until_the_axis_moves_again() {
    let text = "G50 X100. Z50.\nT0108\nG28 U0 W0\nG00 Z10.\nX30.";
    let mut setup = lathe(&[(8, 0.4, -0.2)]);
    setup.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    let r = ok(text, &setup);
    same(r.blocks[2].state.lathe.vector, [0.0; 3]);
    // With the reference position at machine zero (setting 7.49
    // `work_zero`), where the tool started and G50 named X100. Z50.
    same(actual(&r, 2), [100.0, 0.0, 50.0]);
    same(actual(&r, 3), [100.0, 0.0, 9.8]);
    same(actual(&r, 4), [30.4, 0.0, 9.8]);
}

#[test]
fn behaviour5_unsupported_lathe_codes_are_errors_with_a_reason() {
    let s = lathe(&[]);
    for (text, why) in [("G43 H1", "T-code offsets"), ("G32 Z-10. F1.5", "thread")] {
        let r = run(text, &s);
        let d = &r.diagnostics[0];
        assert_eq!(d.code, "unsupported-g-code");
        assert!(d.message.contains(why), "{text}: {}", d.message);
    }
    assert_eq!(errors("G00 Y10.", &s), vec!["mill-address"]);
    assert_eq!(errors("G00 X10. D01", &s), vec!["mill-address"]);
}

#[test]
fn behaviour5_offset_number_beyond_the_table_is_an_error() {
    let mut s = lathe(&[]);
    s.table_size = 32;
    assert_eq!(errors("T0133", &s), vec!["out-of-range"]);
}

#[test]
fn behaviour5_offset_change_with_no_move_in_arc_mode_is_an_error() {
    let s = lathe(&[(8, 0.4, -0.2)]);
    assert_eq!(
        errors("G00 X20. Z0\nG02 X40. Z-10. R10. F0.2\nT0108", &s),
        vec!["offset-motion-mode"]
    );
}

#[test]
fn behaviour5_9_g50_needs_x_and_z_or_s() {
    assert_eq!(errors("G50", &lathe(&[])), vec!["g50-without-axis"]);
    assert!(errors("G50 S3000", &lathe(&[])).is_empty());
    // U and W set the coordinate incrementally.
    let r = ok("G50 X100. Z50.\nG50 U-10. W5.", &lathe(&[]));
    same(programmed(&r, 1), [90.0, 0.0, 55.0]);
}

#[test]
fn behaviour5_10_a_turning_cycle_needs_its_x_and_z() {
    assert_eq!(
        errors("G50 X60. Z2.\nG90 X50. F0.2", &lathe(&[])),
        vec!["cycle-without-target"]
    );
}
