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

use crate::machine::Ahead;
use crate::syntax::{Block, Blocks, Resume};

/// Blocks read ahead for one running block, kept while it runs (the
/// machine may ask for the same block twice).
#[derive(Default)]
pub(super) struct Reader<'t> {
    /// The run's block these were read for (its index), if any.
    for_index: Option<u32>,
    /// The blocks that run after it, in order (skipped blocks left out).
    blocks: Vec<Block>,
    /// The parser reading them, once a block asked.
    side: Option<Blocks<'t>>,
    /// The side parser read to the program's end.
    done: bool,
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

    /// Forgets what was read ahead for another block than `index`.
    fn for_block(&mut self, index: u32) {
        if self.for_index != Some(index) {
            self.for_index = Some(index);
            self.blocks.clear();
            self.side = None;
            self.done = false;
        }
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
    /// Reads one more block that runs; false at the program's end.
    fn read_one(&mut self) -> bool {
        let r = &mut *self.reader;
        let block_skip = r.block_skip;
        if r.done {
            return false;
        }
        // Blocks of a batch first (the two-thread run), then the text.
        if let From::Read { blocks, then } = &self.from {
            let seen = r.blocks.len();
            let mut taken = 0;
            for b in blocks.iter() {
                if b.skip && block_skip {
                    continue;
                }
                if taken == seen {
                    r.blocks.push(b.clone());
                    return true;
                }
                taken += 1;
            }
            if r.side.is_none() {
                match then {
                    Some((text, options, at)) => {
                        r.side = Some(Blocks::resume(text, *options, *at));
                    }
                    None => {
                        r.done = true;
                        return false;
                    }
                }
            }
        }
        let side = match (&mut r.side, &self.from) {
            (Some(side), _) => side,
            (None, From::Parser(parser)) => r.side.insert(parser.fork()),
            (None, From::Read { .. }) => {
                r.done = true;
                return false;
            }
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
                r.blocks.push(block);
                return true;
            }
        }
    }
}

impl Ahead for Peek<'_, '_> {
    fn peek(&mut self, k: usize) -> Option<&Block> {
        self.reader.for_block(self.index);
        while self.reader.blocks.len() <= k {
            if !self.read_one() {
                return None;
            }
        }
        self.reader.blocks.get(k)
    }
}
