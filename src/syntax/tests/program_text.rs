//! Behaviour 1.4, 1.9 (the byte order mark), 1.21–1.23: program headers,
//! several programs in a file, other dialects' text, P with a point.

use super::*;

fn places(prog: &Program) -> Vec<(u32, u32, &'static str)> {
    prog.diagnostics
        .iter()
        .map(|d| (d.line, d.column, d.code))
        .collect()
}

#[test]
fn behaviour1_4_colon_is_the_program_number_address() {
    let prog = p(":1234 (PART 7)\nG00 X1.\n:0012\nG00 X2.");
    assert_eq!(value(&prog.blocks[0], Address::O), 1234.0);
    // `:0012` is a second program's header: read, not yielded (1.21).
    assert_eq!(prog.blocks.len(), 2);
    assert_eq!(places(&prog), vec![(3, 1, "program-not-run")]);
    assert!(prog.diagnostics[0].message.contains("`:0012`"));
    let prog = p(":(NOTE)\nG00 X1.");
    assert_eq!(places(&prog), vec![(1, 1, "missing-number")]);
    assert!(
        prog.diagnostics[0]
            .message
            .contains("program number address of ISO code")
    );
}

#[test]
fn behaviour1_4_a_name_in_angle_brackets_opens_the_program() {
    // Fanuc 30i: a file name in < > at the start of the program section.
    let prog = p("%\n<PART_7> (SHAFT)\nG00 X1.\nM30\n%\n");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    // The name line is no block (it moves nothing and has no word).
    assert_eq!(prog.blocks.len(), 2);
    assert_eq!(prog.blocks[0].span.line, 3);
    assert_eq!(codes(&p("<PART_7\nG00 X1.")), vec!["program-name"]);
}

#[test]
fn behaviour1_4_a_name_after_o_is_read_as_the_name_with_a_warning() {
    for (text, shown) in [
        ("OCIRCLE(CIRCLE)\nG00 X1.", "`OCIRCLE`"),
        ("O7997A(CUTOFF)\nG00 X1.", "`O7997A`"),
        ("O<SHAFT>\nG00 X1.", "`O<SHAFT>`"),
        ("O[your six digits]\nG00 X1.", "`O[your six digits]`"),
    ] {
        let prog = p(text);
        assert_eq!(places(&prog), vec![(1, 1, "program-name")], "{text}");
        let d = &prog.diagnostics[0];
        assert!(!d.is_error(), "a warning: {}", d.message);
        assert!(d.message.contains(shown), "{}", d.message);
        assert!(d.message.contains("O1234 (NAME)"), "{}", d.message);
        // The name line is a header and no block, as <NAME> is.
        assert_eq!(prog.blocks.len(), 1, "{text}");
        // The comment after the name is no part of the error.
        assert_eq!(d.end_column as usize, 1 + shown.len() - 2, "{text}");
        // The next line is read as usual.
        assert_eq!(value(prog.blocks.last().unwrap(), Address::X), 1.0);
    }
    // Digits then words written without a blank are words (O1234 is the number).
    let prog = p("O1234G00X1.");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    assert_eq!(value(&prog.blocks[0], Address::X), 1.0);
}

#[test]
fn behaviour1_9_a_byte_order_mark_opening_the_text_is_read_as_nothing() {
    let prog = p("\u{feff}G01 X1. F100.");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    assert_eq!(value(&prog.blocks[0], Address::X), 1.0);
    // Anywhere else it is a character outside words.
    let prog = p("G01 X1.\n\u{feff}G00 X2.");
    assert_eq!(places(&prog), vec![(2, 1, "unexpected-character")]);
}

#[test]
fn behaviour1_21_a_later_program_is_read_from_a_fresh_context_and_not_yielded() {
    // The first program is in inch and was warned about an integer word;
    // the second is read in the setup's mm with its own warning.
    let text = "O1\nG20\nX12345\nM30\nO2\nX12345\nG81 Z-1. R1. K3\n";
    let prog = p(text);
    assert_eq!(prog.blocks.len(), 4);
    assert_eq!(
        places(&prog),
        vec![
            (3, 1, "integer-dimension"),
            (5, 1, "program-not-run"),
            (6, 1, "integer-dimension")
        ]
    );
    assert!(prog.diagnostics[0].message.contains("1.2345 in"));
    assert!(
        prog.diagnostics[1]
            .message
            .contains("`O2` starts a second program")
    );
    assert!(prog.diagnostics[2].message.contains("12.345 mm"));
    // A third program is "another" one; its K is a repeat count of its own cycle.
    let prog = p("O1\nG81 Z-1. R1.\nO2\nO3\nK2.5");
    assert_eq!(codes(&prog), vec!["program-not-run", "program-not-run"]);
    assert!(
        prog.diagnostics[1]
            .message
            .contains("starts another program")
    );
    // Blocks before the first header belong to the program it opens.
    let prog = p("G00 X1.\nO1000\nG00 X2.");
    assert!(prog.diagnostics.is_empty());
    assert_eq!(prog.blocks.len(), 3);
}

#[test]
fn behaviour1_21_after_the_closing_percent_another_program_is_read_not_yielded() {
    let text = "%\nO1\nG00 X1.\nM30\n%\n%\n(SUB)\nO2\nG01 X5.\nM99\n%\n";
    let prog = p(text);
    assert_eq!(prog.blocks.len(), 3);
    assert_eq!(places(&prog), vec![(8, 1, "program-not-run")]);
    // A block after the tape end makes a header there a later program,
    // even without a header before.
    let prog = p("G00 X1.\n%\n:2\nG00 X2.\n");
    assert_eq!(prog.blocks.len(), 1);
    assert_eq!(places(&prog), vec![(3, 1, "program-not-run")]);
    // No header after the tape end: the text is not read (1.3).
    assert_eq!(
        codes(&p("%\nG00 X1.\n%\nG00 X2.\n")),
        vec!["text-after-tape-end"]
    );
}

#[test]
fn behaviour1_22_semicolon_comments_are_refused_once_a_line_with_the_hint_once_a_program() {
    let text = "O1\n; SIMPLE MILL\nG00 X1. ; rapid to the part\nO2\n;note\n";
    let prog = p(text);
    assert_eq!(
        places(&prog),
        vec![
            (2, 3, "semicolon-comment"),
            (3, 11, "semicolon-comment"),
            (4, 1, "program-not-run"),
            (5, 2, "semicolon-comment"),
        ]
    );
    let hint = "`;` ends a block on Fanuc-family controls; write comments in ( )";
    assert!(prog.diagnostics[0].message.contains(hint));
    assert!(!prog.diagnostics[1].message.contains(hint));
    assert!(prog.diagnostics[1].message.contains("see line 2"));
    // A program of its own gets the hint again.
    assert!(prog.diagnostics[3].message.contains(hint));
    // The error covers the rest of the line.
    assert_eq!(prog.diagnostics[1].end_column, 11 + 17);
    // Words after `;` that are G-code are a block (Fanuc), and an error in
    // them is theirs, not a comment's.
    assert!(p("G00 X1.;G01 Y2. F100.").diagnostics.is_empty());
    assert_eq!(codes(&p("G00 X1.;G01 Y1.2.3")), vec!["malformed-number"]);
}

#[test]
fn behaviour1_22_linuxcnc_o_words_and_cncsimulator_lines_name_their_dialect() {
    for text in [
        "o100 sub",
        "O100 SUB",
        "o100 endsub",
        "o<probe> call [1] [2]",
        "o101 if [#1 GT 0]",
        "o102 while [#2 LT 10]",
    ] {
        let prog = p(text);
        assert_eq!(places(&prog), vec![(1, 1, "other-dialect")], "{text}");
        assert!(prog.diagnostics[0].message.contains("LinuxCNC o-word"));
        assert!(prog.diagnostics[0].message.contains(&format!("`{text}`")));
    }
    let prog = p("$AddRegPart 1 X2.925 Y2.005\nG00 X1.");
    assert_eq!(places(&prog), vec![(1, 1, "other-dialect")]);
    assert!(
        prog.diagnostics[0]
            .message
            .contains("`$AddRegPart` is a CNCSimulator Pro directive")
    );
    assert_eq!(value(&prog.blocks[1], Address::X), 1.0);
}

#[test]
fn behaviour1_23_a_decimal_point_in_p_is_refused_or_read_as_seconds() {
    let prog = p("G04 P3.");
    assert_eq!(places(&prog), vec![(1, 5, "decimal-point")]);
    assert!(
        prog.diagnostics[0]
            .message
            .contains("dwell_p_decimal_point")
    );
    let haas = |o: &mut ParseOptions| o.dwell_p = DwellPDecimalPoint::Seconds;
    let prog = p_with("G04 P3.\nG04 P2500\nG04 P-1.\nG01 X1. D1.", haas);
    let p0 = prog.blocks[0].get(Address::P).unwrap();
    assert_eq!((p0.value, p0.point), (3.0, true));
    let p1 = prog.blocks[1].get(Address::P).unwrap();
    assert_eq!((p1.value, p1.point), (2500.0, false));
    // Only P, and not negative.
    assert_eq!(codes(&prog), vec!["out-of-range", "decimal-point"]);
}
