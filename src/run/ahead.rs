//! Look-ahead: the blocks after the one running, for the rules that need
//! them (a chamfer or corner rounding at a block's end needs the next move's
//! direction; cutter radius compensation reads ahead as the control does).
//! The machine asks for them through [`Ahead`] only when a rule needs them,
//! so a block that needs none costs nothing.
//!
//! The blocks are read by a second parser forked at the running block's end
//! ([`Blocks::fork`]), never by the run's own: the run's parser, its
//! diagnostics and its checkpoints stay where the blocks run (behaviour 2.1),
//! and the blocks are read again when they run. How far a run has read
//! ahead is its *horizon*: a checkpoint keeps it, because the machine's state
//! there may follow from text past the checkpoint's place, and a run made
//! again after an edit resumes only at a checkpoint whose horizon is before
//! the edit (`again.rs`).

use std::collections::VecDeque;

use crate::machine::Ahead;
use crate::syntax::{Block, Blocks, Resume};

/// Blocks read ahead for one running block, kept while it runs (the
/// machine may ask for the same block twice) and, read from the run's own
/// text, for the blocks after it: when the next block runs, the ones read
/// past it still follow it (cutter compensation reads ahead at every block:
/// each block is then read once more, not once more per block before it).
#[derive(Default)]
pub(super) struct Reader<'t> {
    /// The run's block these were read for (its index), if any.
    for_index: Option<u32>,
    /// The blocks that run after it, in order (skipped blocks left out);
    /// in a batch of the two-thread run, the ones after the batch.
    blocks: VecDeque<Block>,
    /// The parser reading them, once a block asked.
    side: Option<Blocks<'t>>,
    /// The side parser read to the program's end.
    done: bool,
    /// They were read by a parser forked from the run's (not from a batch).
    forked: bool,
    /// The furthest byte any look-ahead of the run has read.
    pub(super) horizon: usize,
    /// Blocks marked `/` are not run (block skip switch on): they are not
    /// the blocks that follow.
    pub(super) block_skip: bool,
}

impl<'t> Reader<'t> {
    /// A reader for a run with the block skip switch as given.
    pub(super) fn new(block_skip: bool) -> Reader<'t> {
        Reader {
            block_skip,
            ..Reader::default()
        }
    }

    /// Look-ahead for block `index`, whose following blocks are read from
    /// `from`: nothing is done until the machine asks (most blocks never
    /// do; the `check` instruction count in docs/performance.md).
    #[inline(always)]
    pub(super) fn at<'r>(&'r mut self, index: u32, from: From<'r, 't>) -> Peek<'r, 't> {
        Peek {
            reader: self,
            index,
            from,
        }
    }

    /// Forgets everything read ahead: the block it was read for did not
    /// run (behaviour 2.24), and the next one takes its index.
    pub(super) fn forget(&mut self) {
        self.for_index = None;
        self.blocks.clear();
        self.side = None;
        self.done = false;
    }

    /// Forgets what was read ahead for another block than `index`, but
    /// for the block right after the one it was read for, reading the run's
    /// own text: that block is the first read, and the others follow it.
    fn for_block(&mut self, index: u32, forked: bool) {
        if self.for_index == Some(index) {
            return;
        }
        let next = self.for_index.and_then(|i| i.checked_add(1)) == Some(index);
        self.for_index = Some(index);
        if self.blocks.is_empty() && self.side.is_none() {
            // Nothing read past a batch: nothing to forget (cutter
            // compensation asks at every block; the 1M-block `check` with
            // G41, docs/performance.md).
            self.done = false;
            self.forked = forked;
            return;
        }
        if next && forked && self.forked && !self.blocks.is_empty() {
            self.blocks.pop_front();
            return;
        }
        self.blocks.clear();
        self.side = None;
        self.done = false;
        self.forked = forked;
    }
}

/// Where the blocks after the running one are read from.
pub(super) enum From<'r, 't> {
    /// Fork the run's parser (it stands at the running block's end).
    Parser(&'r Blocks<'t>),
    /// Blocks already read (the rest of a batch of the two-thread run),
    /// then the text from the place after the last of them.
    // The two-thread run is native only (`pipeline.rs`).
    #[cfg_attr(target_arch = "wasm32", allow(dead_code))]
    Read {
        /// The blocks read after the running one.
        blocks: &'r [Block],
        /// A parser standing after the last of them, to fork.
        then: Option<(&'t str, crate::syntax::ParseOptions, Resume)>,
    },
}

/// [`Ahead`] for the running block.
pub(super) struct Peek<'r, 't> {
    reader: &'r mut Reader<'t>,
    /// The running block's index.
    index: u32,
    from: From<'r, 't>,
}

impl Peek<'_, '_> {
    /// Reads one more block that runs past what the reader holds (past
    /// the batch in the two-thread run); false at the program's end.
    fn read_one(&mut self) -> bool {
        let r = &mut *self.reader;
        let block_skip = r.block_skip;
        if r.done {
            return false;
        }
        if r.side.is_none() {
            match &self.from {
                From::Parser(parser) => r.side = Some(parser.fork()),
                // After a batch: the text from the place after its last block.
                From::Read { then, .. } => match then {
                    Some((text, options, at)) => {
                        r.side = Some(Blocks::resume(text, *options, *at));
                    }
                    None => {
                        r.done = true;
                        return false;
                    }
                },
            }
        }
        let Some(side) = r.side.as_mut() else {
            return false;
        };
        let mut block = Block::default();
        loop {
            if !side.next_into(&mut block) {
                r.done = true;
                r.horizon = r.horizon.max(side.offset());
                return false;
            }
            r.horizon = r.horizon.max(side.offset());
            if !(block.skip && block_skip) {
                r.blocks.push_back(block);
                return true;
            }
        }
    }
}

impl<'r> Ahead for Peek<'r, '_> {
    fn peek(&mut self, k: usize) -> Option<&Block> {
        let batch: Option<&'r [Block]> = match &self.from {
            From::Parser(_) => None,
            From::Read { blocks, .. } => Some(blocks),
        };
        self.reader.for_block(self.index, batch.is_none());
        // The blocks of a batch (the two-thread run) are lent as they are.
        let mut k = k;
        if let Some(batch) = batch {
            let block_skip = self.reader.block_skip;
            // Without the block skip switch every block of the batch runs:
            // the k-th is at hand (cutter compensation asks at every block).
            if !block_skip {
                if let Some(b) = batch.get(k) {
                    return Some(b);
                }
                k -= batch.len();
            } else {
                let mut count = 0;
                for b in batch.iter().filter(|b| !b.skip) {
                    if count == k {
                        return Some(b);
                    }
                    count += 1;
                }
                k -= count;
            }
        }
        while self.reader.blocks.len() <= k {
            if !self.read_one() {
                return None;
            }
        }
        self.reader.blocks.get(k)
    }
}
