//! Behaviour 22.18 (`docs/behaviour.md`): LinuxCNC's G80 is a motion code —
//! the interpreter starts in it, it ends G0–G3 as well as a canned cycle,
//! and in it an axis word needs a code on its line that uses it. The
//! move-by-move comparison with rs274 is `tests/linuxcnc/m01_*.ngc` and
//! `tests/linuxcnc/refused/r08`, `r12`, `r34`, `r35`; behaviour 22.19, the
//! `%` lines: `m02_*.ngc`, `refused/r36`, `r37`.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;

#[test]
fn behaviour22_18_linuxcnc_starts_in_g80_so_an_axis_word_alone_is_refused() {
    let l = linuxcnc();
    assert_eq!(
        error_line("G21 G90\nX1 Y1\nM2\n", &l),
        ("axis-without-motion", 2)
    );
    // An M code uses no axis word either.
    assert_eq!(
        error_line("G21\nS1000 M3 Z5\nM2\n", &l),
        ("axis-without-motion", 2)
    );
    // The state panel shows the mode the control is in: G80, not G0.
    let r = ok("G21\nM2\n", &l);
    assert_eq!(r.blocks[0].state.modal_codes().motion, "G80");
    // The Fanuc family starts in G00 and moves (behaviour 2.3).
    let r = ok("G21\nX1. Y1.\nM30\n", &mill(&[]));
    same(r.moves[0].to, [1.0, 1.0, 0.0]);
}

#[test]
fn behaviour22_18_g80_ends_g0_and_refuses_axis_words_on_its_line() {
    let l = linuxcnc();
    // G0 X0 Y0 Z5, a G81 at X1 Y1 (5 moves with the R level), G80, then G0
    // X2 moves; Y3 alone after the second G80 has no mode left to move in.
    let text = "G21 G90 F100\nG0 X0 Y0 Z5\nG81 X1 Y1 Z-1 R1\nG80\nG0 X2\nG80\nY3\nM2\n";
    assert_eq!(error_line(text, &l), ("axis-without-motion", 7));
    assert_eq!(
        error_line("G21 F100\nG0 Z5\nG81 X1 Y1 Z-1 R1\nG80 X5\nM2\n", &l),
        ("axis-with-g80", 4)
    );
    // Under fanuc G80 leaves G00 in effect: X5 after it is a rapid.
    let r = ok(
        "G21 F100\nG0 Z5.\nG81 X1. Y1. Z-1. R1.\nG80\nX5.\nM30\n",
        &mill(&[]),
    );
    same(r.moves.last().unwrap().to, [5.0, 1.0, 5.0]);
}

#[test]
fn behaviour22_18_g10_g28_g92_and_g43_1_use_their_axis_words_in_g80() {
    let l = linuxcnc();
    // At X0 Y0 Z0, G92 X2 Y2 makes the unmoved tool read X2 Y2; G43.1
    // Z1.5 is an offset, so G0 X5 Y5 Z5 takes the tool's reference point
    // to Z 5 + 1.5 = 6.5.
    let r = ok("G21 G90\nG92 X2 Y2\nG43.1 Z1.5\nG0 X5 Y5 Z5\nM2\n", &l);
    assert!(r.moves.len() == 1, "{:?}", r.moves);
    same(programmed(&r, 1), [2.0, 2.0, 0.0]);
    same(r.moves[0].to, [5.0, 5.0, 6.5]);
    // G28 Z0 goes home by Z0 (a straight move to the reference) without a
    // motion mode: no error.
    ok("G21 G90\nG28 Z0\nM2\n", &l);
    // G10 L2 P2 X1 Y1 writes G55's origin and moves nothing.
    let r = ok("G21 G90\nG10 L2 P2 X1 Y1\nM2\n", &l);
    assert!(r.moves.is_empty(), "{:?}", r.moves);
}

#[test]
fn behaviour22_19_a_percent_is_a_tape_mark_only_alone_and_first_or_closing() {
    let l = linuxcnc();
    // Blank lines before the opening `%`; the closing one ends the program
    // without M2: G0 X1 is the one move, X5 after it is not read.
    let r = ok("\n  \n%\nG21 G0 X1\n%\nG0 X5\n", &l);
    assert_eq!(r.moves.len(), 1);
    same(r.moves[0].to, [1.0, 0.0, 0.0]);
    // A `%` after a block of a text that did not open with one; after a
    // comment line; with text after it.
    assert_eq!(
        error_line("G21 G0 X1\n%\nG0 X2\nM2\n", &l),
        ("bad-character", 2)
    );
    assert_eq!(
        error_line("(plate)\n%\nG21 G0 X1\nM2\n", &l),
        ("bad-character", 2)
    );
    assert_eq!(
        error_line("% plate\nG21 G0 X1\nM2\n", &l),
        ("bad-character", 1)
    );
    // The Fanuc family reads a `%` after blocks as the tape's end (1.3).
    let r = ok("G21 G0 X1.\n%\nG0 X2.\n", &mill(&[]));
    assert_eq!(r.moves.len(), 1);
}
