//! Behaviour 12 and settings 7.17–7.19 (`docs/behaviour.md`): the control
//! profile and the settings whose defaults it gives — two G codes of one
//! group (1.11), the lathe's G-code systems — and the words the parser reads
//! but the machine refuses until they are modelled (1.7).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Control, GCodeSystem, SameGroupCodes, Settings};
use offsetlab::{MachineKind, MoveKind, Setup, run};

fn with_control(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

fn warnings(r: &offsetlab::Run) -> Vec<&'static str> {
    r.diagnostics
        .iter()
        .filter(|d| !d.is_error())
        .map(|d| d.code)
        .collect()
}

#[test]
fn behaviour12_the_profile_gives_the_defaults_and_a_setting_set_wins() {
    let mut s = Settings::default();
    assert_eq!(s.control, Control::Yasnac);
    assert_eq!(s.same_group_codes(), SameGroupCodes::Error);
    assert_eq!(s.gcode_system(), GCodeSystem::A);
    s.control = Control::Fanuc;
    assert_eq!(s.same_group_codes(), SameGroupCodes::LastWins);
    s.control = Control::Haas;
    assert_eq!(s.same_group_codes(), SameGroupCodes::LastWins);
    assert_eq!(s.gcode_system(), GCodeSystem::A);
    s.same_group_codes = Some(SameGroupCodes::Error);
    assert_eq!(s.same_group_codes(), SameGroupCodes::Error);
    // In a document: `control` and a setting left out (the control's) or set.
    let setup = Setup::from_json(r#"{"settings":{"control":"fanuc"}}"#).unwrap();
    assert_eq!(setup.settings.same_group_codes(), SameGroupCodes::LastWins);
    assert!(setup.to_json().contains("\"control\": \"fanuc\""));
    assert!(!setup.to_json().contains("same_group_codes"));
    let e = Setup::from_json(r#"{"settings":{"control":"siemens"}}"#).unwrap_err();
    assert!(e.to_string().contains("unknown variant `siemens`"), "{e}");
}

#[test]
fn behaviour1_11_two_codes_of_a_group_are_an_error_on_yasnac() {
    assert_eq!(
        errors("G91 G28 X0 Y0 Z100. G90", &Setup::default()),
        vec!["modal-conflict"]
    );
}

#[test]
fn behaviour1_11_the_last_code_of_a_group_wins_on_fanuc_and_haas_with_a_warning() {
    // Fanuc: "G91 G28 X0 Y0 Z100. G90" is G28 in G90: the intermediate point
    // is X0 Y0 Z100. in work coordinates, then the reference — on the Fanuc
    // and Haas profiles a typical machine's (setting 7.49, behaviour 13.15):
    // X0 Y0 over the work zero and Z at the top of a VF-2's travel, 508 mm
    // (G54 at machine zero, so machine and work coordinates agree): from
    // X10 Y20 Z30, moves to (0, 0, 100) then (0, 0, 508); the block leaves
    // G90 in effect, so X5. goes to (5, 0, 508).
    for control in [Control::Fanuc, Control::Haas] {
        let s = with_control(Setup::default(), control);
        let text = "G00 X10. Y20. Z30.\nG91 G28 X0 Y0 Z100. G90\nX5.";
        let r = ok(text, &s);
        assert_eq!(warnings(&r), vec!["modal-conflict"]);
        let d = &r.diagnostics[0];
        assert!(
            d.message.contains("the last one, G90, is in effect"),
            "{}",
            d.message
        );
        assert_eq!((d.span.line, d.span.start), (2, 19 + 20));
        let g28: Vec<_> = r.moves.iter().filter(|m| m.line == 2).collect();
        same(g28[0].to, [0.0, 0.0, 100.0]);
        same(g28[1].to, [0.0, 0.0, 508.0]);
        // G90 stays: X5. is absolute.
        same(actual(&r, 2), [5.0, 0.0, 508.0]);
    }
    // A setting set in the setup wins over the profile.
    let mut s = with_control(Setup::default(), Control::Fanuc);
    s.settings.same_group_codes = Some(SameGroupCodes::Error);
    assert_eq!(errors("G00 G01 X1.", &s), vec!["modal-conflict"]);
}

#[test]
fn behaviour1_11_last_wins_in_every_group_and_the_block_reads_the_last() {
    let mut s = with_control(Setup::default(), Control::Fanuc);
    // The tool starts at the work zero (setting 7.49): the positions are
    // not the point here.
    s.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    // G00 then G01: the move is a feed; G20 then G21: metric.
    let r = ok("G00 G01 X10. F100.\nG20 G21 X12.", &s);
    assert_eq!(r.moves[0].kind, MoveKind::Feed);
    same(actual(&r, 1), [12.0, 0.0, 0.0]);
    assert_eq!(warnings(&r), vec!["modal-conflict", "modal-conflict"]);
}

fn lathe_in(system: GCodeSystem) -> Setup {
    let mut s = lathe(&[]);
    s.settings.gcode_system = Some(system);
    s
}

#[test]
fn behaviour7_18_system_b_g90_g91_are_distance_modes_and_g77_the_turning_cycle() {
    let s = lathe_in(GCodeSystem::B);
    // G92 sets X100 Z50; G91 X-20. W-5.: both incremental, to X80 Z45;
    // G90 X60.: absolute; G77 X50. Z20. F0.2 is the turning cycle from
    // (60, 45): rapid to X50, feed to Z20, feed out to X60, rapid back.
    let text = "G92 X100. Z50.\nG00 G91 X-20. W-5.\nG90 X60.\nG77 X50. Z20. F0.2";
    let r = ok(text, &s);
    same(actual(&r, 1), [80.0, 0.0, 45.0]);
    same(actual(&r, 2), [60.0, 0.0, 45.0]);
    let cycle: Vec<_> = r.moves.iter().filter(|m| m.line == 4).collect();
    assert_eq!(cycle.len(), 4);
    same(cycle[0].to, [50.0, 0.0, 45.0]);
    same(cycle[1].to, [50.0, 0.0, 20.0]);
    same(cycle[2].to, [60.0, 0.0, 20.0]);
    same(cycle[3].to, [60.0, 0.0, 45.0]);
    let b = at_line(&r, text, 4);
    assert_eq!(b.modal.motion, "G77");
    assert_eq!(b.modal.distance, Some("G90"));
    assert_eq!(b.modal.feed_mode, "G95");
    // The summary names the system (the page's summary line says it).
    assert_eq!(offsetlab::view::summary(&r).gcode_system, Some("B"));
    assert_eq!(
        offsetlab::view::summary(&ok("G00 X1.", &lathe(&[]))).gcode_system,
        Some("A")
    );
    assert_eq!(
        offsetlab::view::summary(&ok("G00 X1.", &Setup::default())).gcode_system,
        None
    );
    // G50 is system A's coordinate setting: refused with the reason.
    let e = run("G50 X100. Z50.", &s);
    assert!(
        e.diagnostics[0].message.contains("set with G92"),
        "{:?}",
        e.diagnostics
    );
}

#[test]
fn behaviour7_18_system_c_numbers_inch_metric_g70_g71_and_the_cycles_g20_g21_g24() {
    let s = lathe_in(GCodeSystem::C);
    // G70: inch. G92 X4. Z2. sets (101.6, 50.8) mm; G24 X3. Z1. is the
    // facing cycle from there: rapid to Z1. (25.4 mm), feed to X3. (76.2),
    // feed back to Z2., rapid to X4.
    let text = "G70\nG92 X4. Z2.\nG24 X3. Z1. F0.01";
    let r = ok(text, &s);
    let cycle: Vec<_> = r.moves.iter().filter(|m| m.line == 3).collect();
    assert_eq!(cycle.len(), 4);
    same(cycle[0].to, [101.6, 0.0, 25.4]);
    same(cycle[1].to, [76.2, 0.0, 25.4]);
    same(cycle[2].to, [76.2, 0.0, 50.8]);
    same(cycle[3].to, [101.6, 0.0, 50.8]);
    assert_eq!(at_line(&r, text, 3).modal.motion, "G24");
    assert_eq!(at_line(&r, text, 3).modal.units, "G70");
    // The mill reads one table whatever the setting.
    let mut m = Setup::default();
    m.settings.gcode_system = Some(GCodeSystem::C);
    assert_eq!(m.machine, MachineKind::Mill);
    let r = ok("G20 G91 X1.", &m);
    same(actual(&r, 0), [25.4, 0.0, 0.0]);
}

#[test]
fn behaviour7_18_system_a_keeps_g90_the_turning_cycle_and_refuses_g91() {
    let s = lathe(&[]);
    let e = run("G91 U1.", &s);
    assert!(
        e.diagnostics[0]
            .message
            .contains("setting gcode_system B or C"),
        "{:?}",
        e.diagnostics
    );
}

#[test]
fn behaviour1_7_words_read_but_not_modelled_are_refused_by_the_machine() {
    let mill = Setup::default();
    // The mill's rotary axes A, B, C are reported (behaviour 13.14,
    // tests/coordinates.rs); the lathe refuses them.
    let text = "G00 X1. E2.";
    let r = run(text, &mill);
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!(d.code, "unsupported-word", "{text}");
    assert!(
        d.message.starts_with("E: thread lead"),
        "{text}: {}",
        d.message
    );
    assert!(r.moves.is_empty(), "{text}: nothing moves");
    let r = run("G01 U1. C1. F0.1", &lathe(&[]));
    assert!(r.diagnostics[0].message.contains("the chamfer word C"));
    // ,C and ,R are modelled on both (behaviour 2.30, 2.35), but not in the
    // lathe's G70–G73 contours.
    let r = run("G01 U4. ,C1. F0.1\nW-2.", &lathe(&[]));
    assert!(
        r.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        r.diagnostics
    );
    let r = run(
        "G71 U1. R0.5\nG71 P10 Q20 U0.2 W0.1 F0.2\nN10 G00 X40.\nG01 Z0 ,C1.\nN20 X50.",
        &lathe(&[]),
    );
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert!(
        d.message
            .starts_with(",C: a chamfer or corner rounding here"),
        "{}",
        d.message
    );
}

#[test]
fn behaviour7_27_to_7_30_the_profiles_give_the_cutter_settings() {
    use offsetlab::setup::{
        CutterCancelWithoutMotion, CutterInterference, CutterOutsideCorner, CutterStartUp,
    };
    // Table 12.2: type A, the Fanuc corners and two blocks read past on
    // every profile; G40 alone takes the vector off but on Haas.
    for control in [Control::Yasnac, Control::Fanuc, Control::Haas] {
        let s = Settings {
            control,
            ..Settings::default()
        };
        assert_eq!(s.cutter_start_up(), CutterStartUp::A);
        assert_eq!(s.cutter_outside_corner(), CutterOutsideCorner::Vectors);
        assert_eq!(s.cutter_blocks_without_motion(), 2);
        assert_eq!(s.cutter_interference_check, CutterInterference::Alarm);
        let want = match control {
            Control::Haas => CutterCancelWithoutMotion::NextMove,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => CutterCancelWithoutMotion::Move,
        };
        assert_eq!(s.cutter_cancel_without_motion(), want);
    }
    // Set in a document, they win; out of range, the setup is refused.
    let setup = Setup::from_json(
        r#"{"settings":{"control":"haas","cutter_start_up":"B","cutter_cancel_without_motion":"move","cutter_blocks_without_motion":4,"cutter_outside_corner":"arc","cutter_interference_check":"off"}}"#,
    )
    .unwrap();
    let s = &setup.settings;
    assert_eq!(s.cutter_start_up(), CutterStartUp::B);
    assert_eq!(
        s.cutter_cancel_without_motion(),
        CutterCancelWithoutMotion::Move
    );
    assert_eq!(s.cutter_blocks_without_motion(), 4);
    assert_eq!(s.cutter_outside_corner(), CutterOutsideCorner::Arc);
    assert_eq!(s.cutter_interference_check, CutterInterference::Off);
    assert!(setup.to_json().contains("\"cutter_start_up\": \"B\""));
    let e = Setup::from_json(r#"{"settings":{"cutter_blocks_without_motion":9}}"#).unwrap_err();
    assert_eq!(e.diagnostics[0].code, "setup-range");
}
