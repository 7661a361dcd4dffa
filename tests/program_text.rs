//! Behaviour 1.4, 1.9, 1.21–1.23 and the rules of sections 2 and 5 they
//! touch (`docs/behaviour.md`): program text as a run sees it — program
//! headers and the programs of a file, other dialects refused once, a
//! dwell's P and S with a decimal point per control, subprogram and macro calls
//! refused, the words of a G04/G50/G28 block.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::EventKind;
use offsetlab::setup::{Control, DwellPDecimalPoint, MachineKind, SDecimalPoint, Settings};
use offsetlab::{End, Setup, run};

fn with_control(mut s: Setup, control: Control) -> Setup {
    s.settings.control = control;
    s
}

#[test]
fn behaviour1_21_the_first_program_runs_and_the_others_are_named_and_not_run() {
    // O1000 moves to X10.; O2000 (a subprogram) would move to X50.
    let text = "%\nO1000 (MAIN)\nG00 X10.\nM30\nO2000 (SUB)\nG01 X50. F100.\nM99\n%\n";
    let r = run(text, &Setup::default());
    assert!(!r.has_errors(), "{:#?}", r.diagnostics);
    // The O1000 block has its report (1.4), then G00 and M30.
    assert_eq!(r.block_count, 3);
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].to, [10.0, 0.0, 0.0]);
    assert_eq!(r.end, End::ProgramEnd { line: 4 });
    let d = &r.diagnostics[0];
    assert_eq!((d.code, d.line, d.column), ("program-not-run", 5, 1));
    assert!(
        d.message.contains("`O2000` starts a second program"),
        "{}",
        d.message
    );
    // Without M30 the run ends where the second program starts: its G01
    // never runs after the first program's blocks.
    let r = run(
        "O1000\nG00 X10.\nO2000\nG01 X50. F100.\n",
        &Setup::default(),
    );
    assert_eq!((r.block_count, r.moves.len()), (2, 1));
    assert_eq!(r.end, End::Completed);
    same(actual(&r, 1), [10.0, 0.0, 0.0]);
}

#[test]
fn behaviour1_21_a_program_the_run_calls_has_no_not_run_warning() {
    // O2 is called (M98) and runs: its warning is withdrawn; O3 is not
    // called and keeps it, at its header (line 7).
    let text = "O1\nM98 P2\nM30\nO2\nG00 X1.\nM99\nO3\nG00 X2.\nM99\n";
    let r = run(text, &Setup::default());
    let warned: Vec<_> = r.diagnostics.iter().map(|d| (d.code, d.line)).collect();
    assert_eq!(warned, vec![("program-not-run", 7)]);
    assert!(r.diagnostics[0].message.contains("this one is not called"));
    // A G65 call counts as well.
    let r = run("O1\nG65 P2 A1.\nM30\nO2\nG00 X#1\nM99\n", &Setup::default());
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.moves.len(), 1);
}

#[test]
fn behaviour1_21_every_header_form_starts_a_program() {
    for header in [":2000", "<SUB_2>", "O2000 (SUB)"] {
        let text = format!("O1000\nG00 X10.\n{header}\nG00 X50.\n");
        let r = run(&text, &Setup::default());
        assert_eq!(r.moves.len(), 1, "{header}");
        let codes: Vec<_> = r.diagnostics.iter().map(|d| d.code).collect();
        assert_eq!(codes, vec!["program-not-run"], "{header}");
    }
}

#[test]
fn behaviour1_4_a_name_after_o_warns_and_the_program_runs() {
    // The plasma shops' macro programs open with OCIRCLE(Circle): a Fanuc
    // or Haas control would not register it, but the name moves nothing.
    let r = ok("OCIRCLE(Circle)\nG00 X1.\n", &Setup::default());
    assert_eq!(r.diagnostics[0].code, "program-name");
    assert_eq!((r.block_count, r.end), (1, End::Completed));
    same(actual(&r, 0), [1.0, 0.0, 0.0]);
}

#[test]
fn behaviour1_9_a_byte_order_mark_opening_the_file_is_no_character() {
    let text = "\u{feff}G00 X10.\nG01 X20. Y5. F100.";
    let r = ok(text, &Setup::default());
    same(actual(&r, 1), [20.0, 5.0, 0.0]);
    // The block's text and columns start after the mark.
    let b = at_line(&r, text, 1);
    assert_eq!((b.column, b.text), (1, "G00 X10."));
}

#[test]
fn behaviour1_22_a_semicolon_comment_stops_the_run_with_the_hint() {
    let text = "; SIMPLE EXAMPLE\nG00 X10.\n";
    let r = run(text, &Setup::default());
    assert_eq!(errors(text, &Setup::default()), vec!["semicolon-comment"]);
    assert_eq!(r.end, End::Error { line: 1 });
    assert!(r.diagnostics[0].message.contains("write comments in ( )"));
}

#[test]
fn behaviour1_23_haas_reads_p_with_a_point_as_seconds_fanuc_and_yasnac_refuse_it() {
    let haas = with_control(Setup::default(), Control::Haas);
    // G04 P3. is 3 s on Haas and P3 3 ms; a G82 hole dwells P0.5 = 0.5 s.
    let text = "G04 P3.\nG04 P3\nG00 X0 Y0 Z10.\nG82 X5. Z-2. R1. P0.5 F100.\nG80\n";
    let r = ok(text, &haas);
    let d = dwells(&r);
    assert_eq!(d.len(), 3);
    assert!(
        (d[0] - 3.0).abs() < 1e-12 && (d[1] - 0.003).abs() < 1e-12,
        "{d:?}"
    );
    assert!((d[2] - 0.5).abs() < 1e-12, "{d:?}");
    for control in [Control::Fanuc, Control::Yasnac] {
        let s = with_control(Setup::default(), control);
        assert_eq!(errors("G04 P3.", &s), vec!["decimal-point"]);
        // Without a point, milliseconds on every control.
        assert_eq!(dwells(&ok("G04 P2500", &s)), vec![2.5]);
    }
    // The setting wins over the profile (behaviour 7.20).
    let mut s = Setup::default();
    s.settings.dwell_p_decimal_point = Some(DwellPDecimalPoint::Seconds);
    assert_eq!(dwells(&ok("G04 P1.5", &s)), vec![1.5]);
}

#[test]
fn behaviour7_57_haas_reads_s_with_a_point_as_its_value_fanuc_and_yasnac_refuse_it() {
    let lathe = Setup {
        machine: MachineKind::Lathe,
        ..Setup::default()
    };
    let haas = with_control(lathe.clone(), Control::Haas);
    // G50 S3000. limits the spindle to 3000 rpm; G97 S1600. turns it at
    // 1600 rpm, as S1600 would.
    let text = "G50 S3000.\nG97 S1600. M03\nG97 S1600 M03\nM30\n";
    let r = ok(text, &haas);
    assert_eq!(r.blocks[0].state.spindle_limit, Some(3000.0));
    assert!(
        r.blocks[0].notes[0].starts_with("G50 S3000: the spindle speed limit"),
        "{:?}",
        r.blocks[0].notes
    );
    assert_eq!(r.blocks[1].state.spindle, Some(1600.0));
    assert_eq!(r.blocks[2].state.spindle, Some(1600.0));
    // A negative speed is out of range with a point too.
    assert_eq!(errors("G97 S-1600. M03", &haas), vec!["out-of-range"]);
    for control in [Control::Fanuc, Control::Yasnac] {
        let s = with_control(lathe.clone(), control);
        let r = run("G97 S1600. M03\n", &s);
        let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
        assert_eq!((d.code, d.line, d.column), ("decimal-point", 1, 5));
        assert!(d.message.contains("s_decimal_point"), "{}", d.message);
    }
    // The setting wins over the profile; T keeps refusing a point on Haas.
    let mut s = with_control(Setup::default(), Control::Fanuc);
    s.settings.s_decimal_point = Some(SDecimalPoint::Value);
    assert_eq!(
        ok("S5000. M03\nM30", &s).blocks[0].state.spindle,
        Some(5000.0)
    );
    assert_eq!(errors("T1. M06", &haas), vec!["decimal-point"]);
    let setup = Setup::from_json(r#"{"settings":{"s_decimal_point":"value"}}"#).unwrap();
    assert_eq!(setup.settings.s_decimal_point(), SDecimalPoint::Value);
    assert_eq!(Settings::default().s_decimal_point(), SDecimalPoint::Error);
}

#[test]
fn behaviour7_26_the_profile_gives_the_dwell_p_rule() {
    let mut s = Settings::default();
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Error);
    s.control = Control::Fanuc;
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Error);
    s.control = Control::Haas;
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Seconds);
    s.dwell_p_decimal_point = Some(DwellPDecimalPoint::Error);
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Error);
    let setup = Setup::from_json(r#"{"settings":{"dwell_p_decimal_point":"seconds"}}"#).unwrap();
    assert_eq!(
        setup.settings.dwell_p_decimal_point(),
        DwellPDecimalPoint::Seconds
    );
    assert!(
        setup
            .to_json()
            .contains("\"dwell_p_decimal_point\": \"seconds\"")
    );
}

#[test]
fn behaviour2_18_subprogram_and_macro_calls_are_errors_not_auxiliary_events() {
    // M98, M97 and M99 run (section 19); M198 calls a program outside the
    // text, which is refused at its M word.
    let r = run("G00 X10.\nM198 P1000\n", &Setup::default());
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.code, d.line, d.column), ("unsupported-m-code", 2, 1));
    assert!(
        d.message
            .contains("M198 calls a subprogram kept outside the program memory (P1000)"),
        "{}",
        d.message
    );
    assert!(r.events.is_empty(), "{:?}", r.events);
    assert_eq!(r.end, End::Error { line: 2 });
    // On the lathe too.
    let lathe = lathe(&[]);
    assert_eq!(errors("M198 P10", &lathe), vec!["unsupported-m-code"]);
    // G65–G67 are run (section 21); Fanuc's G66.1 is refused with why.
    let r = run("G66.1 P9001 A1.", &Setup::default());
    assert_eq!(r.diagnostics[0].code, "unsupported-g-code");
    assert!(
        r.diagnostics[0]
            .message
            .contains("G66.1 (a call at every block) is not modelled")
    );
}

#[test]
fn behaviour2_9_a_lathe_dwell_takes_x_or_u_once() {
    let lathe = lathe(&[]);
    let r = run("G04 U1. X2.", &lathe);
    let d = &r.diagnostics[0];
    // At the second word written.
    assert_eq!((d.code, d.column), ("dwell-words", 9));
    assert_eq!(dwells(&ok("G04 U1.5", &lathe)), vec![1.5]);
}

#[test]
fn behaviour2_19_a_lathe_g50_s_is_said_to_be_the_speed_limit() {
    let r = ok("S800 M03\nG50 S2000", &lathe(&[]));
    // The spindle speed stays 800; the block says what S2000 is.
    assert_eq!(r.blocks[1].state.spindle, Some(800.0));
    assert!(
        explain(&r, 1).contains("G50 S2000: the spindle speed limit"),
        "{}",
        explain(&r, 1)
    );
}

#[test]
fn behaviour2_13_a_lathe_arc_with_r_and_i_k_uses_r_with_a_warning() {
    // From X40 Z-10 to X50 Z-20 with R10: I3. is ignored, said so.
    let r = run("G00 X40. Z-10.\nG02 X50. Z-20. R10. I3. F0.2", &lathe(&[]));
    let codes: Vec<_> = r.diagnostics.iter().map(|d| d.code).collect();
    assert_eq!(codes, vec!["arc-r-and-center"]);
    let arc = r.moves[1].arc.expect("an arc");
    assert!((arc.programmed_radius - 10.0).abs() < 1e-9);
}

#[test]
fn behaviour5_9_a_t_code_in_a_g50_g28_or_g04_block_is_refused_not_dropped() {
    // Before, the T code was dropped: no offset, no turret index, no word.
    let lathe = lathe(&[(1, 0.4, -0.2)]);
    for text in ["G50 X100. Z50. T0101", "G28 U0. T0101", "G04 U1. T0101"] {
        let r = run(text, &lathe);
        let d = &r.diagnostics[0];
        assert_eq!((d.code, d.line), ("unused-word", 1), "{text}");
        assert!(r.events.is_empty() && r.moves.is_empty(), "{text}");
    }
    // Written in a block of its own, it indexes and offsets as usual: from
    // X100 Z50 (G50) the offset motion goes to X100.4 Z49.8.
    let r = ok("G50 X100. Z50.\nT0101", &lathe);
    same(actual(&r, 1), [100.4, 0.0, 49.8]);
}

#[test]
fn behaviour2_22_a_t_code_in_a_cycles_first_block_is_taken_not_dropped() {
    // G71's first block (depth of cut and escape) with T0202: the turret
    // indexes to tool 02 and its offset (X0.6 Z0.1) applies from the
    // cycle's first move, as in the second block. It was dropped before.
    let text = "G00 X50. Z2.\nG71 U2. R0.5 T0202\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X30.\nG01 Z-20.\nN20 X50.\n";
    let r = ok(text, &lathe(&[(2, 0.6, 0.1)]));
    assert!(
        r.events
            .iter()
            .any(|e| e.line == 2 && matches!(e.kind, EventKind::ToolIndex { tool: 2 })),
        "{:?}",
        r.events
    );
    assert!(
        explain(&r, 1)
            .contains("the new offset applies from the cycle's first move: X 0.600 Z 0.100"),
        "{}",
        explain(&r, 1)
    );
}
