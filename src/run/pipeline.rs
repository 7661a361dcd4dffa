//! A large program's run on two threads, for the CLI: one thread reads the
//! blocks, the other runs them, so that the parser (about half of a run,
//! `docs/performance.md`) and the machine work at the same time. The
//! parser never depends on the machine (it reads the whole program whether
//! or not the run stops, for its diagnostics), so the blocks can be read
//! ahead; what the machine adds to the parser's diagnostics (its warnings,
//! which share their cap) is put back in the order one thread reports it.
//! The result is the one-thread run's, field for field (`tests/pipeline.rs`).

use std::sync::Arc;
use std::sync::mpsc::{channel, sync_channel};

use super::ahead::From;
use super::checkpoint::Totals;
use super::{RunOptions, Runner, Step, close, counts, fresh, stop};
use crate::diag::Diagnostic;
use crate::machine::{Flow, Machine};
use crate::report::Run;
use crate::setup::Setup;
use crate::syntax::{Block, Blocks, MAX_DIAGNOSTICS, ParseOptions, Resume, check_size};

/// Programs shorter than this run on one thread: a thread and its hand-overs
/// cost more than they save on a program that runs in a few milliseconds.
pub const PIPELINE_FROM_BYTES: usize = 1 << 20;

/// Blocks handed over at a time, and how many such batches are under way.
/// A hand-over can wake the other thread (a futex call), so batches are
/// large, but not larger than the caches: the size that gave the fastest
/// 1M-block `check` (target 6 in docs/performance.md, `scripts/best-of.sh`).
const BATCH: usize = 2048;
const BATCHES: usize = 4;

/// How many blocks ahead of the running one the machine's thread asks for
/// a block's words: they were written on the other core, and a block's first
/// read of them (the look-ahead of the block before it, in offset mode)
/// otherwise waits for them to come over.
const PREFETCH_AHEAD: usize = 4;

/// Asks the processor for the cache lines of `block`'s words (the first
/// and the last: most blocks' words fit in two), without waiting for them.
#[inline(always)]
fn prefetch_words(block: &Block) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
        let words = block.words.as_slice();
        let start = words.as_ptr().cast::<i8>();
        let last = std::mem::size_of_val(words).saturating_sub(1);
        // SAFETY: a prefetch reads nothing and cannot fault; both
        // pointers are inside the block's word buffer (or at its start).
        #[allow(unsafe_code)]
        unsafe {
            _mm_prefetch::<_MM_HINT_T0>(start);
            _mm_prefetch::<_MM_HINT_T0>(start.wrapping_add(last));
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = block;
}

/// Blocks read by the parser's thread for the machine's.
struct Batch {
    /// The blocks (reused from batch to batch: their words keep their room).
    blocks: Vec<Block>,
    /// How many of `blocks` were read.
    len: usize,
    /// Per block read, how many diagnostics the parser had reported by its
    /// end: the machine's warnings about the block come after these.
    reported: Vec<u32>,
    /// The parser's place after the last block read, for look-ahead past
    /// the batch (`run/ahead.rs`); None when the text ends in the batch.
    then: Option<Resume>,
}

/// The run [`super::run_with`] makes, on two threads when `text` is at
/// least [`PIPELINE_FROM_BYTES`] long, the machine has two cores and the run
/// keeps no checkpoints; otherwise, or when the diagnostics would reach
/// their cap (where the order of the two threads' reports decides which are
/// kept), on one.
pub fn run_pipelined(text: &str, setup: &Setup, options: RunOptions) -> Run {
    let two = std::thread::available_parallelism().is_ok_and(|n| n.get() >= 2);
    if two
        && text.len() >= PIPELINE_FROM_BYTES
        && let Some(run) = on_two_threads(text, setup, options)
    {
        return run;
    }
    super::run_with(text, setup, options)
}

/// The run on two threads whatever the program's size, or None where
/// [`run_pipelined`] runs on one thread. For the tests, which compare it
/// with the one-thread run on programs of every size.
#[doc(hidden)]
pub fn run_on_two_threads(text: &str, setup: &Setup, options: RunOptions) -> Option<Run> {
    on_two_threads(text, setup, options)
}

/// The run on two threads, or None when it cannot be told apart from the
/// one-thread run only by running that (a refused setup or program is left
/// to it too, and a run keeping checkpoints: the parser's place at each is
/// on the other thread).
fn on_two_threads(text: &str, setup: &Setup, options: RunOptions) -> Option<Run> {
    // A run that continues past errors (behaviour 2.24) puts the machine
    // back before a block that failed: one thread does.
    if options.checkpoint_every != 0
        || setup.settings.continue_past_errors
        || !setup.programs.is_empty()
        || !setup.validate().is_empty()
        || check_size(text).is_some()
    {
        return None;
    }
    std::thread::scope(|scope| {
        let (full, filled) = sync_channel::<Batch>(BATCHES);
        let (give_back, emptied) = channel::<Batch>();
        for _ in 0..BATCHES {
            let batch = Batch {
                blocks: Vec::new(),
                len: 0,
                reported: Vec::with_capacity(BATCH),
                then: None,
            };
            give_back.send(batch).ok()?;
        }
        // The main thread's stack (8 MiB), not a spawned thread's 2 MiB:
        // the parser must read on this thread whatever it reads on one.
        let reader = std::thread::Builder::new().stack_size(8 << 20);
        let reader = reader.spawn_scoped(scope, move || {
            let mut parser = Blocks::new(text, ParseOptions::from(setup));
            // Ends at the program's end, or when the machine's thread has
            // gone (it panicked).
            while let Ok(mut batch) = emptied.recv() {
                batch.len = 0;
                batch.reported.clear();
                while batch.len < BATCH {
                    if batch.blocks.len() == batch.len {
                        batch.blocks.push(Block::default());
                    }
                    if !parser.next_into(&mut batch.blocks[batch.len]) {
                        break;
                    }
                    batch.len += 1;
                    batch.reported.push(parser.diagnostics().len() as u32);
                }
                let last = batch.len < BATCH;
                batch.then = (!last).then(|| parser.resume_point());
                if full.send(batch).is_err() || last {
                    break;
                }
            }
            parser
        });
        // No thread to be had: one thread runs it.
        let Ok(reader) = reader else {
            return None;
        };

        let mut result = fresh(setup);
        let mut totals = Totals::default();
        let machine = Machine::new(Arc::new(setup.clone()));
        let mut r = Runner::at(
            text,
            Blocks::new("", ParseOptions::from(setup)),
            machine,
            setup,
            options,
        );
        let mut run_diagnostics: Vec<Diagnostic> = Vec::new();
        let mut warnings: Vec<(u32, Diagnostic)> = Vec::new();
        let options_parse = ParseOptions::from(setup);
        for batch in filled.iter() {
            let then = batch.then.map(|at| (text, options_parse, at));
            for i in 0..batch.len {
                if let Some(later) = batch.blocks[..batch.len].get(i + PREFETCH_AHEAD) {
                    prefetch_words(later);
                }
                let reported = batch.reported[i];
                // The block runs where the parser's thread read it (lent,
                // not moved into the runner: a block is a few hundred bytes
                // and the 1M-block `check`, target 6 in
                // docs/performance.md, runs a million of them); the rest of
                // the batch is what follows it.
                let (head, rest) = batch.blocks[..batch.len].split_at(i + 1);
                let block = &head[i];
                let (index, first_move) = (r.index, r.move_count);
                let from = From::Read { blocks: rest, then };
                let mut ahead = r.ahead.at(index, from);
                let step = super::execute(
                    block,
                    &mut r.machine,
                    &mut r.out,
                    &r.options,
                    (&mut r.index, &mut r.move_count, &mut r.stopped),
                    r.block_skip,
                    (&mut ahead, &mut r.sequences),
                );
                match step {
                    // A subprogram call or return: the blocks read ahead
                    // are not the ones that run next; one thread runs it
                    // (behaviour 19).
                    Some(Step::Ran(Flow::Jump)) => return None,
                    // A macro statement's jump or loop (behaviour 20.11).
                    Some(Step::Ran(_)) if r.machine.jump.is_some() => return None,
                    Some(Step::Ran(flow)) => {
                        let ran = (index, first_move, flow);
                        super::account(
                            &mut result,
                            &mut totals,
                            &mut (),
                            &r.options,
                            setup.machine,
                            (block, &mut r.out, &r.machine, &mut None),
                            ran,
                            |w| warnings.push((reported, w)),
                        );
                    }
                    Some(Step::Stopped(d)) => {
                        stop(&mut result, &mut run_diagnostics, block.span.line, d);
                    }
                    // No skips here: such a run is made on one thread.
                    Some(Step::Passed | Step::Skipped(_)) | None => {}
                }
            }
            // Gone only once the parser is done.
            let _ = give_back.send(batch);
        }
        let parser = match reader.join() {
            Ok(parser) => parser,
            Err(panic) => std::panic::resume_unwind(panic),
        };
        let kept = parser.diagnostics().len() + warnings.len();
        if parser.dropped() > 0 || kept > MAX_DIAGNOSTICS {
            return None;
        }
        // One thread reports a block's warnings right after what the
        // parser reported up to the block's end.
        let mut diagnostics = Vec::with_capacity(kept + run_diagnostics.len());
        let mut warnings = warnings.into_iter().peekable();
        for (i, d) in parser.into_diagnostics().into_iter().enumerate() {
            while let Some((_, w)) = warnings.next_if(|(before, _)| *before as usize <= i) {
                diagnostics.push(w);
            }
            diagnostics.push(d);
        }
        diagnostics.extend(warnings.map(|(_, w)| w));
        diagnostics.append(&mut run_diagnostics);
        counts(&mut result, &r);
        close(&mut result, &mut [], totals, diagnostics, text);
        Some(result)
    })
}
