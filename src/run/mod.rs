//! The driver: pulls blocks from the streaming parser, runs them on the
//! machine, and collects the report. Parse errors are reported for the whole
//! program; execution stops at the first error, parse or run, the way a
//! control stops at an alarm (spec 2).

use std::sync::Arc;

pub(crate) mod again;
#[cfg(not(target_arch = "wasm32"))]
mod pipeline;

pub use again::{Earlier, Reuse, Tail};
use again::{Plan, take_tail};
#[cfg(not(target_arch = "wasm32"))]
pub use pipeline::{PIPELINE_FROM_BYTES, run_on_two_threads, run_pipelined};

use crate::diag::{self, Diagnostic};
use crate::machine::{Flow, Machine, Out};
use crate::report::{BlockReport, Bounds, End, Event, Run, include_move};
use crate::setup::{MachineKind, Setup, Units};
use crate::syntax::{Address, Block, Blocks, ParseOptions, Resume};

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
    /// Keep a [`Checkpoint`] before every this many blocks (0: none), and
    /// each block's line, so that any block's report can be made again by
    /// [`report_at`] instead of being kept: a few bytes per block instead
    /// of a few hundred (the page's way to hold a million-block run).
    pub checkpoint_every: u32,
}

impl Default for RunOptions {
    fn default() -> Self {
        RunOptions {
            keep_blocks: true,
            keep_moves: true,
            max_moves: MAX_MOVES,
            max_blocks: MAX_BLOCKS,
            checkpoint_every: 0,
        }
    }
}

/// Everything needed to go on running a program before block `index`: the
/// parser's place and the machine's state. A machine is a few hundred bytes
/// and shares the setup, so a checkpoint every thousand blocks costs well
/// under a byte per block.
#[derive(Clone, Debug)]
pub struct Checkpoint {
    /// The first block run after this point.
    pub index: u32,
    /// Moves made before this point.
    pub move_count: usize,
    parser: Resume,
    machine: Machine,
    /// What the blocks from here to the next checkpoint add to the run's
    /// totals, so that a run made again after an edit ([`rerun_observed`])
    /// can take the totals of the parts before and after the edit.
    segment: Segment,
}

/// The totals of the blocks between two checkpoints.
#[derive(Clone, Debug, Default)]
struct Segment {
    /// Bounds of their moves.
    bounds: Option<Bounds>,
    /// Offset registers they name, ascending.
    registers: Vec<u16>,
    /// Units of their first move.
    first_units: Option<Units>,
}

impl Segment {
    fn add(&mut self, other: &Segment) {
        if let Some(b) = other.bounds {
            merge(&mut self.bounds, b);
        }
        self.registers.extend_from_slice(&other.registers);
        self.registers.sort_unstable();
        self.registers.dedup();
        self.first_units = self.first_units.or(other.first_units);
    }
}

fn merge(into: &mut Option<Bounds>, b: Bounds) {
    match into {
        None => *into = Some(b),
        Some(a) => {
            for i in 0..3 {
                a.min[i] = if b.min[i] < a.min[i] {
                    b.min[i]
                } else {
                    a.min[i]
                };
                a.max[i] = if b.max[i] > a.max[i] {
                    b.max[i]
                } else {
                    a.max[i]
                };
            }
        }
    }
}

/// Checkpoints of the same program are equal when they stand at the same
/// place (the machine state there follows from the program).
impl PartialEq for Checkpoint {
    fn eq(&self, other: &Self) -> bool {
        (self.index, self.move_count, self.parser.offset())
            == (other.index, other.move_count, other.parser.offset())
    }
}

/// Runs a program with a setup, keeping every block report.
pub fn run(text: &str, setup: &Setup) -> Run {
    run_with(text, setup, RunOptions::default())
}

/// What one step of a [`Runner`] did.
enum Step {
    /// A block ran (its report is in the runner's `out` and machine).
    Ran(Flow),
    /// A block was read but not run (skipped, or after the run stopped).
    Passed,
    /// The run stops here: a parse error, a run error or a limit.
    Stopped(Option<Diagnostic>),
}

/// The block loop shared by a whole run and a run resumed from a
/// checkpoint, so both execute exactly the same way.
struct Runner<'t> {
    parser: Blocks<'t>,
    machine: Machine,
    block: Block,
    out: Out,
    options: RunOptions,
    block_skip: bool,
    /// Blocks executed so far.
    index: u32,
    /// Moves made so far.
    move_count: usize,
    /// The run has stopped (an error, a limit, M02/M30): the rest is only
    /// parsed, for its diagnostics.
    stopped: bool,
}

impl<'t> Runner<'t> {
    fn new(text: &'t str, setup: &Setup, options: RunOptions) -> Runner<'t> {
        let machine = Machine::new(Arc::new(setup.clone()));
        Runner::at(
            Blocks::new(text, ParseOptions::from(setup)),
            machine,
            setup,
            options,
        )
    }

    /// [`Runner::resume`] with the diagnostics reported before `at`.
    fn resume_after(
        text: &'t str,
        setup: &Setup,
        options: RunOptions,
        at: &Checkpoint,
        diagnostics: Vec<Diagnostic>,
    ) -> Runner<'t> {
        let parser = Blocks::resume_after(text, ParseOptions::from(setup), at.parser, diagnostics);
        Runner {
            index: at.index,
            move_count: at.move_count,
            ..Runner::at(parser, at.machine.clone(), setup, options)
        }
    }

    /// Resumes at a checkpoint, whose machine already holds the setup (a
    /// report made again for the page does not copy the setup).
    fn resume(text: &'t str, setup: &Setup, options: RunOptions, at: &Checkpoint) -> Runner<'t> {
        let parser = Blocks::resume(text, ParseOptions::from(setup), at.parser);
        Runner {
            index: at.index,
            move_count: at.move_count,
            ..Runner::at(parser, at.machine.clone(), setup, options)
        }
    }

    fn at(parser: Blocks<'t>, machine: Machine, setup: &Setup, options: RunOptions) -> Runner<'t> {
        Runner {
            parser,
            machine,
            block: Block::default(),
            out: Out::default(),
            options,
            block_skip: setup.settings.block_skip,
            index: 0,
            move_count: 0,
            stopped: false,
        }
    }

    /// [`account`]s for the block just run (`index`, its first move and
    /// what it did); its warnings go to `report`, with the parser.
    #[inline(always)]
    fn account(
        &mut self,
        result: &mut Run,
        totals: &mut Totals,
        observer: &mut impl Observer,
        kind: MachineKind,
        (index, first_move, flow): (u32, usize, Flow),
        mut report: impl FnMut(&mut Blocks<'t>, Diagnostic),
    ) {
        let Runner {
            block,
            out,
            machine,
            parser,
            options,
            ..
        } = self;
        let ran = (index, first_move, flow);
        account(
            result,
            totals,
            observer,
            options,
            kind,
            (block, out, machine),
            ran,
            |w| report(parser, w),
        );
    }

    fn checkpoint(&self) -> Checkpoint {
        Checkpoint {
            index: self.index,
            move_count: self.move_count,
            parser: self.parser.resume_point(),
            machine: self.machine.clone(),
            segment: Segment::default(),
        }
    }

    /// Reads and runs the next block; None at the end of the program.
    fn step(&mut self) -> Option<Step> {
        if !self.parser.next_into(&mut self.block) {
            return None;
        }
        self.execute()
    }

    /// Runs the block just read into `self.block`; always Some (the
    /// answer of [`Runner::step`], made in place: a `Step` made here and
    /// wrapped there was copied, 18 instructions a block).
    #[inline(always)]
    fn execute(&mut self) -> Option<Step> {
        let block = &self.block;
        if self.stopped {
            return Some(Step::Passed);
        }
        if block.error {
            self.stopped = true;
            return Some(Step::Stopped(None));
        }
        if block.skip && self.block_skip {
            return Some(Step::Passed);
        }
        self.out.clear();
        if self.index as usize >= self.options.max_blocks {
            self.stopped = true;
            return Some(Step::Stopped(Some(Diagnostic::error(
                "too-many-blocks",
                block.span,
                format!(
                    "the program runs more than {} blocks (see the limits in the README); the run stops here",
                    self.options.max_blocks
                ),
            ))));
        }
        self.machine.moves_left = self.options.max_moves.saturating_sub(self.move_count);
        match self.machine.execute(block, self.index, &mut self.out) {
            Ok(flow) => {
                self.index += 1;
                self.move_count += self.out.moves.len();
                self.stopped = flow == Flow::End;
                Some(Step::Ran(flow))
            }
            Err(d) => {
                self.stopped = true;
                Some(Step::Stopped(Some(d)))
            }
        }
    }
}

/// Runs a program with a setup.
pub fn run_with(text: &str, setup: &Setup, options: RunOptions) -> Run {
    run_observed(text, setup, options, &mut ())
}

/// Watches a run as it goes.
pub trait Observer {
    /// Every move, as it is made (whether or not the run keeps it): the
    /// page builds its toolpath this way without keeping the moves.
    fn on_move(&mut self, _m: &crate::machine::Move) {}

    /// After every [`PROGRESS_EVERY`] bytes of program: how many bytes have
    /// been read (the page shows a large program's progress).
    fn on_progress(&mut self, _read: usize) {}

    /// A run made again ([`rerun_observed`]) starts after the earlier run's
    /// first `prefix_moves` moves, before any other call.
    fn on_resume(&mut self, _prefix_moves: usize) {}
}

/// Nothing to watch.
impl Observer for () {}

/// A closure watches the moves.
impl<F: FnMut(&crate::machine::Move)> Observer for F {
    fn on_move(&mut self, m: &crate::machine::Move) {
        self(m)
    }
}

/// Bytes of program between two [`Observer::on_progress`] calls.
pub const PROGRESS_EVERY: usize = 1 << 20;

/// Runs a program with a setup, telling `observer` each move and how far
/// it has read.
pub fn run_observed(
    text: &str,
    setup: &Setup,
    options: RunOptions,
    observer: &mut impl Observer,
) -> Run {
    rerun_observed(text, setup, options, None, observer).0
}

/// The totals a run keeps as it goes.
#[derive(Default)]
struct Totals {
    /// Since the last checkpoint (all of them without checkpoints).
    segment: Segment,
    /// Before the last checkpoint.
    before: Segment,
}

impl Totals {
    /// Closes the segment of the last checkpoint (if any) at a new one.
    fn close(&mut self, checkpoints: &mut [Checkpoint]) {
        let mut segment = std::mem::take(&mut self.segment);
        segment.registers.sort_unstable();
        self.before.add(&segment);
        if let Some(last) = checkpoints.last_mut() {
            last.segment = segment;
        }
    }
}

/// Runs `text` as [`run_observed`] does, from the earlier run of a text it
/// was edited from where it can: it resumes at the earlier run's last
/// checkpoint before the edit and, once past the edit, stops at the first
/// checkpoint of the earlier run where the parser and the machine stand as
/// they stood then, and takes the earlier run's end from there. The run is
/// the same as a whole run of `text` would be, but for where its
/// checkpoints are. Only runs that keep checkpoints and neither block
/// reports nor moves (the page's) are made again; `observer` is told of
/// the moves actually made, and [`Reuse`] says which moves of the earlier
/// run come before and after them.
pub fn rerun_observed(
    text: &str,
    setup: &Setup,
    options: RunOptions,
    earlier: Option<Earlier<'_>>,
    observer: &mut impl Observer,
) -> (Run, Reuse) {
    let mut result = fresh(setup);
    let mut reuse = Reuse::default();
    let mut setup_problems = setup.validate();
    setup_problems.extend(crate::syntax::check_size(text));
    if !setup_problems.is_empty() {
        result.diagnostics = setup_problems;
        result.end = End::Error { line: 0 };
        return (result, reuse);
    }
    let plan = earlier.and_then(|e| Plan::new(e, text, setup, options));
    let mut totals = Totals::default();
    let mut r = match &plan {
        None => Runner::new(text, setup, options),
        Some(plan) => plan.resume(
            text,
            setup,
            options,
            &mut result,
            &mut totals,
            &mut reuse,
            observer,
        ),
    };
    let mut run_diagnostics: Vec<Diagnostic> = Vec::new();
    let every = options.checkpoint_every;
    let mut next_progress = PROGRESS_EVERY;
    let mut last_pos = usize::MAX;
    loop {
        if !r.stopped
            && every > 0
            && result
                .checkpoints
                .last()
                .is_none_or(|c| r.index >= c.index.saturating_add(every))
        {
            totals.close(&mut result.checkpoints);
            result.checkpoints.push(r.checkpoint());
        }
        if let Some(plan) = &plan
            && r.parser.offset() != last_pos
        {
            last_pos = r.parser.offset();
            if let Some((k, d)) = plan.caught_up(&r, &options) {
                reuse.tail = Some(take_tail(&mut result, &mut r, &mut totals, plan, k, &d));
                break;
            }
        }
        let index = r.index;
        let first_move = r.move_count;
        if r.parser.offset() >= next_progress {
            observer.on_progress(r.parser.offset());
            next_progress = r.parser.offset() + PROGRESS_EVERY;
        }
        let Some(step) = r.step() else { break };
        let flow = match step {
            Step::Passed => continue,
            Step::Stopped(d) => {
                stop(&mut result, &mut run_diagnostics, r.block.span.line, d);
                continue;
            }
            Step::Ran(flow) => flow,
        };
        // Warnings share the diagnostics cap with the parser's (a warning
        // per block could otherwise fill memory and the page's list).
        let ran = (index, first_move, flow);
        r.account(
            &mut result,
            &mut totals,
            observer,
            setup.machine,
            ran,
            |parser, w| parser.report(w),
        );
    }
    if reuse.tail.is_none() {
        counts(&mut result, &r);
    }
    let mut diagnostics = r.parser.into_diagnostics();
    diagnostics.append(&mut run_diagnostics);
    close(&mut result, totals, diagnostics, text);
    (result, reuse)
}

/// A run of nothing yet.
fn fresh(setup: &Setup) -> Run {
    Run {
        machine: setup.machine,
        units: setup.units,
        end_units: setup.units,
        blocks: Vec::new(),
        moves: Vec::new(),
        events: Vec::new(),
        diagnostics: Vec::new(),
        block_count: 0,
        registers: Vec::new(),
        move_count: 0,
        bounds: None,
        end: End::Completed,
        checkpoints: Vec::new(),
        lines: Vec::new(),
    }
}

/// The run's counts where the runner stopped.
fn counts(result: &mut Run, r: &Runner<'_>) {
    result.block_count = r.index;
    result.move_count = r.move_count;
    result.end_units = r.machine.state().modal.units;
}

/// The run's totals and its diagnostics, in order, with their columns.
fn close(result: &mut Run, mut totals: Totals, mut diagnostics: Vec<Diagnostic>, text: &str) {
    totals.close(&mut result.checkpoints);
    let all = totals.before;
    result.bounds = all.bounds;
    result.registers = all.registers;
    result.units = all.first_units.unwrap_or(result.end_units);
    diag::finish(&mut diagnostics, text);
    result.diagnostics = diagnostics;
}

/// The run stops at a block on line `line` (an error or a limit).
fn stop(result: &mut Run, run_diagnostics: &mut Vec<Diagnostic>, line: u32, d: Option<Diagnostic>) {
    result.end = End::Error {
        line: d.as_ref().map_or(line, |d| d.span.line.max(line)),
    };
    run_diagnostics.extend(d);
}

/// Adds what a block that ran did to the run and its totals, and tells the
/// observer of its moves; its warnings go to `report`. (One place for the
/// run on one thread and the run on two, [`pipeline`].)
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn account(
    result: &mut Run,
    totals: &mut Totals,
    observer: &mut impl Observer,
    options: &RunOptions,
    kind: MachineKind,
    (block, out, machine): (&Block, &mut Out, &Machine),
    (index, first_move, flow): (u32, usize, Flow),
    mut report: impl FnMut(Diagnostic),
) {
    let segment = &mut totals.segment;
    if segment.first_units.is_none() && !out.moves.is_empty() {
        segment.first_units = Some(machine.state().modal.units);
    }
    for m in &out.moves {
        include_move(&mut segment.bounds, m);
        observer.on_move(m);
    }
    if options.keep_moves {
        result.moves.extend_from_slice(&out.moves);
    }
    // Most blocks have no event and no warning: the tests skip setting
    // up the two drains (callgrind: 30 instructions a block).
    if !out.events.is_empty() {
        result.events.extend(out.events.drain(..).map(|kind| Event {
            block: index,
            line: block.span.line,
            kind,
        }));
    }
    if !out.warnings.is_empty() {
        for w in out.warnings.drain(..) {
            report(w);
        }
    }
    if options.keep_blocks {
        result.blocks.push(BlockReport {
            index,
            span: block.span,
            state: *machine.state(),
            notes: std::mem::take(&mut out.notes),
            first_move: first_move as u32,
            move_count: out.moves.len() as u32,
        });
    }
    if options.checkpoint_every > 0 {
        result.lines.push(block.span.line);
    }
    let offset_words = match kind {
        MachineKind::Mill => block.holds(Address::D) || block.holds(Address::H),
        MachineKind::Lathe => block.holds(Address::T),
    };
    for w in block.words.iter().filter(|_| offset_words) {
        let n = match (w.address, kind) {
            (Address::D | Address::H, MachineKind::Mill) => w.int() as u16,
            (Address::T, MachineKind::Lathe) => (w.int() % 100) as u16,
            _ => 0,
        };
        if n != 0 && !segment.registers.contains(&n) {
            segment.registers.push(n);
        }
    }
    if flow == Flow::End {
        result.end = End::ProgramEnd {
            line: block.span.line,
        };
    }
}

/// The report of block `index` of `run` (a run of `text` and `setup` made
/// with checkpoints), made again from the checkpoint before it; None when
/// the run has no such block or no checkpoints. It equals the report a run
/// keeping every block would have kept.
pub fn report_at(text: &str, setup: &Setup, run: &Run, index: u32) -> Option<BlockReport> {
    if index >= run.block_count {
        return None;
    }
    let at = run.checkpoints.iter().rev().find(|c| c.index <= index)?;
    let options = RunOptions {
        keep_blocks: true,
        keep_moves: false,
        max_moves: usize::MAX,
        max_blocks: usize::MAX,
        checkpoint_every: 0,
    };
    let mut r = Runner::resume(text, setup, options, at);
    loop {
        let this = r.index;
        let first_move = r.move_count;
        match r.step()? {
            Step::Ran(_) if this == index => {
                return Some(BlockReport {
                    index,
                    span: r.block.span,
                    state: *r.machine.state(),
                    notes: std::mem::take(&mut r.out.notes),
                    first_move: first_move as u32,
                    move_count: r.out.moves.len() as u32,
                });
            }
            Step::Ran(_) | Step::Passed => {}
            Step::Stopped(_) => return None,
        }
    }
}
