//! Behaviour 17.5–17.11: G10 programmable data input — the mill's tool
//! offsets by memory type, the lathe's geometry and wear, the work offsets,
//! the alarms, what the run reports, and the round trip (a program that sets
//! its registers with G10 draws the path the same registers in the table
//! draw).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

use offsetlab::machine::EventKind;
use offsetlab::setup::{Control, ExtendedWork, OffsetMemory};
use offsetlab::view::summary;
use offsetlab::{Setup, run};

/// A mill setup of offset memory `m` with registers `(number, value)`.
fn memory(m: OffsetMemory, registers: &[(u16, f64)]) -> Setup {
    let mut s = mill(registers);
    s.settings.offset_memory = Some(m);
    s
}

/// The single error code of a run, and its message.
#[track_caller]
fn alarm(text: &str, setup: &Setup) -> (&'static str, String) {
    let r = run(text, setup);
    let errors: Vec<_> = r.diagnostics.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errors.len(), 1, "{:#?}", r.diagnostics);
    (errors[0].code, errors[0].message.clone())
}

#[test]
fn behaviour17_5_memory_a_l11_sets_the_one_value_and_g91_adds() {
    let s = memory(OffsetMemory::A, &[(1, 4.0)]);
    // L11 sets register 01 to 10; H01 and D01 both read it.
    let text = "G10 L11 P1 R10.\nG43 Z0 H01\nG91 G45 X10. D01\nG10 L1 P1 R2.5\nG43 Z0 H01";
    let r = ok(text, &s);
    // G43 Z0 H01 → Z 10; G91 G45 X10. D01 → X 10 + 10 = 20.
    same(actual(&r, 1), [0.0, 0.0, 10.0]);
    same(actual(&r, 2), [20.0, 0.0, 10.0]);
    // L1 is L11 (Fanuc: for older programs); in G91 (set the block
    // before) R adds: 10 + 2.5 = 12.5, read by the next H01: Z 0 + 12.5
    // (Z0 in G91 moves no Z of its own; X stays at 20).
    assert!(explain(&r, 3).contains("register 01 = 12.500 (was 10.000, G91 adds R)"));
    same(actual(&r, 4), [20.0, 0.0, 12.5]);
    // Memory A has no geometry and wear: L10 is the alarm.
    let (code, msg) = alarm("G10 L10 P1 R5.", &s);
    assert_eq!(code, "g10-words");
    assert!(
        msg.contains("offset memory A") && msg.contains("PS0031"),
        "{msg}"
    );
}

#[test]
fn behaviour17_5_memory_b_l10_geometry_and_l11_wear_shared() {
    let s = memory(OffsetMemory::B, &[]);
    let text = "G10 L10 P2 R100.\nG10 L11 P2 R-0.2\nG43 Z5. H02\nG91 G46 X50. D02";
    let r = ok(text, &s);
    // H02 = 100 - 0.2 = 99.8: Z 5 + 99.8 = 104.8; D02 the same: X 50 - 99.8
    // = -49.8.
    same(actual(&r, 2), [0.0, 0.0, 104.8]);
    same(actual(&r, 3), [-49.8, 0.0, 104.8]);
    assert!(explain(&r, 1).contains("register 02 wear = -0.200 (was 0.000)"));
    let (code, msg) = alarm("G10 L12 P2 R5.", &s);
    assert_eq!(code, "g10-words");
    assert!(msg.contains("offset memory B"), "{msg}");
}

#[test]
fn behaviour17_5_memory_c_l10_to_l13_set_the_h_and_d_tables() {
    let s = memory(OffsetMemory::C, &[(1, 4.0)]);
    // H01: geometry 120, wear -0.1 → 119.9. D01: geometry 5, wear 0.02 →
    // 5.02. Register 01 held 4 for both before.
    let text = "G10 L10 P1 R120.\nG10 L11 P1 R-0.1\nG10 L12 P1 R5.\nG10 L13 P1 R0.02\nG43 Z0 H01\nG91 G45 X10. D01";
    let r = ok(text, &s);
    // The example sentence of the task: geometry of D01 was 4 (the shared
    // value).
    assert_eq!(
        explain(&r, 2),
        "G10 L12 P1 R5.000: D01 geometry = 5.000 (was 4.000)."
    );
    same(actual(&r, 4), [0.0, 0.0, 119.9]);
    // G45 X10. D01 → 10 + 5.02 = 15.02.
    same(actual(&r, 5), [15.02, 0.0, 119.9]);
}

#[test]
fn behaviour17_6_lathe_p_below_10000_is_the_wear_and_above_the_geometry() {
    let s = lathe(&[]);
    // Geometry X 0.4 Z -0.2, then wear U 0.02 W -0.01 added (wear was 0):
    // offset 05 = X 0.42, Z -0.21. From X100 Z50, T0105 moves to X100.42
    // Z49.79.
    let text = "G50 X100. Z50.\nG10 P10005 X0.4 Z-0.2\nG10 P5 U0.02 W-0.01\nG00 T0105\nG10 P5 U0.01\nT0105";
    let r = ok(text, &s);
    same(actual(&r, 3), [100.42, 0.0, 49.79]);
    // U adds to the wear: 0.02 + 0.01 = 0.03; the offset in force keeps
    // its value until the T code names it again.
    assert!(explain(&r, 4).contains("X wear = 0.030 (was 0.020)"));
    assert!(explain(&r, 4).contains("in force with its old values"));
    same(actual(&r, 4), [100.42, 0.0, 49.79]);
    same(actual(&r, 5), [100.43, 0.0, 49.79]);
}

#[test]
fn behaviour17_6_lathe_haas_l10_geometry_and_l11_wear() {
    // Haas: L10 the geometry, L1 or L11 the wear, X Z absolute.
    let text = "G50 X100. Z50.\nG10 L10 P3 X-0.6 Z0.3\nG10 L11 P3 X0.1\nG10 L1 P3 Z-0.05\nT0303";
    let r = ok(text, &lathe(&[]));
    // X -0.6 + 0.1 = -0.5, Z 0.3 - 0.05 = 0.25: X99.5 Z50.25.
    same(actual(&r, 4), [99.5, 0.0, 50.25]);
}

#[test]
fn behaviour17_6_lathe_r_c_and_q_set_the_nose_radius_and_the_tip() {
    // Q3 is the tip direction 3 (no integer-dimension warning: a digit);
    // R sets the nose radius geometry, C adds to it.
    let text = "G10 P10005 R0.8 Q3\nG10 P10005 C-0.05\nM30";
    let r = run(text, &lathe(&[]));
    assert!(r.diagnostics.is_empty(), "{:#?}", r.diagnostics);
    let set = summary(&r).set_by_program;
    let field = |f: &str| set.iter().find(|s| s.set.field == f).unwrap();
    assert_eq!((field("r").set.value, field("r").line), (0.75, 2));
    assert_eq!((field("t").set.value, field("t").line), (3.0, 1));
    assert!(explain(&r, 0).contains("tip T = 3 (was 0)"));
    // Q is a digit 0–9.
    let (code, _) = alarm("G10 P5 Q12", &lathe(&[]));
    assert_eq!(code, "g10-words");
    // P0 is Fanuc's work coordinate shift, not modelled.
    let (code, msg) = alarm("G10 P0 X1.", &lathe(&[]));
    assert_eq!(code, "g10-number");
    assert!(msg.contains("G10 L2 P0"), "{msg}");
}

#[test]
fn behaviour17_6_in_g_code_system_b_g91_makes_x_add() {
    let mut s = lathe(&[(2, 0.5, 0.0)]);
    s.settings.gcode_system = Some(offsetlab::setup::GCodeSystem::B);
    // Geometry X 0.5 + 0.1 = 0.6 from X100 Z50: X100.6.
    let r = ok("G92 X100. Z50.\nG91 G10 P10002 X0.1\nG90 T0102", &s);
    same(actual(&r, 2), [100.6, 0.0, 50.0]);
}

#[test]
fn behaviour17_7_alarms_stop_the_run_at_the_g10_block() {
    let c = memory(OffsetMemory::C, &[]);
    let cases: &[(&str, &str, &str)] = &[
        ("G10 L12 P100 R1.", "g10-number", "1 to 99"),
        ("G10 L12 P0 R1.", "g10-number", "PS0031"),
        ("G10 L12 R1.", "g10-words", "needs P"),
        ("G10 L12 P1", "g10-words", "needs R"),
        ("G10 L12 P1 R1000.", "g10-value", "PS0032"),
        ("G10 L12 P1 R999.\nG10 L13 P1 R1.", "g10-value", "PS0032"),
        ("G10 P1 R1.", "g10-words", "needs L"),
        ("G10 L3 P1", "g10-words", "L3"),
        (
            "G10 L12 P1 R1. X5.",
            "g10-words",
            "X is not one of its words",
        ),
        ("G01 G10 L12 P1 R1.", "g10-words", "G01 in a G10 block"),
        ("G10 L12 P1 R1. M03", "g10-words", "M"),
        ("G10 L2 P7 X1.", "g10-number", "P1 to P6"),
        ("G10 L2 P1", "g10-words", "no axis"),
        ("G10 L20 P49 X1.", "g10-number", "P1 to P48"),
    ];
    for (text, code, said) in cases {
        let (got, msg) = alarm(text, &c);
        assert_eq!(got, *code, "{text}: {msg}");
        assert!(msg.contains(said), "{text}: {msg}");
    }
    let l = lathe(&[]);
    for (text, code) in [
        ("G10 P5 X1. U1.", "g10-words"),
        ("G10 P5 R1. C1.", "g10-words"),
        ("G10 P200 X1.", "g10-number"),
        ("G10 P10100 X1.", "g10-number"),
        ("G10 P5", "g10-words"),
        ("G10 L12 P5 X1.", "g10-words"),
    ] {
        assert_eq!(alarm(text, &l).0, code, "{text}");
    }
    // The run stops at the alarm: the blocks before it ran, none after.
    let r = run("G00 X10.\nG10 L12 P1 R1000.\nG00 X20.", &c);
    assert_eq!(r.block_count, 1);
    // Haas numbers the additional systems G154 P1–P99.
    let mut haas = Setup::default();
    haas.settings.control = Control::Haas;
    assert_eq!(haas.settings.extended_work_offsets(), ExtendedWork::G154);
    ok("G10 L20 P99 X1.", &haas);
}

#[test]
fn behaviour17_8_later_blocks_read_the_new_value_and_earlier_ones_keep_theirs() {
    let s = mill(&[(1, 10.0)]);
    let text = "G43 Z0 H01\nG10 L11 P1 R20.\nG00 X5.\nG43 Z0 H01";
    let r = ok(text, &s);
    // Before the G10: H01 = 10 → Z10, and it stays in force with 10 until
    // H01 is named again; then 20 → Z20.
    same(actual(&r, 0), [0.0, 0.0, 10.0]);
    same(actual(&r, 2), [5.0, 0.0, 10.0]);
    same(actual(&r, 3), [5.0, 0.0, 20.0]);
    assert!(
        explain(&r, 1).ends_with(
            "register 01 = 20.000 (was 10.000); H01 is in force with its old value until an H word names it again."
        ),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour17_8_the_block_the_events_and_the_summary_carry_what_was_set() {
    let s = memory(OffsetMemory::C, &[(1, 4.0)]);
    let text = "G00 X1.\nG10 L12 P1 R5.\nG10 L12 P3 R6.\nG91 G10 L12 P1 R0.5\nM30";
    let r = ok(text, &s);
    // The block's report.
    let b = &r.blocks[1];
    assert_eq!(b.data.len(), 1);
    assert_eq!(
        (b.data[0].table, b.data[0].key.as_str(), b.data[0].field),
        ("offsets", "01", "d_geometry")
    );
    assert_eq!((b.data[0].value, b.data[0].was), (5.0, 4.0));
    let view = at_line(&r, text, 2);
    assert_eq!(view.data_set.len(), 1);
    assert!(r.blocks[0].data.is_empty());
    // The events, one per value, at their lines.
    let lines: Vec<u32> = r
        .events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::DataSet(_)))
        .map(|e| e.line)
        .collect();
    assert_eq!(lines, vec![2, 3, 4]);
    // The summary: the last value of each, with its line; the registers it
    // set are the run's registers.
    let sum = summary(&r);
    let d01 = &sum.set_by_program[0];
    assert_eq!((d01.line, d01.set.value, d01.set.was), (4, 5.5, 5.0));
    assert_eq!(sum.set_by_program.len(), 2);
    assert_eq!(sum.registers, vec![1, 3]);
    let json = serde_json::to_value(&sum).unwrap();
    assert_eq!(json["set_by_program"][0]["field"], "d_geometry");
    assert_eq!(json["set_by_program"][0]["line"], 4);
}

#[test]
fn behaviour17_8_runs_made_again_reach_what_g10_wrote() {
    // Two runs whose G10 wrote different values do not run the same course:
    // an edit of the G10's R reruns the blocks after it.
    use offsetlab::{Earlier, RunOptions, rerun_observed};
    let setup = memory(OffsetMemory::C, &[]);
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        checkpoint_every: 1,
        ..RunOptions::default()
    };
    let before = "G10 L10 P1 R10.\nG43 Z0 H01\nG00 X1.\nG00 X2.\nG00 X3.\n";
    let after = "G10 L10 P1 R20.\nG43 Z0 H01\nG00 X1.\nG00 X2.\nG00 X3.\n";
    let (old, checkpoints, _) = rerun_observed(before, &setup, options, None, &mut ());
    let earlier = Earlier {
        text: before,
        run: &old,
        checkpoints: &checkpoints,
    };
    let (new, _, _) = rerun_observed(after, &setup, options, Some(earlier), &mut ());
    let whole = offsetlab::run_with(after, &setup, options);
    assert_eq!(new, whole);
    // Z 0 + 20 = 20 at the end.
    assert_eq!(new.bounds.unwrap().max[2], 20.0);
}

#[test]
fn behaviour17_9_work_offsets_l2_and_l20() {
    let s = Setup::default();
    // G54's zero set to X-100 Y-50 before the move: G00 X0 Y0 ends at
    // machine X-100 Y-50.
    let text = "G10 L2 P1 X-100. Y-50. Z0\nG00 X0 Y0\nG91 G10 L2 P1 X10.\nG90 G00 X0 Y0\nG10 L20 P2 X-300. Y-200. Z-100.\nG54.1 P2\nG00 X0 Y0 Z0";
    let r = ok(text, &s);
    let m = |i: usize| r.blocks[i].state.machine_position();
    same(m(1), [-100.0, -50.0, 0.0]);
    // G91 adds: X -100 + 10 = -90. G54 is in force: its zero moves at
    // once; the tool stays at machine X-100, which now reads X-10.
    same(programmed(&r, 2), [-10.0, 0.0, 0.0]);
    same(m(2), [-100.0, -50.0, 0.0]);
    assert!(
        explain(&r, 2).contains("G54 is in force"),
        "{}",
        explain(&r, 2)
    );
    same(m(3), [-90.0, -50.0, 0.0]);
    // G54.1 P2 at machine X-300 Y-200 Z-100.
    same(m(6), [-300.0, -200.0, -100.0]);
}

#[test]
fn behaviour17_9_p0_is_the_external_offset_every_system_carries() {
    let s = Setup::from_json(r#"{"work_offsets":{"G55":{"x":-200,"y":0,"z":0}}}"#).unwrap();
    // EXT X-10 Z-5: G55's zero is X-200 - 10 = -210, Z -5.
    let text = "G10 L2 P0 X-10. Z-5.\nG55 G00 X0 Y0 Z0";
    let r = ok(text, &s);
    same(r.blocks[1].state.machine_position(), [-210.0, 0.0, -5.0]);
    // In the document the external offset is work_offsets.EXT.
    let d = Setup::from_json(r#"{"work_offsets":{"EXT":{"x":-10,"y":0,"z":0}}}"#).unwrap();
    let r = ok("G00 X0 Y0", &d);
    same(r.blocks[0].state.machine_position(), [-10.0, 0.0, 0.0]);
    // The start position is in G54, which carries EXT too: the tool starts
    // at machine X-10 and G00 X0 does not move it.
    assert!(r.moves.is_empty());
}

#[test]
fn behaviour17_9_inch_words_are_converted_to_the_setups_units() {
    // A metric setup, a G20 program: X-1. is -25.4 mm.
    let r = ok("G20\nG10 L2 P1 X-1.\nG00 X0", &Setup::default());
    same(r.blocks[2].state.machine_position(), [-25.4, 0.0, 0.0]);
    let set = summary(&r).set_by_program;
    assert_eq!(set[0].set.value, -25.4);
}

#[test]
fn behaviour17_11_g10_then_use_draws_the_path_of_the_same_table() {
    // Memory C: the program writes H01, D01, G54 and G54.1 P1 and uses
    // them; the second run has them in its setup and no G10. The tool
    // starts at machine zero in both: G54 at machine zero until the G10
    // (so the tool reads X200 Y100 Z300 once G54 moves to X-200 Y-100
    // Z-300), and the table's run starts there, in G54 coordinates.
    let body = "G54 G00 X0 Y0\nG43 Z10. H01\nG91 G01 G45 X30. D01 F200.\nG47 Y20.\nG46 X-30.\nG90 G54.1 P1 G00 X0 Y0\nG49 G00 Z50.\nM30\n";
    let program = format!(
        "G10 L10 P1 R100.\nG10 L11 P1 R-0.25\nG10 L12 P1 R6.\nG10 L13 P1 R-0.1\nG10 L2 P1 X-200. Y-100. Z-300.\nG10 L20 P1 X-50. Y-60. Z-300.\n{body}"
    );
    let mut plain = Setup::default();
    plain.settings.control = Control::Fanuc;
    // Machine zero at the start, not the Fanuc profile's typical home
    // (setting 7.49): the table's run gives its start explicitly.
    plain.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    let with_g10 = ok(&program, &plain);
    let table = Setup::from_json(
        r#"{"settings":{"control":"fanuc"},"start":{"x":200,"y":100,"z":300},"offsets":{"01":{"h":100,"h_wear":-0.25,"d":6,"d_wear":-0.1}},"work_offsets":{"G54":{"x":-200,"y":-100,"z":-300}},"extended_work_offsets":{"01":{"x":-50,"y":-60,"z":-300}}}"#,
    )
    .unwrap();
    let with_table = ok(body, &table);
    let moves = |r: &offsetlab::Run| {
        r.moves
            .iter()
            .map(|m| (m.kind, m.from, m.to, m.programmed_from, m.programmed_to))
            .collect::<Vec<_>>()
    };
    // G10 blocks make no move: the moves are the same, one for one
    // (their block numbers differ by the six G10 blocks).
    assert_eq!(moves(&with_g10), moves(&with_table));
    // By hand: G43 Z10. H01 → Z 10 + 99.75 = 109.75 in G54 (machine Z
    // -300 + 109.75 = -190.25); G45 X30. → 30 + 5.9 = 35.9.
    // (blocks 0–5 are the G10s, 6 the G54 move, 7 the G43, 8 the G45).
    same(with_g10.blocks[8].state.actual, [35.9, 0.0, 109.75]);
    assert_eq!(with_g10.blocks[8].state.machine_position()[2], -190.25);
}
