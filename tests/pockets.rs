//! Behaviour 14.12–14.13 (`docs/behaviour.md`): Haas G12/G13 circular pocket
//! milling — the generated arcs and lines, computed here by hand, with the D
//! register as Haas applies it, the passes of L, and the refusals.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{CirclePocket, Control, Mirror};
use offsetlab::{Move, MoveKind, run};
use std::f64::consts::PI;

/// A Haas mill with registers `(number, value)`, the tool starting at the
/// work zero (setting 7.49: the pockets are worked from there, not from the
/// profile's typical home).
fn haas(registers: &[(u16, f64)]) -> offsetlab::Setup {
    let mut s = mill(registers);
    s.settings.control = Control::Haas;
    s.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    s
}

#[track_caller]
fn arc(m: &Move, radius: f64, programmed_radius: f64, centre: [f64; 3], sweep: f64) {
    let a = m.arc.expect("an arc");
    assert!(
        (a.radius - radius).abs() < 1e-9,
        "radius {} want {radius}",
        a.radius
    );
    assert!(
        (a.programmed_radius - programmed_radius).abs() < 1e-9,
        "programmed radius {} want {programmed_radius}",
        a.programmed_radius
    );
    same(a.center, centre);
    assert!(
        (a.sweep - sweep).abs() < 1e-9,
        "sweep {} want {sweep}",
        a.sweep
    );
}

#[test]
fn behaviour14_12_the_haas_example_i_k_q_cuts_circles_from_i_out_to_k() {
    // The Haas manual's rough-and-finish form in inches, I0.25 K1.0 Q0.25,
    // with D01 = 0.125 (a 1/4 in end mill) about X1. Y2.: the contour's
    // circles have radii 0.25, 0.5, 0.75, 1.0 and the tool centre runs 0.125
    // inside each, on 0.125, 0.375, 0.625, 0.875.
    let mut s = haas(&[(1, 0.125)]);
    s.units = offsetlab::Units::Inch;
    let text = "G00 X1. Y2.\nG13 I0.25 K1.0 Q0.25 D01 Z-0.1 F10.";
    let r = ok(text, &s);
    let mm = |v: f64| v * 25.4;
    let p = |x: f64, y: f64, z: f64| [mm(x), mm(y), mm(z)];
    let moves: Vec<&Move> = r.moves.iter().filter(|m| m.line == 2).collect();
    // Z feed, lead-in, 4 circles, 3 steps out, lead-out.
    assert_eq!(moves.len(), 10);
    assert_eq!(moves[0].kind, MoveKind::Feed);
    same(moves[0].to, p(1.0, 2.0, -0.1));
    // Lead-in: half circle from the centre (1, 2) to the first circle, CCW
    // (G13): the tool's from (1, 2) to (1.125, 2) about (1.0625, 2), radius
    // 0.0625; the contour's to (1.25, 2) about (1.125, 2), radius 0.125.
    assert_eq!(moves[1].kind, MoveKind::ArcCcw);
    same(moves[1].from, p(1.0, 2.0, -0.1));
    same(moves[1].to, p(1.125, 2.0, -0.1));
    same(moves[1].programmed_to, p(1.25, 2.0, -0.1));
    arc(moves[1], mm(0.0625), mm(0.125), p(1.0625, 2.0, -0.1), PI);
    // The circles: full turns about the centre.
    for (k, (r_tool, r_contour)) in [(0.125, 0.25), (0.375, 0.5), (0.625, 0.75), (0.875, 1.0)]
        .into_iter()
        .enumerate()
    {
        let c = moves[2 + 2 * k];
        assert_eq!(c.kind, MoveKind::ArcCcw);
        same(c.from, p(1.0 + r_tool, 2.0, -0.1));
        same(c.to, p(1.0 + r_tool, 2.0, -0.1));
        arc(c, mm(r_tool), mm(r_contour), p(1.0, 2.0, -0.1), 2.0 * PI);
        if k < 3 {
            // The step out to the next circle: a feed along +X by Q (0.25).
            let step = moves[3 + 2 * k];
            assert_eq!(step.kind, MoveKind::Feed);
            same(step.from, p(1.0 + r_tool, 2.0, -0.1));
            same(step.to, p(1.0 + r_tool + 0.25, 2.0, -0.1));
            same(step.programmed_to, p(1.0 + r_contour + 0.25, 2.0, -0.1));
        }
    }
    // Lead-out: half circle from (1.875, 2) back to the centre about
    // (1.4375, 2), radius 0.4375 (contour: from (2, 2) about (1.5, 2), 0.5).
    arc(moves[9], mm(0.4375), mm(0.5), p(1.4375, 2.0, -0.1), PI);
    same(moves[9].to, p(1.0, 2.0, -0.1));
    same(actual(&r, 1), p(1.0, 2.0, -0.1));
    let s = explain(&r, 1);
    assert!(s.starts_with("G13 circular pocket (Haas), counter-clockwise about X1.0000 Y2.0000: 4 circles of radius 0.2500 to 1.0000 in steps of 0.2500, the tool centre on radii 0.1250 to 0.8750, inside the contour by D01 (0.1250)"), "{s}");
}

#[test]
fn behaviour14_12_i_alone_cuts_one_circle_and_k_need_not_be_a_whole_number_of_steps() {
    // G12 I10. with D01 = 3 from the centre (0, 0), X and Y given in the
    // block: a rapid to (20, 10), lead-in CW to (27, 10), the circle of
    // radius 7 CW, lead-out back. CW: the sweeps are negative.
    let r = ok("G12 X20. Y10. I10. D01 F200.", &haas(&[(1, 3.0)]));
    assert_eq!(r.moves.len(), 4);
    assert_eq!(r.moves[0].kind, MoveKind::Rapid);
    same(r.moves[0].to, [20.0, 10.0, 0.0]);
    arc(&r.moves[1], 3.5, 5.0, [23.5, 10.0, 0.0], -PI);
    // A clockwise half circle from the centre to +X starts at the angle π
    // about its own centre and passes above it, through (23.5, 13.5).
    assert!((r.moves[1].arc.unwrap().start_angle - PI).abs() < 1e-9);
    arc(&r.moves[2], 7.0, 10.0, [20.0, 10.0, 0.0], -2.0 * PI);
    arc(&r.moves[3], 3.5, 5.0, [23.5, 10.0, 0.0], -PI);
    // K0.. I5 K12 Q3 gives 5, 8, 11, 12: the last step is 1.
    let r = ok("G13 I5. K12. Q3. F100.", &haas(&[]));
    let circles: Vec<f64> = r
        .moves
        .iter()
        .filter_map(|m| m.arc)
        .filter(|a| (a.sweep - 2.0 * PI).abs() < 1e-9)
        .map(|a| a.programmed_radius)
        .collect();
    assert_eq!(circles, vec![5.0, 8.0, 11.0, 12.0]);
    // D00 is the tool centreline: both paths are the same.
    assert!(
        r.moves
            .iter()
            .all(|m| m.from == m.programmed_from && m.to == m.programmed_to)
    );
}

#[test]
fn behaviour14_12_l_repeats_the_pass_and_in_g91_z_steps_down_each_time() {
    // G91 Z-1. L3 from Z0: passes at Z-1, -2, -3, each a feed down, lead-in,
    // circle, lead-out (4 moves), ending at the centre at Z-3.
    let r = ok("G12 G91 Z-1. I6. L3 D01 F100.", &haas(&[(1, 2.0)]));
    assert_eq!(r.moves.len(), 12);
    for (k, z) in [-1.0, -2.0, -3.0].into_iter().enumerate() {
        assert_eq!(r.moves[4 * k].kind, MoveKind::Feed);
        same(r.moves[4 * k].to, [0.0, 0.0, z]);
        arc(&r.moves[4 * k + 2], 4.0, 6.0, [0.0, 0.0, z], -2.0 * PI);
    }
    same(programmed(&r, 0), [0.0, 0.0, -3.0]);
    assert!(
        explain(&r, 0).ends_with("3 passes (L3)."),
        "{}",
        explain(&r, 0)
    );
    // In G90 the depth is the same on every pass: the second pass has no
    // move down (4 + 3 moves), its lead-in starts at the centre at Z-1.
    let r = ok("G12 Z-1. I6. L2 F100.", &haas(&[]));
    assert_eq!(r.moves.len(), 7);
    same(r.moves[4].from, [0.0, 0.0, -1.0]);
    assert!(r.moves[4].arc.is_some());
}

#[test]
fn behaviour14_12_the_offsets_and_mirror_image_carry_the_pocket() {
    // G43 H02 = 50: the actual Z is 50 above the programmed one throughout.
    let r = ok("G43 Z10. H02\nG12 Z-5. I4. F100.", &haas(&[(2, 50.0)]));
    assert!(
        r.moves[1..]
            .iter()
            .all(|m| (m.to[2] - m.programmed_to[2] - 50.0).abs() < 1e-9)
    );
    same(actual(&r, 1), [0.0, 0.0, 45.0]);
    // Mirror image of X: the lead-in goes to -X and G12 turns the other way.
    let mut s = haas(&[]);
    s.settings.mirror = Mirror { x: true, y: false };
    let r = ok("G12 I4. F100.", &s);
    same(r.moves[0].to, [-4.0, 0.0, 0.0]);
    assert_eq!(r.moves[1].kind, MoveKind::ArcCcw);
}

#[test]
fn behaviour14_12_a_pocket_is_bounded_by_the_move_budget() {
    let options = offsetlab::RunOptions {
        max_moves: 100,
        ..offsetlab::RunOptions::default()
    };
    let r = offsetlab::run_with("G12 I1. K9000. Q0.001 L9999 F100.", &haas(&[]), options);
    assert_eq!(r.diagnostics.last().unwrap().code, "too-many-moves");
    assert!(r.moves.len() <= 100);
}

#[test]
fn behaviour14_13_pocket_words_are_checked_as_haas_does() {
    let s = haas(&[(1, 3.0)]);
    for (text, why) in [
        ("G12 F100.", "needs I"),
        ("G12 I3. D01 F100.", "greater than the tool radius"),
        ("G12 I5. K4. Q1. F100.", "must be greater than I"),
        ("G12 I5. K10. F100.", "K needs Q"),
        ("G12 I5. Q1. F100.", "goes with K"),
        ("G12 I5. K10. Q-1. F100.", "must be positive"),
        ("G12 I5. L0 F100.", "1 or more"),
        ("G12 I5. J1. F100.", "does not read J"),
        ("G12 I5. H01 F100.", "does not read H"),
        ("G18\nG12 I5. F100.", "XY plane"),
        ("G81 X0 Z-5. R1. F10.\nG12 I5.", "canned cycle"),
    ] {
        let r = run(text, &s);
        let e = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!(e.code, "pocket-words", "{text}");
        assert!(e.message.contains(why), "{text}: {}", e.message);
    }
}

#[test]
fn behaviour14_13_fanuc_and_yasnac_mills_alarm_on_g12_and_g13() {
    for control in [Control::Yasnac, Control::Fanuc] {
        let mut s = mill(&[]);
        s.settings.control = control;
        let r = run("G12 I5. F100.", &s);
        let e = &r.diagnostics[0];
        assert_eq!(e.code, "unsupported-g-code");
        assert!(
            e.message.contains("circular pocket milling on a Haas mill"),
            "{}",
            e.message
        );
        // The setting models the pocket on them too.
        s.settings.circle_pocket = Some(CirclePocket::Haas);
        ok("G12 I5. F100.", &s);
    }
    // And a Haas profile may refuse it.
    let mut s = haas(&[]);
    s.settings.circle_pocket = Some(CirclePocket::Alarm);
    assert_eq!(errors("G13 I5. F100.", &s), vec!["unsupported-g-code"]);
}

#[test]
fn behaviour14_12_the_haas_modes_fixture_runs_to_its_end_as_computed_by_hand() {
    let (text, setup) = fixture("haas_modes");
    let r = ok(&text, &setup);
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    // N45: back at the centre at Z-2, the length vector +3 on the actual Z.
    let state = |line: u32| r.blocks.iter().find(|b| b.span.line == line).unwrap().state;
    same(state(11).programmed, [20.0, 10.0, -2.0]);
    same(state(11).actual, [20.0, 10.0, 1.0]);
    // N50: two passes down by 1 from Z-2: Z-4.
    same(state(12).programmed, [20.0, 10.0, -4.0]);
    // N45 makes a feed down, lead-in, 3 circles, 2 steps, lead-out: 8 moves.
    assert_eq!(r.moves.iter().filter(|m| m.line == 11).count(), 8);
}
