//! Helpers shared by the native integration tests.
#![allow(dead_code)]

pub mod programs;
pub mod session;

use offsetlab::geometry::Xyz;
use offsetlab::report::Run;
use offsetlab::view::{BlockView, block_view};
use offsetlab::{Checkpoints, MachineKind, RunOptions, Setup, run, run_observed};

/// A mill setup with registers `(number, value)`.
pub fn mill(registers: &[(u16, f64)]) -> Setup {
    let mut s = Setup::default();
    for (n, v) in registers {
        s.set_register(&format!("{n}={v}")).unwrap();
    }
    s
}

/// A lathe setup with registers `(number, x, z)`.
pub fn lathe(registers: &[(u16, f64, f64)]) -> Setup {
    let mut s = Setup {
        machine: MachineKind::Lathe,
        ..Setup::default()
    };
    for (n, x, z) in registers {
        s.set_register(&format!("{n}=X{x},Z{z}")).unwrap();
    }
    s
}

/// Runs and asserts that no error was reported.
pub fn ok(text: &str, setup: &Setup) -> Run {
    let r = run(text, setup);
    assert!(!r.has_errors(), "unexpected errors: {:#?}", r.diagnostics);
    r
}

/// Runs and returns the error codes (errors only).
pub fn errors(text: &str, setup: &Setup) -> Vec<&'static str> {
    run(text, setup)
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .map(|d| d.code)
        .collect()
}

/// The report of the block on `line` (the last one if two share it).
pub fn at_line<'a>(r: &'a Run, text: &'a str, line: u32) -> BlockView<'a> {
    let b = r
        .blocks
        .iter()
        .rev()
        .find(|b| b.span.line == line)
        .unwrap_or_else(|| panic!("no block on line {line}"));
    block_view(b, text)
}

/// Asserts two positions are equal to a micrometre.
#[track_caller]
pub fn same(got: Xyz, want: Xyz) {
    for i in 0..3 {
        assert!(
            (got[i] - want[i]).abs() < 1e-6,
            "got {got:?}, want {want:?}"
        );
    }
}

/// Actual position after block `i` (mm).
pub fn actual(r: &Run, i: usize) -> Xyz {
    r.blocks[i].state.actual
}

/// Programmed position after block `i` (mm).
pub fn programmed(r: &Run, i: usize) -> Xyz {
    r.blocks[i].state.programmed
}

/// The explanation of block `i`.
pub fn explain(r: &Run, i: usize) -> String {
    r.blocks[i].explanation()
}

/// A fixture of `tests/data`: its program and its setup.
pub fn fixture(name: &str) -> (String, Setup) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/");
    let text = std::fs::read_to_string(format!("{dir}{name}.nc")).unwrap();
    let setup =
        Setup::from_json(&std::fs::read_to_string(format!("{dir}{name}.json")).unwrap()).unwrap();
    (text, setup)
}

/// A run keeping a checkpoint every `every` blocks and no block reports
/// (as the page runs), with its checkpoints.
pub fn checkpointed(text: &str, setup: &Setup, every: u32) -> (Run, Checkpoints) {
    let options = RunOptions {
        keep_blocks: false,
        checkpoint_every: every,
        ..RunOptions::default()
    };
    run_observed(text, setup, options, &mut ())
}

/// The first error: (code, line, column).
pub fn first_error(r: &Run) -> (&'static str, u32, u32) {
    let d = r
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .expect("an error");
    (d.code, d.line, d.column)
}

/// The code and line of the first error running `text` with `setup`.
pub fn error_line(text: &str, setup: &Setup) -> (&'static str, u32) {
    let (code, line, _) = first_error(&run(text, setup));
    (code, line)
}

/// A mill setup under the linuxcnc profile (behaviour 22).
pub fn linuxcnc() -> Setup {
    let mut s = Setup::default();
    s.settings.control = offsetlab::setup::Control::Linuxcnc;
    s
}

/// The seconds of every dwell the run made, in order.
pub fn dwells(r: &Run) -> Vec<f64> {
    r.events
        .iter()
        .filter_map(|e| match e.kind {
            offsetlab::machine::EventKind::Dwell { seconds } => Some(seconds),
            _ => None,
        })
        .collect()
}
