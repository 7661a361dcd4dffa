//! The CLI's run on two threads (`run_pipelined`: the parser on one, the
//! machine on the other) is the one-thread run, field for field: totals,
//! moves, block reports, events, the end, and every diagnostic in the same
//! place and order — the machine's warnings among the parser's as one
//! thread reports them, and the cap of 1000 kept the same way (near it the
//! run is made on one thread). Checked on every fixture, hostile input and
//! fuzz finding, on programs crossing many batches of blocks, and on random
//! programs.
#![cfg(not(target_arch = "wasm32"))]

mod common;
#[path = "../benches/programs.rs"]
mod programs;

use std::path::Path;

use offsetlab::syntax::MAX_DIAGNOSTICS;
use offsetlab::{
    PIPELINE_FROM_BYTES, Run, RunOptions, Setup, run_on_two_threads, run_pipelined, run_with,
};
use proptest::prelude::*;

/// What the CLI's `check` keeps, what its `run` keeps, and both with small
/// limits (a run stopped by a limit part-way through a batch).
fn options() -> [RunOptions; 4] {
    let check = RunOptions {
        keep_blocks: false,
        keep_moves: false,
        ..RunOptions::default()
    };
    let run = RunOptions::default();
    [
        check,
        run,
        RunOptions {
            max_blocks: 300,
            ..check
        },
        RunOptions {
            max_moves: 7,
            ..run
        },
    ]
}

/// True when the run jumps (its checkpoints say so).
fn jumps(text: &str, setup: &Setup, options: RunOptions) -> bool {
    let options = RunOptions {
        checkpoint_every: 1_000_000,
        ..options
    };
    offsetlab::run_observed(text, setup, options, &mut ())
        .1
        .calls
}

/// The two-thread run equals the one-thread run, or is refused only where
/// the diagnostics reach their cap.
fn assert_same(text: &str, setup: &Setup, what: &str) {
    for options in options() {
        let one = run_with(text, setup, options);
        match run_on_two_threads(text, setup, options) {
            Some(two) => assert_runs_equal(&two, &one, what),
            // A program that jumps (a call, a macro GOTO or loop) runs on
            // one thread (behaviour 19.9, 20.15).
            None => assert!(
                one.diagnostics.len() >= MAX_DIAGNOSTICS
                    || !setup.validate().is_empty()
                    || offsetlab::syntax::check_size(text).is_some()
                    || jumps(text, setup, options),
                "{what}: refused with {} diagnostics",
                one.diagnostics.len()
            ),
        }
    }
}

fn assert_runs_equal(two: &Run, one: &Run, what: &str) {
    assert_eq!(two.diagnostics, one.diagnostics, "{what}: diagnostics");
    assert_eq!(two.end, one.end, "{what}: end");
    assert_eq!(
        (two.block_count, two.move_count),
        (one.block_count, one.move_count),
        "{what}: counts"
    );
    assert_eq!(two.bounds, one.bounds, "{what}: bounds");
    assert_eq!(two.registers, one.registers, "{what}: registers");
    assert_eq!(
        (two.units, two.end_units),
        (one.units, one.end_units),
        "{what}: units"
    );
    assert_eq!(two.events, one.events, "{what}: events");
    assert_eq!(two.moves, one.moves, "{what}: moves");
    assert_eq!(two.blocks, one.blocks, "{what}: block reports");
    assert_eq!(two, one, "{what}: the whole run");
}

fn files(dir: &str) -> Vec<std::path::PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_file() && p.extension().is_none_or(|e| e != "md" && e != "json"))
        .collect();
    files.sort();
    files
}

#[test]
fn every_fixture_and_hostile_input_runs_the_same_on_two_threads() {
    let mut seen = 0;
    for path in files("tests/data")
        .into_iter()
        .chain(files("tests/data/hostile"))
    {
        let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
        let setup = std::fs::read_to_string(path.with_extension("json"))
            .ok()
            .and_then(|json| Setup::from_json(&json).ok())
            .unwrap_or_default();
        assert_same(&text, &setup, &path.display().to_string());
        seen += 1;
    }
    assert!(seen > 20, "{seen} files");
}

#[test]
fn fuzz_findings_run_the_same_on_two_threads() {
    for path in files("tests/data/fuzz/run") {
        let bytes = std::fs::read(&path).unwrap();
        // A 44-byte setup header, then the program (fuzz/common/mod.rs);
        // here the program alone, with two setups.
        let text = String::from_utf8_lossy(bytes.get(44..).unwrap_or_default()).into_owned();
        assert_same(&text, &Setup::default(), &path.display().to_string());
        assert_same(
            &text,
            &common::mill(&[(1, 6.0), (2, -3.5)]),
            &path.display().to_string(),
        );
    }
}

#[test]
fn programs_of_many_batches_run_the_same_on_two_threads() {
    let (text, setup) = common::fixture("pocket_g43_drill");
    let without_end = text.replace("M30", "");
    assert_same(&without_end.repeat(60), &setup, "pocket ×60");
    let mut setup = Setup::default();
    setup.set_register("01=100").unwrap();
    assert_same(
        &programs::mill_program(3000),
        &setup,
        "benchmark program, 3000 blocks",
    );
}

#[test]
fn look_ahead_across_batches_runs_the_same_on_two_threads() {
    // Every block chamfers its end (behaviour 2.30), so the block that ends
    // a batch reads the next batch's first block ahead: the text past the
    // batch, read from the batch's end.
    let square = "G91 G01 X10. ,C1. F100.\nY10. ,C1.\nX-10. ,C1.\nY-10. ,C1.\n";
    let text = format!("{}G90 X20. Y0\n", square.repeat(1100));
    let one = offsetlab::run(&text, &Setup::default());
    assert!(!one.has_errors(), "{:?}", one.diagnostics.first());
    assert_same(&text, &Setup::default(), "chamfered squares, 4401 blocks");
}

#[test]
fn warnings_between_parse_diagnostics_keep_their_order_across_batches() {
    // A machine warning (R with I/J, H00) and parse diagnostics in every
    // few blocks, at the same places as each other: one thread reports a
    // block's warnings after what the parser reported up to its end.
    let mut text = String::from("G90 G01 F100. X0 Y0\n");
    for i in 0..700 {
        text.push_str(match i % 4 {
            0 => "G01 X0. Y0.\n",
            1 => "G02 X10. Y0. R5. I5.\n",
            2 => "G01 G43 H00 Z1.\n",
            _ => "G49 G01 X3 Y1.\n", // the parser's integer-dimension warning, once
        });
    }
    // The run stops at an error; the parser reads on.
    text.push_str("G01 X1.2.3\n");
    text.push_str(&"G01 X1. Q\n".repeat(100));
    let setup = Setup::default();
    let one = run_with(&text, &setup, RunOptions::default());
    let codes = |code: &str| one.diagnostics.iter().filter(|d| d.code == code).count();
    assert_eq!(codes("arc-r-and-center"), 175);
    assert_eq!(codes("length-offset-h00"), 175);
    assert_eq!(codes("integer-dimension"), 1);
    assert_eq!(codes("missing-number"), 100);
    assert_same(&text, &setup, "warnings and parse diagnostics");
}

#[test]
fn near_the_diagnostics_cap_the_run_is_made_on_one_thread() {
    // 1400 warnings: which 1000 are kept depends on the order of the two
    // threads' reports, so run_pipelined runs on one thread.
    let mut text = String::from("G90 G01 F100. X0 Y0\n");
    while text.len() < PIPELINE_FROM_BYTES + 1000 {
        text.push_str(
            "G02 X10. Y0 R5. I5.\nG03 X0 Y0 R5. I-5.\n(padding padding padding padding padding)\n",
        );
    }
    let setup = Setup::default();
    let check = options()[0];
    assert!(run_on_two_threads(&text, &setup, check).is_none());
    let one = run_with(&text, &setup, check);
    assert_eq!(
        one.diagnostics.len(),
        MAX_DIAGNOSTICS + 1,
        "capped, and the note that says so"
    );
    assert_runs_equal(&run_pipelined(&text, &setup, check), &one, "capped");
}

#[test]
fn a_large_program_runs_on_two_threads_with_the_one_thread_result() {
    let mut setup = Setup::default();
    setup.set_register("01=100").unwrap();
    let text = programs::mill_program(40_000);
    assert!(text.len() >= PIPELINE_FROM_BYTES, "{} bytes", text.len());
    for options in options() {
        let one = run_with(&text, &setup, options);
        assert_runs_equal(&run_pipelined(&text, &setup, options), &one, "40k blocks");
    }
}

/// A line of a random program: motion, offsets, cycles, errors, warnings,
/// ends, skips and comments.
fn line() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => (-50i32..50, -50i32..50).prop_map(|(x, y)| format!("G01 X{x}. Y{y}. F200.")),
        3 => (1i32..20).prop_map(|r| format!("G02 X{r}. Y0 R{r}.")),
        2 => (1i32..9).prop_map(|i| format!("G03 X0 Y0 I{i}.")),
        2 => Just("G91 G00 G46 X30. Y20. D01".to_string()),
        2 => Just("G90 G47 X10. D02".to_string()),
        2 => Just("G43 Z5. H01".to_string()),
        1 => Just("G43 H00 Z1.".to_string()),
        1 => Just("G49".to_string()),
        1 => Just("G02 X10. Y0 R5. I5.".to_string()),
        1 => Just("G81 X5. Y5. Z-3. R2. F80.".to_string()),
        1 => Just("G80".to_string()),
        1 => Just("G20".to_string()),
        1 => Just("G21".to_string()),
        1 => Just("/G01 X3.".to_string()),
        1 => Just("G01 X1.2.3".to_string()),
        1 => Just("G01 X1. Q".to_string()),
        1 => Just("(comment".to_string()),
        1 => Just("M30".to_string()),
        1 => Just("%".to_string()),
        1 => Just(String::new()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    #[test]
    fn random_programs_run_the_same_on_two_threads(
        lines in prop::collection::vec(line(), 0..900),
        crlf in any::<bool>(),
    ) {
        let text = lines.join(if crlf { "\r\n" } else { "\n" });
        let setup = common::mill(&[(1, 6.0), (2, -3.5)]);
        assert_same(&text, &setup, "random program");
    }
}
