//! Behaviour 22.9 (`docs/behaviour.md`): LinuxCNC's tool table under the
//! linuxcnc profile — T, M6, M61, G43/G43.1/G43.2/G49, G41/G42 D,
//! G41.1/G42.1 and G10 L1/L10/L11. Each worked by hand; the move-by-move
//! comparison with rs274 is `tests/linuxcnc/t*.ngc` and
//! `tests/linuxcnc/refused/rt*.ngc` (`scripts/oracle-linuxcnc.py`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Control, ToolTable};
use offsetlab::{Setup, Units};

/// Tool 1: 1 in long, 0.25 in across; tool 2: −0.5 in, 0.5 in; tool 3:
/// 0.25 in, 0.125 in — the table in inches, as a LinuxCNC inch machine's.
const TABLE: &str = "T1 P1 Z1.0 D0.25 ;quarter inch\nT2 P2 Z-0.5 D0.5\nT3 P5 Z0.25 D0.125\n";

fn with_table() -> Setup {
    let mut s = linuxcnc();
    let (mut table, warnings) = ToolTable::parse(TABLE).unwrap();
    assert!(warnings.is_empty());
    table.units = Some(Units::Inch);
    s.tool_table = Some(table);
    s
}

#[test]
fn behaviour22_9_g43_reads_the_spindle_tool_or_h_from_the_table_and_moves_nothing() {
    // T1 M6 then G43 at Z10: the offset is 25.4 mm; the machine stays at
    // Z10, the position reads 10 − 25.4 = −15.4. G0 Z5 lands at 5 + 25.4.
    let r = ok(
        "G21 G90\nG0 Z10\nT1 M6\nG43\nG91 G0 Z0\nG90 G0 Z5\nM2\n",
        &with_table(),
    );
    assert_eq!(r.moves.len(), 2);
    same(r.moves[1].to, [0.0, 0.0, 30.4]);
    let b = r.blocks.iter().find(|b| b.span.line == 4).unwrap();
    same(b.state.programmed, [0.0, 0.0, -15.4]);
    // G43 H2: −0.5 in = −12.7 mm: Z5 lands at −7.7; G49 then Z5 at 5.
    let r = ok("G21 G90\nG43 H2\nG0 Z5\nG49\nG0 Z5\nM2\n", &with_table());
    same(r.moves[0].to, [0.0, 0.0, -7.7]);
    same(r.moves[1].to, [0.0, 0.0, 5.0]);
    // A G20 program reads the inch table as it is: Z0.5 + 1.0 = 1.5 in.
    let r = ok("G20 G90\nT1 M6 G43\nG0 Z0.5\nM2\n", &with_table());
    same(r.moves[0].to, [0.0, 0.0, 1.5 * 25.4]);
}

#[test]
fn behaviour22_9_g43_1_is_the_offset_written_and_g43_2_adds_a_tool() {
    // G43.1 Z3.5: Z10 lands at 13.5; G43.1 Z-2 replaces it: 8.
    let r = ok(
        "G21 G90\nG43.1 Z3.5\nG0 Z10\nG43.1 Z-2\nG0 Z10\nM2\n",
        &with_table(),
    );
    same(r.moves[0].to, [0.0, 0.0, 13.5]);
    same(r.moves[1].to, [0.0, 0.0, 8.0]);
    // G43 H1 (25.4) then G43.2 H3 (6.35): Z10 lands at 10 + 31.75.
    let r = ok("G21 G90\nG43 H1\nG43.2 H3\nG0 Z10\nM2\n", &with_table());
    same(r.moves[0].to, [0.0, 0.0, 41.75]);
    // G43.2 without H is refused, as rs274 refuses it.
    assert_eq!(
        errors("G21\nG43.2 Z1\nM2\n", &with_table()),
        vec!["g43-2-words"]
    );
    // G43.1 X: an X tool offset is not modelled on the mill.
    assert_eq!(
        errors("G21\nG43.1 X1 Z1\nM2\n", &with_table()),
        vec!["tool-offset-axis"]
    );
}

#[test]
fn behaviour22_9_t_h_d_and_m61_must_name_tools_of_the_table() {
    for (text, code) in [
        ("G21\nT7\nM2\n", "tool-not-in-table"),
        ("G21\nG43 H9\nM2\n", "tool-not-in-table"),
        ("G21 F100\nG41 D9 G1 X1\nM2\n", "tool-not-in-table"),
        ("G21\nM61 Q9\nM2\n", "tool-not-in-table"),
        ("G21\nG10 L1 P9 Z1\nM2\n", "tool-not-in-table"),
        ("G21\nH1 G0 Z1\nM2\n", "h-without-g43"),
        ("G21 F100\nD1 G1 X1\nM2\n", "d-without-g41"),
        ("G21\nM61\nM2\n", "m61-words"),
        ("G21 F100\nG41.1 G1 X1\nM2\n", "g41-1-words"),
        ("G21\nT1.5\nM2\n", "decimal-point"),
        ("G21\nM61 Q-1\nM2\n", "tool-number"),
    ] {
        assert_eq!(errors(text, &with_table()), vec![code], "{text}");
    }
    // T0 is no tool: accepted, every offset 0.
    let r = ok("G21\nT0 M6 G43\nG0 Z5\nM2\n", &with_table());
    same(r.moves[0].to, [0.0, 0.0, 5.0]);
    // M61 Q2 G43: tool 2's −12.7 without a change; Z5 lands at −7.7.
    let r = ok("G21\nM61 Q2 G43\nG0 Z5\nM2\n", &with_table());
    same(r.moves[0].to, [0.0, 0.0, -7.7]);
}

#[test]
fn behaviour22_9_g41_offsets_by_half_the_table_diameter_and_g41_1_by_half_d() {
    // G41 D1 along +X: tool 1's 0.25 in is 6.35 mm across, so the tool
    // runs 3.175 mm to the left (+Y) of Y0.
    let r = ok(
        "G21 G90 F100\nG0 X-20\nG41 D1 G1 X-10\nG1 X10\nG40 G1 X20\nM2\n",
        &with_table(),
    );
    same(r.moves[2].to, [10.0, 3.175, 0.0]);
    // G42 without D, and G42 D0, take the spindle tool: T2's 0.5 in is
    // 12.7 mm across, 6.35 to the right (−Y).
    for g42 in ["G42", "G42 D0"] {
        let text = format!("G21 G90 F100\nT2 M6\nG0 X-20\n{g42} G1 X-10\nG1 X10\nG40 G1 X20\nM2\n");
        let r = ok(&text, &with_table());
        same(r.moves[2].to, [10.0, -6.35, 0.0]);
    }
    // G41.1 D8: the diameter itself, 4 mm to the left.
    let r = ok(
        "G21 G90 F100\nG0 X-20\nG41.1 D8 G1 X-10\nG1 X10\nG40 G1 X20\nM2\n",
        &with_table(),
    );
    same(r.moves[2].to, [10.0, 4.0, 0.0]);
}

#[test]
fn behaviour22_9_g10_l1_l10_l11_set_a_tool_entry() {
    // G10 L1 P1 Z10 R2: tool 1 is 10 mm long and 4 mm across (R the
    // radius); G41 D1 then runs 2 mm left, G43 H1 Z5 lands at 15.
    let r = ok(
        "G21 G90 F100\nG10 L1 P1 Z10 R2\nG43 H1\nG0 X-20 Z5\nG41 D1 G1 X-10\nG1 X10\nG40 G1 X20\nM2\n",
        &with_table(),
    );
    same(r.moves[0].to, [-20.0, 0.0, 15.0]);
    same(r.moves[2].to, [10.0, 2.0, 15.0]);
    // G54 Z at −30 in the machine; at work Z20 (machine −10), G10 L10 P1
    // Z0 gives tool 1 Z 20 − 0 = 20, so G0 Z5 lands at 25; L11 P2 Z0 at
    // that point (work 25, machine −5) gives tool 2 Z −5 − 0: Z5 lands at 0.
    let r = ok(
        "G21 G90\nG10 L2 P1 Z-30\nG0 Z20\nG10 L10 P1 Z0\nG43 H1\nG0 Z5\nG10 L11 P2 Z0\nG43 H2\nG0 Z5\nM2\n",
        &with_table(),
    );
    let ends: Vec<f64> = r.moves.iter().map(|m| m.to[2]).collect();
    assert_eq!(ends.len(), 3);
    assert!(
        (ends[1] - 25.0).abs() < 1e-9 && ends[2].abs() < 1e-9,
        "{ends:?}"
    );
}

#[test]
fn behaviour22_9_a_linuxcnc_program_ends_with_m2_m30_or_a_closing_percent() {
    assert_eq!(
        errors("G21\nG0 X1\n", &with_table()),
        vec!["no-program-end"]
    );
    assert!(errors("%\nG21\nG0 X1\n%\n", &with_table()).is_empty());
    // The Fanuc family stops at the text's end.
    assert!(errors("G21\nG0 X1.\n", &Setup::default()).is_empty());
}

#[test]
fn behaviour22_9_without_a_table_the_registers_stand_for_it() {
    // No table: T7 is accepted and G43 H1 reads register H01.
    let mut s = linuxcnc();
    s.set_register("01=5.").unwrap();
    let r = ok("G21\nT7 M6\nG43 H1\nG0 Z5\nM2\n", &s);
    same(r.moves[0].to, [0.0, 0.0, 10.0]);
}

#[test]
fn behaviour22_9_links_keep_the_tool_table() {
    use offsetlab::Document;
    use offsetlab::share::{decode, encode_plain, link};
    let doc = Document {
        program: "G21\nT1 M6 G43\nG0 Z5\nM2\n".into(),
        setup: with_table(),
        ..Document::default()
    };
    let plain = encode_plain(&doc, false);
    assert!(
        plain.contains("tool_table=T1%20P1%20Z1%20D0.25%20;quarter%20inch%0A"),
        "{plain}"
    );
    assert!(plain.contains("tool_table_units=inch"));
    let back = decode(&format!("#{plain}")).unwrap().document;
    assert_eq!(back.setup.tool_table, doc.setup.tool_table);
    let compact = link("http://localhost/", &doc, false).unwrap();
    let back = decode(&compact).unwrap().document;
    assert_eq!(back.setup.tool_table, doc.setup.tool_table);
    // Through the link, tool 1 still offsets Z5 to 30.4.
    let r = ok(&back.program, &back.setup);
    same(r.moves[0].to, [0.0, 0.0, 30.4]);
    // Units without a table are refused at the link, not read as an empty
    // table that would refuse every T of the program.
    let e = decode("#program=M2&tool_table_units=inch").unwrap_err();
    assert!(e.message.contains("give tool_table= too"), "{e:?}");
}

#[test]
fn behaviour22_9_linuxcnc_entry_is_a_corner_and_g40_alone_moves_nothing() {
    use offsetlab::setup::{CutterCancelWithoutMotion, CutterStartUp, Settings};
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.cutter_start_up(), CutterStartUp::Corner);
    assert_eq!(
        s.cutter_cancel_without_motion(),
        CutterCancelWithoutMotion::NextMove
    );
    // G42 D1 (r = 3.175) from (−5, −5) to (0, 0): the entry ends r to the
    // right of its own direction (1, 1)/√2, at (r/√2, −r/√2); an arc round
    // (0, 0) then brings the tool to (r, 0), r right of the +Y block.
    let r = ok(
        "G21 G17 G90 F100\nG0 X-5 Y-5 Z5\nG42 D1 G1 X0 Y0\nG1 Y25\nG40 G1 X10 Y30\nM2\n",
        &with_table(),
    );
    let k = 3.175 / 2f64.sqrt();
    same(r.moves[1].to, [k, -k, 5.0]);
    same(r.moves[2].to, [3.175, 0.0, 5.0]);
    same(r.moves[3].to, [3.175, 25.0, 5.0]);
    // G40 alone moves nothing: the next G0 leaves the offset path from
    // (10, 6.35) left of +X (tool 2, r = 6.35) straight to (30, 30).
    let r = ok(
        "G21 G17 G90 F100\nG0 X-20 Y0 Z5\nG41 D2 G1 X-10\nG1 X10\nG40\nG0 X30 Y30\nM2\n",
        &with_table(),
    );
    same(r.moves[2].to, [10.0, 6.35, 5.0]);
    assert_eq!(r.moves.len(), 4);
    same(r.moves[3].from, [10.0, 6.35, 5.0]);
    same(r.moves[3].to, [30.0, 30.0, 5.0]);
    // The plane may change between that G40 and the move.
    let r = ok(
        "G21 G17 G90 F100\nG0 X-20 Y0 Z5\nG41 D3 G1 X-10\nG1 X10\nG40\nG18\nG0 X20 Z10\nM2\n",
        &with_table(),
    );
    same(r.moves.last().unwrap().to, [20.0, 0.0, 10.0]);
}

#[test]
fn behaviour22_9_m6_and_m61_after_g40_read_the_position_where_the_tool_is() {
    // Tool 2 (r = 6.35) left of +X ends at (10, 6.35); G40 alone leaves the
    // vector on. T2 M6 then takes the position from the tool: Z up stays at
    // X10 Y6.35, and G0 X0 keeps that Y (rs274 -g, tests/linuxcnc/a08).
    let text =
        "G21 G17 G90 F100\nG0 X-20 Y0 Z5\nG41 D2 G1 X-10\nG1 X10\nG40\nT2 M6\nG0 Z20\nG0 X0\nM2\n";
    let r = ok(text, &with_table());
    same(r.moves[3].to, [10.0, 6.35, 20.0]);
    same(r.moves[4].to, [0.0, 6.35, 20.0]);
    let b = r.blocks.iter().find(|b| b.span.line == 6).unwrap();
    same(b.state.programmed, [10.0, 6.35, 5.0]);
    // M61 does the same; a T alone does not (the Z move leaves the path).
    let r = ok(&text.replace("T2 M6", "M61 Q2"), &with_table());
    same(r.moves[4].to, [0.0, 6.35, 20.0]);
    let r = ok(&text.replace("T2 M6", "T2"), &with_table());
    same(r.moves[3].to, [10.0, 0.0, 20.0]);
    // M6 with G41 on is refused, on a G40 line too (the tool change comes
    // first in LinuxCNC's order of execution).
    for m6 in ["T2 M6", "G40 T2 M6"] {
        let text = format!("G21 G17 G90 F100\nG0 X-20 Y0 Z5\nG41 D2\n{m6}\nM2\n");
        assert_eq!(
            error_line(&text, &with_table()),
            ("tool-change-in-compensation", 4)
        );
    }
}

#[test]
fn behaviour22_10_tool_parameters_read_the_spindle_tools_entry() {
    // T1 M6: #5400 = 1, #5403 = its Z 1.0 and #5410 its diameter 0.25, as
    // the inch table holds them, read into a G21 program's words as mm.
    let r = ok(
        "G21 G90\nT1 M6\nG0 X#5403 Y#5410 Z#5400\nT0 M6\nG0 X#5403 Y#5410 Z#5400\nM2\n",
        &with_table(),
    );
    same(r.moves[0].to, [1.0, 0.25, 1.0]);
    same(r.moves[1].to, [0.0, 0.0, 0.0]);
    // Read only, as in LinuxCNC.
    assert_eq!(
        errors("G21\n#5403 = 2\nM2\n", &with_table()),
        vec!["macro-system-variable"]
    );
}

#[test]
fn behaviour22_11_linuxcnc_g92_1_zeroes_the_offset_and_g53_moves_in_g0_or_g1() {
    let l = linuxcnc();
    // G92 X0 at X10 shifts the zero by 10: G0 X1 is machine X11. G92.1
    // alone cancels the shift on every axis: the tool, unmoved, reads X11,
    // and G0 X5 goes from there to machine (and work) X5.
    let r = ok("G21 G90\nG0 X10\nG92 X0\nG0 X1\nG92.1\nG0 X5\nM2\n", &l);
    same(r.moves[1].to, [1.0, 0.0, 0.0]);
    same(r.moves[2].from, [11.0, 0.0, 0.0]);
    same(r.moves[2].to, [5.0, 0.0, 0.0]);
    // With an axis word it is refused (rs274 would move with it in G0; in
    // the G80 it starts in, rs274 refuses the axis word, 22.18).
    assert_eq!(errors("G21 G0\nG92.1 X0\nM2\n", &l), vec!["g92-1-value"]);
    assert_eq!(
        errors("G21\nG92.1 X0\nM2\n", &l),
        vec!["axis-without-motion"]
    );
    // G53 in G1 feeds; in G2 it is refused ("Must use g0 or g1 with g53").
    let r = ok("G21 G90 F100\nG1 X1\nG53 X10\nM2\n", &l);
    assert!(
        matches!(r.moves[1].kind, offsetlab::MoveKind::Feed),
        "{:?}",
        r.moves[1].kind
    );
    assert_eq!(
        errors("G21 F100\nG2 X1 Y1 R1\nG53 X10\nM2\n", &l),
        vec!["g53-motion"]
    );
}
