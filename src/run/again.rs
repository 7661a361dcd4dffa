//! Runs made again after an edit ([`rerun_observed`]), a wrapper around the
//! plain run's loop: where a run of the edited text can start from the
//! earlier run (its last checkpoint before the edit), where it has caught
//! up with it (a checkpoint after the edit where the parser and the
//! machine stand as they stood then), and how the earlier run's end is
//! taken from there, shifted by what the edit added or removed.

use super::checkpoint::{Checkpoint, Checkpoints, Segment};
use super::{Lookout, Making, Observer, RunOptions, Runner};
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
    /// The checkpoints its run kept.
    pub checkpoints: &'a Checkpoints,
}

/// Runs `text` as [`super::run_observed`] does, from the earlier run of a
/// text it was edited from where it can: it resumes at the earlier run's
/// last checkpoint before the edit and, once past the edit, stops at the
/// first checkpoint of the earlier run where the parser and the machine
/// stand as they stood then, and takes the earlier run's end from there.
/// The run is the same as a whole run of `text` would be, but for where its
/// checkpoints are. Only runs that keep checkpoints and neither block
/// reports nor moves (the page's) are made again (others, and those
/// without `earlier`, are whole runs); `observer` is told of the moves
/// actually made, and [`Reuse`] says which moves of the earlier run come
/// before and after them.
pub fn rerun_observed(
    text: &str,
    setup: &Setup,
    options: RunOptions,
    earlier: Option<Earlier<'_>>,
    observer: &mut impl Observer,
) -> (Run, Checkpoints, Reuse) {
    // A run with a library is made whole (its blocks are not read in the
    // text's order, as a run with calls, behaviour 19.9).
    let plan = match earlier {
        Some(earlier) if setup.programs.is_empty() && super::refused(text, setup).is_none() => {
            Plan::new(earlier, text, setup, options)
        }
        _ => None,
    };
    let Some(plan) = plan else {
        let (run, checkpoints) = super::run_observed(text, setup, options, observer);
        return (run, checkpoints, Reuse::default());
    };
    let mut making = Making::new(setup);
    let mut reuse = Reuse::default();
    let mut r = plan.resume(text, setup, options, &mut making, &mut reuse, observer);
    let mut catch_up = CatchUp {
        plan: &plan,
        last_pos: usize::MAX,
        tail: None,
    };
    making.drive(&mut r, setup.machine, observer, &mut catch_up);
    reuse.tail = catch_up.tail;
    let (run, checkpoints) = making.finish(r, text, reuse.tail.is_none());
    (run, checkpoints, reuse)
}

/// Watches a run made again for the place where it has caught up with the
/// earlier run, and ends it there with the earlier run's end.
struct CatchUp<'p, 'a> {
    plan: &'p Plan<'a>,
    /// The parser's place when last asked (a block read but not run
    /// leaves it where it was: asked once per place).
    last_pos: usize,
    /// The earlier run's end, once taken.
    tail: Option<Tail>,
}

impl Lookout for CatchUp<'_, '_> {
    fn ends_here(&mut self, r: &mut Runner<'_>, making: &mut Making) -> bool {
        if r.parser.offset() == self.last_pos {
            return false;
        }
        self.last_pos = r.parser.offset();
        let Some((k, d)) = self.plan.caught_up(r) else {
            return false;
        };
        self.tail = Some(take_tail(making, r, self.plan, k, &d));
        true
    }
}

/// What a run made again ([`rerun_observed`]) took from the earlier run.
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
struct Shift {
    blocks: i64,
    moves: i64,
    bytes: i64,
    lines: i64,
}

/// How a run made again uses the earlier run: where it resumes, and where
/// the two texts are the same again.
struct Plan<'a> {
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
    fn new(
        earlier: Earlier<'a>,
        text: &str,
        setup: &Setup,
        options: RunOptions,
    ) -> Option<Plan<'a>> {
        let old = earlier.run;
        let checkpoints = &earlier.checkpoints.points;
        if options.keep_blocks || options.keep_moves || options.checkpoint_every == 0 {
            return None;
        }
        // A run that called subprograms reads the text in another order
        // than it stands (behaviour 19.9): it is made whole.
        if earlier.checkpoints.calls {
            return None;
        }
        if checkpoints.first()?.machine.setup() != setup {
            return None;
        }
        let (a, b) = (earlier.text.as_bytes(), text.as_bytes());
        let (prefix, suffix) = common_ends(a, b);
        let bytes = b.len() as i64 - a.len() as i64;
        // A block that read the text by sequence number (a G70–G73 and its
        // contour, behaviour 15.3) up to a place past the edit's start may
        // come out otherwise: the run resumes before the first such block,
        // and catches up only after the last (each search reads the text
        // from its start, so the text it depends on is all before `upto`).
        let dependent = || {
            earlier
                .checkpoints
                .reads
                .iter()
                // An edit right at the end of the text read (`upto` is
                // exclusive) can still extend its last word ("X52." typed
                // on to "X52.3"): it counts.
                .filter(|r| r.upto as usize >= prefix)
                .map(|r| r.start as usize)
        };
        let before = dependent().min().map_or(prefix, |s| prefix.min(s + 1));
        let mut same_from = b.len() - suffix;
        if let Some(last) = dependent().max().filter(|&s| s >= a.len() - suffix) {
            same_from = same_from.max(shift(last as i64, bytes) as usize + 1);
        }
        // The last checkpoint before the edit: the parser there had read
        // the text before it and looked one character further at most (the
        // LF after a CR), and no block before it read ahead into the edit
        // (its horizon). The first one, at the start, always qualifies.
        let resume = checkpoints
            .partition_point(|c| c.parser.offset() == 0 || c.horizon < before)
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
            same_from,
            bytes,
            tail_ok: !old.diagnostics.iter().any(limited),
        })
    }

    /// Starts the run at the earlier run's checkpoint before the edit:
    /// the part before it is the earlier run's, as it was made.
    fn resume<'t>(
        &self,
        text: &'t str,
        setup: &Setup,
        options: RunOptions,
        making: &mut Making,
        reuse: &mut Reuse,
        observer: &mut impl Observer,
    ) -> Runner<'t> {
        let old = self.earlier.run;
        let earlier = self.earlier.checkpoints;
        let c = &earlier.points[self.resume];
        let before = c.parser.offset();
        let points = &mut making.checkpoints.points;
        *points = earlier.points[..=self.resume].to_vec();
        for k in &points[..self.resume] {
            making.totals.before.add(&k.segment);
        }
        points[self.resume].segment = Segment::default();
        making.run.events =
            old.events[..old.events.partition_point(|e| e.block < c.index)].to_vec();
        making.checkpoints.lines = earlier.lines[..c.index as usize].to_vec();
        making.checkpoints.reads =
            earlier.reads[..earlier.reads.partition_point(|r| r.index < c.index)].to_vec();
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
    fn caught_up(&self, r: &Runner<'_>) -> Option<(usize, Shift)> {
        let pos = r.parser.offset();
        if !self.tail_ok
            || r.stopped
            || r.calls.is_some()
            || r.loops.is_some()
            || pos < self.same_from
            || r.parser.dropped() > 0
        {
            return None;
        }
        let old = self.earlier.run;
        let options = &r.options;
        let at = shift(pos as i64, -self.bytes) as usize;
        let k = self
            .earlier
            .checkpoints
            .points
            .binary_search_by_key(&at, |c| c.parser.offset())
            .ok()?;
        let c = &self.earlier.checkpoints.points[k];
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
    // a million-block text is compared well within an edit's budget
    // (bench-browser target 4; `cargo bench --bench edit`).
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
fn take_tail(
    making: &mut Making,
    r: &mut Runner<'_>,
    plan: &Plan<'_>,
    k: usize,
    d: &Shift,
) -> Tail {
    let old = plan.earlier.run;
    let earlier = plan.earlier.checkpoints;
    let c = &earlier.points[k];
    let Making {
        run: result,
        checkpoints,
        totals,
        ..
    } = making;
    let at = c.parser.offset();
    let line = |l: u32| shift(i64::from(l), d.lines) as u32;
    // The earlier checkpoint stands where the runner stands. A checkpoint
    // the runner has just made there (nothing ran since) gives way to it;
    // otherwise the runner's last segment ends here.
    let points = &mut checkpoints.points;
    if points.last().is_some_and(|l| l.index == r.index) {
        points.pop();
    } else {
        totals.close(points);
    }
    let first = points.len();
    points.extend(earlier.points[k..].iter().map(|c| c.shifted(d)));
    let (last, taken) = points[first..]
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
    checkpoints
        .lines
        .extend(earlier.lines[c.index as usize..].iter().map(|&l| line(l)));
    // The blocks of the tail read no text the edit changed (`Plan::new`):
    // what they read stays where it was.
    let first_read = earlier.reads.partition_point(|r| r.index < c.index);
    checkpoints
        .reads
        .extend(earlier.reads[first_read..].iter().map(|r| super::Read {
            index: shift(i64::from(r.index), d.blocks) as u32,
            start: shift(i64::from(r.start), d.bytes) as u32,
            upto: r.upto,
        }));
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
            horizon: shift(self.horizon as i64, d.bytes) as usize,
            // The machine's own note of its place is set by the next block.
            machine: self.machine.clone(),
            segment: self.segment.clone(),
            calls: self.calls.clone(),
            loops: self.loops.clone(),
        }
    }
}
