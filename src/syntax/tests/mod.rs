//! Parser tests: every rule and every error of spec section 1.

use super::*;
use crate::setup::{DecimalInput, DwellPDecimalPoint, MachineKind, Units};
use crate::syntax::codes::GCode;

mod program_text;

fn p(text: &str) -> Program {
    parse(text, &ParseOptions::default())
}

fn p_with(text: &str, f: impl FnOnce(&mut ParseOptions)) -> Program {
    let mut o = ParseOptions::default();
    f(&mut o);
    parse(text, &o)
}

fn codes(prog: &Program) -> Vec<&'static str> {
    prog.diagnostics.iter().map(|d| d.code).collect()
}

fn value(b: &Block, a: Address) -> f64 {
    b.value(a).unwrap_or_else(|| panic!("no {a:?} in {b:?}"))
}

#[test]
fn behaviour1_1_blocks_end_at_newline_or_semicolon() {
    let prog = p("G00 X1.;G01 Y2.\r\nG00 Z3.\rX4.\nX5.");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    let lines: Vec<u32> = prog.blocks.iter().map(|b| b.span.line).collect();
    // Two blocks on one line both belong to that line.
    assert_eq!(lines, vec![1, 1, 2, 3, 4]);
    assert_eq!(value(&prog.blocks[1], Address::Y), 2.0);
    assert_eq!(value(&prog.blocks[3], Address::X), 4.0);
}

#[test]
fn behaviour1_3_tape_marks_program_numbers_sequence_numbers_and_comments() {
    let prog = p("%\nO1234 (PART 7)\nN10 G01 X1. (MOVE) Y2. F100.\n(ONLY A COMMENT)\n\n%\n");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    assert_eq!(prog.blocks.len(), 2);
    assert_eq!(value(&prog.blocks[0], Address::O), 1234.0);
    assert_eq!(value(&prog.blocks[1], Address::N), 10.0);
    assert_eq!(value(&prog.blocks[1], Address::Y), 2.0);
    assert_eq!(prog.blocks[1].span.line, 3);
}

#[test]
fn behaviour1_2_semicolon_inside_a_comment_does_not_end_the_block() {
    let prog = p("G00 X1. (A; B) Y2.");
    assert_eq!(prog.blocks.len(), 1);
    assert_eq!(value(&prog.blocks[0], Address::Y), 2.0);
}

#[test]
fn behaviour1_5_spaces_inside_words_and_lower_case() {
    let prog = p("g0 1 x 1 2 . 5 y-.5 f 100");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    let b = &prog.blocks[0];
    assert_eq!(b.get(Address::G).unwrap().gcode(), GCode::new(1));
    assert_eq!(value(b, Address::X), 12.5);
    assert_eq!(value(b, Address::Y), -0.5);
    assert_eq!(value(b, Address::F), 100.0);
}

#[test]
fn behaviour1_6_block_skip_marks_the_block() {
    let prog = p("/G00 X1.\n /2 G00 X2.\nG00 X3.");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    let skips: Vec<bool> = prog.blocks.iter().map(|b| b.skip).collect();
    assert_eq!(skips, vec![true, true, false]);
}

#[test]
fn behaviour1_6_misplaced_block_skip_is_an_error() {
    let prog = p("G00 /X1.");
    assert_eq!(codes(&prog), vec!["unexpected-character"]);
    assert_eq!(prog.diagnostics[0].column, 5);
}

#[test]
fn behaviour1_10_same_address_twice_is_an_error() {
    let prog = p("G01 X10. X20.");
    assert_eq!(codes(&prog), vec!["duplicate-address"]);
    let d = &prog.diagnostics[0];
    assert_eq!((d.line, d.column, d.end_column), (1, 10, 14));
    assert!(d.message.contains("X10. and X20."), "{}", d.message);
    assert!(prog.blocks[0].error);
    let prog = p("G45 X1. D1 D2");
    assert_eq!(codes(&prog), vec!["duplicate-address"]);
}

#[test]
fn behaviour1_11_two_g_codes_of_one_group_is_an_error() {
    let prog = p("G43 G44 Z1. H1\nG00 G01 X1.");
    assert_eq!(codes(&prog), vec!["modal-conflict", "modal-conflict"]);
    assert_eq!(prog.diagnostics[0].column, 5);
    assert!(prog.diagnostics[0].message.contains("group 08"));
    assert_eq!(prog.diagnostics[1].line, 2);
    // Codes of different groups are fine.
    assert!(
        p("G90 G00 G17 G21 G40 G49 G80 X0 Y0")
            .diagnostics
            .is_empty()
    );
}

#[test]
fn behaviour4_9_two_position_offset_codes_in_one_block_is_an_error() {
    let prog = p("G91 G45 G46 X10. D1");
    assert_eq!(codes(&prog), vec!["modal-conflict"]);
}

#[test]
fn behaviour1_8_letter_without_number_is_an_error() {
    let prog = p("G01 X;\nG01 X Y1.");
    assert_eq!(codes(&prog), vec!["missing-number", "missing-number"]);
    assert_eq!(prog.diagnostics[0].column, 5);
    assert_eq!(prog.diagnostics[1].line, 2);
}

#[test]
fn behaviour1_8_malformed_numbers_are_errors() {
    let prog = p("X1.2.3\nX--1\nX-\nX1-2");
    assert_eq!(
        codes(&prog),
        vec![
            "malformed-number",
            "malformed-number",
            "malformed-number",
            "malformed-number"
        ]
    );
    assert!(
        prog.diagnostics[0]
            .message
            .contains("`1.2.3` is not a number")
    );
}

#[test]
fn behaviour1_12_unknown_g_code_is_an_error() {
    let prog = p("G07 X1.\nG06 D1 X1.\nG61.1 Q1.");
    assert_eq!(
        codes(&prog),
        vec![
            "unsupported-g-code",
            "unsupported-g-code",
            "unsupported-g-code"
        ]
    );
    assert_eq!(prog.diagnostics[1].line, 2);
}

#[test]
fn behaviour1_19_parsing_continues_after_an_error() {
    let prog = p("X1.2.3\nG01 X1. Y\nG00 X5.");
    assert_eq!(prog.blocks.len(), 3);
    assert!(prog.blocks[0].error && prog.blocks[1].error && !prog.blocks[2].error);
    assert_eq!(value(&prog.blocks[1], Address::X), 1.0);
    assert_eq!(value(&prog.blocks[2], Address::X), 5.0);
}

#[test]
fn behaviour1_15_decimal_input_increment_is_the_default() {
    let prog = p("X12345 Y1.5 Z0");
    let b = &prog.blocks[0];
    assert_eq!(value(b, Address::X), 12.345);
    assert_eq!(value(b, Address::Y), 1.5);
    assert_eq!(value(b, Address::Z), 0.0);
    // The first integer dimension word gets a warning saying how it was read.
    assert_eq!(codes(&prog), vec!["integer-dimension"]);
    let d = &prog.diagnostics[0];
    assert_eq!(d.severity, crate::diag::Severity::Warning);
    assert!(d.message.contains("read as 12.345 mm"), "{}", d.message);
    assert!(d.message.contains("X12.345"), "{}", d.message);
    // Only the first.
    let prog = p("X12345\nY100");
    assert_eq!(codes(&prog), vec!["integer-dimension"]);
    // A zero reads the same either way: no warning.
    assert!(p("G91 X0 Y0").diagnostics.is_empty());
}

#[test]
fn behaviour1_15_decimal_input_increment_in_inch() {
    let prog = p("G20\nX12345");
    assert_eq!(value(&prog.blocks[1], Address::X), 1.2345);
    let prog = p_with("X12345", |o| o.units = Units::Inch);
    assert_eq!(value(&prog.blocks[0], Address::X), 1.2345);
}

#[test]
fn behaviour1_15_decimal_input_calculator() {
    let prog = p_with("X12345 Y1.5", |o| {
        o.decimal_input = DecimalInput::Calculator
    });
    assert_eq!(value(&prog.blocks[0], Address::X), 12345.0);
    assert_eq!(value(&prog.blocks[0], Address::Y), 1.5);
    assert!(prog.diagnostics.is_empty());
}

#[test]
fn behaviour1_13_integer_words_are_not_affected_by_decimal_input() {
    let prog = p("N10 G04 P1000\nT0101 M06 D01 H02 S800 F100");
    assert!(prog.diagnostics.is_empty(), "{:?}", prog.diagnostics);
    let b = &prog.blocks[1];
    assert_eq!(value(b, Address::T), 101.0);
    assert_eq!(value(b, Address::D), 1.0);
    assert_eq!(value(b, Address::H), 2.0);
    assert_eq!(value(b, Address::S), 800.0);
    // F is read in units either way.
    assert_eq!(value(b, Address::F), 100.0);
    assert_eq!(value(&prog.blocks[0], Address::P), 1000.0);
}

#[test]
fn behaviour1_13_integer_words_refuse_a_decimal_point() {
    let prog = p("G01 X1. D1.");
    assert_eq!(codes(&prog), vec!["decimal-point"]);
}

#[test]
fn behaviour1_17_ranges() {
    let prog = p("X99999.999\nX100000.\nY-100000.");
    assert_eq!(codes(&prog), vec!["out-of-range", "out-of-range"]);
    let prog = p("G20\nX9999.9999\nX10000.");
    assert_eq!(codes(&prog), vec!["out-of-range"]);
    assert_eq!(prog.diagnostics[0].line, 3);
    // Offset numbers 00 to the table size.
    let prog = p("D00 H99\nD100\nH-1");
    assert_eq!(codes(&prog), vec!["out-of-range", "out-of-range"]);
    let prog = p_with("D12", |o| o.table_size = 10);
    assert_eq!(codes(&prog), vec!["out-of-range"]);
    assert!(prog.diagnostics[0].message.contains("00 to 10"));
}

#[test]
fn behaviour5_lathe_t_codes_are_checked_against_the_table() {
    let lathe = |o: &mut ParseOptions| o.machine = MachineKind::Lathe;
    assert!(p_with("T0108", lathe).diagnostics.is_empty());
    assert_eq!(codes(&p_with("T10000", lathe)), vec!["out-of-range"]);
    let prog = p_with("T0150", |o| {
        o.machine = MachineKind::Lathe;
        o.table_size = 40;
    });
    assert_eq!(codes(&prog), vec!["out-of-range"]);
}

#[test]
fn behaviour1_2_unclosed_comment_is_an_error() {
    let prog = p("G00 X1. (OPEN\nG00 X2.");
    assert_eq!(codes(&prog), vec!["unclosed-comment"]);
    assert_eq!(prog.blocks.len(), 2);
    assert_eq!(prog.diagnostics[0].column, 9);
}

#[test]
fn behaviour1_9_characters_outside_words_are_errors() {
    // `#100=1.` and `X[1+2]` are macro syntax (behaviour 20.8); `@`, and a
    // `]` or `=` outside a macro, are not part of any word.
    let prog = p("#100=1.\nG00 X[1+2]\nG00 X1. @\nG00 X1. ]");
    assert_eq!(
        codes(&prog),
        vec!["unexpected-character", "unexpected-character"]
    );
    assert!(prog.blocks[0].macros.is_some() && prog.blocks[1].macros.is_some());
    assert!(prog.diagnostics[1].message.contains("macro"));
}

#[test]
fn behaviour1_7_unsupported_addresses_are_errors() {
    let prog = p("G01 V90. X1.");
    assert_eq!(codes(&prog), vec!["unsupported-address"]);
    assert!(prog.diagnostics[0].message.contains("V is not an address"));
}

#[test]
fn behaviour1_7_rotary_axes_e_and_comma_words_are_read() {
    let prog = p("G01 A90. B-45.5 C10. E0.25 X1. ,C2. ,r1.5");
    assert_eq!(codes(&prog), Vec::<&str>::new());
    let b = &prog.blocks[0];
    assert_eq!(value(b, Address::A), 90.0);
    assert_eq!(value(b, Address::B), -45.5);
    assert_eq!(value(b, Address::C), 10.0);
    assert_eq!(value(b, Address::E), 0.25);
    assert_eq!(value(b, Address::CommaC), 2.0);
    assert_eq!(value(b, Address::CommaR), 1.5);
    assert_eq!(Address::CommaC.letter(), ",C");
    // Without a point they follow decimal input like any dimension word.
    let prog = p("G01 ,C2000");
    assert_eq!(value(&prog.blocks[0], Address::CommaC), 2.0);
    // A comma word the parser does not read.
    let prog = p("G01 X1. ,A30.");
    assert_eq!(codes(&prog)[0], "unexpected-character");
    assert!(prog.diagnostics[0].message.contains(",C (chamfer)"));
}

#[test]
fn behaviour1_3_text_after_the_closing_percent_is_not_read() {
    let prog = p("%\nG00 X1.\n%\nG00 X2.\n");
    assert_eq!(prog.blocks.len(), 1);
    assert_eq!(codes(&prog), vec!["text-after-tape-end"]);
    assert_eq!(prog.diagnostics[0].line, 4);
    // A closing % alone at the end is normal.
    assert!(p("%\nG00 X1.\n%\n\n").diagnostics.is_empty());
}

#[test]
fn behaviour1_16_k_in_a_canned_cycle_is_a_repeat_count() {
    let prog = p("G81 X1. Y1. Z-5. R1. K3 F100.\nG80\nG02 X1. K1");
    assert_eq!(value(&prog.blocks[0], Address::K), 3.0);
    assert_eq!(value(&prog.blocks[2], Address::K), 0.001);
}

#[test]
fn behaviour1_12_lathe_uses_system_a_g_codes() {
    let lathe = |o: &mut ParseOptions| o.machine = MachineKind::Lathe;
    let prog = p_with("G90 G00 X1.", lathe);
    assert_eq!(codes(&prog), vec!["modal-conflict"]);
    assert!(prog.diagnostics[0].message.contains("turning cycles"));
    assert_eq!(codes(&p_with("G91 U1.", lathe)), vec!["unsupported-g-code"]);
    assert_eq!(codes(&p_with("G43 H1", lathe)), vec!["unsupported-g-code"]);
}

#[test]
fn behaviour1_20_word_spans() {
    let prog = p("N10 G01 X12.5");
    let x = prog.blocks[0].get(Address::X).unwrap();
    assert_eq!((x.span.start, x.span.end, x.span.line), (8, 13, 1));
    assert_eq!(prog.blocks[0].span, Span::new(0, 13, 1));
}

#[test]
fn behaviour1_9_binary_junk_is_reported_not_fatal() {
    let text = "G00\u{0}\u{7}X1.\u{1b}[0m\nG00 X\u{FFFD}";
    let prog = p(text);
    assert!(!prog.diagnostics.is_empty());
    assert!(
        prog.diagnostics
            .iter()
            .all(|d| d.line >= 1 && d.column >= 1)
    );
}

#[test]
fn too_many_diagnostics_are_capped() {
    let text = "X1.2.3\n".repeat(MAX_DIAGNOSTICS + 50);
    let prog = p(&text);
    assert_eq!(prog.diagnostics.len(), MAX_DIAGNOSTICS + 1);
    assert_eq!(
        prog.diagnostics.last().unwrap().code,
        "too-many-diagnostics"
    );
}

/// The (line, column, code) of each diagnostic.
/// What a parser of `text` ends with: the blocks, the diagnostics in the
/// order they were reported (before [`crate::diag::finish`] sorts them) and
/// the context it stands in at the end.
type Reading = (Vec<Block>, Vec<Diagnostic>, (usize, u32, Units, bool, bool));

fn read_all(text: &str, options: ParseOptions, one_pass: bool) -> Reading {
    let mut blocks = Blocks {
        one_pass,
        ..Blocks::new(text, options)
    };
    let mut out = Vec::new();
    let mut block = Block::default();
    while blocks.next_into(&mut block) {
        out.push(block.clone());
    }
    let end = blocks.resume_point();
    let context = (
        end.pos,
        end.line,
        end.units,
        end.in_cycle,
        end.warned_integer,
    );
    (out, blocks.into_diagnostics(), context)
}

/// Words and other pieces of blocks that exercise the two readings: the
/// context codes (G20/G21, canned cycles), words they change (dimensions
/// with and without a point, K), errors of every kind, duplicates and
/// conflicts, comments and block ends.
const PIECES: &[&str] = &[
    "G20",
    "G21",
    "G81",
    "G83",
    "G80",
    "G00",
    "G01",
    "G02",
    "G03",
    "G43",
    "G49",
    "G90",
    "G91",
    "G17",
    "G18",
    "G45",
    "G46",
    "G05.1",
    "G7",
    "G20.",
    "G-1",
    "G1.23",
    "X1",
    "X1.5",
    "X-2.",
    "Y25",
    "Y.5",
    "Z100000",
    "Z-99999.",
    "I1.",
    "J-2",
    "K3",
    "K2.5",
    "K10000",
    "G71",
    "G73",
    "G76",
    "P10.",
    "Q20",
    "D.05",
    "D7000",
    "R1.",
    "Q2",
    "U1.",
    "W-1",
    "L2",
    "L10000",
    "P100",
    "H01",
    "H99",
    "D02",
    "D1.",
    "M03",
    "M05",
    "M30",
    "M08",
    "M09",
    "N10",
    "N-1",
    "O1234",
    "F100.",
    "F-1",
    "F1000000",
    "S1200",
    "T0101",
    "T1234",
    "T",
    "A1",
    "E2",
    "#1",
    ":12",
    "O12",
    "O1A",
    "OAB",
    "<NM>",
    "<",
    "o1 sub",
    "$X1",
    "P3.",
    "[",
    "@",
    "x 1 2 . 5",
    "g 0 1",
    "X1.2.3",
    "X--1",
    "X1234567890123456",
    "(C)",
    "(A;B)",
    "(OPEN",
    ")",
    "%",
    "/",
    "/2",
    ";",
    "\n",
    "\r\n",
    " ",
    "\t",
    "",
];

fn program_of(pieces: &[usize], seps: &[bool]) -> String {
    let mut text = String::new();
    for (i, &p) in pieces.iter().enumerate() {
        text.push_str(PIECES[p % PIECES.len()]);
        if seps.get(i).copied().unwrap_or(true) {
            text.push(' ');
        }
    }
    text
}

fn options_of(lathe: bool, inch: bool, calculator: bool, skip: bool) -> ParseOptions {
    let dwell_p = match calculator {
        true => DwellPDecimalPoint::Seconds,
        false => DwellPDecimalPoint::Error,
    };
    ParseOptions {
        machine: if lathe {
            MachineKind::Lathe
        } else {
            MachineKind::Mill
        },
        units: if inch { Units::Inch } else { Units::Mm },
        decimal_input: if calculator {
            DecimalInput::Calculator
        } else {
            DecimalInput::Increment
        },
        table_size: 50,
        block_skip: skip,
        dwell_p,
        // Both readings of a lathe cycle's D (behaviour 15.2).
        depth_word: if skip {
            crate::setup::DepthWord::Increments
        } else {
            crate::setup::DepthWord::Dimension
        },
        ..ParseOptions::default()
    }
}

#[cfg(not(target_arch = "wasm32"))]
proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
    /// The one-pass reading yields exactly what the two-pass reading (spec
    /// 1 as written) yields: the same blocks, the same diagnostics in the
    /// same order, the same context after the program.
    #[test]
    fn the_one_pass_reading_agrees_with_the_two_pass_reading(
        pieces in proptest::collection::vec(0..PIECES.len(), 0..40),
        seps in proptest::collection::vec(proptest::bool::weighted(0.8), 0..40),
        lathe: bool, inch: bool, calculator: bool, skip: bool,
    ) {
        let text = program_of(&pieces, &seps);
        let options = options_of(lathe, inch, calculator, skip);
        proptest::prop_assert_eq!(
            read_all(&text, options, true),
            read_all(&text, options, false),
            "{:?}", text
        );
    }
}

#[test]
fn the_one_pass_reading_agrees_at_the_diagnostics_cap() {
    // More diagnostics than are kept, among blocks of both readings: the
    // cap keeps the same first ones.
    let lines = [
        "N1 G01 X1. Y2.",
        "X1 Y2 G20",
        "G01 X1.2.3 A1 # (OPEN",
        "X10 K3 G81 K4",
        "G21 X1 Y1 X2",
        "M03 M04 G00 G01",
    ];
    let text: String = (0..1200)
        .map(|i| lines[i % lines.len()])
        .collect::<Vec<_>>()
        .join("\n");
    for options in [
        options_of(false, false, false, true),
        options_of(true, true, true, false),
    ] {
        let (fast, slow) = (
            read_all(&text, options, true),
            read_all(&text, options, false),
        );
        assert!(fast.1.len() > MAX_DIAGNOSTICS);
        assert_eq!(fast, slow);
    }
}

#[test]
fn behaviour1_11_a_g_code_after_30000_words_is_found_for_its_span_and_message() {
    // M codes of distinct numbers are distinct groups, so all are admitted:
    // 30 000 words of 6 and 7 bytes, within the longest block (1.25; a block
    // cannot hold the 65 535 words past which a group's word is searched
    // for instead of indexed).
    let mut text: String = (1000..31000).map(|m| format!("M{m} ")).collect();
    let at = text.len();
    text.push_str("G01 X1. G02");
    assert!(text.len() < MAX_BLOCK_BYTES);
    let prog = p(&text);
    let b = &prog.blocks[0];
    assert!(b.words.len() > 30_000);
    let g01 = b.group_word(codes::Group::Motion).expect("the G01 word");
    assert_eq!((g01.span.start as usize, g01.value), (at, 1.0));
    assert_eq!(b.code_span(codes::Group::Motion), g01.span);
    // The clash names the first code of the group, as in a short block.
    let clash = prog
        .diagnostics
        .iter()
        .find(|d| d.code == "modal-conflict")
        .unwrap();
    let short = p("G01 X1. G02");
    let expected = short
        .diagnostics
        .iter()
        .find(|d| d.code == "modal-conflict")
        .unwrap();
    assert_eq!(clash.message, expected.message);
}

#[test]
fn a_g80_in_the_text_after_a_semicolon_cancels_no_cycle_in_either_reading() {
    // Found by the property above: the text after `;` is taken back as
    // one error (behaviour 1.22), its G80 with it, so K2.5 on the next line
    // is still a G73 repeat count written with a point (decimal-point).
    let text = "G73 ; G80 O1A \n K2.5 ";
    let options = options_of(false, false, false, false);
    let one = read_all(text, options, true);
    assert_eq!(one, read_all(text, options, false));
    assert!(
        one.1.iter().any(|d| d.code == "decimal-point"),
        "{:?}",
        one.1
    );
}
