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
use crate::syntax::{Address, Block, Blocks, Header, ParseOptions, Resume, program_headers};

/// Most sequence numbers looked up by program kept (a program that jumps
/// to ever other numbers is read again rather than fill memory).
const MAX_LOCAL: usize = 4096;

/// The program's text, searchable by sequence number, and by program
/// number for the subprogram calls (behaviour 19).
pub(crate) struct Sequences<'t> {
    text: &'t str,
    options: ParseOptions,
    index: Option<Index<'t>>,
    /// The text's program headers, found at the first call.
    headers: Option<Vec<Header>>,
    /// Per program start and sequence number, where the block is.
    local: HashMap<(usize, u32), Option<Resume>>,
    /// Where the program being read starts (None: the main program).
    pub(super) current: Option<Resume>,
    /// Where the program M99 returns to starts (None: the main program).
    pub(super) caller: Option<Resume>,
    /// Subprogram calls open.
    pub(super) depth: usize,
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
            headers: None,
            local: HashMap::new(),
            current: None,
            caller: None,
            depth: 0,
        }
    }

    /// The header of program O`n` (the first, when two share a number).
    pub(crate) fn program(&mut self, n: u32) -> Option<Header> {
        let text = self.text;
        let headers = self.headers.get_or_insert_with(|| program_headers(text));
        headers.iter().find(|h| h.number == n).copied()
    }

    /// The first header of the text, the main program's when it comes
    /// before `pos` (a call in the main program is past its header).
    pub(crate) fn main_header(&mut self, pos: usize) -> Option<Header> {
        let text = self.text;
        let headers = self.headers.get_or_insert_with(|| program_headers(text));
        headers.first().filter(|h| h.pos <= pos).copied()
    }

    /// Where the main program starts: the text's start.
    pub(crate) fn main_start(&self) -> Resume {
        Blocks::new(self.text, self.options).resume_point()
    }

    /// A parser reading one program of the text from `at`.
    pub(crate) fn parser_at(&self, at: Resume) -> Blocks<'t> {
        Blocks::resume(self.text, self.options, at).one_program()
    }

    /// A parser reading the whole text from `at`, with the diagnostics
    /// reported before it (the run's first parser, at a checkpoint).
    pub(crate) fn whole_parser_at(
        &self,
        at: Resume,
        diagnostics: Vec<crate::diag::Diagnostic>,
    ) -> Blocks<'t> {
        Blocks::resume_after(self.text, self.options, at, diagnostics)
    }

    /// Where the block with sequence number `n` of the program that starts
    /// at `start` (None: the main program) stands: the first such block of
    /// that program, or None (behaviour 19.4, 19.5). The reusable jump
    /// target of a GOTO as of an M99 P.
    pub(crate) fn find_in(&mut self, start: Option<Resume>, n: u32) -> Option<Resume> {
        let start = start.unwrap_or_else(|| self.main_start());
        let key = (start.offset(), n);
        if let Some(found) = self.local.get(&key) {
            return *found;
        }
        let mut blocks = self.parser_at(start);
        let mut block = Block::default();
        let mut found = None;
        loop {
            let before = blocks.resume_point();
            if !blocks.next_into(&mut block) {
                break;
            }
            if block.get(Address::N).is_some_and(|w| w.int() == n) {
                found = Some(before);
                break;
            }
        }
        if self.local.len() >= MAX_LOCAL {
            self.local.clear();
        }
        self.local.insert(key, found);
        found
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

    fn block_text(&self, span: crate::diag::Span) -> Option<&str> {
        self.text.get(span.start as usize..span.end as usize)
    }

    fn has_program(&mut self, n: u32) -> bool {
        self.program(n).is_some()
    }

    fn has_local(&mut self, n: u32) -> bool {
        self.find_in(self.current, n).is_some()
    }

    fn has_return(&mut self, n: u32) -> bool {
        let to = match self.depth {
            0 => self.current,
            _ => self.caller,
        };
        self.find_in(to, n).is_some()
    }

    fn depth(&self) -> usize {
        self.depth
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
