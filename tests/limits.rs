//! The limits of the README's "Limits" table: each is a clear diagnostic,
//! never a hang, an abort or a NaN. The extreme programs run through the
//! same invariant checks as the `run` fuzz target (`fuzz/common/mod.rs`).
#![cfg(not(target_arch = "wasm32"))]

#[path = "../fuzz/common/mod.rs"]
mod fuzz_common;

use offsetlab::report::End;
use offsetlab::syntax::{
    MAX_BLOCK_BYTES, MAX_DIAGNOSTICS, MAX_PROGRAM_BYTES, MAX_REPEATS, check_size,
};
use offsetlab::{MAX_BLOCKS, MAX_MOVES, ParseOptions, RunOptions, Setup, Units, parse, run_with};

fn codes(r: &offsetlab::Run) -> Vec<&'static str> {
    r.diagnostics.iter().map(|d| d.code).collect()
}

#[test]
fn a_program_over_256_mib_is_refused_before_parsing() {
    let mut text = "G01 X1. F100.\n".repeat(MAX_PROGRAM_BYTES / 14 + 1);
    assert!(text.len() > MAX_PROGRAM_BYTES);
    let r = offsetlab::run(&text, &Setup::default());
    assert_eq!(codes(&r), ["program-too-large"]);
    assert_eq!(r.end, End::Error { line: 0 });
    assert_eq!((r.block_count, r.move_count), (0, 0));
    let d = &r.diagnostics[0];
    assert_eq!((d.line, d.column), (0, 0));
    assert!(d.message.contains("256 MiB"), "{}", d.message);
    let p = parse(&text, &ParseOptions::default());
    assert!(p.blocks.is_empty());
    assert_eq!(p.diagnostics[0].code, "program-too-large");
    // Exactly the limit is read.
    text.truncate(MAX_PROGRAM_BYTES);
    assert!(check_size(&text).is_none());
}

#[test]
fn too_many_blocks_stop_the_run_at_the_block_that_passes_the_limit() {
    // Blocks without motion do not count against the move limit.
    let text = "M08\n".repeat(20);
    for (keep_blocks, keep_moves) in [(true, true), (false, false)] {
        let options = RunOptions {
            keep_blocks,
            keep_moves,
            max_blocks: 10,
            ..RunOptions::default()
        };
        let r = run_with(&text, &Setup::default(), options);
        assert_eq!(codes(&r), ["too-many-blocks"]);
        assert_eq!(r.block_count, 10);
        assert_eq!(r.end, End::Error { line: 11 });
        assert_eq!((r.diagnostics[0].line, r.diagnostics[0].column), (11, 1));
        assert_eq!(r.events.len(), 10);
    }
}

#[test]
fn the_limits_are_the_documented_values() {
    assert_eq!(MAX_PROGRAM_BYTES, 256 * 1024 * 1024);
    assert_eq!(MAX_BLOCK_BYTES, 256 * 1024);
    assert_eq!(MAX_BLOCKS, 5_000_000);
    assert_eq!(MAX_MOVES, 5_000_000);
    assert_eq!(MAX_DIAGNOSTICS, 1000);
    assert_eq!(MAX_REPEATS, 9999);
    assert_eq!(offsetlab::machine::arc::MAX_ARC_SEGMENTS, 1024);
    assert_eq!(offsetlab::render::DRAW_TOLERANCE_PX, 0.2);
    assert_eq!(offsetlab::toolpath::CHORD_TOLERANCE, 0.01);
    assert_eq!(offsetlab::share::MAX_INFLATED, 2 * 1024 * 1024);
    assert_eq!(offsetlab::share::MAX_LINK, 4 * 1024 * 1024);
    let readme = include_str!("../README.md");
    let table = &readme[readme.find("## Limits").unwrap()..];
    let table = &table[..table[3..].find("\n## ").unwrap()];
    for row in [
        "| program size | 256 MiB",
        "| block length | 256 KiB",
        "| blocks per run | 5,000,000",
        "| moves per run | 5,000,000",
        "| diagnostics reported | 1000",
        "| canned-cycle repeats K/L | 9999",
        "| pecks per G73/G83 hole | 10,000",
        "| segments per drawn arc | 1024",
        "| chord tolerance of drawn arcs | 0.2 px on screen |",
        "| share link | 4 MiB",
        "| inflated link document | 2 MiB",
        "| positions | 10⁹ mm",
    ] {
        assert!(table.contains(row), "README Limits table lacks `{row}`");
    }
}

#[test]
fn the_default_move_limit_stops_a_runaway_cycle_quickly() {
    // K9999 holes of up to 10,000 pecks each would be ~3·10⁸ moves.
    let text = "G90 G00 Z10.\nG91 G83 X0.001 Z-10. R-1. Q0.001 K9999 F100.\nM30";
    let start = std::time::Instant::now();
    let options = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        ..RunOptions::default()
    };
    let r = run_with(text, &Setup::default(), options);
    assert_eq!(codes(&r), ["too-many-moves"]);
    assert_eq!(r.end, End::Error { line: 2 });
    assert!(r.move_count <= MAX_MOVES);
    assert!(start.elapsed().as_secs() < 60, "{:?}", start.elapsed());
}

/// Programs at the edges of every number: huge and tiny arcs, positions
/// near 10⁹ mm, inch scaling, offsets at ±999.999. None may produce a NaN
/// or an infinity anywhere (moves, block states, toolpath, JSON).
#[test]
fn extreme_numbers_never_reach_the_report_as_nan_or_infinity() {
    let programs = [
        "G02 X0.001 Y0 R99999.999 F100.",
        "G02 X0.002 Y0 R0.001 F100.",
        "G02 X0 Y0 R10. F100.",
        "G02 X0 Y0 I0.000001 F100.",
        "G03 X0 Y0 I-99999.999 J99999.999 F1.",
        "G02 X99999.999 Y0 R-0.001 F1.",
        "G02 X99999.999 Y-99999.999 R-99999.999 F1.",
        "G18 G03 X-99999.999 Z99999.999 R99999.999 F1.",
        "G91 G01 X99999.999 F1.\n".repeat(10_002).leak(),
        "G20 G91 G01 X9999.9999 Y-9999.9999 Z9999.9999 F1.\n"
            .repeat(4000)
            .leak(),
        "G91 G81 X99999.999 Z-1. R0 K9999 F1.",
        "G92 X99999.999 Y99999.999 Z99999.999\nG91 G00 X99999.999\nG90 X-99999.999",
        "G00 G43 Z-99999.999 H01\nG47 X99999.999 D01\nG02 X0 Y0 I-50000. D01 F1.",
        "G20 G00 X9999.9999\nG21 X-99999.999\nG20 G02 X0 Y0 I9999.9999 F.0001",
        "G04 P99999999\nG04 X99999.999\nG04 X0.0001",
        "G01 X1. F999999.\nF0.0001 Y1.\nS99999999 M03",
    ];
    let mut setup = Setup::default();
    for spec in ["01=999.999", "02=-999.999", "03=0.001"] {
        setup.set_register(spec).unwrap();
    }
    let mut inch = setup.clone();
    inch.units = Units::Inch;
    for text in programs {
        for s in [&setup, &inch] {
            fuzz_common::check_run_with(s, text, MAX_MOVES);
        }
    }
    // Positions past 10⁹ mm stop with numeric-overflow.
    let r = offsetlab::run(programs[8], &setup);
    assert_eq!(codes(&r), ["numeric-overflow"]);
    assert_eq!(r.end, End::Error { line: 10_001 });
}

#[test]
fn lathe_extremes_never_reach_the_report_as_nan_or_infinity() {
    let programs = [
        "G00 X99999.999 Z99999.999 T0101\nG02 X-99999.999 Z-99999.999 R-99999.999 F1.",
        "G50 X99999.999 Z-99999.999\nG90 X-99999.999 Z99999.999 R99999.999 F1.",
        "T0199\nG92 X1. Z-99999.999 F99999.999\nG94 X0 Z0 R-99999.999 F1.",
        "G20 G00 U9999.9999 W-9999.9999\nG03 U0 W0 I0.0001 F1.",
    ];
    let mut setup = Setup {
        machine: offsetlab::MachineKind::Lathe,
        ..Setup::default()
    };
    setup.set_register("01=X999.999,Z-999.999").unwrap();
    setup.set_register("99=X-999.999,Z999.999").unwrap();
    for text in programs {
        fuzz_common::check_run_with(&setup, text, MAX_MOVES);
    }
}

/// Found with the hostile corpus: the columns of diagnostics and of JSON
/// block reports were found by scanning back to the start of the line each
/// time, quadratic on a long line — 19.5 s for 1000 errors after a 20 MB
/// comment, 7 s for the JSON of 50,000 `;`-separated blocks on one line
/// (minutes for a megabyte). Now one pass (`diag::Columns`).
#[test]
fn long_lines_are_located_in_linear_time() {
    // 100 blocks of a 200 000-character comment (each within 1.25's block
    // length) on one line, then 1000 malformed words.
    let chunk = format!("({});", "A".repeat(200_000));
    let text = format!("{}{}", chunk.repeat(100), "X1.2.3 ".repeat(1000));
    let start = std::time::Instant::now();
    let r = offsetlab::run(&text, &Setup::default());
    assert_eq!(r.diagnostics.len(), 1000);
    assert_eq!(r.diagnostics[999].column, 100 * 200_003 + 7 * 999 + 1);
    let one_line = "X1.;Y1.;".repeat(25_000);
    let r = offsetlab::run(&one_line, &Setup::default());
    assert_eq!(r.blocks.len(), 50_000);
    let json = serde_json::to_string(&offsetlab::view::RunView {
        run: &r,
        text: &one_line,
    })
    .unwrap();
    assert!(json.contains(r#""line":1,"column":199997,"end_column":200000,"text":"Y1.""#));
    assert!(start.elapsed().as_secs() < 30, "{:?}", start.elapsed());
}

/// Found while checking the diagnostics cap: the run's warnings were not
/// capped (one `arc-r-no-motion` per block: 5 million blocks, 5 million
/// warnings). They now share the 1000 with the parser's diagnostics.
#[test]
fn run_warnings_share_the_diagnostics_cap() {
    let text = "G02 R1. F1.\n".repeat(5000);
    for keep in [true, false] {
        let options = RunOptions {
            keep_blocks: keep,
            keep_moves: keep,
            ..RunOptions::default()
        };
        let r = run_with(&text, &Setup::default(), options);
        assert_eq!(r.block_count, 5000);
        assert_eq!(r.diagnostics.len(), MAX_DIAGNOSTICS + 1);
        assert!(
            r.diagnostics[..1000]
                .iter()
                .all(|d| d.code == "arc-r-no-motion")
        );
        let last = &r.diagnostics[1000];
        assert_eq!(last.code, "too-many-diagnostics");
        assert!(
            last.message.starts_with("4000 more diagnostics"),
            "{}",
            last.message
        );
        assert!(!r.has_errors());
    }
    // The error that stops a run is always reported, past the cap too.
    let text = "G02 R1. F1.\n".repeat(1500) + "G02 X10. R1.\n";
    let r = offsetlab::run(&text, &Setup::default());
    assert_eq!(r.end, End::Error { line: 1501 });
    assert!(
        r.diagnostics
            .iter()
            .any(|d| d.code == "arc-radius" && d.line == 1501)
    );
}

#[test]
fn behaviour1_25_a_block_past_256_kib_is_refused_whole_and_one_within_is_read() {
    // Line 2 holds X1. X2. … : 70 000 words of 4–8 bytes, over 256 KiB
    // — refused at its first column, its words not read one by one (one
    // error, not 1000 of 1.10's `X` twice).
    let words: String = (0..70_000).map(|i| format!("X{}.", i % 100)).collect();
    assert!(words.len() > MAX_BLOCK_BYTES);
    let text = format!("G90 G00 X0 Y0\nG01{words} F100.\nM30\n");
    let r = run_with(&text, &Setup::default(), RunOptions::default());
    assert_eq!(codes(&r), ["block-too-long"]);
    let d = &r.diagnostics[0];
    assert_eq!((d.line, d.column), (2, 1));
    assert!(
        d.message
            .contains(&format!("{} bytes long", words.len() + 9)),
        "{}",
        d.message
    );
    assert_eq!(r.end, End::Error { line: 2 });
    // A comment's `;` does not end the block early: `(A;B…)` is one block.
    let comment = format!("G00 X1. (A;{})\nM30\n", "B".repeat(MAX_BLOCK_BYTES));
    let r = run_with(&comment, &Setup::default(), RunOptions::default());
    assert_eq!(codes(&r), ["block-too-long"]);
    // Just within: a 200 000-byte comment after a move is read, the move made.
    let within = format!("G00 X1. ({})\nM30\n", "C".repeat(200_000));
    let r = run_with(&within, &Setup::default(), RunOptions::default());
    assert!(r.diagnostics.is_empty(), "{:?}", codes(&r));
    assert_eq!(r.move_count, 1);
}

#[test]
fn behaviour1_25_a_clean_block_past_the_limit_is_refused_too() {
    // A block the one-pass reading would read (blanks, one word) is refused
    // the same way: the limit does not depend on what is wrong with it.
    let text = format!("G00{}X1.\nM30\n", " ".repeat(MAX_BLOCK_BYTES));
    let r = run_with(&text, &Setup::default(), RunOptions::default());
    assert_eq!(codes(&r), ["block-too-long"]);
    assert_eq!(r.move_count, 0);
}
