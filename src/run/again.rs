//! Runs made again after an edit ([`super::rerun_observed`]): where a run
//! of the edited text can start from the earlier run (its last checkpoint
//! before the edit), where it has caught up with it (a checkpoint after the
//! edit where the parser and the machine stand as they stood then), and
//! how the earlier run's end is taken from there, shifted by what the edit
//! added or removed.

use super::{Checkpoint, Observer, RunOptions, Runner, Segment, Totals};
use crate::diag::{Diagnostic, Span};
use crate::report::{End, Event, Run};
use crate::setup::Setup;
use crate::syntax::{MAX_DIAGNOSTICS, shift};

/// A run of a text that has since been edited into the one to run now,
/// made with the same setup and options.
#[derive(Clone, Copy, Debug)]
pub struct Earlier<'a> {
    /// The text as it was.
    pub text: &'a str,
    /// Its run.
    pub run: &'a Run,
}

/// What a run made again ([`super::rerun_observed`]) took from the earlier run.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Reuse {
    /// The earlier run's first `prefix_moves` moves are this run's first
    /// moves (the observer was told only of the moves after them).
    pub prefix_moves: usize,
    /// Past the edit the run caught up with the earlier one and took the
    /// rest of it: the observer was not told of those moves either.
    pub tail: Option<Tail>,
}

/// The earlier run's end, taken as this run's end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tail {
    /// The earlier run's moves from this one on are this run's last moves…
    pub from_move: usize,
    /// …of blocks this many indices further on…
    pub blocks: i64,
    /// …and this many lines further down.
    pub lines: i64,
}

/// How far a point after an edit moved from the earlier run to this one.
#[derive(Clone, Copy, Debug)]
pub(super) struct Shift {
    blocks: i64,
    moves: i64,
    bytes: i64,
    lines: i64,
}

/// How a run made again uses the earlier run: where it resumes, and where
/// the two texts are the same again.
pub(super) struct Plan<'a> {
    earlier: Earlier<'a>,
    /// The earlier run's checkpoint this run resumes at.
    resume: usize,
    /// From this byte on the new text is the earlier text from
    /// `same_from - bytes` on.
    same_from: usize,
    /// Length of the new text minus that of the earlier one.
    bytes: i64,
    /// The earlier run's end may be taken: it stopped at no limit and kept
    /// every diagnostic (a limit or the cap falls elsewhere when the edit
    /// adds or removes blocks, moves or diagnostics).
    tail_ok: bool,
}

impl<'a> Plan<'a> {
    pub(super) fn new(
        earlier: Earlier<'a>,
        text: &str,
        setup: &Setup,
        options: RunOptions,
    ) -> Option<Plan<'a>> {
        let old = earlier.run;
        if options.keep_blocks || options.keep_moves || options.checkpoint_every == 0 {
            return None;
        }
        if old.checkpoints.first()?.machine.setup() != setup {
            return None;
        }
        let (a, b) = (earlier.text.as_bytes(), text.as_bytes());
        let (prefix, suffix) = common_ends(a, b);
        // The last checkpoint before the edit: the parser there had read
        // the text before it and looked one character further at most (the
        // LF after a CR). The first one, at the start, always qualifies.
        let resume = old
            .checkpoints
            .partition_point(|c| c.parser.offset() == 0 || c.parser.offset() < prefix)
            .checked_sub(1)?;
        let limited = |d: &Diagnostic| {
            matches!(
                d.code,
                "too-many-diagnostics" | "too-many-moves" | "too-many-blocks"
            )
        };
        Some(Plan {
            earlier,
            resume,
            same_from: b.len() - suffix,
            bytes: b.len() as i64 - a.len() as i64,
            tail_ok: !old.diagnostics.iter().any(limited),
        })
    }

    /// Starts the run at the earlier run's checkpoint before the edit:
    /// the part before it is the earlier run's, as it was made.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn resume<'t>(
        &self,
        text: &'t str,
        setup: &Setup,
        options: RunOptions,
        result: &mut Run,
        totals: &mut Totals,
        reuse: &mut Reuse,
        observer: &mut impl Observer,
    ) -> Runner<'t> {
        let old = self.earlier.run;
        let c = &old.checkpoints[self.resume];
        let before = c.parser.offset();
        result.checkpoints = old.checkpoints[..=self.resume].to_vec();
        for k in &result.checkpoints[..self.resume] {
            totals.before.add(&k.segment);
        }
        result.checkpoints[self.resume].segment = Segment::default();
        result.events = old.events[..old.events.partition_point(|e| e.block < c.index)].to_vec();
        result.lines = old.lines[..c.index as usize].to_vec();
        let diagnostics = old
            .diagnostics
            .iter()
            .filter(|d| (d.span.start as usize) < before)
            .cloned()
            .collect();
        reuse.prefix_moves = c.move_count;
        observer.on_resume(c.move_count);
        Runner::resume_after(text, setup, options, c, diagnostics)
    }

    /// The earlier checkpoint the runner stands at, if the two runs go on
    /// alike from there: the same text ahead, the same parser and machine
    /// state, room under the limits and the cap for the earlier run's end.
    pub(super) fn caught_up(&self, r: &Runner<'_>, options: &RunOptions) -> Option<(usize, Shift)> {
        let pos = r.parser.offset();
        if !self.tail_ok || r.stopped || pos < self.same_from || r.parser.dropped() > 0 {
            return None;
        }
        let old = self.earlier.run;
        let at = shift(pos as i64, -self.bytes) as usize;
        let k = old
            .checkpoints
            .binary_search_by_key(&at, |c| c.parser.offset())
            .ok()?;
        let c = &old.checkpoints[k];
        let here = r.parser.resume_point();
        if !here.same_course(&c.parser) || !r.machine.same_course(&c.machine) {
            return None;
        }
        let d = Shift {
            blocks: i64::from(r.index) - i64::from(c.index),
            moves: r.move_count as i64 - c.move_count as i64,
            bytes: self.bytes,
            lines: i64::from(here.line()) - i64::from(c.parser.line()),
        };
        let blocks = i64::from(old.block_count) + d.blocks;
        let moves = old.move_count as i64 + d.moves;
        let tail_diagnostics = old
            .diagnostics
            .iter()
            .filter(|x| x.span.start as usize >= at)
            .count();
        let room = r.parser.diagnostics().len() + tail_diagnostics <= MAX_DIAGNOSTICS;
        (blocks <= options.max_blocks as i64 && moves <= options.max_moves as i64 && room)
            .then_some((k, d))
    }
}

/// Lengths of the common start and end of `a` and `b`, which do not
/// overlap in either: what an edit of `a` into `b` left as it was.
pub(crate) fn common_ends(a: &[u8], b: &[u8]) -> (usize, usize) {
    let prefix = common_prefix(a, b);
    (prefix, common_suffix(a, b, a.len().min(b.len()) - prefix))
}

/// Length of the common start of `a` and `b`.
fn common_prefix(a: &[u8], b: &[u8]) -> usize {
    // A page at a time (`==` on slices is a `memcmp`), then byte by byte:
    // a 30 MB text in a few milliseconds.
    const STEP: usize = 4096;
    let mut n = 0;
    while n + STEP <= a.len().min(b.len()) && a[n..n + STEP] == b[n..n + STEP] {
        n += STEP;
    }
    n + a[n..]
        .iter()
        .zip(&b[n..])
        .take_while(|(x, y)| x == y)
        .count()
}

/// Length of the common end of `a` and `b`, at most `max`.
fn common_suffix(a: &[u8], b: &[u8], max: usize) -> usize {
    const STEP: usize = 4096;
    let mut n = 0;
    while n + STEP <= max
        && a[a.len() - n - STEP..a.len() - n] == b[b.len() - n - STEP..b.len() - n]
    {
        n += STEP;
    }
    let (a, b) = (&a[..a.len() - n], &b[..b.len() - n]);
    n + a
        .iter()
        .rev()
        .zip(b.iter().rev())
        .take(max - n)
        .take_while(|(x, y)| x == y)
        .count()
}

/// Ends a run made again with the earlier run's end from its checkpoint
/// `k`, where the runner caught up with it, shifted by `d`.
pub(super) fn take_tail(
    result: &mut Run,
    r: &mut Runner<'_>,
    totals: &mut Totals,
    plan: &Plan<'_>,
    k: usize,
    d: &Shift,
) -> Tail {
    let old = plan.earlier.run;
    let c = &old.checkpoints[k];
    let at = c.parser.offset();
    let line = |l: u32| shift(i64::from(l), d.lines) as u32;
    // The earlier checkpoint stands where the runner stands. A checkpoint
    // the runner has just made there (nothing ran since) gives way to it;
    // otherwise the runner's last segment ends here.
    if result
        .checkpoints
        .last()
        .is_some_and(|l| l.index == r.index)
    {
        result.checkpoints.pop();
    } else {
        totals.close(&mut result.checkpoints);
    }
    let first = result.checkpoints.len();
    result
        .checkpoints
        .extend(old.checkpoints[k..].iter().map(|c| c.shifted(d)));
    let (last, taken) = result.checkpoints[first..]
        .split_last()
        .expect("the earlier run has the checkpoint k");
    for c in taken {
        totals.before.add(&c.segment);
    }
    // The last segment is complete, and closed again with the run.
    totals.segment = last.segment.clone();
    let first_event = old.events.partition_point(|e| e.block < c.index);
    result
        .events
        .extend(old.events[first_event..].iter().map(|e| Event {
            block: shift(i64::from(e.block), d.blocks) as u32,
            line: line(e.line),
            kind: e.kind.clone(),
        }));
    result
        .lines
        .extend(old.lines[c.index as usize..].iter().map(|&l| line(l)));
    r.parser.report_all(
        old.diagnostics
            .iter()
            .filter(|x| x.span.start as usize >= at)
            .map(|x| {
                let mut x = x.clone();
                x.span = Span {
                    start: shift(i64::from(x.span.start), d.bytes) as u32,
                    end: shift(i64::from(x.span.end), d.bytes) as u32,
                    line: line(x.span.line),
                };
                x.line = x.span.line;
                x
            }),
    );
    result.block_count = shift(i64::from(old.block_count), d.blocks) as u32;
    result.move_count = shift(old.move_count as i64, d.moves) as usize;
    result.end = match old.end {
        End::Completed => End::Completed,
        End::ProgramEnd { line: l } => End::ProgramEnd { line: line(l) },
        End::Error { line: l } => End::Error { line: line(l) },
    };
    result.end_units = old.end_units;
    Tail {
        from_move: c.move_count,
        blocks: d.blocks,
        lines: d.lines,
    }
}

impl Checkpoint {
    /// The same point in a text edited before it: `blocks`, `moves`,
    /// `bytes` and `lines` further on.
    fn shifted(&self, d: &Shift) -> Checkpoint {
        Checkpoint {
            index: shift(i64::from(self.index), d.blocks) as u32,
            move_count: shift(self.move_count as i64, d.moves) as usize,
            parser: self.parser.shifted(d.bytes, d.lines),
            // The machine's own note of its place is set by the next block.
            machine: self.machine.clone(),
            segment: self.segment.clone(),
        }
    }
}
