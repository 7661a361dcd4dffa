//! Behaviour 14.20–14.21 and 7.60 (`docs/behaviour.md`): Haas G47 text
//! engraving — the strokes of offsetlab's font placed by X, Y, J and I, the
//! depths R and Z, the serial number in #599, and the refusals; Fanuc and
//! YASNAC keep G47 as the position offset.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::setup::{Control, G47Code};
use offsetlab::{Move, MoveKind};

fn haas() -> offsetlab::Setup {
    let mut s = mill(&[]);
    s.settings.control = Control::Haas;
    s.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
    s
}

fn on_line(r: &offsetlab::Run, line: u32) -> Vec<&Move> {
    r.moves.iter().filter(|m| m.line == line).collect()
}

#[test]
fn behaviour14_20_p0_engraves_the_comment_from_the_lower_left_j_high() {
    // J6. makes the font's grid unit 1 mm (the capitals 6 units high, each
    // character 6 units on): "LT" from X10 Y20, R2, Z-0.5.
    // L: (0,6) (0,0) (4,0) -> (10,26) (10,20) (14,20).
    // T: (0,6)-(4,6) and (2,6)-(2,0) of the second character, 6 on:
    //    (16,26)-(20,26) and (18,26)-(18,20).
    let text = "G00 Z5.\nG47 P0 (LT) X10. Y20. J6. R2. Z-0.5 F300. E100.";
    let r = ok(text, &haas());
    let m = on_line(&r, 2);
    let ends: Vec<([f64; 3], MoveKind)> = m.iter().map(|m| (m.programmed_to, m.kind)).collect();
    let want: Vec<([f64; 3], MoveKind)> = vec![
        ([10.0, 20.0, 5.0], MoveKind::Rapid),
        ([10.0, 20.0, 2.0], MoveKind::Rapid),
        // L
        ([10.0, 26.0, 2.0], MoveKind::Rapid),
        ([10.0, 26.0, -0.5], MoveKind::Feed),
        ([10.0, 20.0, -0.5], MoveKind::Feed),
        ([14.0, 20.0, -0.5], MoveKind::Feed),
        ([14.0, 20.0, 2.0], MoveKind::Rapid),
        // T, the bar
        ([16.0, 26.0, 2.0], MoveKind::Rapid),
        ([16.0, 26.0, -0.5], MoveKind::Feed),
        ([20.0, 26.0, -0.5], MoveKind::Feed),
        ([20.0, 26.0, 2.0], MoveKind::Rapid),
        // T, the stem
        ([18.0, 26.0, 2.0], MoveKind::Rapid),
        ([18.0, 26.0, -0.5], MoveKind::Feed),
        ([18.0, 20.0, -0.5], MoveKind::Feed),
        ([18.0, 20.0, 2.0], MoveKind::Rapid),
    ];
    assert_eq!(ends.len(), want.len(), "{ends:?}");
    for ((got, gk), (w, wk)) in ends.iter().zip(&want) {
        same(*got, *w);
        assert_eq!(gk, wk);
    }
    let notes = &r.blocks.iter().find(|b| b.span.line == 2).unwrap().notes;
    assert!(
        notes
            .iter()
            .any(|n| n.starts_with("G47 text engraving (Haas): \"LT\"")
                && n.contains("3 strokes")
                && n.contains("E100")),
        "{notes:?}"
    );
}

#[test]
fn behaviour14_20_i_turns_the_line_about_the_start_and_g91_takes_r_and_z_as_distances() {
    // I90.: the line runs along +Y. The grid point (gx, gy) of character k
    // lands at X = 0 - gy, Y = 6k + gx (J6.). "-" is (0,3)-(4,3): from
    // (-3, 0) to (-3, 4). In G91 from Z10: R-8. is Z2, Z-2.5 from R is Z-0.5.
    let text = "G00 Z10.\nG91\nG47 P45 I90. J6. R-8. Z-2.5 F300.";
    let r = ok(text, &haas());
    let m = on_line(&r, 3);
    let cut: Vec<&&Move> = m.iter().filter(|m| m.kind == MoveKind::Feed).collect();
    assert_eq!(cut.len(), 2);
    same(cut[0].programmed_to, [-3.0, 0.0, -0.5]);
    same(cut[1].programmed_to, [-3.0, 4.0, -0.5]);
    same(m.last().unwrap().programmed_to, [-3.0, 4.0, 2.0]);
    // Without J the text is 1 inch high: a "." (one plunge at (2,0)) of
    // P46 at I0 from X0 Y0 lands at X = 2 * 25.4 / 6.
    let r = ok("G00 Z5.\nG47 P46 R1. Z-0.1 F100.", &haas());
    let m = on_line(&r, 2);
    let plunge = m.iter().find(|m| m.kind == MoveKind::Feed).unwrap();
    same(plunge.programmed_to, [2.0 * 25.4 / 6.0, 0.0, -0.1]);
}

#[test]
fn behaviour14_20_p1_engraves_599_in_the_comments_digits_and_counts_it_up() {
    // (1234) sets #599 = 1234 and engraves it; the next block's (####)
    // engraves 1235 and #599 becomes 1236. #599 = 7 in (###) is 007.
    let text = "G00 Z5.\nG47 P1 (1234) J6. R2. Z-1. F100.\nG47 P1 (####) J6. R2. Z-1. F100.\n#1 = #599\n#599 = 7\nG47 P1 (###) J6. R2. Z-1. F100.";
    let r = ok(text, &haas());
    let said = |line: u32| {
        r.blocks
            .iter()
            .find(|b| b.span.line == line)
            .unwrap()
            .notes
            .join(" | ")
    };
    assert!(
        said(2).contains("serial number 1234 engraved in 4 digits as 1234; #599 is now 1235"),
        "{}",
        said(2)
    );
    assert!(said(3).contains("\"1235\""), "{}", said(3));
    assert!(said(6).contains("as 007"), "{}", said(6));
    assert!(said(6).contains("#599 is now 8"), "{}", said(6));
}

#[test]
fn behaviour14_21_g47_refuses_what_it_cannot_engrave() {
    let s = haas();
    for (text, why) in [
        ("G47 P0 X1. Z-1. R1. F100.", "has none"),
        ("G47 P2 (A) Z-1. R1. F100.", "0 (the comment's text)"),
        ("G47 P0 (A) R1. F100.", "needs Z"),
        ("G47 P0 (A) Z2. R1. F100.", "below R"),
        ("G47 P0 (A) Z-1. R1. J0.01 F100.", "at least 0.001 inch"),
        ("G47 P0 (A) Z-1. R1. I400. F100.", "−360 to 360"),
        ("G47 P0 (A) Z-1. R1. K1. F100.", "does not read K"),
        ("G47 P1 (AB) Z-1. R1. F100.", "serial number"),
        ("G18\nG47 P0 (A) Z-1. R1. F100.", "XY plane"),
        (
            "G41 D1 X1. F100.\nG47 P0 (A) Z-1. R1.",
            "cancel cutter compensation",
        ),
        ("G68 X0 Y0 R30.\nG47 P0 (A) Z-1. R1. F100.", "rotation"),
    ] {
        let r = offsetlab::run(text, &s);
        let e = r
            .diagnostics
            .iter()
            .find(|d| d.severity == offsetlab::diag::Severity::Error);
        let e = e.unwrap_or_else(|| panic!("{text}: no error"));
        assert_eq!(e.code, "g47-words", "{text}: {}", e.message);
        assert!(e.message.contains(why), "{text}: {}", e.message);
    }
}

#[test]
fn behaviour7_60_fanuc_and_yasnac_keep_g47_as_the_double_extension_and_the_setting_chooses() {
    // Fanuc: G47 X10. with D01 = 2 moves 10 + 2 * 2 = 14 (behaviour 4).
    for control in [Control::Fanuc, Control::Yasnac] {
        let mut s = mill(&[(1, 2.0)]);
        s.settings.control = control;
        s.settings.machine_positions = Some(offsetlab::setup::MachinePositions::WorkZero);
        let r = ok("G91 G01 F100.\nG47 X10. D01", &s);
        same(r.moves.last().unwrap().to, [14.0, 0.0, 0.0]);
        // The setting makes it engraving there too.
        s.settings.g47 = Some(G47Code::Engraving);
        ok("G00 Z5.\nG47 P65 J6. R2. Z-1. F100.", &s);
    }
    let mut s = haas();
    s.settings.g47 = Some(G47Code::PositionOffset);
    s.set_register("1=2").unwrap();
    let r = ok("G91 G01 F100.\nG47 X10. D01", &s);
    same(r.moves.last().unwrap().to, [14.0, 0.0, 0.0]);
}
