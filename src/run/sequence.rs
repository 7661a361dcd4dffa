//! Finding a block by its sequence number and reading on from there
//! (behaviour 15.3): the run's answer to the machine's [`ProgramText`].
//!
//! The run streams the program, so a block that names a sequence number
//! (G70–G73's P and Q; subprogram calls by N later) is found by reading the
//! text again with a parser of its own. That parser goes through the text
//! once, from the start, as far as the first search needs, and notes where
//! each sequence number first appears, so later searches of a long program
//! do not read it again; the blocks asked for are then read by a fresh
//! parser resumed at that place, in the context (units, canned cycle) the
//! text gives them there. Nothing is read until a block asks.

use std::collections::HashMap;

use crate::machine::program::ProgramText;
use crate::syntax::{Address, Block, Blocks, ParseOptions, Resume};

/// The program's text, searchable by sequence number.
pub(crate) struct Sequences<'t> {
    text: &'t str,
    options: ParseOptions,
    index: Option<Index<'t>>,
}

/// Where each sequence number first appears, as far as the text has been
/// searched.
struct Index<'t> {
    scanner: Blocks<'t>,
    block: Block,
    first: HashMap<u32, Resume>,
    done: bool,
}

impl<'t> Sequences<'t> {
    /// The text of a run, parsed with the run's options.
    pub(crate) fn new(text: &'t str, options: ParseOptions) -> Sequences<'t> {
        Sequences {
            text,
            options,
            index: None,
        }
    }

    /// Where the parser stands before the first block whose sequence
    /// number is `n` (searching the text from its start), or None.
    pub(crate) fn find(&mut self, n: u32) -> Option<Resume> {
        let index = self.index.get_or_insert_with(|| Index {
            scanner: Blocks::new(self.text, self.options),
            block: Block::default(),
            first: HashMap::new(),
            done: false,
        });
        if let Some(at) = index.first.get(&n) {
            return Some(*at);
        }
        while !index.done {
            let before = index.scanner.resume_point();
            if !index.scanner.next_into(&mut index.block) {
                index.done = true;
                break;
            }
            if let Some(w) = index.block.get(Address::N) {
                let m = w.int();
                index.first.entry(m).or_insert(before);
                if m == n {
                    return Some(before);
                }
            }
        }
        None
    }
}

impl ProgramText for Sequences<'_> {
    fn read_from(&mut self, n: u32, each: &mut dyn FnMut(&Block) -> bool) -> Option<u32> {
        let at = self.find(n)?;
        let mut blocks = Blocks::resume(self.text, self.options, at);
        let mut block = Block::default();
        let mut start = None;
        while blocks.next_into(&mut block) {
            start.get_or_insert(block.span.start);
            if !each(&block) {
                break;
            }
        }
        start
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers_from(text: &str, n: u32, count: usize) -> Option<(u32, Vec<u32>)> {
        let mut s = Sequences::new(text, ParseOptions::default());
        let mut seen = Vec::new();
        let at = s.read_from(n, &mut |b| {
            seen.push(b.span.line);
            seen.len() < count
        })?;
        Some((at, seen))
    }

    #[test]
    fn behaviour15_3_the_first_block_with_the_number_and_the_blocks_after_it() {
        let text = "G00 X1.\nN10 X2.\nN20 X3.\nN10 X4.\nX5.\n";
        // N10 first appears on line 2 (byte 8); the next three blocks follow.
        assert_eq!(numbers_from(text, 10, 3), Some((8, vec![2, 3, 4])));
        assert_eq!(numbers_from(text, 20, 9), Some((16, vec![3, 4, 5])));
        assert_eq!(numbers_from(text, 30, 1), None);
    }

    #[test]
    fn behaviour15_3_a_search_after_another_uses_what_the_first_found() {
        let text = "N1 X1.;N2 X2.;N3 X3.";
        let mut s = Sequences::new(text, ParseOptions::default());
        assert!(s.find(3).is_some());
        // N1 was passed on the way to N3: found without reading again.
        let at = s.find(1).map(|r| r.offset());
        assert_eq!(at, Some(0));
        assert_eq!(s.find(2).map(|r| r.offset()), Some(7));
        assert!(s.find(4).is_none());
    }
}
