//! Behaviour 22 (`docs/behaviour.md`): the linuxcnc profile's program text
//! and defaults — numbers as values, P in seconds, `;` comments, the
//! comments that speak, the start at the origin — with settings 7.1, 7.26
//! and 7.61. The move-by-move comparison with LinuxCNC's own interpreter is
//! `scripts/oracle-linuxcnc.py` over `tests/linuxcnc/` (`make test`).
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::machine::EventKind;
use offsetlab::setup::{Control, DecimalInput, DwellPDecimalPoint, Semicolon, Settings};
use offsetlab::{Setup, run};

fn linuxcnc() -> Setup {
    let mut s = Setup::default();
    s.settings.control = Control::Linuxcnc;
    s
}

fn dwells(r: &offsetlab::Run) -> Vec<f64> {
    r.events
        .iter()
        .filter_map(|e| match e.kind {
            EventKind::Dwell { seconds } => Some(seconds),
            _ => None,
        })
        .collect()
}

#[test]
fn behaviour22_1_the_linuxcnc_profile_reads_numbers_as_values_and_starts_at_the_origin() {
    let mut s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.decimal_input(), DecimalInput::Calculator);
    s.control = Control::Haas;
    assert_eq!(s.decimal_input(), DecimalInput::Increment);
    // `X1` is 1 mm and `.5` is 0.5 mm; G91 `X-2` from X1 is X-1.
    let r = ok("G21 G90\nG0 X1 Y.5 Z3\nG91 G1 X-2 F100\nM2\n", &linuxcnc());
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [1.0, 0.5, 3.0]);
    same(r.moves[1].to, [-1.0, 0.5, 3.0]);
    // The run starts at the origin, as rs274 does with no parameter file.
    same(r.moves[0].from, [0.0, 0.0, 0.0]);
    // G28 alone goes to the stored position, 0 on every axis.
    let r = ok("G21\nG0 X5 Y6 Z7\nG28\nM2\n", &linuxcnc());
    same(r.moves.last().unwrap().to, [0.0, 0.0, 0.0]);
    // Set in the setup, the Fanuc reading wins: `X1` is 0.001 mm.
    let mut setup = linuxcnc();
    setup.settings.decimal_input = Some(DecimalInput::Increment);
    let r = ok("G21\nG0 X1000\nM2\n", &setup);
    same(r.moves[0].to, [1.0, 0.0, 0.0]);
}

#[test]
fn behaviour7_26_linuxcnc_dwells_p_seconds_with_or_without_a_point() {
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.dwell_p_decimal_point(), DwellPDecimalPoint::Always);
    // G4 P2 is 2 s, P1.5 1.5 s; a G82's P0.25 a quarter of a second.
    let r = ok(
        "G21 G90\nG4 P2\nG4 P1.5\nG0 Z5\nG82 X1 Y1 Z-2 R1 P0.25 F100\nG80\nM2\n",
        &linuxcnc(),
    );
    assert_eq!(dwells(&r), vec![2.0, 1.5, 0.25]);
    // Haas keeps P3 as 3 ms.
    let mut haas = Setup::default();
    haas.settings.control = Control::Haas;
    let r = ok("G04 P3\nM30\n", &haas);
    assert_eq!(dwells(&r), vec![0.003]);
}

#[test]
fn behaviour7_61_a_semicolon_starts_a_comment_under_linuxcnc_and_the_setting_chooses() {
    let text =
        "; a whole line of comment: G1 X99\nG21 G90 ; G0 X50\nG0 X1 (a ; in a comment) Y2\nM2\n";
    let r = ok(text, &linuxcnc());
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].to, [1.0, 2.0, 0.0]);
    // The block's text runs to the line's end, its comment shown with it.
    let b = &r.blocks[0];
    assert_eq!(
        &text[b.span.start as usize..b.span.end as usize],
        "G21 G90 ; G0 X50"
    );
    // Fanuc: `;` ends a block, and the text after it is words.
    let mut fanuc = Setup::default();
    fanuc.settings.control = Control::Fanuc;
    assert!(errors(text, &fanuc).contains(&"semicolon-comment"));
    let r = ok("G21 G90;G0 X1.;G1 X2. F100.\nM30\n", &fanuc);
    assert_eq!(r.moves.len(), 2);
    // The setting wins over the profile, either way.
    fanuc.settings.semicolon = Some(Semicolon::Comment);
    let r = ok(text, &fanuc);
    assert_eq!(r.moves.len(), 1);
    let mut l = linuxcnc();
    l.settings.semicolon = Some(Semicolon::EndOfBlock);
    assert!(errors(text, &l).contains(&"semicolon-comment"));
    let setup = Setup::from_json(r#"{"settings":{"semicolon":"comment"}}"#).unwrap();
    assert_eq!(setup.settings.semicolon(), Semicolon::Comment);
    assert!(setup.to_json().contains("\"semicolon\": \"comment\""));
}

#[test]
fn behaviour22_2_msg_and_debug_comments_are_notes_of_their_block() {
    let text = "G21\n(MSG, Insert the 6 mm end mill)\nG0 X1 (debug,X is #1) Z2\n(print,done)\n(a plain comment)\nM2\n";
    let r = ok(text, &linuxcnc());
    let notes: Vec<(u32, &str)> = r
        .blocks
        .iter()
        .flat_map(|b| b.notes.iter().map(move |n| (b.span.line, n.as_str())))
        .collect();
    assert_eq!(
        notes,
        vec![
            (2, "(MSG) Insert the 6 mm end mill"),
            (
                3,
                "(DEBUG) X is #1 (offsetlab shows it as written, without the parameters' values)"
            ),
            (4, "(PRINT) done"),
        ]
    );
    // A plain comment line is no block; the move is still made.
    assert_eq!(r.blocks.len(), 5);
    same(r.moves[0].to, [1.0, 0.0, 2.0]);
    // On the Fanuc family a comment is only a comment.
    let r = run(text.replace("X1", "X1.").as_str(), &Setup::default());
    assert!(
        r.blocks
            .iter()
            .all(|b| b.notes.iter().all(|n| !n.contains("MSG")))
    );
}

#[test]
fn behaviour22_3_linuxcnc_offsets_at_the_next_z_pecks_back_0_254_mm_and_starts_in_g99() {
    use offsetlab::setup::LengthOffsetWithoutZ;
    let s = Settings {
        control: Control::Linuxcnc,
        ..Settings::default()
    };
    assert_eq!(s.length_offset_without_z(), LengthOffsetWithoutZ::NextZ);
    // H01 = 25: G43 without Z moves nothing; the next Z5 lands at Z30.
    let mut setup = linuxcnc();
    setup.set_register("H01=25.").unwrap();
    let r = ok("G21 G90\nG43 H1\nG0 X10\nG0 Z5\nM2\n", &setup);
    assert_eq!(r.moves.len(), 2);
    same(r.moves[0].to, [10.0, 0.0, 0.0]);
    same(r.moves[1].to, [10.0, 0.0, 30.0]);
    // G83 from Z10 to Z-2 with R1, Q1 pecks: in at R1 → Z0, back to R, down
    // to 0.254 above Z0, on to Z-1, back to R, down to Z-0.746, to Z-2.
    // No G98/G99: LinuxCNC's start mode G99 returns to R, not to Z10.
    let r = ok(
        "G21 G90\nG0 X5 Y5 Z10\nG83 Z-2 R1 Q1 F100\nG80\nM2\n",
        &linuxcnc(),
    );
    let z: Vec<f64> = r.moves.iter().skip(1).map(|m| m.to[2]).collect();
    let want = [1.0, 0.0, 1.0, 0.254, -1.0, 1.0, -0.746, -2.0, 1.0];
    assert_eq!(z.len(), want.len(), "{z:?}");
    for (got, want) in z.iter().zip(want) {
        assert!((got - want).abs() < 1e-9, "{z:?}");
    }
}
