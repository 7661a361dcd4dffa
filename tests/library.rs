//! Behaviour 19.10–19.12 (`docs/behaviour.md`): the setup's library of
//! programs — programs kept by number with the document, called by M98 and
//! G65 as the programs of the file are, each block and diagnostic told in
//! its own program's lines. Positions are worked out by hand.
#![cfg(not(target_arch = "wasm32"))]

mod common;
use common::*;
use offsetlab::{End, RunOptions, Setup, report_at, run, run_with};

fn with_library(programs: &[(u32, &str)]) -> Setup {
    let mut s = Setup::default();
    for (n, text) in programs {
        s.programs.insert(*n, text.to_string());
    }
    s
}

const MAIN: &str = "O1000\nG90 G00 X0 Y0 Z0\nM98 P1002 L2\nM30\n";
const STEP: &str = "O1002\nG91 G01 X10. F100\nM99\n";

#[test]
fn behaviour19_10_m98_calls_a_program_of_the_setups_library() {
    let setup = with_library(&[(1002, STEP)]);
    let r = run(MAIN, &setup);
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    // Twice X+10 from X0: X10 then X20; the main program's M30 on line 4.
    let xs: Vec<f64> = r.moves.iter().map(|m| m.to[0]).collect();
    assert_eq!(xs.last().copied(), Some(20.0));
    assert_eq!(r.end, End::ProgramEnd { line: 4 });
    // The G01 of O1002 is line 2 of its own text, from byte 6 ("O1002\n")
    // to byte 23 (6 + "G91 G01 X10. F100".len() = 6 + 17).
    let inside: Vec<_> = r
        .blocks
        .iter()
        .filter(|b| b.place.as_ref().is_some_and(|p| p.program == "O1002"))
        .collect();
    // Each pass: its header (line 1), the G01 (line 2), M99 (line 3).
    let lines: Vec<u32> = inside.iter().map(|b| b.span.line).collect();
    assert_eq!(lines, vec![1, 2, 3, 1, 2, 3]);
    let g01 = inside[1];
    assert_eq!((g01.span.start, g01.span.end), (6, 23));
    assert_eq!(
        g01.place.as_ref().unwrap().stack,
        vec!["O1000 line 3", "O1002"]
    );
    assert!(g01.place.as_ref().unwrap().library);
    // Its view reads its text from the library (the file's bytes 6..23
    // are `G90 G00 X0 Y0 Z0`'s).
    let g01_index = g01.index as usize;
    let view = offsetlab::view::block_views(&r, MAIN)
        .nth(g01_index)
        .unwrap();
    assert_eq!(
        (view.text, view.line, view.column),
        ("G91 G01 X10. F100", 2, 1)
    );
    // The moves of the library program carry its lines too.
    assert!(
        r.moves
            .iter()
            .filter(|m| m.to[0] > 0.0)
            .all(|m| m.line == 2)
    );
}

#[test]
fn behaviour19_10_a_number_both_hold_is_the_main_files_program() {
    // The file's own O1002 moves X+5: one pass to X5, the second to X10
    // (the library's X+10 would end at X20).
    let main = "O1000\nG90 G00 X0 Y0 Z0\nM98 P1002 L2\nM30\nO1002\nG91 G01 X5. F100\nM99\n";
    let r = run(main, &with_library(&[(1002, STEP)]));
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.moves.last().map(|m| m.to[0]), Some(10.0));
    assert!(
        r.moves
            .iter()
            .filter(|m| m.to[0] > 0.0)
            .all(|m| m.line == 6)
    );
}

#[test]
fn behaviour19_10_g65_calls_a_macro_of_the_library_and_a_library_program_calls_another() {
    // O9010 moves to X = #24 * 2 (X6. → 12.) and calls O1002 once: X+10
    // from 12 is 22.
    let main = "O1000\nG90 G00 X0 Y0 Z0\nG65 P9010 X6.\nM30\n";
    let macro_ = "O9010\nG90 G01 X[#24*2] F100\nM98 P1002\nM99\n";
    let r = run(main, &with_library(&[(1002, STEP), (9010, macro_)]));
    assert!(r.diagnostics.is_empty(), "{:?}", r.diagnostics);
    assert_eq!(r.moves.last().map(|m| m.to[0]), Some(22.0));
    let last = r
        .blocks
        .iter()
        .rfind(|b| b.place.as_ref().is_some_and(|p| p.program == "O1002"))
        .unwrap();
    // M98 on line 3 of O9010, the G65 on line 3 of the main program.
    assert_eq!(
        last.place.as_ref().unwrap().stack,
        vec!["O1000 line 3 (G65, level 1)", "O9010 line 3", "O1002"]
    );
    // The call's note names its return line in O9010's own terms.
    let call = r
        .blocks
        .iter()
        .find(|b| b.notes.iter().any(|n| n.starts_with("M98")))
        .unwrap();
    assert_eq!(call.span.line, 3);
    assert!(
        call.notes
            .iter()
            .any(|n| n.ends_with("returns to line 4 of O9010")),
        "{:?}",
        call.notes
    );
}

#[test]
fn behaviour19_11_a_diagnostic_in_a_library_program_names_it() {
    // Line 3 of O1002 divides by zero: its line and column are O1002's
    // (the divisor `0` is the 6th character of `#1=1/0`; line 3 starts at
    // byte 6 + 17 + 1 = 24 of O1002's text, the `0` at 24 + 5 = 29), its
    // message names O1002; the run ends at that line.
    let bad = "O1002\nG91 G01 X10. F100\n#1=1/0\nM99\n";
    let r = run(MAIN, &with_library(&[(1002, bad)]));
    let d = r.diagnostics.iter().find(|d| d.is_error()).unwrap();
    assert_eq!((d.line, d.column, d.span.start), (3, 6, 29), "{d:?}");
    assert!(d.message.starts_with("in O1002: "), "{}", d.message);
    assert_eq!(r.end, End::Error { line: 3 });
    // A program the main program calls but neither holds: PS0076.
    let r = run(MAIN, &with_library(&[(1003, "O1003\nM99\n")]));
    let (code, line, column) = first_error(&r);
    assert_eq!((code, line, column), ("program-not-found", 3, 5));
    // No program-not-run warning for a library program never called.
    assert!(r.diagnostics.iter().all(|d| d.code != "program-not-run"));
}

#[test]
fn behaviour19_12_a_checkpoint_inside_a_library_program_gives_the_same_report() {
    let main = "O1000\nG90 G00 X0 Y0 Z0\nG65 P9010 X6.\nM98 P1002 L3\nM30\n";
    let macro_ = "O9010\n#100=#24+1\nG90 G01 X[#100*2] F100\nM98 P1002\nM99\n";
    let setup = with_library(&[(1002, STEP), (9010, macro_)]);
    let full = run(main, &setup);
    assert!(full.diagnostics.is_empty(), "{:?}", full.diagnostics);
    // (6 + 1) * 2 = 14, then four times X+10: 54.
    assert_eq!(full.moves.last().map(|m| m.to[0]), Some(54.0));
    for every in [1, 2, 3, 7, 1000] {
        let (light, checkpoints) = checkpointed(main, &setup, every);
        assert_eq!(light.block_count, full.block_count);
        assert_eq!(light.moves, full.moves);
        assert_eq!(light.diagnostics, full.diagnostics);
        assert_eq!(light.end, full.end);
        for (i, kept) in full.blocks.iter().enumerate() {
            let again = report_at(main, &setup, &checkpoints, i as u32);
            assert_eq!(again.as_ref(), Some(kept), "block {i}, every {every}");
        }
    }
    // The run on two threads hands a run with a library to one thread.
    let one = run_with(main, &setup, RunOptions::default());
    assert_eq!(
        offsetlab::run_pipelined(main, &setup, RunOptions::default()),
        one
    );
    assert!(offsetlab::run_on_two_threads(main, &setup, RunOptions::default()).is_none());
}

#[test]
fn behaviour9_10_the_document_and_its_links_carry_the_library() {
    use offsetlab::Document;
    use offsetlab::share::{decode, encode};
    let json = r#"{"version":1,"program":"O1000\nM98 P1002\nM30","programs":{"1002":"O1002\nG01 X10. F100\nM99"}}"#;
    let d = Document::from_json(json).unwrap();
    assert_eq!(
        d.setup.programs.get(&1002).map(String::as_str),
        Some("O1002\nG01 X10. F100\nM99")
    );
    // Written back: the same document (keys as numbers in strings).
    assert!(
        d.to_json()
            .contains(r#""programs":{"1002":"O1002\nG01 X10. F100\nM99"}"#)
    );
    assert_eq!(Document::from_json(&d.to_json()).unwrap(), d);
    // The compact link carries it, and reads back to the same document.
    let link = encode(&d);
    assert_eq!(decode(&link).unwrap().document, d);
    // A document without a library writes no `programs`.
    assert!(!Document::default().to_json().contains("programs"));
    // A program that does not open with its own header is refused.
    let bad = r#"{"program":"M98 P1002","programs":{"1002":"G01 X10.\nM99"}}"#;
    let e = Document::from_json(bad).unwrap_err();
    assert_eq!(e.diagnostics[0].code, "setup-program");
    let bad = r#"{"programs":{"1002":"O1003\nM99"}}"#;
    assert!(Document::from_json(bad).is_err());
    let bad = r#"{"programs":{"0":"O0\nM99"}}"#;
    assert!(Document::from_json(bad).is_err());
}
