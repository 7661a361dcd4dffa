//! What a run keeps to be taken up again without keeping a report per
//! block: a [`Checkpoint`] before every so many blocks and each block's
//! line, held in [`Checkpoints`] beside the run's [`Run`](crate::Run) (the
//! report never holds the run's own machinery). From them
//! [`super::report_at`] makes any block's report again, the page finds the
//! block of a line, and a run after an edit resumes before it (`again.rs`).
//! Also the totals the run keeps per stretch between two checkpoints, so
//! that a run made again can add those before and after the edit.

use super::{RunOptions, Runner, Step};
use crate::machine::{EventKind, Machine};
use crate::report::BlockReport;
use crate::report::Bounds;
use crate::setup::Setup;
use crate::setup::Units;
use crate::syntax::Resume;

/// What a run made with [`crate::RunOptions::checkpoint_every`] keeps
/// beside its [`Run`](crate::Run): empty without.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Checkpoints {
    /// Where [`crate::run::report_at`] can resume, in block order.
    pub points: Vec<Checkpoint>,
    /// Per executed block, its 1-based line.
    pub lines: Vec<u32>,
    /// The blocks whose result depends on text other than their own (a
    /// G70–G73 reads its contour by sequence number, behaviour 15.3), in
    /// block order: a run made again after an edit of that text runs them
    /// again (`again.rs`).
    pub reads: Vec<Read>,
    /// The run called a subprogram or returned with M99 (behaviour 19):
    /// its checkpoints stand in several programs, so a run made again
    /// after an edit runs whole (`again.rs`).
    pub calls: bool,
}

/// A block that read the program's text up to a place (behaviour 15.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Read {
    /// The block's index among the executed blocks.
    pub index: u32,
    /// Byte offset of the block's start.
    pub start: u32,
    /// Its result depends on the text before this byte offset (the search
    /// for a sequence number reads from the program's start).
    pub upto: u32,
}

impl Checkpoints {
    /// Executed blocks (each has a line).
    pub fn block_count(&self) -> usize {
        self.lines.len()
    }

    /// The last executed block at or before 1-based `line` (the block a
    /// cursor on that line belongs to, or the one before a comment line),
    /// or None when no block runs before it.
    pub fn block_at_line(&self, line: u32) -> Option<u32> {
        let n = self.lines.partition_point(|&l| l <= line);
        n.checked_sub(1).and_then(|n| u32::try_from(n).ok())
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
    pub(super) parser: Resume,
    /// The furthest byte of the text the machine's state here follows from:
    /// the parser's place, or further when a block before read ahead
    /// (`run/ahead.rs`). A run made again resumes only where this is before
    /// the edit.
    pub(super) horizon: usize,
    pub(super) machine: Machine,
    /// What the blocks from here to the next checkpoint add to the run's
    /// totals, so that a run made again after an edit
    /// ([`crate::rerun_observed`]) can take the totals of the parts before
    /// and after the edit.
    pub(super) segment: Segment,
    /// The open subprogram calls here (behaviour 19.9): a report made
    /// again inside a subprogram reads on where the run read, and returns
    /// where it returned. None before the run's first call.
    pub(super) calls: Option<Box<super::calls::Saved>>,
    /// The macro loops running here (behaviour 20.15).
    pub(super) loops: Option<Box<super::flow::Saved>>,
}

/// Checkpoints of the same program are equal when they stand at the same
/// place (the machine state there follows from the program).
impl PartialEq for Checkpoint {
    fn eq(&self, other: &Self) -> bool {
        (
            self.index,
            self.move_count,
            self.parser.offset(),
            self.horizon,
        ) == (
            other.index,
            other.move_count,
            other.parser.offset(),
            other.horizon,
        )
    }
}

/// The totals of the blocks between two checkpoints.
#[derive(Clone, Debug, Default)]
pub(super) struct Segment {
    /// Bounds of their moves.
    pub(super) bounds: Option<Bounds>,
    /// Offset registers they name, ascending.
    pub(super) registers: Vec<u16>,
    /// Units of their first move.
    pub(super) first_units: Option<Units>,
    /// Their path length and time.
    pub(super) travel: crate::travel::Travel,
    /// The blocks among them skipped past their errors (behaviour 2.24).
    pub(super) skipped: u32,
    /// The largest |radius| of cutter or nose radius compensation among
    /// their blocks that moved with it engaged (mm; behaviour 10.5).
    pub(super) cutter_reach: f64,
}

impl Segment {
    pub(super) fn add(&mut self, other: &Segment) {
        if let Some(b) = other.bounds {
            merge(&mut self.bounds, b);
        }
        self.registers.extend_from_slice(&other.registers);
        self.registers.sort_unstable();
        self.registers.dedup();
        self.first_units = self.first_units.or(other.first_units);
        self.travel.add(&other.travel);
        self.skipped = self.skipped.saturating_add(other.skipped);
        if other.cutter_reach > self.cutter_reach {
            self.cutter_reach = other.cutter_reach;
        }
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

/// The totals a run keeps as it goes.
#[derive(Default)]
pub(super) struct Totals {
    /// Since the last checkpoint (all of them without checkpoints).
    pub(super) segment: Segment,
    /// Before the last checkpoint.
    pub(super) before: Segment,
}

impl Totals {
    /// Closes the segment of the last checkpoint (if any) at a new one.
    pub(super) fn close(&mut self, checkpoints: &mut [Checkpoint]) {
        let mut segment = std::mem::take(&mut self.segment);
        segment.registers.sort_unstable();
        self.before.add(&segment);
        if let Some(last) = checkpoints.last_mut() {
            last.segment = segment;
        }
    }
}

/// The report of block `index` of a run of `text` and `setup` that kept
/// `checkpoints`, made again from the checkpoint before it; None when the
/// run has no such block or kept no checkpoints. It equals the report a run
/// keeping every block would have kept.
pub fn report_at(
    text: &str,
    setup: &Setup,
    checkpoints: &Checkpoints,
    index: u32,
) -> Option<BlockReport> {
    if let Some(joined) = super::library::Joined::new(text, setup) {
        return joined.report_at(checkpoints, index);
    }
    if index as usize >= checkpoints.block_count() {
        return None;
    }
    let at = checkpoints.points.iter().rev().find(|c| c.index <= index)?;
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
        let before = r.machine.state().machine_position();
        match r.step()? {
            Step::Ran(flow) if this == index => {
                let place = match r.calls.is_some() {
                    true => r.place_of(flow),
                    false => None,
                };
                return Some(BlockReport {
                    index,
                    span: r.block.span,
                    state: *r.machine.state(),
                    before,
                    notes: std::mem::take(&mut r.out.notes),
                    first_move: first_move as u32,
                    move_count: r.out.moves.len() as u32,
                    data: r
                        .out
                        .events
                        .iter()
                        .filter_map(|e| match e {
                            EventKind::DataSet(set) => Some(set.clone()),
                            _ => None,
                        })
                        .collect(),
                    variables: r
                        .out
                        .events
                        .iter()
                        .filter_map(|e| match e {
                            EventKind::VariableSet(set) => Some(*set),
                            _ => None,
                        })
                        .collect(),
                    watch: r.machine.watched(),
                    place,
                });
            }
            Step::Ran(_) | Step::Passed | Step::Skipped(_) => {}
            Step::Stopped(_) => return None,
        }
    }
}
