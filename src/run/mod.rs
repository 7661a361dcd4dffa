//! The driver: pulls blocks from the streaming parser, runs them on the
//! machine, and collects the report. Parse errors are reported for the whole
//! program; execution stops at the first error, parse or run, the way a
//! control stops at an alarm (behaviour 2.1).
//!
//! [`run_observed`] is the run: one loop over the blocks, which may keep
//! [`Checkpoints`] beside the [`Run`] it makes. A run made again after an
//! edit (`again.rs`) wraps that loop: it starts it at the earlier run's
//! checkpoint before the edit and stops it where it catches up with the
//! earlier run. The run on two threads (`pipeline.rs`) shares the loop's
//! accounting of a block.

use std::sync::Arc;

pub(crate) mod again;
mod ahead;
mod calls;
mod checkpoint;
mod flow;
mod library;
mod macrocall;
mod macros;
mod named;
mod observer;
mod oword;
#[cfg(not(target_arch = "wasm32"))]
pub(crate) mod pipeline;
mod sequence;
mod skip;

use checkpoint::Totals;
pub use checkpoint::{Checkpoint, Checkpoints, Read, report_at};
pub use observer::{Observer, PROGRESS_EVERY};

use crate::diag::{self, Diagnostic};
use crate::machine::program::ProgramText;
use crate::machine::{Ahead, EventKind, Flow, Machine, Out};
use crate::report::{BlockReport, End, Event, Place, Run, include_move};
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
    /// The block could not run and is passed over, the machine as it was
    /// before it (setting `continue_past_errors`, behaviour 2.24): the
    /// run's error, or None for the parser's.
    Skipped(Option<Diagnostic>),
}

/// The block loop shared by a whole run and a run resumed from a
/// checkpoint, so both execute exactly the same way.
struct Runner<'t> {
    parser: Blocks<'t>,
    /// The text again, for the blocks that read it by sequence number
    /// (behaviour 15.3).
    sequences: sequence::Sequences<'t>,
    /// The blocks after the running one, when the machine asks.
    ahead: ahead::Reader<'t>,
    machine: Machine,
    block: Block,
    out: Out,
    options: RunOptions,
    block_skip: bool,
    /// Continue past errors (behaviour 2.24).
    keep_going: bool,
    /// Blocks executed so far.
    index: u32,
    /// Moves made so far.
    move_count: usize,
    /// The run has stopped (an error, a limit, M02/M30): the rest is only
    /// parsed, for its diagnostics.
    stopped: bool,
    /// The subprogram calls, once the run has made one (behaviour 19).
    calls: Option<Box<calls::Calls<'t>>>,
    /// The place of the block just run when it jumped (its report's:
    /// where it was before the jump).
    block_place: Option<Box<Place>>,
    /// The macro loops running, once the run has met a jump or a loop
    /// (behaviour 20.11–20.15).
    loops: Option<Box<flow::Loops>>,
}

impl<'t> Runner<'t> {
    fn new(text: &'t str, setup: &Setup, options: RunOptions) -> Runner<'t> {
        let machine = Machine::new(Arc::new(setup.clone()));
        Runner::at(
            text,
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
        let mut r = Runner {
            index: at.index,
            move_count: at.move_count,
            ..Runner::at(text, parser, at.machine.clone(), setup, options)
        };
        r.ahead.horizon = at.horizon;
        r.restore_calls(at);
        r
    }

    /// Resumes at a checkpoint, whose machine already holds the setup (a
    /// report made again for the page does not copy the setup).
    fn resume(text: &'t str, setup: &Setup, options: RunOptions, at: &Checkpoint) -> Runner<'t> {
        let parser = Blocks::resume(text, ParseOptions::from(setup), at.parser);
        let mut r = Runner {
            index: at.index,
            move_count: at.move_count,
            ..Runner::at(text, parser, at.machine.clone(), setup, options)
        };
        r.ahead.horizon = at.horizon;
        r.restore_calls(at);
        r
    }

    fn at(
        text: &'t str,
        parser: Blocks<'t>,
        machine: Machine,
        setup: &Setup,
        options: RunOptions,
    ) -> Runner<'t> {
        Runner {
            parser,
            sequences: sequence::Sequences::new(text, ParseOptions::from(setup)),
            ahead: ahead::Reader::new(setup.settings.block_skip),
            machine,
            block: Block::default(),
            out: Out::for_reports(options.keep_blocks),
            options,
            block_skip: setup.settings.block_skip,
            keep_going: setup.settings.continue_past_errors,
            index: 0,
            move_count: 0,
            stopped: false,
            calls: None,
            block_place: None,
            loops: None,
        }
    }

    /// The calls open at checkpoint `at`, taken up (behaviour 19.9).
    fn restore_calls(&mut self, at: &Checkpoint) {
        self.loops = at.loops.as_deref().map(flow::Saved::restore);
        let Some(saved) = at.calls.as_deref() else {
            return;
        };
        let parser = std::mem::replace(&mut self.parser, Blocks::new("", ParseOptions::default()));
        let (calls, parser) = saved.restore(&self.sequences, parser);
        self.parser = parser;
        self.calls = Some(calls);
        saved.aim(&mut self.sequences);
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
        if self.calls.is_some() && self.options.keep_blocks {
            self.block_place = self.place_of(flow);
        }
        let Runner {
            block,
            out,
            machine,
            parser,
            options,
            calls,
            block_place,
            ..
        } = self;
        let ran = (index, first_move, flow);
        account(
            result,
            totals,
            observer,
            options,
            kind,
            (block, out, machine, block_place),
            ran,
            // The machine's warnings go with the first parser's
            // diagnostics, wherever the blocks are read (behaviour 19).
            |w| match calls.as_deref_mut().and_then(|c| c.main_parser()) {
                Some(main) => report(main, w),
                None => report(parser, w),
            },
        );
    }

    fn checkpoint(&self) -> Checkpoint {
        Checkpoint {
            index: self.index,
            move_count: self.move_count,
            parser: self.parser.resume_point(),
            horizon: self.ahead.horizon.max(self.parser.offset()),
            machine: self.machine.clone(),
            segment: Default::default(),
            calls: self.calls.as_ref().map(|c| Box::new(c.save())),
            loops: self.loops.as_ref().map(|l| Box::new(l.save())),
        }
    }

    /// Reads and runs the next block; None at the end of the program.
    fn step(&mut self) -> Option<Step> {
        if !self.parser.next_into(&mut self.block) {
            // The text's end, or a subprogram's (behaviour 19).
            return self.program_ends().or_else(|| self.text_ends());
        }
        if self.keep_going {
            // Out of line (behaviour 2.24): off, one test per block (the
            // `check` instruction count in docs/performance.md).
            return self.step_keeping_going();
        }
        self.run_block()
    }

    /// Runs the block just read ([`Runner::step`]).
    #[inline(always)]
    fn run_block(&mut self) -> Option<Step> {
        let mut ahead = self.ahead.at(self.index, ahead::From::Parser(&self.parser));
        let step = execute(
            &self.block,
            &mut self.machine,
            &mut self.out,
            &self.options,
            (&mut self.index, &mut self.move_count, &mut self.stopped),
            self.block_skip,
            (&mut ahead, &mut self.sequences),
        );
        // A call or return, or the block limit (its message names a loop):
        // asked of the machine and the count, not of the step (which is
        // made in place, as `execute` says).
        // A program that made a macro call (behaviour 21) takes the same
        // way out: a G66 in force may call after the block's move.
        if self.machine.jump.is_some()
            || self.machine.macro_calls.is_some()
            || self.index as usize >= self.options.max_blocks
        {
            return step.map(|s| self.after_block(s));
        }
        step
    }
}

/// Runs the block just read (a runner's `block`, with the runner's other
/// parts: split so that look-ahead may borrow the parser meanwhile);
/// always Some (the answer of [`Runner::step`], made in place: a `Step`
/// made here and wrapped there was copied every block; the `check`
/// instruction count in docs/performance.md guards it).
#[inline(always)]
fn execute(
    block: &Block,
    machine: &mut Machine,
    out: &mut Out,
    options: &RunOptions,
    (index, move_count, stopped): (&mut u32, &mut usize, &mut bool),
    block_skip: bool,
    (ahead, program): (&mut dyn Ahead, &mut dyn ProgramText),
) -> Option<Step> {
    if *stopped {
        return Some(Step::Passed);
    }
    if block.error {
        *stopped = true;
        return Some(Step::Stopped(None));
    }
    if block.skip && block_skip {
        return Some(Step::Passed);
    }
    out.clear();
    if *index as usize >= options.max_blocks {
        *stopped = true;
        return Some(Step::Stopped(Some(Diagnostic::error(
            "too-many-blocks",
            block.span,
            format!(
                "the program runs more than {} blocks (see the limits in the README); the run stops here",
                options.max_blocks
            ),
        ))));
    }
    let resolved;
    let block = match &block.macros {
        None => block,
        Some(m) if let Some(call) = &m.call => {
            // G65, G66, G67 (behaviour 21): no block for the machine.
            let result = macrocall::call(block, m, call, machine, out, program);
            return Some(macrocall::ran(result, index, stopped));
        }
        // A jump or a loop's statement leaves its step in the machine's
        // `jump` (behaviour 20.11–20.14), which the runner takes.
        Some(m) => match macros::resolve(block, m, machine, out) {
            Ok(b) => {
                resolved = b;
                &resolved
            }
            Err(d) => {
                *stopped = true;
                return Some(Step::Stopped(Some(d)));
            }
        },
    };
    machine.moves_left = options.max_moves.saturating_sub(*move_count);
    match machine.execute(block, *index, out, ahead, program) {
        Ok(flow) => {
            if block.speaks {
                machine.comment_messages(block, out, program);
            }
            *index += 1;
            *move_count += out.moves.len();
            *stopped = flow == Flow::End;
            Some(Step::Ran(flow))
        }
        Err(d) => {
            *stopped = true;
            Some(Step::Stopped(Some(d)))
        }
    }
}

/// Runs a program with a setup (its checkpoints, if the options ask for
/// any, are not kept: see [`run_observed`]).
pub fn run_with(text: &str, setup: &Setup, options: RunOptions) -> Run {
    run_observed(text, setup, options, &mut ()).0
}

/// Runs a program with a setup, telling `observer` each move and how far
/// it has read; with [`RunOptions::checkpoint_every`], also its
/// [`Checkpoints`] (otherwise empty).
pub fn run_observed(
    text: &str,
    setup: &Setup,
    options: RunOptions,
    observer: &mut impl Observer,
) -> (Run, Checkpoints) {
    if let Some(joined) = library::Joined::new(text, setup) {
        return joined.run_observed(options, observer);
    }
    run_text(text, setup, options, observer)
}

/// [`run_observed`] of one text (a run with a library reads the text it
/// makes of it with its own setup, `library.rs`).
fn run_text(
    text: &str,
    setup: &Setup,
    options: RunOptions,
    observer: &mut impl Observer,
) -> (Run, Checkpoints) {
    if let Some(refused) = refused(text, setup) {
        return (refused, Checkpoints::default());
    }
    let mut making = Making::new(setup);
    let mut r = Runner::new(text, setup, options);
    making.drive(&mut r, setup.machine, observer, &mut ());
    making.finish(r, text, true)
}

/// The run of a setup that does not validate or a program too large to
/// read: nothing runs, the diagnostics say why. None for a run that goes.
fn refused(text: &str, setup: &Setup) -> Option<Run> {
    let mut problems = setup.validate();
    problems.extend(crate::syntax::check_size(text));
    if problems.is_empty() {
        return None;
    }
    let mut result = fresh(setup);
    result.diagnostics = problems;
    result.end = End::Error { line: 0 };
    Some(result)
}

/// Asked before each block whether the run ends there, its end taken from
/// elsewhere: a run made again after an edit (`again.rs`) ends where it
/// has caught up with the earlier run. The plain run's `()` never ends it,
/// so its loop carries no such check.
trait Lookout {
    /// True when the run ends before the block `r` is about to read (the
    /// lookout has then made its end in `making`).
    fn ends_here(&mut self, r: &mut Runner<'_>, making: &mut Making) -> bool;
}

impl Lookout for () {
    #[inline(always)]
    fn ends_here(&mut self, _: &mut Runner<'_>, _: &mut Making) -> bool {
        false
    }
}

/// A run in the making: the report so far, its checkpoints, the totals and
/// the diagnostics of the run itself (which follow the parser's).
struct Making {
    run: Run,
    checkpoints: Checkpoints,
    totals: Totals,
    run_diagnostics: Vec<Diagnostic>,
}

impl Making {
    fn new(setup: &Setup) -> Making {
        Making {
            run: fresh(setup),
            checkpoints: Checkpoints::default(),
            totals: Totals::default(),
            run_diagnostics: Vec::new(),
        }
    }

    /// The block loop: runs the blocks `r` reads until the program's end
    /// or until `lookout` ends the run, keeping a checkpoint before every
    /// [`RunOptions::checkpoint_every`] blocks.
    #[inline(always)]
    fn drive(
        &mut self,
        r: &mut Runner<'_>,
        kind: MachineKind,
        observer: &mut impl Observer,
        lookout: &mut impl Lookout,
    ) {
        let every = r.options.checkpoint_every;
        let mut next_progress = PROGRESS_EVERY;
        loop {
            if !r.stopped
                && every > 0
                && self
                    .checkpoints
                    .points
                    .last()
                    .is_none_or(|c| r.index >= c.index.saturating_add(every))
            {
                self.totals.close(&mut self.checkpoints.points);
                self.checkpoints.points.push(r.checkpoint());
            }
            if lookout.ends_here(r, self) {
                break;
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
                Step::Skipped(d) => {
                    self.totals.segment.skipped += 1;
                    r.report_skipped(d);
                    continue;
                }
                Step::Stopped(d) => {
                    stop(
                        &mut self.run,
                        &mut self.run_diagnostics,
                        r.block.span.line,
                        d,
                    );
                    continue;
                }
                Step::Ran(flow) => flow,
            };
            // Warnings share the diagnostics cap with the parser's (a warning
            // per block could otherwise fill memory and the page's list).
            let ran = (index, first_move, flow);
            r.account(
                &mut self.run,
                &mut self.totals,
                observer,
                kind,
                ran,
                |parser, w| parser.report(w),
            );
            if every > 0 {
                self.checkpoints.calls |= flow == Flow::Jump;
                self.checkpoints.lines.push(r.block.span.line);
                if let Some(upto) = r.out.reads {
                    self.checkpoints.reads.push(Read {
                        index,
                        start: r.block.span.start,
                        upto,
                    });
                }
            }
        }
    }

    /// The run and its checkpoints where `r` stopped; `counted`: the
    /// counts are `r`'s (a run that took its end from the earlier run has
    /// them from there).
    fn finish(mut self, r: Runner<'_>, text: &str, counted: bool) -> (Run, Checkpoints) {
        if counted {
            counts(&mut self.run, &r);
        }
        let calls = r.calls;
        let mut diagnostics = r.parser.into_diagnostics();
        diagnostics.append(&mut self.run_diagnostics);
        if let Some(calls) = &calls {
            calls.withdraw_not_run(&mut diagnostics);
        }
        close(
            &mut self.run,
            &mut self.checkpoints.points,
            self.totals,
            diagnostics,
            text,
        );
        (self.run, self.checkpoints)
    }
}

/// The tool's machine position before the block being reported (6.12):
/// the last block's after it — a run that keeps reports keeps every one
/// from the first — or where the run starts. Out of line: the runs that
/// keep no reports (`check`) never come here.
#[inline(never)]
fn position_before(blocks: &[BlockReport], machine: &Machine) -> crate::geometry::Xyz {
    match blocks.last() {
        Some(b) => b.state.machine_position(),
        None => machine.setup().start_machine_position_mm(),
    }
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
        offset_memory: setup.settings.offset_memory(),
        gcode_system: setup.settings.gcode_system(),
        move_count: 0,
        bounds: None,
        travel: Default::default(),
        end: End::Completed,
        skipped: 0,
        cutter_reach: 0.0,
        library: Default::default(),
        positions: setup.positions_in_effect(),
    }
}

/// The run's counts where the runner stopped.
fn counts(result: &mut Run, r: &Runner<'_>) {
    result.block_count = r.index;
    result.move_count = r.move_count;
    result.end_units = r.machine.state().modal.units;
}

/// The run's totals and its diagnostics, in order, with their columns.
fn close(
    result: &mut Run,
    checkpoints: &mut [Checkpoint],
    mut totals: Totals,
    mut diagnostics: Vec<Diagnostic>,
    text: &str,
) {
    totals.close(checkpoints);
    let all = totals.before;
    result.bounds = all.bounds;
    result.travel = all.travel;
    result.skipped = all.skipped;
    result.cutter_reach = all.cutter_reach;
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
    (block, out, machine, place): (&Block, &mut Out, &Machine, &mut Option<Box<Place>>),
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
    if !out.moves.is_empty() {
        let state = machine.state();
        segment
            .travel
            .block(&out.moves, state, machine.setup().rapid_rate_mm());
        // The circle the page draws round the tool (behaviour 10.17).
        if state.cutter.engaged() {
            let radius = state.cutter.radius.abs();
            if radius > segment.cutter_reach {
                segment.cutter_reach = radius;
            }
        }
    }
    if options.keep_moves {
        result.moves.extend_from_slice(&out.moves);
    }
    // Most blocks have no event and no warning: the tests skip setting
    // up the two drains (the `check` instruction count in
    // docs/performance.md guards it).
    let mut data = Vec::new();
    let mut variables = Vec::new();
    if !out.events.is_empty() {
        // A G10's values: the registers it set are the run's too, and its
        // block's report carries them (behaviour 6.9, 17.8).
        for e in &out.events {
            if let EventKind::Dwell { seconds } = e {
                segment.travel.dwell(*seconds);
            }
            if let EventKind::DataSet(set) = e {
                if let ("offsets" | "lathe_offsets", Ok(n)) = (set.table, set.key.parse::<u16>())
                    && !segment.registers.contains(&n)
                {
                    segment.registers.push(n);
                }
                if options.keep_blocks {
                    data.push(set.clone());
                }
            }
            if let EventKind::VariableSet(set) = e
                && options.keep_blocks
            {
                variables.push(*set);
            }
        }
        let events = out.events.drain(..).map(|kind| Event {
            block: index,
            line: block.span.line,
            kind,
        });
        if observer.takes_reports() {
            events.for_each(|e| observer.on_event(&e));
        } else if options.keep_blocks {
            result.events.extend(events);
        } else {
            // A run without reports (`check`, the page) keeps what the
            // summary and the drawing read of its events — G10's settings,
            // tool changes, M codes — but not each macro assignment: a
            // block's report made again from a checkpoint has its own
            // (8.15), and a macro loop would otherwise keep one per pass.
            result
                .events
                .extend(events.filter(|e| !matches!(e.kind, EventKind::VariableSet(_))));
        }
    }
    if !out.warnings.is_empty() {
        for w in out.warnings.drain(..) {
            report(w);
        }
    }
    if options.keep_blocks {
        let before = position_before(&result.blocks, machine);
        let report = BlockReport {
            index,
            span: block.span,
            state: *machine.state(),
            before,
            notes: std::mem::take(&mut out.notes),
            first_move: first_move as u32,
            move_count: out.moves.len() as u32,
            data,
            variables,
            watch: machine.watched(),
            place: place.take(),
        };
        // An observer that takes the reports gets each; the run keeps only
        // the last (the next block's position before, 6.12).
        if observer.takes_reports() {
            observer.on_block(&report);
            result.blocks.clear();
        }
        result.blocks.push(report);
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
