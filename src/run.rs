//! The driver: pulls blocks from the streaming parser, runs them on the
//! machine, and collects the report. Parse errors are reported for the whole
//! program; execution stops at the first error, parse or run, the way a
//! control stops at an alarm (spec 2).

use crate::diag::{self, Diagnostic};
use crate::machine::{Flow, Machine, Out};
use crate::report::{BlockReport, End, Event, Run, include_move};
use crate::setup::{MachineKind, Setup};
use crate::syntax::{Address, Block, Blocks, ParseOptions};

/// Most moves one run records by default; past this the run stops with an
/// error (a move is about 200 bytes: 5 million is about 1 GB).
pub const MAX_MOVES: usize = 5_000_000;

/// Most blocks one run executes by default; past this the run stops with an
/// error. Blocks without motion (M codes, dwells, G92) do not count against
/// [`MAX_MOVES`], and a block report is a few hundred bytes, so without this
/// a large program of such blocks could exhaust memory.
pub const MAX_BLOCKS: usize = 5_000_000;

/// What to keep of a run.
#[derive(Clone, Copy, Debug)]
pub struct RunOptions {
    /// Keep a report per block (the `check` fast path does not need them).
    pub keep_blocks: bool,
    /// Keep every move (the `check` fast path only counts them and keeps
    /// their bounds).
    pub keep_moves: bool,
    /// Most moves to record before stopping with `too-many-moves`.
    pub max_moves: usize,
    /// Most blocks to execute before stopping with `too-many-blocks`
    /// (counted whether or not their reports are kept, so `check` and `run`
    /// stop at the same block).
    pub max_blocks: usize,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions {
            keep_blocks: true,
            keep_moves: true,
            max_moves: MAX_MOVES,
            max_blocks: MAX_BLOCKS,
        }
    }
}

/// Runs a program with a setup, keeping every block report.
pub fn run(text: &str, setup: &Setup) -> Run {
    run_with(text, setup, RunOptions::default())
}

/// Runs a program with a setup.
pub fn run_with(text: &str, setup: &Setup, options: RunOptions) -> Run {
    let mut result = Run {
        machine: setup.machine,
        units: setup.units,
        blocks: Vec::new(),
        moves: Vec::new(),
        events: Vec::new(),
        diagnostics: Vec::new(),
        block_count: 0,
        registers: Vec::new(),
        move_count: 0,
        bounds: None,
        end: End::Completed,
    };
    let mut setup_problems = setup.validate();
    setup_problems.extend(crate::syntax::check_size(text));
    if !setup_problems.is_empty() {
        result.diagnostics = setup_problems;
        result.end = End::Error { line: 0 };
        return result;
    }
    let mut parser = Blocks::new(text, ParseOptions::from(setup));
    let mut machine = Machine::new(setup);
    let mut block = Block::default();
    let mut out = Out::default();
    let mut run_diagnostics: Vec<Diagnostic> = Vec::new();
    let mut stopped = false;
    let mut units_known = false;
    let mut registers = std::collections::BTreeSet::new();
    while parser.next_into(&mut block) {
        if stopped {
            continue;
        }
        if block.error {
            stopped = true;
            result.end = End::Error {
                line: block.span.line,
            };
            continue;
        }
        if block.skip && setup.settings.block_skip {
            continue;
        }
        out.clear();
        let index = result.block_count;
        if index as usize >= options.max_blocks {
            stopped = true;
            result.end = End::Error {
                line: block.span.line,
            };
            run_diagnostics.push(Diagnostic::error(
                "too-many-blocks",
                block.span,
                format!(
                    "the program runs more than {} blocks (see the limits in the README); the run stops here",
                    options.max_blocks
                ),
            ));
            continue;
        }
        machine.moves_left = options.max_moves.saturating_sub(result.move_count);
        let flow = match machine.execute(&block, index, &mut out) {
            Ok(flow) => flow,
            Err(d) => {
                result.end = End::Error {
                    line: d.span.line.max(block.span.line),
                };
                run_diagnostics.push(d);
                stopped = true;
                continue;
            }
        };
        if !units_known && !out.moves.is_empty() {
            units_known = true;
            result.units = machine.state().modal.units;
        }
        let first_move = result.move_count as u32;
        for m in &out.moves {
            include_move(&mut result.bounds, m);
        }
        result.move_count += out.moves.len();
        if options.keep_moves {
            result.moves.extend_from_slice(&out.moves);
        }
        result.events.extend(out.events.drain(..).map(|kind| Event {
            block: index,
            line: block.span.line,
            kind,
        }));
        // Warnings share the diagnostics cap with the parser's (a warning
        // per block could otherwise fill memory and the page's list).
        for w in out.warnings.drain(..) {
            parser.report(w);
        }
        if options.keep_blocks {
            result.blocks.push(BlockReport {
                index,
                span: block.span,
                state: *machine.state(),
                notes: std::mem::take(&mut out.notes),
                first_move,
                move_count: out.moves.len() as u32,
            });
        }
        result.block_count += 1;
        for w in &block.words {
            let n = match (w.address, setup.machine) {
                (Address::D | Address::H, MachineKind::Mill) => w.int() as u16,
                (Address::T, MachineKind::Lathe) => (w.int() % 100) as u16,
                _ => 0,
            };
            if n != 0 {
                registers.insert(n);
            }
        }
        if flow == Flow::End {
            stopped = true;
            result.end = End::ProgramEnd {
                line: block.span.line,
            };
        }
    }
    if !units_known {
        result.units = machine.state().modal.units;
    }
    result.registers = registers.into_iter().collect();
    let mut diagnostics = parser.into_diagnostics();
    diagnostics.append(&mut run_diagnostics);
    diag::finish(&mut diagnostics, text);
    result.diagnostics = diagnostics;
    result
}
